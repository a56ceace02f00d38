//! Stage 4: the precision ladder — the root at `f64` (then double-double above 106 bits, and
//! about half the working precision above 1024 bits) lifted to the working precision by chord
//! steps with the stage below's F′, or at double-double by one Halley step.

use super::finish::{carry_cubic, finish};
use super::newton::{slope_at, solve_core, Chord, Handed, Newton, Stage};
use super::seed::lowest_stage;
use super::Shape;
use crate::error::{Error, Result};
use crate::estimate::RelError;
use crate::physics::Speed;
use crate::routes::evaluate::{Evaluator, IntegralOptions};
use crate::routes::graded::GradedBody;
use crate::routes::{Evaluation, Method};
use crate::scalar::{Dd, Real};
use std::cell::OnceCell;
use std::sync::{Arc, OnceLock};

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
    /// root), rounded to `f64`, when it converges from there within
    /// [`super::seed::GUESS_EVALUATIONS`], else from the static ellipse. A bound that misses
    /// the tolerance (or 1/64 without one: a stop from a far seed at |ln k| ≫ 1) is refined
    /// from its own root at the working precision; one still missing it is
    /// [`Error::Unreachable`].
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
        let wanted = tol
            .clone()
            .unwrap_or_else(|| T::from_ratio(1, 64, ratio.prec()));
        if shape.error_estimate <= wanted {
            return Ok(shape);
        }
        let refined = solve_core(&self.top, ratio, Stage::from(Some(&shape.k), None))?.0;
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

    /// The ladder: at `f64` the plain solve; above, the `f64` stage (inputs rounded to `f64`,
    /// the speed by its gap), above 106 bits the double-double stage ([`Self::via_dd`]), above
    /// 1024 bits the half-precision stage instead ([`Self::via_mid`]); then the working
    /// precision from the last stage's root and F′ — one Halley step or two chord steps at
    /// double-double, a few chord steps above. If a lower stage fails, the working precision
    /// solves alone. `allow_chord`: whether the last evaluation may skip the k-derivatives
    /// (false for a stage that hands them on).
    fn climb(&self, ratio: &T, tol: Option<T>, guess: Option<f64>, allow_chord: bool) -> Handed<T> {
        let p = ratio.prec();
        if T::bits(p) <= 53 {
            return lowest_stage(&self.top, ratio, allow_chord, tol, guess);
        }
        if let Some(done) = self.via_mid(ratio, &tol, guess, allow_chord) {
            return done;
        }
        let alone = |tol| lowest_stage(&self.top, ratio, allow_chord, tol, None);
        // Each lower stage ends on a Newton step, so that its derivatives serve the next.
        let Some(Ok((s64, slope64))) = (self.lower(&self.stage64, |s| s.solve_cache().at_f64(s)))
            .map(|ev| lowest_stage(ev, &ratio.to_f64(), false, None, guess))
        else {
            return alone(tol);
        };
        if T::bits(p) > 106 {
            if let Some(shape) = self.via_dd(ratio, &tol, s64.k, slope64.as_ref(), allow_chord) {
                return shape;
            }
        }
        // The Halley step, unless rounding the inputs to f64 moved the root by more than
        // ~1e-15 (k's sensitivity to the gap's relative change is about 1/4), where two chord
        // steps are cheaper than the attempt and a Newton step.
        let moved = |x: &T| {
            let x64 = x.to_f64();
            (x.clone() - T::from_f64(x64, p)).abs().to_f64() / x64.abs().max(f64::MIN_POSITIVE)
        };
        let speed = self.top.speed();
        let perturbation = moved(ratio) + moved(speed.material().nu()) + moved(speed.gap());
        let seed = T::from_f64(s64.k, p);
        let errs = (T::from_f64(F64_SLOPE, p), T::from_f64(F64_SEED, p));
        let stage = Stage {
            seed_slope: slope64.as_ref().map(|c| lift(c, p, errs)),
            halley: T::bits(p) <= 106 && perturbation <= 1e-15,
            allow_chord,
            ..Stage::from(Some(&seed), tol)
        };
        solve_core(&self.top, ratio, stage)
    }

    /// Above [`MID_ABOVE_BITS`] the stage below p bits is the same solve at
    /// m = p/2 + [`MID_GUARD_BITS`] bits: its root and F′ (~2^-m each) leave one or two chord
    /// steps at p instead of Newton's steps from the double-double root. Its root is bounded by
    /// its estimate and 2^(11−m), its F′ by 2^(16−m) (the double-double margins); a stage that
    /// ended on a chord step gets its derivatives by one more evaluation at its precision.
    /// `None` (the ladder goes on from `f64`) at or below 1024 bits, at fixed precision, or
    /// when that stage fails.
    fn via_mid(
        &self,
        ratio: &T,
        tol: &Option<T>,
        guess: Option<f64>,
        allow_chord: bool,
    ) -> Option<Handed<T>> {
        let p = ratio.prec();
        let bits = T::bits(p);
        if bits <= MID_ABOVE_BITS {
            return None;
        }
        let pm = T::lower_prec(p, bits / 2 + MID_GUARD_BITS)?;
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
        let c = c.or_else(|| slope_at(&mid.top, &ratio_m, s.k.clone().ln()))?;
        let (m, one) = (T::bits(pm) as i32, T::one(p));
        let seed_err = s
            .error_estimate
            .with_prec(p)
            .max_of(one.clone().mul_pow2(11 - m));
        let seed = s.k.with_prec(p);
        let stage = Stage {
            seed_slope: Some(lift(&c, p, (one.mul_pow2(16 - m), seed_err))),
            allow_chord,
            ..Stage::from(Some(&seed), tol.clone())
        };
        Some(solve_core(&self.top, ratio, stage))
    }

    /// The double-double stage from the `f64` root, then the working precision from its root
    /// (its root off by ~2^-100: one Newton step fewer); `None` when the double-double stage
    /// fails.
    fn via_dd(
        &self,
        ratio: &T,
        tol: &Option<T>,
        k64: f64,
        slope64: Option<&Chord<f64>>,
        allow_chord: bool,
    ) -> Option<Handed<T>> {
        let p = ratio.prec();
        let seed_dd = Dd::from_f64(k64, ());
        let errs = (Dd::from_f64(F64_SLOPE, ()), Dd::from_f64(F64_SEED, ()));
        let stage = Stage {
            seed_slope: slope64.map(|c| lift(c, (), errs)),
            allow_chord: false,
            ..Stage::from(Some(&seed_dd), None)
        };
        let ratio_dd = Dd::from_float(&ratio.to_float(T::bits(p)), ());
        let (s, c) = solve_core(
            self.lower(&self.stage_dd, |s| s.solve_cache().at_dd(s))?,
            &ratio_dd,
            stage,
        )
        .ok()?;
        let seed = T::from_float(&s.k.to_float(106), p);
        let errs = (T::from_f64(DD_SLOPE, p), T::from_f64(DD_SEED, p));
        let stage = Stage {
            seed_slope: c.as_ref().map(|c| lift(c, p, errs)),
            allow_chord,
            ..Stage::from(Some(&seed), tol.clone())
        };
        Some(solve_core(&self.top, ratio, stage))
    }
}

