//! The Green's function as the paper prints it, (5)–(6): a second form the crate's stable
//! (44)–(45) is checked against where it is well conditioned. It loses every digit as V → 0
//! (two vanishing quantities divided) and is 0/0 at V = 0, so the library does not use it.

use moving_hertz::physics::{Material, Speed};
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
    v.m2sq().clone() * (T::one(p) - v.m1sq()).sqrt() / (T::pi(p) * r)
}
