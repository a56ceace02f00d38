//! Stage 3: Newton's method on F(λ) = ln(I2/(I1·A1/B1)), λ = ln k, inside a bracket of known
//! signs (bisection when a step leaves it), with chord steps — evaluations without the
//! k-derivatives, stepping with an F′ in hand — where that F′ is close enough.

use super::finish::{carry_error, finish};
use super::seed::static_seed;
use super::{shape_residual, shape_slope, Shape};
use crate::error::{Error, Result};
use crate::estimate::RelError;
use crate::routes::evaluate::Evaluator;
use crate::routes::{fast, AxisRatio, Evaluation};
use crate::scalar::{short, Real};

/// A stage's result: the shape and the derivatives it hands on to the stage above.
pub(super) type Handed<T> = Result<(Shape<T>, Option<Chord<T>>)>;

/// The bound on one stage's evaluations.
pub(super) const MAX_EVALUATIONS: usize = 200;

/// F, F′ and the integrals at λ; with `chord` (derivatives kept from an earlier iterate or a
/// lower stage) the derivatives are not evaluated, and their relative error grows by ≲ 8|Δλ|.
#[inline(always)]
pub(super) fn residual<T: Real>(
    ev: &Evaluator<T>,
    ratio: &T,
    lam: &T,
    chord: Option<&Chord<T>>,
) -> Result<(T, T, Evaluation<T>)> {
    let ax = AxisRatio::new(lam.clone().exp())?;
    let mut ci = ev.for_newton(&ax, chord.is_none())?;
    let f = shape_residual(&ci, ratio);
    let df = match chord {
        Some(c) => {
            ci.dk = Some([c.di1.clone(), c.di2.clone()]);
            let age = (lam.clone() - &c.lam).abs().mul_i64(8) + &c.rel_err;
            ci.extra_error = age + &T::epsilon(ratio.prec()).mul_i64(fast::DK_BOUND_EPS);
            c.df.clone()
        }
        None => shape_slope(&ax.k, &ci),
    };
    Ok((f, df, ci))
}

/// How one stage runs: its seed (`None`: the static ellipse), the derivatives handed on from
/// below with a bound on the seed's error, whether its last evaluation may skip the
/// k-derivatives, whether it tries the Halley step, the tolerance on k (`None`: ε) and its
/// evaluation budget.
pub(super) struct Stage<'s, T: Real> {
    pub(super) seed: Option<&'s T>,
    pub(super) seed_slope: Option<(Chord<T>, T)>,
    pub(super) allow_chord: bool,
    pub(super) halley: bool,
    pub(super) tol: Option<T>,
    pub(super) budget: usize,
}

impl<'s, T: Real> Stage<'s, T> {
    /// A stage from `seed`, chord steps allowed, no derivatives handed on.
    pub(super) fn from(seed: Option<&'s T>, tol: Option<T>) -> Self {
        Stage {
            seed,
            seed_slope: None,
            allow_chord: true,
            halley: false,
            tol,
            budget: MAX_EVALUATIONS,
        }
    }
}

/// Runs one stage: the k = 1 probe (unseeded), the Halley step when the stage asks for it and the handed-on derivatives
/// allow it ([`super::halley`]), else chord steps with them when they are close enough, then
/// the safeguarded iteration. Returns the shape and the last derivatives evaluated.
#[inline]
pub(super) fn solve_core<T: Real>(ev: &Evaluator<T>, ratio: &T, stage: Stage<'_, T>) -> Handed<T> {
    let mut newton = Newton::new(ev, ratio, &stage);
    if stage.seed.is_none() && ev.method() != crate::routes::Method::Adaptive {
        newton.probe_k_one()?;
    }
    if let Some((c, err)) = stage.seed_slope {
        if newton.seeded && c.df.is_positive() && c.df.is_finite() {
            if stage.halley && super::halley::f_second(&c, &newton.lam).is_some() {
                if let Some(shape) = newton.halley_step(&c)? {
                    return Ok((shape, None));
                }
            } else {
                newton.adopt_slope(c, &err);
            }
        }
    }
    newton.iterate()
}

/// One stage's iteration state.
pub(super) struct Newton<'a, T: Real + 'static> {
    pub(super) ratio: &'a T,
    pub(super) evaluator: &'a Evaluator<T>,
    /// The stopping rules' unit: ε, or the tolerance asked for.
    pub(super) eps: T,
    seeded: bool,
    allow_chord: bool,
    pub(super) lam: T,
    /// The bracket in λ, F(lo) < 0 < F(hi), grown as evaluations reveal signs.
    pub(super) lo: Option<T>,
    pub(super) hi: Option<T>,
    last_step: Option<T>,
    /// Derivatives for a chord step at the next evaluation (none: a Newton step).
    chord: Option<Chord<T>>,
    /// The last derivatives evaluated, handed to the next stage.
    fresh_slope: Option<Chord<T>>,
    pub(super) spent: usize,
    budget: usize,
    /// The longest unbracketed step: 2, doubled after each step cut to it.
    reach: T,
    /// The λ a step longer than 2 may reach: the fixed rules' k ≤ 2^180, and k⁴ ≥ 2⁸ times the
    /// smallest normal number ([`AxisRatio`]'s range with a margin).
    lam_range: (f64, f64),
}

