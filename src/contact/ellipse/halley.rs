//! The ladder's Halley step: a double-double stage one evaluation from the `f64` root, with
//! F″ and I″ by secants between the `f64` stage's last two iterates — one evaluation with
//! derivatives instead of two chord evaluations (`docs/calibration.md`). Its control
//! arithmetic runs in `f64`, which holds every quantity at double-double.

use super::finish::finish;
use super::newton::{residual, Chord, Newton};
use super::Shape;
use crate::error::Result;
use crate::routes::evaluate::Evaluator;
use crate::routes::Evaluation;
use crate::scalar::Real;

/// y(x + h) and y′(x + h) for y(x + h) = y + y′h + c2h² + c3h³.
fn carry_cubic<T: Real>(y: &T, dy: &T, c2: &T, c3: &T, h: &T) -> (T, T) {
    let val = y.clone() + (dy.clone() + (c2.clone() + c3.clone() * h) * h) * h;
    let der = dy.clone() + (c2.clone().mul_i64(2) + c3.clone().mul_i64(3) * h) * h;
    (val, der)
}

/// The distance in λ of [`secant_partner`]'s evaluation: √r for derivatives of relative error
/// r ~ 2⁻⁴⁰, where the secant's rounding and truncation errors balance.
const PARTNER_STEP: f64 = 9.5367431640625e-7; // 2^-20

/// A guessed stage that converged in one evaluation leaves no earlier iterate for the next
/// stage's secant F″ ([`f_second`]): one more evaluation with derivatives at [`PARTNER_STEP`]
/// from its root supplies it. Unchanged if that evaluation fails.
pub(super) fn secant_partner<S: Real>(ev: &Evaluator<S>, ratio: &S, mut c: Chord<S>) -> Chord<S> {
    let lam = c.lam.clone() + S::from_f64(PARTNER_STEP, ratio.prec());
    if let Ok((_, df, ci)) = residual(ev, ratio, &lam, None) {
        c.before = Some([lam, df, ci.di1_dk(), ci.di2_dk()]);
    }
    c
}

impl<T: Real> Newton<'_, T> {
    /// The Halley step from the lower root λ ([`halley_from_f64`]): one evaluation with
    /// derivatives; `None`, and a Newton step instead, when its bounds miss ε.
    pub(super) fn halley_step(&mut self, c: &Chord<T>) -> Result<Option<Shape<T>>> {
        let lam = self.lam.clone();
        let (f, df, ci) = residual(self.evaluator, self.ratio, &lam, None)?;
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
