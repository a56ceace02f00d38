//! The Green's function as the paper prints it, (5)–(6): a second form the crate's stable
//! (44)–(45) is checked against where it is well conditioned. It loses every digit as V → 0
//! (two vanishing quantities divided) and is 0/0 at V = 0, so the library does not use it.

use moving_hertz::physics::{GreenFunction, Material, Speed};
use moving_hertz::scalar::Real;

/// R of (6) as printed: (2 − x)² − 4√((1 − γx)(1 − x)), x = M2² ≤ 1.
pub fn rayleigh_function<T: Real>(gamma: &T, x: &T) -> T {
    let p = x.prec();
    let one = T::one(p);
    let a = one.clone() - gamma.clone() * x;
    let b = one - x;
    (T::from_i64(2, p) - x).square() - (a * b).sqrt().mul_i64(4)
}

/// Γ of (5) as printed: M2²√(1 − M1²)/(π R).
pub fn gamma<T: Real>(mat: &Material<T>, v: &Speed<T>) -> T {
    let p = v.mr().prec();
    let r = rayleigh_function(mat.gamma(), v.m2sq());
    v.m2sq().clone() * (T::one(p) - mat.gamma().clone() * v.m2sq()).sqrt() / (T::pi(p) * r)
}

/// Γ(V) of (5) by the library's stable form (44): −G(M_R²)/(1 − M_R²). Negative;
/// Γ(0) = −(1 − ν)/π.
pub fn gamma_44<T: Real>(g: &GreenFunction<T>, v: &Speed<T>) -> T {
    -(g.g_regular(v.mr2()) / v.one_minus_mr2())
}

/// R(V) by the corrected factorisation (`docs/errata.md` #1):
/// x (x − m1)(x² − s x + q)/D with x = M2², accurate to a few ε for every 0 ≤ M_R < 1 (the
/// printed (6) loses everything as V → 0).
pub fn rayleigh_factorised<T: Real>(mat: &Material<T>, v: &Speed<T>) -> T {
    let p = v.mr().prec();
    let one = T::one(p);
    let x = v.m2sq().clone();
    let a = one.clone() - mat.gamma().clone() * v.m2sq();
    let b = one - &x;
    let d = (T::from_i64(2, p) - &x).square() + (a * b).sqrt().mul_i64(4);
    let r = mat.roots();
    let quad = x.clone() * (x.clone() - &r.sum23) + &r.prod23;
    // x − m1 = −m1 (1 − M_R²).
    -(x * &r.m1 * v.one_minus_mr2() * quad / d)
}
