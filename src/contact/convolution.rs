//! Validation of the solution by the physics, independent of Galin's theorem: the surface
//! displacement as the convolution (7) of the computed pressure with the moving-load Green's
//! function (4), in polar coordinates around the field point (`docs/theory.md`, "The Green's
//! function", states the integral). Along each ray the pressure p0 √(1 − X²/a² − Y²/b²) of (9)
//! is integrated exactly: with h the ellipse's support normal to the ray
//! (h² = a² sin²φ + b² cos²φ) and d the ray line's distance from the centre, the chord has
//! half-length L = ab√(h² − d²)/h², and the integral is that of √C·√(L² − u²), √C = h/(ab), over
//! the part of the chord ahead of the point (the area of a circular segment), written with
//! h − d and h + d (no cancellation). Lengths are in units of m = max(a, b).
//!
//! The angular integral is done by adaptive Gauss–Legendre quadrature with breakpoints where its
//! integrand has kinks or peaks: where g(V|sin φ|) peaks (φ = π/2, 3π/2, width ~√(1 − M_R²) as
//! M_R → 1, offsets growing geometrically around them) and at the rays tangent to the ellipse.
//!
//! * **Near** (distance r from the centre at most m, inside or outside the contact): over
//!   φ ∈ [0, 2π].
//! * **Far** (r > m): only the rays within the tangents carry pressure, a window of half-width
//!   about m/r around the direction to the centre. The angle is then measured from that
//!   direction, ψ = φ − θ₀ − π (θ₀ the field point's polar angle), so that the window is resolved
//!   at any distance: d = r sin ψ, and the tangents are the roots of a quadratic in tan ψ with
//!   coefficients formed in m/r. The window is integrated alone (the whole chord lies ahead).
//!   Beyond r = 2^(bits + 20)·m, where u_z is below 2^−bits of d0, the convolution is refused
//!   ([`FAR_LIMIT_LOG2`]).

use super::solution::ContactSolution;
use crate::error::{Error, Result};
use crate::numerics::quadrature::{integrate, name_the_input, Limits, Quadrature};
use crate::physics::GreenFunction;
use crate::scalar::Real;

/// The far method's reach: field points at most 2^(bits + FAR_LIMIT_LOG2)·max(a, b) from the
/// centre (`bits` the working precision's), beyond which [`displacement`] refuses.
pub const FAR_LIMIT_LOG2: i32 = 20;

/// The field point and the ellipse in units of m = max(a, b).
struct Scaled<T> {
    m: T,
    x: T,
    y: T,
    a: T,
    b: T,
}

impl<T: Real> Scaled<T> {
    fn new(sol: &ContactSolution<T>, x: &T, y: &T) -> Self {
        let m = sol.a.value.clone().max_of(sol.b.value.clone());
        Scaled {
            x: x.clone() / &m,
            y: y.clone() / &m,
            a: sol.a.value.clone() / &m,
            b: sol.b.value.clone() / &m,
            m,
        }
    }

    /// The support h of the ellipse in the direction normal to a ray whose direction has sine
    /// `s` and cosine `c`: h² = a² s² + b² c².
    fn support(&self, c: &T, s: &T) -> T {
        ((self.a.clone() * s).square() + &(self.b.clone() * c).square()).sqrt()
    }

    /// ∫ √(1 − X²/a² − Y²/b²) dR along the chord of a ray line at distance `d` (≥ 0) from the
    /// centre, normal support `h`, whose midpoint is at R = `centre` along the ray, over R ≥ 0
    /// (see the module docs); `None` for the centre means the whole chord lies ahead.
    fn ray(&self, h: &T, d: &T, centre: Option<&T>) -> T {
        let p = h.prec();
        let hh = (h.clone() - d) * &(h.clone() + d);
        if !hh.is_positive() {
            return T::zero(p);
        }
        let ab = self.a.clone() * &self.b;
        let whole = || ab.clone() * &hh / &(h.clone() * &h.square()) * &T::pi(p).mul_pow2(-1);
        let Some(c) = centre else {
            return whole();
        };
        let half = ab.clone() * &hh.clone().sqrt() / &h.square();
        if *c >= half {
            return whole();
        }
        if !(c.clone() + &half).is_positive() {
            return T::zero(p);
        }
        // The part u = R − c ∈ [−c, L] of the chord, with ∫ √(L² − u²) du = prim.
        let prim = |u: &T| -> T {
            let s = (half.square() - u.square()).max_of(T::zero(p)).sqrt();
            let r = (u.clone() / &half).max_of(-T::one(p)).min_of(T::one(p));
            u.clone() * s.mul_pow2(-1) + half.square().mul_pow2(-1) * r.asin()
        };
        let sqrt_c = h.clone() / &ab;
        sqrt_c * (prim(&half) - prim(&-(c.clone())))
    }
}

