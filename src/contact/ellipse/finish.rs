//! Stage 5: the root and its error bound — the integrals carried from the last evaluation to
//! the root, and the final step in k itself where |ln k| is large.

use super::{shape_residual, shape_slope, Shape};
use crate::routes::Evaluation;
use crate::scalar::Real;

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

/// Above this |ln k| the solve ends with a Newton step in k itself; below, e^λ's rounding
/// (≤ |λ|ε/2 = 4ε) stays in k and its bound (`docs/calibration.md`).
const STEP_IN_K_ABOVE: f64 = 8.0;

/// The shape at λ from the integrals `ci` evaluated at `k_old`, carried to k = e^λ, with
/// `last_step` a bound on |λ − λ*|. Up to |λ| = [`STEP_IN_K_ABOVE`] k's bound is
/// 2(δI/I)/F′ (F′ floored at 1/4) + 2·last_step + (|λ| + 4)ε. Above, one Newton step in k
/// itself, k·e^{−F/F′} on the carried integrals, whose bound is the integrals' error through
/// F, (2δI/I + 4ε)/F′; the step's error from F′'s, |F/F′|·8(r + δI/I)/F′; the second-order
/// remainder 16(|λ − λ*| + |F/F′|)²; and 4ε of rounding. Where F′ is not positive and finite
/// no step is taken.
#[inline]
pub(super) fn finish<T: Real>(
    lam: T,
    k_old: T,
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
    carry(&mut ci, &k_old, &stepped);
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
    let second = (last_step.abs() + &delta.clone().abs()).square();
    Shape {
        error_estimate: through_f
            + &(delta.abs() * &df_error)
            + &second.mul_i64(16)
            + &eps.mul_i64(4),
        k,
        integrals: ci,
        iterations,
    }
}