impl<'a, T: Real> Newton<'a, T> {
    fn new(evaluator: &'a Evaluator<T>, ratio: &'a T, stage: &Stage<'_, T>) -> Self {
        let p = ratio.prec();
        let k0 = match stage.seed {
            Some(s) if s.is_positive() && s.is_finite() => s.clone(),
            _ => T::from_f64(static_seed(ratio.to_f64()), p),
        };
        let eps = T::epsilon(p);
        let ln2 = std::f64::consts::LN_2;
        Newton {
            ratio,
            evaluator,
            eps: stage.tol.clone().map_or(eps.clone(), |t| t.max_of(eps)),
            seeded: stage.seed.is_some(),
            allow_chord: stage.allow_chord,
            lam: k0.ln(),
            lo: None,
            hi: None,
            last_step: None,
            chord: None,
            fresh_slope: None,
            spent: 0,
            budget: stage.budget,
            reach: T::from_i64(2, p),
            lam_range: (
                (RelError::of(&T::min_positive(p)).log2() + 8.0) / 4.0 * ln2,
                crate::routes::graded::K_MAX_LOG2 as f64 * ln2,
            ),
        }
    }

    pub(super) fn prec(&self) -> T::Prec {
        self.ratio.prec()
    }

    /// Chord steps with the derivatives `c` handed on from below (relative error r at the seed,
    /// the seed within `seed_err`) when the error r·seed_err of one chord step is one that a
    /// Newton step then ends, 64(r·seed_err)² ≤ ε: the chord path evaluates the k-derivatives
    /// no more often than Newton's ([`Self::plan_chord`] keeps the slope while the next chord
    /// step is expected to stop).
    fn adopt_slope(&mut self, c: Chord<T>, seed_err: &T) {
        let r = c.rel_err.clone() + &(self.lam.clone() - &c.lam).abs();
        if (r * seed_err).square().mul_i64(64) <= self.eps {
            self.chord = Some(c);
        }
    }

    /// Evaluate, step, stop, until the budget is spent.
    #[inline]
    fn iterate(mut self) -> Handed<T> {
        let p = self.prec();
        while self.spent < self.budget {
            let lam = self.lam.clone();
            let (f, df, ci) = residual(self.evaluator, self.ratio, &lam, self.chord.as_ref())?;
            self.spent += 1;
            let fresh = self.chord.is_none();
            if fresh {
                self.hand_on(&lam, &df, &ci);
            }
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
            // How far behind the derivative of this step lies (0 for a Newton step).
            let age = (self.chord.as_ref())
                .map_or_else(|| T::zero(p), |c| (lam.clone() - &c.lam).abs() + &c.rel_err);
            self.lam = next;
            if let Some(shape) = self.converged(&lam, ci, &step, &age, &scale, was_newton) {
                return Ok((shape, self.fresh_slope));
            }
            self.plan_chord(&step, &age, &scale, was_newton, fresh);
            self.last_step = Some(step);
        }
        Err(Error::NoConvergence {
            what: "Newton iteration for the axis ratio k",
            iterations: self.spent,
            reached: self.last_step.map(|s| short(&s)).unwrap_or_default(),
        })
    }