/// u_z(x, y) by the convolution (7) at relative tolerance `tol` (see the module docs), with the
/// quadrature's estimate of its absolute error. Works inside and outside the contact.
///
/// Errors: [`Error::Domain`] for a point farther than 2^(bits + [`FAR_LIMIT_LOG2`])·max(a, b)
/// from the centre, or one whose integrand leaves the working type's exponent range; the
/// quadrature's.
pub fn displacement<T: Real>(
    sol: &ContactSolution<T>,
    x: &T,
    y: &T,
    tol: &T,
) -> Result<Quadrature<T>> {
    let p = x.prec();
    let sc = Scaled::new(sol, x, y);
    let limit = T::one(p).mul_pow2(T::bits(p) as i32 + FAR_LIMIT_LOG2);
    let refuse = |bound| {
        Error::domain(
            "field point (x, y)",
            format!("({}, {})", x.to_decimal(), y.to_decimal()),
            bound,
        )
    };
    // hypot does not overflow before its result does (then ∞, refused as too far).
    let rho = sc.x.clone().hypot(&sc.y);
    if rho > limit {
        return Err(refuse(
            "distance from the centre at most 2^(bits + 20)·max(a, b)",
        ));
    }
    let q = if rho > T::one(p) {
        let unresolved = "tangent rays whose angles are normal numbers of the working type";
        far(sol, &sc, &rho, tol).ok_or_else(|| refuse(unresolved))?
    } else {
        near(sol, &sc, x, y, tol)
    };
    let overflow =
        "a point whose convolution integrand stays within the working type's exponent range";
    let q = q.map_err(|e| name_the_input(e, || refuse(overflow)))?;
    let pi = T::pi(p);
    let scale = sol.p0.value.clone() * &sc.m / &(pi.mul_pow2(1) * &sol.problem().shear_modulus);
    Ok(Quadrature {
        value: q.value * &scale,
        error: q.error * &scale,
        evaluations: q.evaluations,
    })
}

/// g(V|sin φ|) from sin φ and cos φ, with 1 − M_R² sin²φ formed as (1 − M_R²) + M_R² cos²φ
/// (no cancellation at the peak, where it falls to 1 − M_R²).
fn green_at<T: Real>(sol: &ContactSolution<T>, green: &GreenFunction<T>, s: &T, c: &T) -> T {
    let speed = &sol.problem().speed;
    let t = speed.mr2().clone() * s.square();
    let omt = speed.one_minus_mr2().clone() + &(speed.mr2().clone() * &c.square());
    green.g_normalised(&t, &omt)
}

/// Breakpoints around an angle where g peaks: the angle and offsets ±√(1 − M_R²)·2^j/4 up to
/// π/4. Each panel then reaches at most twice as far from the peak as it starts: with offsets
/// growing by 4 the quadrature's first estimate missed the error of the panels near a sharp
/// peak (at M_R = 1 − 10⁻⁹ by up to 5 times its bound, `f64`, tolerance 10⁻¹²).
fn peak_points<T: Real>(sol: &ContactSolution<T>, centre: &T) -> Vec<T> {
    let p = centre.prec();
    let eps = sol.problem().speed.one_minus_mr2().clone().sqrt();
    let quarter_pi = T::pi(p).mul_pow2(-2);
    let mut pts = vec![centre.clone()];
    let mut d = eps.mul_pow2(-2);
    while d < quarter_pi {
        pts.push(centre.clone() - &d);
        pts.push(centre.clone() + &d);
        d = d.mul_pow2(1);
    }
    pts
}

/// Sorts and deduplicates breakpoints, keeping those strictly inside (lo, hi) between lo and hi.
fn breakpoints<T: Real>(lo: T, hi: T, inner: Vec<T>) -> Vec<T> {
    let mut pts: Vec<T> = inner.into_iter().filter(|v| *v > lo && *v < hi).collect();
    pts.push(lo);
    pts.push(hi);
    pts.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    pts.dedup_by(|a, b| *a == *b);
    pts
}

/// The angular integral over φ ∈ [0, 2π] for a point at most m from the centre (in units of m).
fn near<T: Real>(
    sol: &ContactSolution<T>,
    sc: &Scaled<T>,
    x: &T,
    y: &T,
    tol: &T,
) -> Result<Quadrature<T>> {
    let p = x.prec();
    let green = GreenFunction::new(sol.problem().speed.material());
    let pi = T::pi(p);
    let f = |phi: &T| -> T {
        let (s, c) = phi.clone().sin_cos();
        let h = sc.support(&c, &s);
        let d = (sc.x.clone() * &s - sc.y.clone() * &c).abs();
        // The chord's midpoint: R = −(x b² cos φ + y a² sin φ)/h².
        let centre = -((sc.x.clone() * &c * &sc.b.square() + sc.y.clone() * &s * &sc.a.square())
            / &h.square());
        green_at(sol, &green, &s, &c) * sc.ray(&h, &d, Some(&centre))
    };
    let half_pi = pi.clone().mul_pow2(-1);
    let mut inner = vec![pi.clone()];
    inner.extend(peak_points(sol, &half_pi));
    inner.extend(peak_points(sol, &(half_pi * T::from_i64(3, p))));
    if !sol.inside(x, y) {
        inner.extend(tangent_angles(sc, &pi));
    }
    let pts = breakpoints(T::zero(p), pi.mul_pow2(1), inner);
    integrate(f, &pts, tol, Limits::default())
}