/// What the ellipse solves at one speed keep, with the speed and shared by its clones: the speed
/// at `f64` and double-double (the lower ladder stages, whose set-ups then serve every solve)
/// and the k = 1 probe's evaluation by method (auto, fixed), which does not depend on A1/B1
/// ([`Newton::probe_k_one`]; it still counts as an evaluation, so that a solve's steps and bits
/// do not depend on whether it was kept).
#[derive(Clone, Debug)]
pub(crate) struct SolveCache<T: Real>(Arc<Kept<T>>);

/// Values kept on first use, one slot each.
type Slots<V> = Box<[OnceLock<V>]>;

#[derive(Debug)]
struct Kept<T: Real> {
    at_f64: OnceLock<Option<Speed<f64>>>,
    at_dd: OnceLock<Option<Speed<Dd>>>,
    probe: [OnceLock<Evaluation<T>>; 2],
    /// F + ln(A1/B1) and F′ at the nodes of [`super::seed::grid_seed`], each on first use.
    grid: OnceLock<Slots<Option<(f64, f64)>>>,
    /// The graded route's node values by plan (units, pole subtracted), each on first use.
    graded: OnceLock<Slots<Arc<GradedBody<T>>>>,
}

impl<T: Real> SolveCache<T> {
    /// An empty cache.
    pub(crate) fn new() -> Self {
        SolveCache(Arc::new(Kept {
            at_f64: OnceLock::new(),
            at_dd: OnceLock::new(),
            probe: [OnceLock::new(), OnceLock::new()],
            grid: OnceLock::new(),
            graded: OnceLock::new(),
        }))
    }

