//! Stage 5 of the ellipse solve: the root and its error bound — the integrals carried from the
//! last evaluation to the root, the final step in k itself where |ln k| is large, and the
//! Hermite stop that ends an unseeded solve one evaluation early.

use super::newton::Point;
use super::{shape_residual, shape_slope, Shape};
use crate::routes::Evaluation;
use crate::scalar::Real;

/// The cubic through (x_b, y_b, y′_b) and (x_a, y_a, y′_a), as coefficients c2, c3 of
/// y(x_b + h) = y_b + y′_b h + c2 h² + c3 h³.
#[inline]
pub(super) fn hermite_coefficients<T: Real>(d: &T, ya: &T, yb: &T, dya: &T, dyb: &T) -> (T, T) {
    let c3 = ((dya.clone() + dyb) * d - (ya.clone() - yb).mul_i64(2)) / (d.square() * d);
    let c2 = (dya.clone() - dyb) / d.clone().mul_i64(2) - (c3.clone() * d).mul_i64(3).mul_pow2(-1);
    (c2, c3)
}

/// y(x + h) and y′(x + h) for y(x + h) = y + y′h + c2h² + c3h³: the integrals carried from an
/// evaluated iterate to the root (the Hermite stop and the double-double Halley step).
#[inline]
pub(super) fn carry_cubic<T: Real>(y: &T, dy: &T, c2: &T, c3: &T, h: &T) -> (T, T) {
    let val = y.clone() + (dy.clone() + (c2.clone() + c3.clone() * h) * h) * h;
    let der = dy.clone() + (c2.clone().mul_i64(2) + c3.clone().mul_i64(3) * h) * h;
    (val, der)
}

/// The Hermite stop of [`solve_core`]: from iterates `a` (earlier) and `b` (this one, both with
/// derivatives), the root λ_b + h of the cubic through F, F′ at both, and I1, I2 (with their
/// k-derivatives) carried to it by the cubics through their values and k-derivatives. Taken when
/// |h| ≤ |D|/8 (D = λ_a − λ_b) and 8(1 + |c3|)D²h²/F′ ≤ ε·scale, the interpolation error
/// (F⁗/24)D²h²/F′ with |F⁗| ≤ 24(1 + |c3|) assumed, c3 the cubic's F‴/6 (measured F″, F‴ of
/// order 0.01–1 in λ). The integrals are interpolated in k: at the root x, the remainder
/// I⁗(ξ)/24·(x − k_a)²(x − k_b)² relative to I(x) is at most
/// 16·((x − k_a)/x)²((x − k_b)/x)²·(x/k_min)⁷ for I ∝ k^-s ln k with s ≤ 3 (k⁴|I⁗|/24I ≤ 16:
/// 15 for I1 ∝ ln k/k³ at k ≫ 1, 5 for I1 ∝ k⁻² at k ≪ 1; ξ ≥ k_min, the least of the three
/// k); also required ≤ ε and added to the integrals' error estimate.
/// Returns λ, the error bound in λ, and the carried integrals.
#[inline]
pub(super) fn hermite_root<T: Real>(
    a: &Point<T>,
    b: &Point<T>,
    eps: &T,
    scale: &T,
) -> Option<(T, T, Evaluation<T>)> {
    let d = a.lam.clone() - &b.lam;
    if d.is_zero() || !b.df.is_positive() {
        return None;
    }
    let (c2, c3) = hermite_coefficients(&d, &a.f, &b.f, &a.df, &b.df);
    // h: Newton's step corrected twice by the cubic's terms (|c2 h| ≪ F′ here).
    let newton = -(b.f.clone() / &b.df);
    let mut h = newton.clone();
    for _ in 0..2 {
        h = newton.clone() - (c2.clone() + c3.clone() * &h) * &h.square() / &b.df;
    }
    // The bounds in the working type: products of squares of steps underflow f64 above
    // about 1075 bits.
    let (ha, da) = (h.clone().abs(), d.clone().abs());
    let one = T::one(eps.prec());
    let err = (c3.abs() + &one).mul_i64(8) * &(da.clone() * &ha).square() / &b.df;
    // The tests in λ first: most attempts end here, before the exponentials below.
    if !(ha.mul_i64(8) <= da && err <= eps.clone() * scale && err.is_finite()) {
        return None;
    }
    // The integrals, in k: Hermite cubics from the two iterates' values and k-derivatives.
    let (ka, kb) = (a.lam.clone().exp(), b.lam.clone().exp());
    let x = (b.lam.clone() + &h).exp();
    let least = ka.clone().min_of(kb.clone()).min_of(x.clone());
    let dk = ka.clone() - &kb;
    let hk = x.clone() - &kb;
    let spread = x.clone() / &least;
    let spread7 = spread.square().square() * &spread.square() * &spread;
    let moved = (x.clone() - &ka) / &x * &(hk.clone() / &x);
    let carry_err = moved.square().mul_i64(16) * &spread7;
    if !(carry_err <= *eps && carry_err.is_finite()) {
        return None;
    }
    let carry = |ya: &T, yb: &T, dya: &T, dyb: &T| {
        let (c2, c3) = hermite_coefficients(&dk, ya, yb, dya, dyb);
        carry_cubic(yb, dyb, &c2, &c3, &hk)
    };
    let (ia, ib) = (&a.ints, &b.ints);
    let (i1, di1) = carry(&ia.i1, &ib.i1, &ia.di1_dk(), &ib.di1_dk());
    let (i2, di2) = carry(&ia.i2, &ib.i2, &ia.di2_dk(), &ib.di2_dk());
    let carried = carry_err;
    let ints = Evaluation {
        i1,
        i2,
        dk: Some([di1, di2]),
        error_estimate: ib.error_estimate.clone() + &carried,
        extra_error: ib.extra_error.clone() + &carried.sqrt(),
        ..ib.clone()
    };
    Some((b.lam.clone() + h, err, ints))
}

