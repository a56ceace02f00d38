//! I2 ~ C (1 − M_R)^(−1/2) + D as M_R → 1: C = π² G(1)/√2 (independent of k) and D against I2
//! computed by the subtracted route at M_R = 1 − 10^-4 … 1 − 10^-12.
//!
//! The expansion (end of section 6 of the paper), with C in closed form and the next,
//! k-dependent term:
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

mod common;

use moving_hertz::numerics::elliptic::ellipke_mc;
use moving_hertz::numerics::quadrature::{integrate, Limits};
use moving_hertz::physics::{GreenFunction, Material};
use moving_hertz::prelude::*;
use moving_hertz::routes::AxisRatio;
use moving_hertz::{integrals, IntegralOptions};

/// I2 by the subtracted route ([`Method::AdaptiveSubtracted`], (48) with S by (53)).
fn subtracted_i2<T: Real>(sp: &Speed<T>, ax: &AxisRatio<T>) -> T {
    let opts = IntegralOptions {
        method: Method::AdaptiveSubtracted,
        ..Default::default()
    };
    integrals(sp, &ax.k, &opts).unwrap().i2.value
}

/// The two-term expansion of I2 as M_R → 1 for one material and axis ratio.
#[derive(Clone, Debug)]
struct I2Asymptotics<T: Real> {
    /// C = π² G(1)/√2 (normalisation of (37)): I2 ~ C (1 − M_R)^(−1/2).
    c: T,
    /// The constant term D = 2π [G(1)(K − 2E) + R(1)].
    d: T,
}

/// C = π² G(1)/√2, the coefficient of (1 − M_R)^(−1/2) in I2 (normalisation of (37)), a function
/// of ν alone. Accuracy: a few ε.
fn leading_coefficient<T: Real>(mat: &Material<T>) -> T {
    let p = mat.nu().prec();
    T::pi(p) * mat.pi_g_rayleigh() / T::from_i64(2, p).sqrt()
}

impl<T: Real> I2Asymptotics<T> {
    /// C and D for `mat` and `axes`; R(1) by adaptive quadrature (its integrand is bounded:
    /// G(cos²α) − G(1) vanishes like sin²α), to a few ε.
    fn new(mat: &Material<T>, axes: &AxisRatio<T>) -> Result<Self> {
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
    fn leading(&self, one_minus_mr: &T) -> T {
        self.c.clone() / one_minus_mr.clone().sqrt()
    }

    /// The two-term approximation C (1 − M_R)^(−1/2) + D, given 1 − M_R; relative error
    /// O(1 − M_R).
    /// The expansion of (48) with (53) as M_R → 1 (end of section 6).
    fn two_term(&self, one_minus_mr: &T) -> T {
        self.leading(one_minus_mr) + &self.d
    }
}

fn check<T: Real>(p: T::Prec, label: &str) {
    for (nu, k) in [
        ("0.25", "0.5"),
        ("0.0", "0.05"),
        ("0.5", "0.001"),
        ("-0.5", "1"),
    ] {
        let mat = Material::new(T::parse(nu, p).unwrap()).unwrap();
        let ax = AxisRatio::new(T::parse(k, p).unwrap()).unwrap();
        let asy = I2Asymptotics::new(&mat, &ax).unwrap();
        assert_eq!(asy.c, leading_coefficient(&mat));
        let mut prev_ratio = f64::INFINITY;
        for j in [4, 6, 8, 10, 12] {
            let mr = T::one(p) - T::one(p) / T::from_i64(10i64.pow(j as u32), p);
            // 1 − M_R of the rounded M_R (exact by Sterbenz's lemma).
            let delta = T::one(p) - &mr;
            let sp = mat.speed(mr).unwrap();
            let i2 = subtracted_i2(&sp, &ax);
            // One term: relative error ~ (D/C)·δ^(1/2); two terms: ~ δ.
            let e1 = ((asy.leading(&delta) - &i2) / &i2).abs().to_f64();
            let e2 = ((asy.two_term(&delta) - &i2) / &i2).abs().to_f64();
            let d = delta.to_f64();
            let dc = (asy.d.clone() / &asy.c).abs().to_f64();
            assert!(
                e1 <= 1.5 * dc * d.sqrt() + 1e-13,
                "{label} nu={nu} k={k} 1-M_R={d:e}: one-term error {e1:e}"
            );
            assert!(
                e2 <= 10.0 * (1.0 + dc) * d + 1e-13,
                "{label} nu={nu} k={k} 1-M_R={d:e}: two-term error {e2:e}"
            );
            // The one-term error, divided by δ^(1/2), tends to |D/C|.
            let ratio = e1 / d.sqrt();
            if j >= 8 {
                assert!(
                    (ratio - dc).abs() <= 0.05 * dc + 1e-6 / d.sqrt(),
                    "{label}: ratio {ratio} vs D/C {dc}"
                );
            }
            prev_ratio = prev_ratio.min(ratio);
        }
        println!(
            "{label} nu={nu} k={k}: C = {:.12e}, D = {:.12e}",
            asy.c.to_f64(),
            asy.d.to_f64()
        );
    }
}

#[test]
fn two_term_asymptotics_of_i2() {
    check::<f64>((), "f64");
    check::<Dd>((), "dd");
}

#[test]
fn leading_coefficient_is_independent_of_k() {
    let mat = Material::new(0.2).unwrap();
    let c = leading_coefficient(&mat);
    // C = π² G(1)/√2; as a function of ν only it equals the limit of I2·(1 − M_R)^(1/2) for
    // different k (the k-dependence enters through D).
    for k in [0.01, 0.3, 1.0] {
        let ax = AxisRatio::new(k).unwrap();
        let sp = mat.speed(1.0 - 1e-12).unwrap();
        let i2 = subtracted_i2(&sp, &ax);
        let est = i2 * 1e-6;
        assert!((est - c).abs() / c < 1e-4, "k = {k}: {est} vs {c}");
    }
}
