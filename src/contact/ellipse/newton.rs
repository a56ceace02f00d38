//! Stage 3 of the ellipse solve: Newton's method on F(λ) = ln(I2/(I1·A1/B1)), λ = ln k,
//! safeguarded by a bracket (bisection when a step leaves it), with its stopping rules and the
//! chord steps at its end.

use super::finish::{carry_error, finish, hermite_root};
use super::ladder::f_second;
use super::seed::static_seed;
use super::{check_ratio, shape_residual, shape_slope, Shape};
use crate::error::{Error, Result};
use crate::estimate::RelError;
use crate::routes::evaluate::Evaluator;
use crate::routes::{fast, AxisRatio, Evaluation, Method};
use crate::scalar::{short, Real};

/// A stage's result: the shape and the derivatives it hands on to the stage above.
pub(super) type Handed<T> = Result<(Shape<T>, Option<Chord<T>>)>;

/// F and F′ = k(I2′/I2 − I1′/I1) at λ, with the integrals. With `chord` (the derivatives
/// kept from an earlier iterate) the derivatives are not evaluated again: a chord step instead
/// of a Newton step.
#[inline(always)]
pub(super) fn residual<T: Real>(
    ev: &Evaluator<T>,
    ratio: &T,
    lam: &T,
    chord: Option<&Chord<T>>,
) -> Result<(T, T, Evaluation<T>)> {
    let p = ratio.prec();
    let ax = AxisRatio::new(lam.clone().exp())?;
    let mut ci = ev.for_newton(&ax, chord.is_none())?;
    let f = shape_residual(&ci, ratio);
    let df = match chord {
        Some(c) => {
            // Derivatives kept from an earlier iterate: their relative error grows by
            // ≲ 8|Δλ| (see [`finish`]).
            ci.dk = Some([c.di1.clone(), c.di2.clone()]);
            let age = (lam.clone() - &c.lam).abs().mul_i64(8) + &c.rel_err;
            ci.extra_error = age + &T::epsilon(p).mul_i64(fast::DK_BOUND_EPS);
            c.df.clone()
        }
        None => shape_slope(&ax.k, &ci),
    };
    Ok((f, df, ci))
}

/// F′ and the integrals' k-derivatives at λ = ln k (one evaluation with derivatives): a
/// secant's partner, or the hand-off of a stage whose last step was a chord step; `None` if
/// that evaluation fails.
pub(super) fn slope_at<S: Real>(ev: &Evaluator<S>, ratio: &S, lam: S) -> Option<Chord<S>> {
    let (_, df, ci) = residual(ev, ratio, &lam, None).ok()?;
    Some(Chord {
        di1: ci.di1_dk(),
        di2: ci.di2_dk(),
        df,
        rel_err: S::zero(lam.prec()),
        before: None,
        lam,
    })
}

/// How one stage of the solve runs: its seed and the derivatives handed on by the stage below,
/// whether its last evaluation may skip the k-derivatives (`allow_chord`; false for a stage that
/// hands its derivatives on), whether a Halley step from the `f64` stage is tried, and the
/// tolerance on k (`None`: the working precision's floor).
pub(super) struct Stage<'s, T: Real> {
    pub(super) seed: Option<&'s T>,
    pub(super) seed_slope: Option<(Chord<T>, T)>,
    pub(super) allow_chord: bool,
    pub(super) halley: bool,
    pub(super) tol: Option<T>,
    /// The evaluations the stage may spend.
    pub(super) budget: usize,
}

impl<T: Real> Stage<'_, T> {
    /// The last (or only) stage: no seed, chord steps allowed.
    pub(super) fn final_stage() -> Self {
        Stage {
            seed: None,
            seed_slope: None,
            allow_chord: true,
            halley: false,
            tol: None,
            budget: MAX_EVALUATIONS,
        }
    }
}