/// The directions φ ∈ [0, 2π) of the rays from an outside point tangent to the ellipse (units
/// of m): the zeros of h² − d² = (b² − y²) cos²φ + 2xy cos φ sin φ + (a² − x²) sin²φ.
fn tangent_angles<T: Real>(sc: &Scaled<T>, pi: &T) -> Vec<T> {
    let pp = (sc.b.clone() - &sc.y) * &(sc.b.clone() + &sc.y);
    let qq = sc.x.clone() * &sc.y;
    let ss = (sc.a.clone() - &sc.x) * &(sc.a.clone() + &sc.x);
    let disc = qq.square() - pp * &ss;
    if disc.is_negative() {
        return Vec::new();
    }
    let sd = disc.sqrt();
    let two_pi = pi.clone().mul_pow2(1);
    let mut out = Vec::new();
    for num in [-(qq.clone()) + &sd, -(qq.clone()) - &sd] {
        let th = num.atan2(&ss);
        // Each tangent direction and its opposite.
        for base in [th.clone(), th + pi] {
            let mut v = base;
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

/// The angular integral for a point at distance `rho` > 1 (units of m) over the window of rays
/// that meet the ellipse, in ψ = φ − θ₀ − π (module docs); `None` when the window's tangents
/// are not normal numbers of the working type.
fn far<T: Real>(
    sol: &ContactSolution<T>,
    sc: &Scaled<T>,
    rho: &T,
    tol: &T,
) -> Option<Result<Quadrature<T>>> {
    let p = rho.prec();
    let one = T::one(p);
    let (c0, s0) = (sc.x.clone() / rho, sc.y.clone() / rho);
    // tan ψ at the tangents: α t² − 2β t − γ = 0, with a/r, b/r.
    let (ar, br) = (sc.a.clone() / rho, sc.b.clone() / rho);
    let alpha = c0.square() * &((one.clone() - &ar) * &(one.clone() + &ar))
        + s0.square() * &((one.clone() - &br) * &(one.clone() + &br));
    let beta = (ar.clone() - &br) * &(ar.clone() + &br) * &s0 * &c0;
    let gamma = (ar * &s0).square() + (br * &c0).square();
    let root = (beta.square() + alpha.clone() * &gamma).sqrt();
    let (t_lo, t_hi) = if beta.is_negative() {
        let q = beta - root;
        (q.clone() / &alpha, -(gamma / &q))
    } else {
        let q = beta + root;
        (-(gamma / &q), q / &alpha)
    };
    let tiny = T::min_positive(p).mul_pow2(T::bits(p) as i32);
    if !(t_hi > tiny && -(t_lo.clone()) > tiny) {
        return None;
    }
    let (lo, hi) = (t_lo.atan(), t_hi.atan());
    let green = GreenFunction::new(sol.problem().speed.material());
    // sin and cos of θ₀ + ψ (the ray's direction up to sign), formed at the wide precision: at
    // g's peak cos(θ₀ + ψ) is of the order of √(1 − M_R²) and cancels in the working type.
    let pw = T::wide_prec(p);
    let (xw, yw) = (sc.x.to_wide(pw), sc.y.to_wide(pw));
    let rho_w = xw.clone().hypot(&yw);
    let f = |psi: &T| -> T {
        let sp = psi.clone().sin();
        let (spw, cpw) = psi.to_wide(pw).sin_cos();
        let s = T::from_wide(&((yw.clone() * &cpw + xw.clone() * &spw) / &rho_w), p);
        let c = T::from_wide(&((xw.clone() * &cpw - yw.clone() * &spw) / &rho_w), p);
        let h = sc.support(&c, &s);
        let d = (rho.clone() * &sp).abs();
        green_at(sol, &green, &s, &c) * sc.ray(&h, &d, None)
    };
    // g peaks where sin(θ₀ + ψ) = ±1: ψ = π/2 − θ₀ modulo π.
    let pi = T::pi(p);
    let mut peak = pi.clone().mul_pow2(-1) - sc.y.clone().atan2(&sc.x);
    while peak > pi.clone().mul_pow2(-1) {
        peak -= &pi;
    }
    while peak <= -(pi.clone().mul_pow2(-1)) {
        peak += &pi;
    }
    let pts = breakpoints(lo, hi, peak_points(sol, &peak));
    Some(integrate(f, &pts, tol, Limits::default()))
}
