//! The moving-load surface Green's function: Γ of (5), its regular part G of (44)–(45) and the
//! normalised g = −πΓ whose Taylor series (35) starts at f0 = 1 − ν.
//!
//! Everything is evaluated through the rationalised form (44)–(45) (`docs/theory.md`), with
//! m2 + m3 = 8 − m1 and m2 m3 = 8/((1 − ν)m1) real for every ν. No term cancels: not as V → 0,
//! where the printed (5) divides two vanishing quantities, nor as V → c_R, where the pole is
//! carried exactly by 1 − M_R² = (1 − M_R)(1 + M_R). Relative accuracy: a few ε for every
//! 0 ≤ M_R < 1 (`tests/rayleigh.rs`, `green_function_static_limit_and_reference`).

use super::material::Material;
use crate::scalar::Real;

/// Constants of Γ and G for one material, precomputed at the working precision.
#[derive(Clone, Debug)]
pub struct GreenFunction<T: Real> {
    gamma: T,
    m1: T,
    s: T,
    q: T,
    /// 1/(π m1).
    inv_pi_m1: T,
    pi: T,
}

impl<T: Real> GreenFunction<T> {
    /// The Green's function constants of `mat`.
    /// The constants of (44)–(45) (γ, the Rayleigh roots of (6), 2/m1), each to a few ε.
    pub fn new(mat: &Material<T>) -> Self {
        let p = mat.nu().prec();
        let pi = T::pi(p);
        let r = mat.roots();
        GreenFunction {
            gamma: mat.gamma().clone(),
            m1: r.m1.clone(),
            s: r.sum23.clone(),
            q: r.prod23.clone(),
            inv_pi_m1: (pi.clone() * &r.m1).recip(),
            pi,
        }
    }

    /// G of (45) at t = (V'/c_R)² ∈ [0, 1], V' being the speed component normal to the ray
    /// (V sin φ in (34)). Positive, and G(0) = (1 − ν)/π. Relative error a few ε.
    #[inline]
    pub fn g_regular(&self, t: &T) -> T {
        let p = t.prec();
        let one = T::one(p);
        let x = self.m1.clone() * t;
        let a = one.clone() - self.gamma.clone() * &x;
        let b = one - &x;
        let d = (T::from_i64(2, p) - &x).square() + (a.clone() * &b).sqrt().mul_i64(4);
        let quad = x.clone() * (x - &self.s) + &self.q;
        a.sqrt() * d * &self.inv_pi_m1 / quad
    }

    /// The divided difference (G(t) − G(t0))/(t − t0), formed without cancellation (valid also
    /// at t = t0, where it is G'(t0)): every difference of square roots is rationalised and the
    /// product and quotient rules for divided differences are applied to
    /// G = √(1 − γx)·D/(π m1 Q), x = m1 t, Q = x² − s x + q. Used by the subtracted route (48).
    /// Relative error a few ε (the terms it adds have moderate, mixed signs).
    pub fn g_divided_difference(&self, t: &T, t0: &T) -> T {
        let p = t.prec();
        let one = T::one(p);
        let x = self.m1.clone() * t;
        let x0 = self.m1.clone() * t0;
        let a = one.clone() - self.gamma.clone() * &x;
        let a0 = one.clone() - self.gamma.clone() * &x0;
        let b = one.clone() - &x;
        let b0 = one.clone() - &x0;
        let sa = a.clone().sqrt();
        let sa0 = a0.clone().sqrt();
        let sab = (a * b).sqrt();
        let sab0 = (a0 * b0).sqrt();
        let two = T::from_i64(2, p);
        let d = (two.clone() - &x).square() + sab.clone().mul_i64(4);
        let d0 = (two - &x0).square() + sab0.clone().mul_i64(4);
        let quad = x.clone() * (x.clone() - &self.s) + &self.q;
        let quad0 = x0.clone() * (x0.clone() - &self.s) + &self.q;
        let xs = x + &x0;
        // Divided differences with respect to t (each carries a factor m1 from dx/dt).
        let d_sa = -(self.gamma.clone() * &self.m1) / (sa.clone() + &sa0);
        let d_ab = self.m1.clone() * (self.gamma.clone() * &xs - &one - &self.gamma);
        let d_sab = d_ab / (sab + &sab0);
        let d_d = d_sab.mul_i64(4) - self.m1.clone() * (T::from_i64(4, p) - &xs);
        let d_q = self.m1.clone() * (xs - &self.s);
        // D[D/Q] = D[D]/Q − D0·D[Q]/(Q·Q0);  D[√a·(D/Q)] = D[√a]·D/Q + √a0·D[D/Q].
        let d_dq = (d_d - d0.clone() * &d_q / &quad0) / &quad;
        (d_sa * d / &quad + sa0 * d_dq) * &self.inv_pi_m1
    }

    /// g = −πΓ = π G/(1 − t) at t = (V'/c_R)², given also 1 − t (formed by the caller without
    /// cancellation). g(0) = 1 − ν = f0 of the series (35).
    #[inline]
    pub fn g_normalised(&self, t: &T, one_minus_t: &T) -> T {
        self.g_regular(t) * &self.pi / one_minus_t
    }
}