/// One stage of the solve ([`Stage`]): Newton's method on F(λ) = ln(I2/(I1·A1/B1)), λ = ln k,
/// with its named steps — the k = 1 probe ([`Newton::probe_k_one`]), the Halley step from a
/// lower precision ([`Newton::halley_step`]), the safeguarded Newton step inside the bracket
/// ([`Newton::next_iterate`]), the Hermite stop ([`Newton::hermite_stop`]), the
/// stopping rules ([`Newton::converged`]) and the chord steps at the end ([`Newton::plan_chord`]).
/// Returns the shape and the derivatives of the last evaluation that computed them (the hand-off
/// to the next stage).
pub(super) fn solve_core<T: Real>(
    evaluator: &Evaluator<T>,
    ratio: &T,
    stage: Stage<'_, T>,
) -> Result<(Shape<T>, Option<Chord<T>>)> {
    check_ratio(ratio)?;
    let method = evaluator.method();
    let mut newton = Newton::new(evaluator, ratio, &stage);
    let halley = stage.halley;
    let halley_slope = (stage.seed_slope).and_then(|(c, err)| newton.adopt_slope(c, &err, halley));
    if stage.seed.is_none() && method != Method::Adaptive {
        newton.probe_k_one()?;
    }
    if let Some(c) = halley_slope {
        if let Some(shape) = newton.halley_step(&c)? {
            return Ok((shape, None));
        }
    }
    newton.iterate()
}

/// The bound on the evaluations of one stage (from the static ellipse).
pub(super) const MAX_EVALUATIONS: usize = 200;

/// The state of one stage's iteration.
pub(super) struct Newton<'a, T: Real + 'static> {
    pub(super) ratio: &'a T,
    pub(super) evaluator: &'a Evaluator<T>,
    /// The stopping rules' unit: ε, or the tolerance asked for.
    pub(super) eps: T,
    pub(super) seeded: bool,
    /// Whether the evaluation expected to be the last may skip the k-derivatives.
    pub(super) allow_chord: bool,
    /// The current iterate λ = ln k.
    pub(super) lam: T,
    /// Bracket [lo, hi] in λ with F(lo) < 0 < F(hi), grown as evaluations reveal signs.
    pub(super) lo: Option<T>,
    pub(super) hi: Option<T>,
    pub(super) last_step: Option<T>,
    /// Derivatives for a chord step at the next evaluation (none: a Newton step).
    pub(super) chord: Option<Chord<T>>,
    /// The derivatives of the last evaluation that computed them, handed to the next stage.
    pub(super) fresh_slope: Option<Chord<T>>,
    /// The last iterate with derivatives, for the Hermite stop.
    pub(super) prev: Option<Point<T>>,
    /// Evaluations spent.
    pub(super) spent: usize,
    /// The evaluations it may spend.
    pub(super) budget: usize,
    /// The longest unbracketed step in λ: 2 (a factor e² in k), doubled after each step cut
    /// to it ([`Newton::next_iterate`]).
    pub(super) reach: T,
    /// The λ range a step longer than 2 may reach: the fixed rules' k ≤ 2^180, and k⁴ ≥ 2⁸
    /// times the smallest normal number (the range [`AxisRatio`] admits, with a margin).
    pub(super) lam_range: (f64, f64),
}

impl<'a, T: Real> Newton<'a, T> {
    /// The iteration of `stage` from its seed, or else from the static ellipse.
    pub(super) fn new(evaluator: &'a Evaluator<T>, ratio: &'a T, stage: &Stage<'_, T>) -> Self {
        let p = ratio.prec();
        let k0 = match stage.seed {
            Some(s) if s.is_positive() && s.is_finite() => s.clone(),
            _ => T::from_f64(static_seed(ratio.to_f64()), p),
        };
        let eps = T::epsilon(p);
        Newton {
            ratio,
            evaluator,
            eps: match &stage.tol {
                Some(t) => t.clone().max_of(eps),
                None => eps,
            },
            seeded: stage.seed.is_some(),
            allow_chord: stage.allow_chord,
            lam: k0.ln(),
            lo: None,
            hi: None,
            last_step: None,
            chord: None,
            fresh_slope: None,
            prev: None,
            spent: 0,
            budget: stage.budget,
            reach: T::from_i64(2, p),
            lam_range: (
                (RelError::of(&T::min_positive(p)).log2() + 8.0) / 4.0 * std::f64::consts::LN_2,
                crate::routes::graded::K_MAX_LOG2 as f64 * std::f64::consts::LN_2,
            ),
        }
    }

