//! Stage 4: the precision ladder — the root at `f64` (then double-double above 106 bits, and
//! about half the working precision above 1024 bits) lifted to the working precision by chord
//! steps with the stage below's F′, or at double-double by one Halley step.

use super::newton::{newton_options, residual, Chord, Handed, Newton};
use super::seed::lowest_stage;
use super::Shape;
use crate::error::{Error, Result};
use crate::estimate::RelError;
use crate::physics::Speed;
use crate::routes::evaluate::Evaluator;
use crate::routes::Method;
use crate::scalar::{Dd, Real};
use std::cell::OnceCell;

/// The ellipse solve for one speed and method: the evaluators of the ladder's stages, each
/// built on first use and kept, so that their set-ups serve every solve at this speed.
pub(crate) struct ShapeSolver<T: Real + 'static> {
    top: Evaluator<T>,
    stage64: OnceCell<Option<Evaluator<f64>>>,
    stage_dd: OnceCell<Option<Evaluator<Dd>>>,
    /// Above [`MID_ABOVE_BITS`], the solver at about half the working precision.
    stage_mid: OnceCell<Option<Box<ShapeSolver<T>>>>,
}

impl<T: Real> ShapeSolver<T> {
    /// The solver for `speed` by `method` (checked by the caller).
    pub(crate) fn new(speed: &Speed<T>, method: Method) -> Result<Self> {
        Ok(ShapeSolver {
            top: Evaluator::new(speed, newton_options(method))?,
            stage64: OnceCell::new(),
            stage_dd: OnceCell::new(),
            stage_mid: OnceCell::new(),
        })
    }

    /// Solves (33) at `ratio` to `tol` (`None`: the working precision's floor) by the ladder,
    /// whose lowest stage starts from the `seed` (the caller's) or the `guess` (a neighbour's
    /// root), rounded to `f64` ([`lowest_stage`]). A bound that misses the tolerance (or 1/64
    /// without one) is refined from its own root at the working precision; one still missing
    /// it is [`Error::Unreachable`].
    #[inline]
    pub(crate) fn solve(
        &self,
        ratio: &T,
        tol: Option<T>,
        seed: Option<&T>,
        guess: Option<f64>,
    ) -> Result<Shape<T>> {
        let guess = seed.map(|s| s.to_f64()).or(guess);
        let shape = self.climb(ratio, tol.clone(), guess, true)?.0;
        let wanted = tol.unwrap_or_else(|| T::from_ratio(1, 64, ratio.prec()));
        if shape.error_estimate <= wanted {
            return Ok(shape);
        }
        // The stops bound the error by about 2|λ|·tol: a step at ε from the root meets tol.
        let refined = Newton::new(&self.top, ratio, Some(&shape.k), None, true).run(None)?;
        let refined = refined.0;
        if refined.error_estimate <= wanted {
            return Ok(refined);
        }
        Err(Error::Unreachable {
            what: "the axis ratio k",
            tolerance: RelError::of(&wanted).to_string(),
            reason: format!(
                "the solve's bound is {}",
                RelError::of(&refined.error_estimate)
            ),
        })
    }

    /// The speed this solver serves.
    pub(crate) fn speed(&self) -> &Speed<T> {
        self.top.speed()
    }