    /// `speed` (the one holding this cache) at `f64`; `None` where it does not convert.
    fn at_f64(&self, speed: &Speed<T>) -> Option<&Speed<f64>> {
        self.0.at_f64.get_or_init(|| speed.at(()).ok()).as_ref()
    }

    /// `speed` at double-double; `None` where it does not convert.
    fn at_dd(&self, speed: &Speed<T>) -> Option<&Speed<Dd>> {
        self.0.at_dd.get_or_init(|| speed.at(()).ok()).as_ref()
    }

    /// The graded route's node values for a plan of `units` (`subtract`: the pole subtracted),
    /// built by `build` on first use and shared by every layout at this speed with that plan
    /// (the same values as a layout built anew); plans of [`GRADED_UNITS`] units or more are
    /// not kept.
    pub(crate) fn graded_body(
        &self,
        units: usize,
        subtract: bool,
        build: impl FnOnce() -> Result<GradedBody<T>>,
    ) -> Result<Arc<GradedBody<T>>> {
        let slots = self
            .0
            .graded
            .get_or_init(|| (0..2 * GRADED_UNITS).map(|_| OnceLock::new()).collect());
        let Some(slot) = slots.get(2 * units + usize::from(subtract)) else {
            return build().map(Arc::new);
        };
        if let Some(body) = slot.get() {
            return Ok(body.clone());
        }
        let body = Arc::new(build()?);
        Ok(slot.get_or_init(|| body).clone())
    }

    /// The slots of the seed grid's `n` nodes.
    pub(super) fn grid(&self, n: usize) -> &[OnceLock<Option<(f64, f64)>>] {
        self.0
            .grid
            .get_or_init(|| (0..n).map(|_| OnceLock::new()).collect())
    }

    /// The probe's slot for `method` (`None`: not kept).
    pub(super) fn probe(&self, method: Method) -> Option<&OnceLock<Evaluation<T>>> {
        match method {
            Method::Auto => Some(&self.0.probe[0]),
            Method::Fixed => Some(&self.0.probe[1]),
            _ => None,
        }
    }
}

/// The plans a speed keeps graded node values for: up to 191 units of ln 2 (k ≤ 2^180 needs
/// at most about 183).
const GRADED_UNITS: usize = 192;

/// The integral options of a Newton iterate: the method, with k-derivatives.
fn newton_options(method: Method) -> IntegralOptions {
    IntegralOptions {
        method,
        derivatives: true,
        ..Default::default()
    }
}

/// Bounds on a lower stage's F′ (relative; a margin over the fixed rules' measured
/// derivative errors) and on its root's error in λ (`docs/calibration.md`).
const F64_SLOPE: f64 = 9.094947017729282e-13; // 2^-40
const F64_SEED: f64 = 3.552713678800501e-15; // 2^-48
const DD_SLOPE: f64 = 8.077935669463161e-28; // 2^-90
const DD_SEED: f64 = 2.524354896707238e-29; // 2^-95

/// Above this precision the stage below is the solve at about half of it ([`ShapeSolver::via_mid`]).
const MID_ABOVE_BITS: u32 = 1024;