    /// The next iterate: the Newton (or chord) step inside the bracket, else bisection;
    /// unbracketed, the step cut to the reach (2, doubled after each cut while the longer step
    /// stays in `lam_range`: far from the root F grows like 2|λ|, so a root at |λ| = L takes
    /// about log₂ L cut steps) and never past a known end. Returns the iterate, whether it is
    /// a full Newton step (which the stopping rules assume) and whether it was cut.
    #[inline]
    fn next_iterate(&self, f: &T, df: &T) -> (T, bool, bool) {
        let lam = &self.lam;
        let newton = (df.is_positive() && df.is_finite()).then(|| lam.clone() - f.clone() / df);
        let half_way = |end: &T| (lam.clone() + end).mul_pow2(-1);
        let one = T::one(self.prec());
        match (&self.lo, &self.hi, newton) {
            (Some(l), Some(h), Some(n)) if n >= *l && n <= *h => (n, true, false),
            (Some(l), Some(h), _) => ((l.clone() + h).mul_pow2(-1), false, false),
            (lo, hi, Some(n)) => {
                let cut = |r: T| lam.clone() + (n.clone() - lam).min_of(r.clone()).max_of(-r);
                let mut next = cut(self.reach.clone());
                let x = next.to_f64();
                if !(x >= self.lam_range.0 && x <= self.lam_range.1) {
                    next = cut(one.mul_i64(2));
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
            (Some(_), None, None) => (lam.clone() + one, false, false),
            (None, _, None) => (lam.clone() - one, false, false),
        }
    }

    /// Keeps this iterate's derivatives for the next stage; a stage that hands them on (no
    /// chord steps) also keeps, of the two iterates with derivatives before, the one whose
    /// distance D from this one minimises the secant's error bound r/D + D (r = 2¹²ε, in the
    /// working type) for the Halley step above.
    #[inline]
    fn hand_on(&mut self, lam: &T, df: &T, ci: &Evaluation<T>) {
        let r = self.eps.clone().mul_i64(4096);
        let bound = |x: &T| {
            let d = (lam.clone() - x).abs();
            (!d.is_zero()).then(|| r.clone() / &d + &d)
        };
        let nearer = |a: Option<T>, b: Option<T>| match (a, b) {
            (Some(a), Some(b)) => a < b,
            (a, b) => a.is_some() && b.is_none(),
        };
        let before = (self.fresh_slope.as_ref())
            .filter(|_| !self.allow_chord)
            .map(|c| match &c.before {
                Some(b) if nearer(bound(&b[0]), bound(&c.lam)) => b.clone(),
                _ => [c.lam.clone(), c.df.clone(), c.di1.clone(), c.di2.clone()],
            });
        self.fresh_slope = Some(Chord::at(lam.clone(), df.clone(), ci, before));
    }

    /// The stopping rules after a step of length `step` from `lam_old` (whose integrals `ci`
    /// [`finish`] carries to the new iterate): the step at rounding level or stalled near it;
    /// or, once converging (seeded, or after two steps), a step δ leaves an error ~δ² (δ·age
    /// for a chord step) and 64δ·max(δ, age) ≤ ε·scale², with the integrals' carry ≤ ε.
    #[inline]
    fn converged(
        &self,
        lam_old: &T,
        ci: Evaluation<T>,
        step: &T,
        age: &T,
        scale: &T,
        newton: bool,
    ) -> Option<Shape<T>> {
        let eps = &self.eps;
        let small = *step <= scale.clone() * &eps.clone().mul_i64(4);
        let stalled = (self.last_step.as_ref())
            .is_some_and(|s| step >= s && *step <= scale.clone() * &eps.clone().mul_i64(64));
        let done = |err: T| finish(self.lam.clone(), lam_old, ci, self.ratio, err, self.spent);
        if small || stalled {
            return Some(done(step.clone()));
        }
        let projected = step.clone() * &step.clone().max_of(age.clone()).mul_i64(64);
        let quadratic = self.seeded || self.spent >= 3;
        let carry = carry_error(step, &age.clone().mul_i64(8));
        if newton && quadratic && projected <= eps.clone() * &scale.square() && carry <= *eps {
            return Some(done(projected / scale));
        }
        None
    }

    /// The chord step at the end: when the next evaluation is expected to be the last
    /// (64δ³ ≤ ε), it skips the k-derivatives and steps with this iterate's F′ (the stop counts
    /// the derivative's age). A slope handed on from below (positive `rel_err`) is kept while
    /// the steps are full ones and the next chord step, whose error is about age·δ, is expected
    /// to stop: 64·age²·δ ≤ ε·scale² (the stop's test one step ahead); else the next iterate
    /// evaluates the derivatives, whose Newton step ends the stage.
    #[inline]
    fn plan_chord(&mut self, step: &T, age: &T, scale: &T, newton: bool, fresh: bool) {
        let past_first = self.seeded || self.spent >= 2;
        if self.allow_chord && newton && past_first && fresh {
            if (step.square() * step).mul_i64(64) <= self.eps.clone() * &scale.square() * scale {
                self.chord = self.fresh_slope.clone();
            }
        } else if !newton || !self.allow_chord {
            self.chord = None;
        } else if (self.chord.as_ref()).is_some_and(|c| c.rel_err.is_positive())
            && (age.clone().square() * step).mul_i64(64) > self.eps.clone() * &scale.square()
        {
            self.chord = None;
        }
    }
}

/// Derivatives kept for chord steps: dI1/dk, dI2/dk and F′ at λ, with F′'s relative error
/// when it comes from a lower precision, and the iterate before (λ, F′, dI1/dk, dI2/dk) for
/// the Halley step's secant second derivatives.
#[derive(Clone)]
pub(super) struct Chord<T> {
    pub(super) lam: T,
    pub(super) di1: T,
    pub(super) di2: T,
    pub(super) df: T,
    pub(super) rel_err: T,
    pub(super) before: Option<[T; 4]>,
}

impl<T: Real> Chord<T> {
    /// The derivatives of `ci` at λ, exact for this precision.
    pub(super) fn at(lam: T, df: T, ci: &Evaluation<T>, before: Option<[T; 4]>) -> Self {
        Chord {
            di1: ci.di1_dk(),
            di2: ci.di2_dk(),
            df,
            rel_err: T::zero(lam.prec()),
            before,
            lam,
        }
    }
}
