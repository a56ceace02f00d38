//! Unit test of `j0_from_pair` (src/routes/mod.rs): J0 = k·(k·I1) + I2 within its counted
//! rounding γ3 at `f64` and double-double, and γ3 not loose.

use super::j0_from_pair;
use crate::estimate::RelError;
use crate::scalar::{Dd, Real};
use rug::Float;

/// J0 = k·(k·I1) + I2 from exact I1, I2 (pair error 0) against the same sum in exact
/// arithmetic, over pseudo-random positive operands of every scale: every error within the
/// counted bound γ3, and some error above `least`·γ3: at `f64` above γ3/3 (0.75ε against
/// 1.5ε), so that a count of one rounding would fail; at double-double, whose worst case of
/// an operation (1.625ε, [`Real::ROUNDING`]) three operations do not reach together, above
/// γ3/8 (0.86ε against 4.9ε).
fn check<T: Real>(p: T::Prec, label: &str, least: f64) {
    let bits = T::bits(p);
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut worst = 0.0f64;
    let bound = RelError::rounding::<T>(3.0, p).to_f64();
    for _ in 0..20_000 {
        // Operands carrying all of `bits` (a sum of two f64 at double-double).
        let mut draw = |scale: f64| {
            let hi = T::from_f64((1.0 + next()) * scale, p);
            hi.clone() + &T::from_f64(next() * scale * f64::EPSILON, p)
        };
        let (k, i1, i2) = (draw(1.0), draw(2f64.powi(-3)), draw(1.0));
        let got = j0_from_pair(&k, &i1, &i2, RelError::ZERO);
        let x = |v: &T| v.to_float(bits);
        let exact = Float::with_val(4 * bits, x(&k) * x(&k)) * x(&i1) + x(&i2);
        let err = (Float::with_val(4 * bits, x(&got.value) - &exact) / &exact).abs();
        let err = err.to_f64();
        assert!(
            err <= got.error.to_f64(),
            "{label}: {err:e} above {}",
            got.error
        );
        worst = worst.max(err);
    }
    println!("{label}: J0's rounding, worst {worst:.3e} against γ3 = {bound:.3e}");
    assert!(
        worst > bound * least,
        "{label}: γ3 loose: {worst:e} against {bound:e}"
    );
}

#[test]
fn j0_rounding_is_within_its_count() {
    check::<f64>((), "f64", 1.0 / 3.0);
    check::<Dd>((), "dd", 1.0 / 8.0);
}
