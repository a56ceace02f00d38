//! Stage 3: Newton's method on F(λ) = ln(I2/(I1·A1/B1)), λ = ln k, inside a bracket of known
//! signs (bisection when a step leaves it), with chord steps (evaluations without the
//! k-derivatives, stepping with an F′ in hand) and, at double-double, the Halley step from the
//! `f64` root. Thresholds and what each tactic saves: `docs/calibration.md`.

use super::finish::{carry_error, finish};
use super::seed::static_seed;
use super::{shape_residual, shape_slope, Shape};
use crate::error::{Error, Result};
use crate::estimate::RelError;
use crate::routes::evaluate::Evaluator;
use crate::routes::{fast, AxisRatio, Evaluation, IntegralOptions, Method};
use crate::scalar::{short, Real};

/// A stage's result: the shape and the derivatives it hands on to the stage above.
pub(super) type Handed<T> = Result<(Shape<T>, Option<Chord<T>>)>;

/// The bound on one stage's evaluations.
pub(super) const MAX_EVALUATIONS: usize = 200;

/// The integral options of a Newton iterate: the method, with k-derivatives.
pub(super) fn newton_options(method: Method) -> IntegralOptions {
    IntegralOptions {
        method,
        derivatives: true,
        ..Default::default()
    }
}

/// F, F′, the integrals and k = e^λ at λ; with `chord` (derivatives kept from an earlier
/// iterate or a lower stage) the derivatives are not evaluated, and their relative error grows
/// by ≲ 8|Δλ|.
#[inline(always)]
pub(super) fn residual<T: Real>(
    ev: &Evaluator<T>,
    ratio: &T,
    lam: &T,
    chord: Option<&Chord<T>>,
) -> Result<(T, T, Evaluation<T>, T)> {
    let ax = AxisRatio::new(lam.clone().exp())?;
    let mut ci = ev.for_newton(&ax, chord.is_none())?;
    let f = shape_residual(&ci, ratio);
    let Some(c) = chord else {
        return Ok((f, shape_slope(&ax.k, &ci), ci, ax.k));
    };
    ci.dk = Some([c.di1.clone(), c.di2.clone()]);
    let age = (lam.clone() - &c.lam).abs().mul_i64(8) + &c.rel_err;
    ci.extra_error = age + &T::epsilon(ratio.prec()).mul_i64(fast::DK_BOUND_EPS);
    Ok((f, c.df.clone(), ci, ax.k))
}

/// Derivatives kept for chord steps: dI1/dk, dI2/dk and F′ at λ, F′'s relative error (from a
/// lower precision), and the iterate before (λ, F′, dI1/dk, dI2/dk) for the Halley step.
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
    /// The derivatives of `ci` at λ.
    pub(super) fn at(lam: T, df: T, ci: &Evaluation<T>, before: Option<[T; 4]>) -> Self {
        let (di1, di2, rel_err) = (ci.di1_dk(), ci.di2_dk(), T::zero(lam.prec()));
        Chord {
            lam,
            di1,
            di2,
            df,
            rel_err,
            before,
        }
    }
}

/// One stage's iteration: `eps` (ε or the tolerance), `allow_chord` (whether the last
/// evaluation may skip the k-derivatives: not for a stage that hands them on), the bracket
/// F(lo) < 0 < F(hi), the chord step's derivatives, the last ones evaluated, the unbracketed
/// reach, and the λ a step longer than 2 may reach (k ≤ 2^180, k⁴ ≥ 2⁸ × the least normal).
pub(super) struct Newton<'a, T: Real + 'static> {
    pub(super) ratio: &'a T,
    pub(super) evaluator: &'a Evaluator<T>,
    pub(super) eps: T,
    seeded: bool,
    allow_chord: bool,
    pub(super) budget: usize,
    pub(super) lam: T,
    pub(super) lo: Option<T>,
    pub(super) hi: Option<T>,
    last_step: Option<T>,
    chord: Option<Chord<T>>,
    fresh_slope: Option<Chord<T>>,
    pub(super) spent: usize,
    reach: T,
    lam_range: (f64, f64),
}

impl<'a, T: Real> Newton<'a, T> {
    /// A stage from `seed` (`None`: the static ellipse) to `tol` (`None`: ε).
    pub(super) fn new(
        evaluator: &'a Evaluator<T>,
        ratio: &'a T,
        seed: Option<&T>,
        tol: Option<T>,
        allow_chord: bool,
    ) -> Self {
        let p = ratio.prec();
        let k0 = match seed {
            Some(s) if s.is_positive() && s.is_finite() => s.clone(),
            _ => T::from_f64(static_seed(ratio.to_f64()), p),
        };
        let (eps, ln2) = (T::epsilon(p), std::f64::consts::LN_2);
        let min_log2 = RelError::of(&T::min_positive(p)).log2();
        Newton {
            ratio,
            evaluator,
            eps: tol.map_or(eps.clone(), |t| t.max_of(eps)),
            seeded: seed.is_some(),
            allow_chord,
            budget: MAX_EVALUATIONS,
            lam: k0.ln(),
            lo: None,
            hi: None,
            last_step: None,
            chord: None,
            fresh_slope: None,
            spent: 0,
            reach: T::from_i64(2, p),
            lam_range: (
                (min_log2 + 8.0) / 4.0 * ln2,
                crate::routes::graded::K_MAX_LOG2 as f64 * ln2,
            ),
        }
    }