/// Bits of the half-precision stage beyond half: a chord step's error ~2^-2m, 64 times that
/// ≤ 2^-p with ~40 bits to spare.
const MID_GUARD_BITS: u32 = 32;

/// A stage's derivatives carried to the next stage's precision `p`, with the bounds
/// `(slope_err, seed_err)` on its F′ and root.
fn lift<S: Real, T: Real>(
    c: &Chord<S>,
    p: T::Prec,
    (slope_err, seed_err): (T, T),
) -> (Chord<T>, T) {
    let up = |x: &S| T::from_float(&x.to_float(S::bits(x.prec())), p);
    let before = c.before.as_ref().map(|b| [0, 1, 2, 3].map(|i| up(&b[i])));
    let (lam, di1, di2, df) = (up(&c.lam), up(&c.di1), up(&c.di2), up(&c.df));
    (
        Chord {
            lam,
            di1,
            di2,
            df,
            rel_err: slope_err,
            before,
        },
        seed_err,
    )
}

/// The distance in λ of [`secant_partner`]'s evaluation: √r for derivatives of relative error
/// r ~ 2⁻⁴⁰, where the secant's rounding and truncation errors balance.
const PARTNER_STEP: f64 = 9.5367431640625e-7; // 2^-20

/// A guessed stage that converged in one evaluation leaves no earlier iterate for the next
/// stage's secant F″ ([`f_second`]): one more evaluation with derivatives at [`PARTNER_STEP`]
/// from its root supplies it. Unchanged if that evaluation fails.
pub(super) fn secant_partner<S: Real>(ev: &Evaluator<S>, ratio: &S, mut c: Chord<S>) -> Chord<S> {
    let lam = c.lam.clone() + S::from_f64(PARTNER_STEP, ratio.prec());
    if let Some(b) = slope_at(ev, ratio, lam) {
        c.before = Some([b.lam, b.df, b.di1, b.di2]);
    }
    c
}

impl<T: Real> Newton<'_, T> {
    /// The double-double stage's Halley step from the `f64` root ([`halley_from_f64`]): one
    /// evaluation with derivatives; `None` and a Newton step instead when its bounds miss ε.
    pub(super) fn halley_step(&mut self, c: &Chord<T>) -> Result<Option<Shape<T>>> {
        let lam = self.lam.clone();
        let (f, df, ci) = self.eval(&lam, None)?;
        self.spent += 1;
        let scale = lam.clone().abs().max_of(T::one(self.prec()));
        if let Some((root, err, ints)) = halley_from_f64(&lam, &f, &df, &ci, c, &self.eps, &scale) {
            return Ok(Some(finish(
                root.clone(),
                &root,
                ints,
                self.ratio,
                err,
                self.spent,
            )));
        }
        if df.is_positive() && df.is_finite() {
            self.lam = lam - f / &df;
        }
        Ok(None)
    }
}

/// F″ at λ0 by the secant between the lower stage's last two iterates (`c`, `c.before`) and
/// its bound 2r|F′|/D + (1 + |F″|)(D + |λ0 − λ_c|) (rounding over their distance D, the
/// truncation with |F‴| ≤ 1 + |F″|); `None` when the bound exceeds 0.1. Needs no evaluation
/// at λ0, so that a stage decides before evaluating whether the Halley step can work.
pub(super) fn f_second<T: Real>(c: &Chord<T>, lam0: &T) -> Option<(f64, f64)> {
    let b = c.before.as_ref()?;
    let (la, lb) = (b[0].to_f64(), c.lam.to_f64());
    let d = (lb - la).abs();
    if d == 0.0 {
        return None;
    }
    let f2 = (c.df.to_f64() - b[1].to_f64()) / (lb - la);
    let off = (lam0.to_f64() - lb).abs();
    let f2_err = 2.0 * c.rel_err.to_f64() * c.df.to_f64().abs() / d + (1.0 + f2.abs()) * (d + off);
    (f2_err.is_finite() && f2_err <= 0.1).then_some((f2, f2_err))
}