    /// The evaluator of the `f64` or double-double stage, on the speed's kept copy at that
    /// precision (`speed`), whose set-ups serve every solve at this speed; `None` where the
    /// speed does not convert.
    fn lower<'s, S: Real<Prec = ()>>(
        &'s self,
        cell: &'s OnceCell<Option<Evaluator<S>>>,
        speed: impl FnOnce(&'s Speed<T>) -> Option<&'s Speed<S>>,
    ) -> Option<&'s Evaluator<S>> {
        cell.get_or_init(|| {
            Evaluator::new(speed(self.top.speed())?, newton_options(self.top.method())).ok()
        })
        .as_ref()
    }

    /// The ladder: at `f64` the plain solve; above, the working precision from the root and F′
    /// of the stage below ([`Self::below`]), or alone if the stages below fail.
    /// `allow_chord`: whether the last evaluation may skip the k-derivatives (not for a stage
    /// that hands them on).
    fn climb(&self, ratio: &T, tol: Option<T>, guess: Option<f64>, allow_chord: bool) -> Handed<T> {
        if T::bits(ratio.prec()) <= 53 {
            return lowest_stage(&self.top, ratio, allow_chord, tol, guess);
        }
        let Some((seed, handed)) = self.below(ratio, guess) else {
            return lowest_stage(&self.top, ratio, allow_chord, tol, None);
        };
        Newton::new(&self.top, ratio, Some(&seed), tol, allow_chord).run(handed)
    }

    /// The stage below p bits, lifted to p: its root and its F′ with the bounds on both: above [`MID_ABOVE_BITS`] the solve at
    /// m = p/2 + [`MID_GUARD_BITS`] bits ([`Self::below_mid`]), else the `f64` stage (inputs
    /// rounded to `f64`), above 106 bits followed by the double-double stage. Each ends on an
    /// evaluation with derivatives, which serve the stage above. `None` when the stages fail.
    fn below(&self, ratio: &T, guess: Option<f64>) -> Option<Lifted<T>> {
        let (p, bits) = (ratio.prec(), T::bits(ratio.prec()));
        let mid = (bits > MID_ABOVE_BITS).then(|| self.below_mid(ratio, guess));
        if let Some(lifted) = mid.flatten() {
            return Some(lifted);
        }
        let ev64 = self.lower(&self.stage64, |s| s.solve_cache().at_f64(s))?;
        let (s64, c64) = lowest_stage(ev64, &ratio.to_f64(), false, None, guess).ok()?;
        if bits > 106 {
            let (seed_dd, handed) = (
                Dd::from_f64(s64.k, ()),
                c64.as_ref().map(|c| lift(c, (), F64_BOUNDS)),
            );
            let ratio_dd = Dd::from_float(&ratio.to_float(bits), ());
            let ev_dd = self.lower(&self.stage_dd, |s| s.solve_cache().at_dd(s));
            let stage_dd = |ev| Newton::new(ev, &ratio_dd, Some(&seed_dd), None, false);
            if let Some(Ok((s, c))) = ev_dd.map(|ev| stage_dd(ev).run(handed)) {
                let seed = T::from_float(&s.k.to_float(106), p);
                return Some((seed, c.map(|c| lift(&c, p, DD_BOUNDS))));
            }
        }
        let slope = c64.map(|c| lift(&c, p, F64_BOUNDS));
        Some((T::from_f64(s64.k, p), slope))
    }

    /// The half-precision stage of [`Self::below`]: its root bounded by its estimate and
    /// 2^(11−m), its F′ by 2^(16−m) (the double-double stage's margins in bits); a stage that
    /// ended on a chord step gets its derivatives by one more evaluation at its precision.
    fn below_mid(&self, ratio: &T, guess: Option<f64>) -> Option<Lifted<T>> {
        let p = ratio.prec();
        let pm = T::lower_prec(p, T::bits(p) / 2 + MID_GUARD_BITS)?;
        let mid = (self.stage_mid)
            .get_or_init(|| {
                let speed = self.top.speed().at::<T>(pm).ok()?;
                ShapeSolver::new(&speed, self.top.method())
                    .ok()
                    .map(Box::new)
            })
            .as_deref()?;
        let ratio_m = ratio.with_prec(pm);
        let (s, c) = mid.climb(&ratio_m, None, guess, false).ok()?;
        let lam = s.k.clone().ln();
        let c = match c {
            Some(c) => c,
            None => {
                let (_, df, ci, _) = residual(&mid.top, &ratio_m, &lam, None).ok()?;
                Chord::at(lam, df, &ci, None)
            }
        };
        let m = T::bits(pm) as i32;
        let (chord, seed_err) = lift(&c, p, (16 - m, 11 - m));
        let seed_err = (s.error_estimate.with_prec(p)).max_of(seed_err);
        Some((s.k.with_prec(p), Some((chord, seed_err))))
    }
}

/// A lower stage's result at the precision above: its root, and its F′ with the bound on its
/// relative error and the bound on the root's.
type Lifted<T> = (T, Option<(Chord<T>, T)>);

/// log₂ of the bounds on a lower stage's F′ (relative; a margin over the fixed rules'
/// measured derivative errors) and on its root's error in λ (`docs/calibration.md`).
const F64_BOUNDS: (i32, i32) = (-40, -48);
const DD_BOUNDS: (i32, i32) = (-90, -95);

/// Above this precision the stage below is the solve at about half of it.
const MID_ABOVE_BITS: u32 = 1024;

/// Bits of the half-precision stage beyond half: a chord step's error ~2^-2m, 64 times that
/// ≤ 2^-p with ~40 bits to spare.
const MID_GUARD_BITS: u32 = 32;

/// A stage's derivatives carried to the next stage's precision `p`, with the bounds
/// 2^slope on its F′ (relative) and 2^seed on its root (in λ), `(slope, seed)` = `log2`.
fn lift<S: Real, T: Real>(c: &Chord<S>, p: T::Prec, log2: (i32, i32)) -> (Chord<T>, T) {
    let up = |x: &S| T::from_float(&x.to_float(S::bits(x.prec())), p);
    let chord = Chord {
        lam: up(&c.lam),
        di1: up(&c.di1),
        di2: up(&c.di2),
        df: up(&c.df),
        rel_err: T::one(p).mul_pow2(log2.0),
        before: c.before.as_ref().map(|b| [0, 1, 2, 3].map(|i| up(&b[i]))),
    };
    (chord, T::one(p).mul_pow2(log2.1))
}