    pub(super) fn prec(&self) -> T::Prec {
        self.ratio.prec()
    }

    /// Runs the stage: the k = 1 probe (unseeded); with derivatives `handed` on from below
    /// (and the bound on the seed's error) the Halley step when they allow it at ≤ 106 bits in
    /// a stage that hands nothing on, else chord steps with them when 64(r·seed_err)² ≤ ε;
    /// then the safeguarded iteration.
    #[inline]
    pub(super) fn run(mut self, handed: Option<(Chord<T>, T)>) -> Handed<T> {
        if !self.seeded && self.evaluator.method() != Method::Adaptive {
            self.probe_k_one()?;
        }
        if let Some((c, seed_err)) = handed {
            if self.seeded && c.df.is_positive() && c.df.is_finite() {
                let halley = self.allow_chord && T::bits(self.prec()) <= 106;
                match halley.then(|| f_second(&c, &self.lam)).flatten() {
                    Some(f2) => {
                        if let Some(shape) = self.halley_step(&c, f2)? {
                            return Ok((shape, None));
                        }
                    }
                    None => {
                        let r = c.rel_err.clone() + &(self.lam.clone() - &c.lam).abs();
                        if (r * &seed_err).square().mul_i64(64) <= self.eps {
                            self.chord = Some(c);
                        }
                    }
                }
            }
        }
        self.iterate()
    }