/// F″, d²I1/dk², d²I2/dk² at λ0 by secants ([`f_second`]) with their bounds; for I″,
/// 2r|I′|/Δk + 100(I/k³)(Δk + |k0 − k_c|) (|k³I‴| ≤ 100 I assumed: 60 for I1 ∝ ln k/k³).
fn curvature<T: Real>(
    c: &Chord<T>,
    lam0: &T,
    ints: &Evaluation<T>,
) -> Option<([f64; 3], [f64; 3])> {
    let (f2, f2_err) = f_second(c, lam0)?;
    let b = c.before.as_ref()?;
    let r = c.rel_err.to_f64();
    let (la, lb) = (b[0].to_f64(), c.lam.to_f64());
    let (ka, kb, k0) = (la.exp(), lb.exp(), lam0.to_f64().exp());
    let dk = kb - ka;
    let reach = dk.abs() + (k0 - kb).abs();
    let second = |dia: &T, dib: &T| (dib.to_f64() - dia.to_f64()) / dk;
    let i_err = |di: &T, i: &T| {
        2.0 * r * di.to_f64().abs() / dk.abs() + 100.0 * i.to_f64() * reach / k0.powi(3)
    };
    Some((
        [f2, second(&b[2], &c.di1), second(&b[3], &c.di2)],
        [f2_err, i_err(&c.di1, &ints.i1), i_err(&c.di2, &ints.i2)],
    ))
}

/// The double-double step straight from the `f64` root λ0: with F, F′, I′ at λ0 and F″, I″
/// from the `f64` stage ([`curvature`]), the Halley step h = δ − F″δ²/(2F′) (δ = −F/F′; error
/// ≤ (|ΔF″|/2F′)δ² + |δ|³, required ≤ ε·scale/4) and I1, I2 carried to second order (relative
/// error ≤ ½|ΔI″|dk²/I, required ≤ ε): one evaluation with derivatives instead of two without.
fn halley_from_f64<T: Real>(
    lam: &T,
    f: &T,
    df: &T,
    ints: &Evaluation<T>,
    c: &Chord<T>,
    eps: &T,
    scale: &T,
) -> Option<(T, T, Evaluation<T>)> {
    let ([f2, i1pp, i2pp], [f2_err, i1_err, i2_err]) = curvature(c, lam, ints)?;
    if !(df.is_positive() && df.is_finite()) {
        return None;
    }
    let p = eps.prec();
    let newton = -(f.clone() / df);
    let (nf, dff) = (newton.to_f64().abs(), df.to_f64());
    let err = f2_err / (2.0 * dff) * nf * nf + nf * nf * nf;
    let epsf = eps.to_f64();
    if !(err.is_finite() && err <= epsf * scale.to_f64() / 4.0) {
        return None;
    }
    let h = newton.clone() - T::from_f64(f2, p) * newton.square() / df.clone().mul_i64(2);
    let k0 = lam.clone().exp();
    let dk = (lam.clone() + &h).exp() - &k0;
    let dkf = dk.to_f64();
    let zero = T::zero(p);
    let carry = |i: &T, di: &T, ipp: f64, ipp_err: f64| -> (T, T, f64) {
        let (val, der) = carry_cubic(i, di, &T::from_f64(ipp / 2.0, p), &zero, &dk);
        (val, der, 0.5 * ipp_err * dkf * dkf / i.to_f64())
    };
    let (i1, di1, e1) = carry(&ints.i1, &ints.di1_dk(), i1pp, i1_err);
    let (i2, di2, e2) = carry(&ints.i2, &ints.di2_dk(), i2pp, i2_err);
    if !(e1.is_finite() && e2.is_finite() && e1.max(e2) <= epsf) {
        return None;
    }
    let carried = T::from_f64(e1.max(e2), p);
    let ints = Evaluation {
        i1,
        i2,
        dk: Some([di1, di2]),
        error_estimate: ints.error_estimate.clone() + &carried,
        extra_error: ints.extra_error.clone() + &carried.sqrt(),
        ..ints.clone()
    };
    Some((lam.clone() + h, T::from_f64(err, p), ints))
}
