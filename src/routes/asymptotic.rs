//! The behaviour of I2 as M_R → 1 (end of section 6): I2 ~ C (1 − M_R)^(−1/2), with C in closed
//! form and the next, k-dependent term.
//!
//! From (48) and (53), with ε² = 1 − M_R² and β = arccos M_R ≈ ε, the bracket of (53) is
//! π/2 − E(e)β + O(β³), so S = π/(2ε) + K(e) − 2E(e) + O(ε). With G(M_R²) = G(1) + O(ε²) and the
//! bounded remainder of (48) tending to
//! R(1) = ∫_0^{π/2} (G(cos²α) − G(1)) cos²α / (sin²α Δ³) dα, and 1/ε = (1 − M_R)^(−1/2)/√2 + O(ε),
//!
//! ```text
//! I2 = C (1 − M_R)^(−1/2) + D + O((1 − M_R)^(1/2)),
//! C = π² G(1)/√2,          D = 2π [ G(1) (K(e) − 2E(e)) + R(1) ],
//! ```
//!
//! in the normalisation of (37) (divide by π for the paper's (34): C_paper = π G(1)/√2). G(1) is
//! G of (45) at V = c_R, x = m1:
//! G(1) = √(1 − γ m1) · [(2 − m1)² + 4√((1 − γ m1)(1 − m1))] / (π m1 (m1² − (m2 + m3) m1 + m2 m3)).
//! **C depends on ν only, not on k**; D depends on ν and k (it grows like 2πG(1) ln(4/k) as k → 0).

use super::AxisRatio;
use crate::error::Result;
use crate::numerics::elliptic::ellipke_mc;
use crate::numerics::quadrature::{integrate, Limits};
use crate::physics::{GreenFunction, Material};
use crate::scalar::Real;

/// The two-term expansion of I2 as M_R → 1 for one material and axis ratio.
#[derive(Clone, Debug)]
pub struct I2Asymptotics<T: Real> {
    /// C = π² G(1)/√2 (normalisation of (37)): I2 ~ C (1 − M_R)^(−1/2).
    pub c: T,
    /// The constant term D = 2π [G(1)(K − 2E) + R(1)].
    pub d: T,
}

/// C = π² G(1)/√2, the coefficient of (1 − M_R)^(−1/2) in I2 (normalisation of (37)), a function
/// of ν alone. Accuracy: a few ε.
pub fn leading_coefficient<T: Real>(mat: &Material<T>) -> T {
    let p = mat.nu().prec();
    T::pi(p) * mat.pi_g_rayleigh() / T::from_i64(2, p).sqrt()
}

impl<T: Real> I2Asymptotics<T> {
    /// C and D for `mat` and `axes`; R(1) by adaptive quadrature (its integrand is bounded:
    /// G(cos²α) − G(1) vanishes like sin²α), to a few ε.
    pub fn new(mat: &Material<T>, axes: &AxisRatio<T>) -> Result<Self> {
        let p = mat.nu().prec();
        let green = GreenFunction::new(mat);
        let one = T::one(p);
        let c = leading_coefficient(mat);
        let (kk, ee) = ellipke_mc(&axes.k2)?;
        // R(1) in the variables of the direct route: left w = tan α, right v = cot α.
        // (G(c) − G(1))/sin²α = −DG(c, 1) (c − 1 = −sin²α), with c = cos²α.
        let left = |w: &T| {
            let w2 = w.square();
            let opw2 = one.clone() + &w2;
            let cos2 = opw2.clone().recip();
            let dg = green.g_divided_difference(&cos2, &one);
            let a = one.clone() + axes.k2.clone() * &w2;
            // cos²α dα/Δ³ = dw / (√(1 + w²)(1 + k²w²)^{3/2}).
            -(dg / (opw2.sqrt() * a.clone() * a.sqrt()))
        };
        let right = |v: &T| {
            let v2 = v.square();
            let opv2 = one.clone() + &v2;
            let cos2 = v2.clone() / &opv2;
            let dg = green.g_divided_difference(&cos2, &one);
            let b = v2.clone() + &axes.k2;
            // cos²α dα/Δ³ = v² dv / (√(1 + v²)(v² + k²)^{3/2}).
            -(dg * v2 / (opv2.sqrt() * b.clone() * b.sqrt()))
        };
        let mut pts = vec![T::zero(p)];
        if axes.k < one {
            let mut x = axes.k.clone().mul_pow2(-4);
            while x < one && x.is_positive() {
                pts.push(x.clone());
                x = x.mul_pow2(2);
            }
        }
        pts.push(one.clone());
        let tol = T::zero(p);
        let lim = Limits::default();
        let r_left = integrate(left, &[T::zero(p), one.clone()], &tol, lim)?;
        let r_right = integrate(right, &pts, &tol, lim)?;
        let r1 = r_left.value + &r_right.value;
        // 2π(G(1)(K − 2E) + R(1)).
        let d = (mat.pi_g_rayleigh().clone() * (kk - ee.mul_i64(2)) + T::pi(p) * r1).mul_pow2(1);
        Ok(I2Asymptotics { c, d })
    }

    /// The one-term approximation C (1 − M_R)^(−1/2), given 1 − M_R.
    /// The first term of the expansion of (48) with (53) as M_R → 1 (end of section 6); relative
    /// error O((1 − M_R)^{1/2}).
    pub fn leading(&self, one_minus_mr: &T) -> T {
        self.c.clone() / one_minus_mr.clone().sqrt()
    }

    /// The two-term approximation C (1 − M_R)^(−1/2) + D, given 1 − M_R; relative error
    /// O(1 − M_R).
    /// The expansion of (48) with (53) as M_R → 1 (end of section 6).
    pub fn two_term(&self, one_minus_mr: &T) -> T {
        self.leading(one_minus_mr) + &self.d
    }
}