/// The relative error of carrying I1, I2 a relative distance `moved` = |dk/k| to first order
/// with k-derivatives of relative error `r`: the Taylor remainder ½|k²I″/I|·moved² with
/// ½|k²I″/I| ≤ 8 (6 for I1 ∝ ln k/k³ at k ≫ 1, with room for I″ between the two k), plus the
/// derivatives' error through |kI′/I| ≤ 4: 16·moved² + 4r·moved (valid for moved ≤ 1/8, which
/// the stopping rules keep: [`Newton::converged`]).
#[inline]
pub(super) fn carry_error<T: Real>(moved: &T, r: &T) -> T {
    (moved.clone().mul_i64(16) + &r.clone().mul_i64(4)) * moved
}

/// Carries I1, I2 of `ci` from `k_old` to `k` to first order, I(k) ≈ I(k_old) + I′(k_old)(k − k_old):
/// their error estimate grows by the carry's error ([`carry_error`]) and the derivatives',
/// which stay those at `k_old`, by ≲ |k I″/I′|·|dk/k| with |k I″/I′| ≤ 8 (5 for I1 ∝ ln k/k³).
#[inline]
pub(super) fn carry<T: Real>(ci: &mut Evaluation<T>, k_old: &T, k: &T) {
    let dk = k.clone() - k_old;
    ci.i1 += &(ci.di1_dk() * &dk);
    ci.i2 += &(ci.di2_dk() * &dk);
    let moved = (dk / k).abs();
    ci.error_estimate += &carry_error(&moved, &ci.extra_error);
    ci.extra_error += &moved.mul_i64(8);
}

/// Above this |λ| = |ln k| the solve ends with a Newton step in k itself ([`finish`]): below it
/// e^λ's rounding, at most |λ|ε/2 = 4ε relative, stays in k (and in its bound), where the step
/// would cost about 5–10% of an `f64` solve (an exponential and a logarithm;
/// docs/calibration.md).
pub(super) const STEP_IN_K_ABOVE: f64 = 8.0;

/// The shape at λ = ln k from the integrals `ci` evaluated at the previous iterate `lam_old`,
/// `last_step` a bound on |λ − λ*| (the step that stopped the iteration, or the Halley and
/// Hermite stops' own estimate). I1, I2 are carried to k = e^λ ([`carry`]).
///
/// That k inherits λ's rounding, half an ulp of λ, as a relative error up to |λ|ε/2. Up to
/// |λ| = [`STEP_IN_K_ABOVE`] the bound carries it: (δI2/I2 + δI1/I1)/F′ (F′ ≥ ~1 here; 1/4 is
/// the floor) plus twice the last step plus (|λ| + 4)ε. Above (λ ≈ −576 at 1 − M_R = 10⁻¹⁰⁰⁰),
/// one Newton step is taken in k itself on the carried integrals: F = ln(I2/(I1·A1/B1)) there,
/// and k ← k·e^{−F/F′} with I1, I2 carried again. Its result's relative error is bounded by
///
/// * the integrals' error through F: (δI2/I2 + δI1/I1 + 4ε)/F′;
/// * the step's own error from F′'s, |F/F′|·8(r + δI/I)/F′ with r the derivatives' relative
///   error (|k I′/I| ≤ 4 each);
/// * the second-order remainder of both steps, 16·(|λ − λ*| + |F/F′|)²;
/// * the rounding of e^{−F/F′} and of the product, 4ε.
///
/// Where F′ is not positive and finite no step is taken, and the first bound applies.
#[inline]
pub(super) fn finish<T: Real>(
    lam: T,
    lam_old: &T,
    mut ci: Evaluation<T>,
    ratio: &T,
    last_step: T,
    iterations: usize,
) -> Shape<T> {
    let p = lam.prec();
    let eps = T::epsilon(p);
    let lam_abs = lam.clone().abs();
    let stepped = lam.exp();
    let own = ci.error_estimate.clone();
    carry(&mut ci, &lam_old.clone().exp(), &stepped);
    let df = shape_slope(&stepped, &ci);
    let floor = df.clone().abs().max_of(T::from_ratio(1, 4, p));
    if lam_abs.to_f64() <= STEP_IN_K_ABOVE || !(df.is_positive() && df.is_finite()) {
        let prop = own.mul_i64(2) / &floor;
        return Shape {
            error_estimate: prop + &last_step.mul_i64(2) + &(eps * &(lam_abs + &T::from_i64(4, p))),
            k: stepped,
            integrals: ci,
            iterations,
        };
    }
    let delta = shape_residual(&ci, ratio) / &df;
    let k = stepped.clone() * &(-delta.clone()).exp();
    carry(&mut ci, &stepped, &k);
    let through_f = (ci.error_estimate.clone().mul_i64(2) + &eps.clone().mul_i64(4)) / &floor;
    let df_error = (ci.extra_error.clone() + &ci.error_estimate).mul_i64(8) / &floor;
    let second = (last_step.abs() + &delta.clone().abs())
        .square()
        .mul_i64(16);
    Shape {
        error_estimate: through_f + &(delta.abs() * &df_error) + &second + &eps.mul_i64(4),
        k,
        integrals: ci,
        iterations,
    }
}
