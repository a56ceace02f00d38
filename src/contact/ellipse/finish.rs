//! Stage 5: the root and its error bound — the integrals carried from the last evaluation to
//! the root, the final step in k itself where |ln k| is large, and the Hermite stop that ends
//! an unseeded solve one evaluation early.

use super::newton::Point;
use super::{shape_residual, shape_slope, Shape};
use crate::routes::Evaluation;
use crate::scalar::Real;

/// c2, c3 of the cubic y(x_b + h) = y_b + y′_b h + c2 h² + c3 h³ through (y_b, y′_b) and
/// (y_a, y′_a) at distance d = x_a − x_b.
fn hermite_coefficients<T: Real>(d: &T, ya: &T, yb: &T, dya: &T, dyb: &T) -> (T, T) {
    let c3 = ((dya.clone() + dyb) * d - (ya.clone() - yb).mul_i64(2)) / (d.square() * d);
    let c2 = (dya.clone() - dyb) / d.clone().mul_i64(2) - (c3.clone() * d).mul_i64(3).mul_pow2(-1);
    (c2, c3)
}

/// y(x + h) and y′(x + h) for y(x + h) = y + y′h + c2h² + c3h³.
pub(super) fn carry_cubic<T: Real>(y: &T, dy: &T, c2: &T, c3: &T, h: &T) -> (T, T) {
    let val = y.clone() + (dy.clone() + (c2.clone() + c3.clone() * h) * h) * h;
    let der = dy.clone() + (c2.clone().mul_i64(2) + c3.clone().mul_i64(3) * h) * h;
    (val, der)
}

/// The Hermite stop: from iterates `a` (earlier) and `b` (both with derivatives), the root
/// λ_b + h of the cubic through F, F′ at both, taken when |h| ≤ |D|/8 (D = λ_a − λ_b) and
/// the interpolation error 8(1 + |c3|)D²h²/F′ ≤ ε·scale (|F⁗| ≤ 24(1 + |c3|) assumed). I1, I2
/// and their k-derivatives are carried to the root x by their cubics in k, whose remainder
/// relative to I is at most 16((x − k_a)/x)²((x − k_b)/x)²(x/k_min)⁷ for I ∝ k⁻ˢ ln k, s ≤ 3
/// (k_min the least of the three k), also required ≤ ε and added to their estimate.
/// Returns λ, its error bound and the carried integrals.
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
    // Newton's step corrected twice by the cubic's terms.
    let newton = -(b.f.clone() / &b.df);
    let mut h = newton.clone();
    for _ in 0..2 {
        h = newton.clone() - (c2.clone() + c3.clone() * &h) * &h.square() / &b.df;
    }
    // In the working type: squares of steps underflow f64 above about 1075 bits.
    let (ha, da) = (h.clone().abs(), d.clone().abs());
    let one = T::one(eps.prec());
    let err = (c3.abs() + &one).mul_i64(8) * &(da.clone() * &ha).square() / &b.df;
    if !(ha.mul_i64(8) <= da && err <= eps.clone() * scale && err.is_finite()) {
        return None;
    }
    let (ka, kb) = (a.lam.clone().exp(), b.lam.clone().exp());
    let x = (b.lam.clone() + &h).exp();
    let least = ka.clone().min_of(kb.clone()).min_of(x.clone());
    let (dk, hk) = (ka.clone() - &kb, x.clone() - &kb);
    let spread = x.clone() / &least;
    let spread7 = spread.square().square() * &spread.square() * &spread;
    let moved = (x.clone() - &ka) / &x * &(hk.clone() / &x);
    let carried = moved.square().mul_i64(16) * &spread7;
    if !(carried <= *eps && carried.is_finite()) {
        return None;
    }
    let carry = |ya: &T, yb: &T, dya: &T, dyb: &T| {
        let (c2, c3) = hermite_coefficients(&dk, ya, yb, dya, dyb);
        carry_cubic(yb, dyb, &c2, &c3, &hk)
    };
    let (ia, ib) = (&a.ints, &b.ints);
    let (i1, di1) = carry(&ia.i1, &ib.i1, &ia.di1_dk(), &ib.di1_dk());
    let (i2, di2) = carry(&ia.i2, &ib.i2, &ia.di2_dk(), &ib.di2_dk());
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
/// with k-derivatives of relative error `r`: ½|k²I″/I|·moved² with ½|k²I″/I| ≤ 8, plus
/// |kI′/I| ≤ 4 times r·moved: 16·moved² + 4r·moved (for moved ≤ 1/8, which the stops keep).
#[inline]
pub(super) fn carry_error<T: Real>(moved: &T, r: &T) -> T {
    (moved.clone().mul_i64(16) + &r.clone().mul_i64(4)) * moved
}

/// Carries I1, I2 of `ci` from `k_old` to `k` to first order; their estimate grows by
/// [`carry_error`], the derivatives' (kept from `k_old`) by |k I″/I′|·|dk/k| with |k I″/I′| ≤ 8.
#[inline]
fn carry<T: Real>(ci: &mut Evaluation<T>, k_old: &T, k: &T) {
    let dk = k.clone() - k_old;
    ci.i1 += &(ci.di1_dk() * &dk);
    ci.i2 += &(ci.di2_dk() * &dk);
    let moved = (dk / k).abs();
    ci.error_estimate += &carry_error(&moved, &ci.extra_error);
    ci.extra_error += &moved.mul_i64(8);
}

/// Above this |ln k| the solve ends with a Newton step in k itself ([`finish`]); below, e^λ's
/// rounding (≤ |λ|ε/2 = 4ε) stays in k and its bound (`docs/calibration.md`).
const STEP_IN_K_ABOVE: f64 = 8.0;

/// The shape at λ from the integrals `ci` evaluated at `lam_old`, carried to k = e^λ, with
/// `last_step` a bound on |λ − λ*|. Up to |λ| = [`STEP_IN_K_ABOVE`] k's bound is
/// 2(δI/I)/F′ (F′ floored at 1/4) + 2·last_step + (|λ| + 4)ε. Above, one Newton step in k
/// itself, k·e^{−F/F′} on the carried integrals, whose bound is the integrals' error through
/// F, (2δI/I + 4ε)/F′; the step's error from F′'s, |F/F′|·8(r + δI/I)/F′; the second-order
/// remainder 16(|λ − λ*| + |F/F′|)²; and 4ε of rounding. Where F′ is not positive and finite
/// no step is taken.
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
        let rounding = eps * &(lam_abs + &T::from_i64(4, p));
        return Shape {
            error_estimate: own.mul_i64(2) / &floor + &last_step.mul_i64(2) + &rounding,
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
