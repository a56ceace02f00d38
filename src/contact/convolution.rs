//! Validation of the solution by the physics, independent of Galin's theorem: the surface
//! displacement as the convolution (7) of the computed pressure with the moving-load Green's
//! function (4),
//!
//! ```text
//! u_z(x, y) = (1/(2πμ)) ∫_0^{2π} g(V |sin φ|) ∫_{ray} p(x + R cos φ, y + R sin φ) dR dφ
//! ```
//!
//! in polar coordinates around the field point (the 1/R of (7) cancels the Jacobian R; g = −πΓ).
//! Along each ray the pressure p0 √(A − 2BR − CR²) of (11) is integrated exactly (it is the area
//! of a segment of a circle: elementary); the angular integral is done by adaptive Gauss–Legendre
//! quadrature with breakpoints where its integrand has kinks or peaks: φ = π/2, 3π/2 (where
//! g(V|sin φ|) peaks with width ~√(1 − M_R²) as M_R → 1) and, outside the contact, the two angles
//! of the rays tangent to the ellipse.

use super::solution::ContactSolution;
use crate::error::Result;
use crate::numerics::quadrature::{integrate, Limits, Quadrature};
use crate::physics::GreenFunction;
use crate::scalar::Real;

/// ∫ √(A − 2BR − CR²) dR over the part of the ray R ≥ 0 inside the ellipse, for the ray of
/// direction φ from (x, y): with c = −B/C and h² = (B² + AC)/C², the integrand is
/// √C·√(h² − (R − c)²), whose integral from R1 to R2 is
/// √C·[(u/2)√(h² − u²) + (h²/2) asin(u/h)] between u = R1 − c and u = R2 − c.
fn ray_integral<T: Real>(sol: &ContactSolution<T>, x: &T, y: &T, cphi: &T, sphi: &T) -> T {
    let p = x.prec();
    let one = T::one(p);
    let ia2 = sol.a.value.clone().square().recip();
    let ib2 = sol.b.value.clone().square().recip();
    let a = one - x.square() * &ia2 - y.square() * &ib2;
    let b = x.clone() * cphi * &ia2 + y.clone() * sphi * &ib2;
    let c = cphi.square() * &ia2 + sphi.square() * &ib2;
    let disc = b.square() + a.clone() * &c;
    if !disc.is_positive() {
        return T::zero(p);
    }
    let h = disc.sqrt() / &c;
    let centre = -(b / &c);
    // The chord is [centre − h, centre + h]; keep its part with R ≥ 0.
    let r_hi = centre.clone() + &h;
    if !r_hi.is_positive() {
        return T::zero(p);
    }
    let u_hi = h.clone();
    let u_lo = (-(centre.clone())).max_of(-(h.clone()));
    let prim = |u: &T| -> T {
        let s = (h.square() - u.square()).max_of(T::zero(p)).sqrt();
        let r = (u.clone() / &h).max_of(-T::one(p)).min_of(T::one(p));
        u.clone() * s.mul_pow2(-1) + h.square().mul_pow2(-1) * r.asin()
    };
    c.sqrt() * (prim(&u_hi) - prim(&u_lo))
}

/// u_z(x, y) by the convolution (7) at relative tolerance `tol` (see the module docs), with the
/// quadrature's estimate of its absolute error. Works inside and outside the contact.
pub fn displacement<T: Real>(
    sol: &ContactSolution<T>,
    x: &T,
    y: &T,
    tol: &T,
) -> Result<Quadrature<T>> {
    let p = x.prec();
    let speed = &sol.problem().speed;
    let green = GreenFunction::new(speed.material());
    let pi = T::pi(p);
    let one = T::one(p);
    let f = |phi: &T| -> T {
        let (s, c) = phi.clone().sin_cos();
        let t = speed.mr2().clone() * s.square();
        let omt = (one.clone() - &t).max_of(speed.one_minus_mr2().clone());
        let g = green.g_normalised(&t, &omt);
        g * ray_integral(sol, x, y, &c, &s)
    };
    // Breakpoints: 0, π/2 ± graded offsets, π, 3π/2 ± offsets, 2π, plus tangent angles.
    let eps = speed.one_minus_mr2().clone().sqrt();
    let half_pi = pi.clone().mul_pow2(-1);
    let mut pts = vec![T::zero(p), pi.clone(), pi.clone().mul_pow2(1)];
    for centre in [half_pi.clone(), half_pi.clone() * T::from_i64(3, p)] {
        pts.push(centre.clone());
        let mut d = eps.clone().mul_pow2(-2);
        while d < half_pi.clone().mul_pow2(-1) {
            pts.push(centre.clone() - &d);
            pts.push(centre.clone() + &d);
            d = d.mul_pow2(2);
        }
    }
    if !sol.inside(x, y) {
        pts.extend(tangent_angles(sol, x, y, &pi));
    }
    pts.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    pts.dedup_by(|a, b| *a == *b);
    let q = integrate(f, &pts, tol, Limits::default())?;
    let scale = sol.p0.value.clone() / (pi.mul_pow2(1) * &sol.problem().shear_modulus);
    Ok(Quadrature {
        value: q.value * &scale,
        error: q.error * &scale,
        evaluations: q.evaluations,
    })
}

/// The directions φ ∈ [0, 2π) of the two rays from an outside point tangent to the ellipse:
/// the roots of B² + AC = 0 as a quadratic form in (cos φ, sin φ).
fn tangent_angles<T: Real>(sol: &ContactSolution<T>, x: &T, y: &T, pi: &T) -> Vec<T> {
    let p = x.prec();
    let one = T::one(p);
    let ia2 = sol.a.value.clone().square().recip();
    let ib2 = sol.b.value.clone().square().recip();
    let a = one - x.square() * &ia2 - y.square() * &ib2; // < 0 outside
                                                         // B² + AC = P cos² + 2Q cos sin + S sin².
    let pp = x.square() * ia2.square() + a.clone() * &ia2;
    let qq = x.clone() * y * &ia2 * &ib2;
    let ss = y.square() * ib2.square() + a * &ib2;
    // Directions where it vanishes: tan φ = (−Q ± √(Q² − P S))/S.
    let disc = qq.square() - pp.clone() * &ss;
    if disc.is_negative() {
        return Vec::new();
    }
    let sd = disc.sqrt();
    let mut out = Vec::new();
    for num in [-(qq.clone()) + &sd, -(qq.clone()) - &sd] {
        let th = num.atan2(&ss);
        // Each tangent direction and its opposite.
        for base in [th.clone(), th.clone() + pi] {
            let mut v = base;
            let two_pi = pi.clone().mul_pow2(1);
            while v.is_negative() {
                v += &two_pi;
            }
            while v >= two_pi {
                v -= &two_pi;
            }
            out.push(v);
        }
    }
    out
}