    pub(super) fn prec(&self) -> T::Prec {
        self.ratio.prec()
    }

    /// F, F′ and the integrals at λ ([`residual`]).
    #[inline(always)]
    pub(super) fn eval(&self, lam: &T, chord: Option<&Chord<T>>) -> Result<(T, T, Evaluation<T>)> {
        residual(self.evaluator, self.ratio, lam, chord)
    }

    /// The hand-off from a lower precision: its derivatives `c` (relative error r) and a bound
    /// `seed_err` on its root's error. Chord steps multiply the error by ~r each: they are
    /// planned when two of them bring the seed's error to ε/64. Returns the slope for the
    /// Halley step instead when `halley` asks for it and the lower stage's secant F″ exists.
    pub(super) fn adopt_slope(
        &mut self,
        c: Chord<T>,
        seed_err: &T,
        halley: bool,
    ) -> Option<Chord<T>> {
        if !(self.seeded && c.df.is_positive() && c.df.is_finite()) {
            return None;
        }
        if halley && f_second(&c, &self.lam).is_some() {
            return Some(c);
        }
        let r = c.rel_err.clone() + &(self.lam.clone() - &c.lam).abs();
        if r.square() * &seed_err.clone().mul_i64(64) <= self.eps {
            self.chord = Some(c);
        }
        None
    }
    /// The Newton iteration proper: evaluate, step, stop.
    pub(super) fn iterate(mut self) -> Result<(Shape<T>, Option<Chord<T>>)> {
        let p = self.prec();
        while self.spent < self.budget {
            let lam = self.lam.clone();
            let (f, df, ci) = self.eval(&lam, self.chord.as_ref())?;
            self.spent += 1;
            if f.is_zero() {
                let shape = finish(lam.clone(), &lam, ci, self.ratio, T::zero(p), self.spent);
                return Ok((shape, self.fresh_slope));
            }
            if f.is_negative() {
                self.lo = Some(lam.clone());
            } else {
                self.hi = Some(lam.clone());
            }
            let (next, was_newton, cut) = self.next_iterate(&f, &df);
            if cut {
                self.reach = self.reach.clone().mul_pow2(1);
            }
            let step = (next.clone() - &lam).abs();
            let scale = lam.clone().abs().max_of(T::one(p));
            // How far the derivative used for this step lies behind (0 for a Newton step).
            let age = self
                .chord
                .as_ref()
                .map_or_else(|| T::zero(p), |c| (lam.clone() - &c.lam).abs() + &c.rel_err);
            let fresh = self.chord.is_none();
            let here = fresh.then(|| Point {
                lam: lam.clone(),
                f,
                df,
                ints: ci.clone(),
            });
            if let Some(done) = self.hermite_stop(here.as_ref(), was_newton, &scale) {
                return Ok(done);
            }
            if let Some(h) = here {
                self.hand_on(&h);
                self.prev = Some(h);
            }
            self.lam = next;
            if let Some(shape) = self.converged(&lam, ci, &step, &age, &scale, was_newton) {
                return Ok((shape, self.fresh_slope));
            }
            self.plan_chord(&step, &scale, was_newton, fresh);
            self.last_step = Some(step);
        }
        Err(Error::NoConvergence {
            what: "Newton iteration for the axis ratio k",
            iterations: self.spent,
            reached: self.last_step.map(|s| short(&s)).unwrap_or_default(),
        })
    }