    /// Evaluate, step, stop, until the budget is spent.
    #[inline]
    fn iterate(mut self) -> Handed<T> {
        let p = self.prec();
        while self.spent < self.budget {
            let lam = self.lam.clone();
            let (f, df, ci, k) = residual(self.evaluator, self.ratio, &lam, self.chord.as_ref())?;
            self.spent += 1;
            let fresh = self.chord.is_none();
            if fresh {
                self.hand_on(&lam, &df, &ci);
            }
            if f.is_zero() {
                let shape = finish(lam.clone(), k, ci, self.ratio, T::zero(p), self.spent);
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
            self.lam = next;
            if let Some(shape) = self.stop_or_plan(&lam, k, ci, step, was_newton, fresh) {
                return Ok((shape, self.fresh_slope));
            }
        }
        Err(Error::NoConvergence {
            what: "Newton iteration for the axis ratio k",
            iterations: self.spent,
            reached: self.last_step.map(|s| short(&s)).unwrap_or_default(),
        })
    }

    /// The next iterate: the Newton (or chord) step inside the bracket, else bisection;
    /// unbracketed, the step cut to the reach (2 where the longer step leaves `lam_range`) and
    /// never past a known end.
    /// Returns the iterate, whether it is a full Newton step and whether it was cut.
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

    /// Keeps this iterate's derivatives for the next stage, and, in a stage that hands them on,
    /// of the two iterates before the one minimising the secant's bound r/D + D (r = 2¹²ε).
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

    /// After a full (`newton`) or cut step δ from `lam_old`, whose integrals `ci` [`finish`]
    /// carries, the stops: δ at rounding level or stalled near it; or, once converging, a
    /// full step with 64δ·max(δ, age) ≤ ε·scale² (age: how far behind the step's derivative
    /// lies) and the integrals' carry ≤ ε. Else the chord step: when the next evaluation is
    /// expected to be the last (64δ³ ≤ ε) it steps with this iterate's F′; a slope handed on
    /// from below (positive `rel_err`) is kept while the steps are full and 64·age²·δ ≤ ε·scale².
    #[inline]
    fn stop_or_plan(
        &mut self,
        lam_old: &T,
        k_old: T,
        ci: Evaluation<T>,
        step: T,
        newton: bool,
        fresh: bool,
    ) -> Option<Shape<T>> {
        let (eps, p) = (&self.eps, self.prec());
        let scale = lam_old.clone().abs().max_of(T::one(p));
        let age = (self.chord.as_ref()).map_or_else(
            || T::zero(p),
            |c| (lam_old.clone() - &c.lam).abs() + &c.rel_err,
        );
        let small = step <= scale.clone() * &eps.clone().mul_i64(4);
        let stalled = (self.last_step.as_ref())
            .is_some_and(|s| step >= *s && step <= scale.clone() * &eps.clone().mul_i64(64));
        let done = |err: T| finish(self.lam.clone(), k_old, ci, self.ratio, err, self.spent);
        if small || stalled {
            return Some(done(step));
        }
        let projected = step.clone() * &step.clone().max_of(age.clone()).mul_i64(64);
        let quadratic = self.seeded || self.spent >= 3;
        let carry = carry_error(&step, &age.clone().mul_i64(8));
        if newton && quadratic && projected <= eps.clone() * &scale.square() && carry <= *eps {
            return Some(done(projected / &scale));
        }
        let past_first = self.seeded || self.spent >= 2;
        if self.allow_chord && newton && past_first && fresh {
            if (step.square() * &step).mul_i64(64) <= eps.clone() * &scale.square() * &scale {
                self.chord = self.fresh_slope.clone();
            }
        } else if !newton
            || !self.allow_chord
            || (self.chord.as_ref()).is_some_and(|c| c.rel_err.is_positive())
                && (age.square() * &step).mul_i64(64) > eps.clone() * &scale.square()
        {
            self.chord = None;
        }
        self.last_step = Some(step);
        None
    }

    /// The Halley step from the `f64` root λ0 at double-double, one evaluation with
    /// derivatives: with F″ by secant ([`f_second`]), h = δ − F″δ²/(2F′) (δ = −F/F′; error
    /// ≤ (|ΔF″|/2F′)δ² + |δ|³, required ≤ ε·scale/4) and I1, I2 carried to second order
    /// ([`carry_second`]). `None`, and a Newton step instead, when a bound misses. Its control
    /// arithmetic runs in `f64`, which holds every quantity at double-double.
    #[inline(never)]
    fn halley_step(&mut self, c: &Chord<T>, (f2, f2_err): (f64, f64)) -> Result<Option<Shape<T>>> {
        let lam = self.lam.clone();
        let (f, df, ci, k) = residual(self.evaluator, self.ratio, &lam, None)?;
        self.spent += 1;
        if !(df.is_positive() && df.is_finite()) {
            return Ok(None);
        }
        let p = self.prec();
        let newton = -(f.clone() / &df);
        let (nf, dff) = (newton.to_f64().abs(), df.to_f64());
        let err = f2_err / (2.0 * dff) * nf * nf + nf * nf * nf;
        let scale = lam.clone().abs().max_of(T::one(p));
        if err.is_finite() && err <= self.eps.to_f64() * scale.to_f64() / 4.0 {
            let h = newton.clone() - T::from_f64(f2, p) * newton.square() / df.clone().mul_i64(2);
            let dk = (lam.clone() + &h).exp() - &k;
            if let Some(ints) = carry_second(c, &lam, &dk, &ci, self.eps.to_f64()) {
                let (root, err) = (lam.clone() + h, T::from_f64(err, p));
                return Ok(Some(finish(
                    root.clone(),
                    root.clone().exp(),
                    ints,
                    self.ratio,
                    err,
                    self.spent,
                )));
            }
        }
        self.lam = lam - f / &df;
        Ok(None)
    }
}

/// F″ at λ0 by the secant between the lower stage's last two iterates (`c`, `c.before`) and
/// its bound 2r|F′|/D + (1 + |F″|)(D + |λ0 − λ_c|) (|F‴| ≤ 1 + |F″|); `None` when the bound
/// exceeds 0.1. It needs no evaluation at λ0.
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

/// I1, I2 of `ints` at λ0 carried by `dk` to second order, with I″ by secants between the
/// lower stage's iterates, of bound 2r|I′|/Δk + 100(I/k³)(Δk + |k0 − k_c|) (|k³I‴| ≤ 100 I
/// assumed: 60 for I1 ∝ ln k/k³); `None` when the carry's error exceeds `eps`.
fn carry_second<T: Real>(
    c: &Chord<T>,
    lam0: &T,
    dk: &T,
    ints: &Evaluation<T>,
    eps: f64,
) -> Option<Evaluation<T>> {
    let b = c.before.as_ref()?;
    let p = lam0.prec();
    let (ka, kb, k0) = (
        b[0].to_f64().exp(),
        c.lam.to_f64().exp(),
        lam0.to_f64().exp(),
    );
    let (dkc, r, dkf) = (kb - ka, c.rel_err.to_f64(), dk.to_f64());
    let reach = dkc.abs() + (k0 - kb).abs();
    let carry = |i: &T, di: T, dia: &T, dib: &T| {
        let ipp_err =
            2.0 * r * dib.to_f64().abs() / dkc.abs() + 100.0 * i.to_f64() * reach / k0.powi(3);
        let c2 = T::from_f64((dib.to_f64() - dia.to_f64()) / dkc / 2.0, p);
        let val = i.clone() + (di.clone() + c2.clone() * dk) * dk;
        (
            val,
            di + c2.mul_i64(2) * dk,
            0.5 * ipp_err * dkf * dkf / i.to_f64(),
        )
    };
    let (i1, di1, e1) = carry(&ints.i1, ints.di1_dk(), &b[2], &c.di1);
    let (i2, di2, e2) = carry(&ints.i2, ints.di2_dk(), &b[3], &c.di2);
    if !(e1.is_finite() && e2.is_finite() && e1.max(e2) <= eps) {
        return None;
    }
    let carried = T::from_f64(e1.max(e2), p);
    Some(Evaluation {
        i1,
        i2,
        dk: Some([di1, di2]),
        error_estimate: ints.error_estimate.clone() + &carried,
        extra_error: ints.extra_error.clone() + &carried.sqrt(),
        ..ints.clone()
    })
}