    /// The next iterate from F, F′ at λ: the Newton (or chord) step when it stays inside the
    /// bracket; bisection when it does not; unbracketed, the step cut to the reach
    /// and never past a known end. The reach starts at 2 (a factor e² in k) and doubles after
    /// each cut step, as long as the longer step stays inside `lam_range` (else 2): far from the
    /// root F grows like 2|λ| (I1 ~ k^{−2} as k → 0, I2 ~ 1/k as k → ∞), so that a root at
    /// |λ| = L takes about log₂ L cut steps instead of L/2 — near the Rayleigh speed the root
    /// falls to k ~ (1 − M_R)^{1/4}, λ ≈ −576 at 1 − M_R = 10⁻¹⁰⁰⁰. Returns the iterate, whether
    /// it is a full Newton step (which the stopping rules assume) and whether it was cut.
    #[inline]
    pub(super) fn next_iterate(&self, f: &T, df: &T) -> (T, bool, bool) {
        let p = self.prec();
        let lam = &self.lam;
        let newton = (df.is_positive() && df.is_finite()).then(|| lam.clone() - f.clone() / df);
        let half_way = |end: &T| (lam.clone() + end).mul_pow2(-1);
        match (&self.lo, &self.hi, newton) {
            // Inside the closed bracket (a converged step may land on its end).
            (Some(l), Some(h), Some(n)) if n >= *l && n <= *h => (n, true, false),
            (Some(l), Some(h), _) => ((l.clone() + h).mul_pow2(-1), false, false),
            (lo, hi, Some(n)) => {
                let cut =
                    |r: &T| lam.clone() + (n.clone() - lam).min_of(r.clone()).max_of(-r.clone());
                let mut next = cut(&self.reach);
                let x = next.to_f64();
                if !(x >= self.lam_range.0 && x <= self.lam_range.1) {
                    next = cut(&T::from_i64(2, p));
                }
                match (lo, hi) {
                    (Some(l), _) if next <= *l => (half_way(l), false, false),
                    (_, Some(h)) if next >= *h => (half_way(h), false, false),
                    _ => {
                        let full = next == n;
                        (next, full, !full)
                    }
                }
            }
            (Some(_), None, None) => (lam.clone() + T::one(p), false, false),
            (None, _, None) => (lam.clone() - T::one(p), false, false),
        }
    }

    /// The Hermite stop ([`hermite_root`]): with F, F′ at this and the previous iterate, the
    /// cubic through them gives the root's remaining step h to O(D²h²), and I1, I2 are carried
    /// by their own cubics — one evaluation fewer than Newton's stop where the step is ≲ 10⁻⁶
    /// but not yet ≲ 10⁻⁹. Only for unseeded solves that may end on any evaluation.
    #[inline]
    pub(super) fn hermite_stop(
        &self,
        here: Option<&Point<T>>,
        was_newton: bool,
        scale: &T,
    ) -> Option<(Shape<T>, Option<Chord<T>>)> {
        if !(self.allow_chord && !self.seeded && was_newton) {
            return None;
        }
        let (a, b) = (self.prev.as_ref()?, here?);
        let (root, err, ints) = hermite_root(a, b, &self.eps, scale)?;
        let slope = Chord {
            lam: b.lam.clone(),
            di1: b.ints.di1_dk(),
            di2: b.ints.di2_dk(),
            df: b.df.clone(),
            rel_err: T::zero(self.prec()),
            before: None,
        };
        Some((
            finish(root.clone(), &root, ints, self.ratio, err, self.spent),
            Some(slope),
        ))
    }

    /// Keeps this iterate's derivatives for the next stage. For its secants (F″, I″, the
    /// Halley step) a ladder stage (no chord steps) also keeps, of the last iterate with
    /// derivatives and the one kept before it, the one whose distance D from this iterate
    /// minimises the secant's error bound r/D + D (r = 2¹²ε, the derivatives' error bound).
    #[inline]
    pub(super) fn hand_on(&mut self, h: &Point<T>) {
        // r/D + D in the working type (2¹²ε underflows f64 above about 1075 bits); `None` at
        // D = 0, where the secant does not exist.
        let r = self.eps.clone().mul_i64(4096);
        let bound = |x: &T| {
            let d = (h.lam.clone() - x).abs();
            (!d.is_zero()).then(|| r.clone() / &d + &d)
        };
        let nearer = |a: Option<T>, b: Option<T>| match (a, b) {
            (Some(a), Some(b)) => a < b,
            (a, b) => a.is_some() && b.is_none(),
        };
        let before = self
            .fresh_slope
            .as_ref()
            .filter(|_| !self.allow_chord)
            .map(|c| match &c.before {
                Some(b) if nearer(bound(&b[0]), bound(&c.lam)) => b.clone(),
                _ => [c.lam.clone(), c.df.clone(), c.di1.clone(), c.di2.clone()],
            });
        self.fresh_slope = Some(Chord {
            lam: h.lam.clone(),
            di1: h.ints.di1_dk(),
            di2: h.ints.di2_dk(),
            df: h.df.clone(),
            rel_err: T::zero(self.prec()),
            before,
        });
    }

    /// The stopping rules after a step of length `step` from `lam_old` (the integrals `ci`
    /// are those at `lam_old`, carried to the new iterate by [`finish`]): the step is at
    /// rounding level, or stopped shrinking near it; or, once Newton is converging (from a
    /// seed, or after two steps), a step δ leaves an error ~δ² — δ·age for a chord step whose
    /// derivative is `age` behind — and 64 δ·max(δ, age) ≤ ε·scale², counted in the estimate,
    /// while the integrals' carry over δ ([`carry_error`]) stays below ε.
    #[inline]
    pub(super) fn converged(
        &self,
        lam_old: &T,
        ci: Evaluation<T>,
        step: &T,
        age: &T,
        scale: &T,
        was_newton: bool,
    ) -> Option<Shape<T>> {
        let eps = &self.eps;
        let small = *step <= scale.clone() * &eps.clone().mul_i64(4);
        let stalled = self
            .last_step
            .as_ref()
            .is_some_and(|s| step >= s && *step <= scale.clone() * &eps.clone().mul_i64(64));
        if small || stalled {
            return Some(finish(
                self.lam.clone(),
                lam_old,
                ci,
                self.ratio,
                step.clone(),
                self.spent,
            ));
        }
        let projected = step.clone() * &step.clone().max_of(age.clone()).mul_i64(64);
        let quadratic = self.seeded || self.spent >= 3;
        // The integrals' carry over the step (|dk/k| ≈ step; the derivatives' relative error
        // ≲ 8·age) is also held to ε.
        let carry = carry_error(step, &age.clone().mul_i64(8));
        if was_newton && quadratic && projected <= eps.clone() * &scale.square() && carry <= *eps {
            let err = projected / scale;
            return Some(finish(
                self.lam.clone(),
                lam_old,
                ci,
                self.ratio,
                err,
                self.spent,
            ));
        }
        None
    }

    /// Chord steps at the end: when the next evaluation is expected to be the last (its step
    /// ~δ², so that δ³ ≤ ε/64), it skips the k-derivatives and steps with this iterate's F′,
    /// which costs no convergence at that distance (a wrong guess costs no accuracy — the stop
    /// counts the derivative's age — and at most one more evaluation without derivatives).
    /// A chord slope used for this step (not `fresh`) is kept for the next while the steps stay
    /// full ones (the ladder's successive chord steps with a lower precision's F′); an
    /// intermediate ladder stage (no chord steps allowed) takes one chord step with the lower
    /// precision's derivative and then evaluates the derivatives, so that it hands on its own F′
    /// (a precision's worth of chord contraction) to the next stage.
    #[inline]
    pub(super) fn plan_chord(&mut self, step: &T, scale: &T, was_newton: bool, fresh: bool) {
        let past_first = self.seeded || self.spent >= 2;
        if self.allow_chord && was_newton && past_first && fresh {
            let cube = step.square() * step;
            if cube.mul_i64(64) <= self.eps.clone() * &scale.square() * scale {
                self.chord = self.fresh_slope.clone();
            }
        } else if !was_newton || !self.allow_chord {
            self.chord = None;
        }
    }
}

/// An iterate with its F, F′ and integrals with their k-derivatives (the Hermite stop).
pub(super) struct Point<T: Real> {
    pub(super) lam: T,
    pub(super) f: T,
    pub(super) df: T,
    pub(super) ints: Evaluation<T>,
}

/// The derivatives kept for chord steps: at λ = `lam`, dI1/dk, dI2/dk and F′, with F′'s
/// relative error when it comes from a lower precision (0 otherwise).
#[derive(Clone)]
pub(super) struct Chord<T> {
    pub(super) lam: T,
    pub(super) di1: T,
    pub(super) di2: T,
    pub(super) df: T,
    pub(super) rel_err: T,
    /// The previous iterate with derivatives: λ, F′, dI1/dk, dI2/dk (for second derivatives by
    /// secants, [`halley_from_f64`]).
    pub(super) before: Option<[T; 4]>,
}
