//! The direct route of sections 6–7: I1 and I2 by quadrature of (46)–(47), plain or with the
//! singular part of I2 subtracted by (48) and integrated in closed form by (53) (both stated in
//! `docs/theory.md`; (53) takes the incomplete integrals at modulus k, `docs/errata.md` #6).
//!
//! **Variables.** In the normalisation of (37), split at α = π/4 and written with w = tan α on
//! the left half and v = cot α on the right (t = M_R² cos²α, ε² = 1 − M_R²):
//!
//! ```text
//! left:  F_L(w) = 2π G(t) √(1 + w²) / ((ε² + w²)(1 + k²w²)^{3/2}),  t = M_R²/(1 + w²),
//!        I1 += ∫_0^1 w² F_L dw,  I2 += ∫_0^1 F_L dw;
//! right: F_R(v) = 2π G(t) √(1 + v²) / ((1 + ε²v²)(v² + k²)^{3/2}),  t = M_R² v²/(1 + v²),
//!        I1 += ∫_0^1 F_R dv,     I2 += ∫_0^1 v² F_R dv.
//! ```
//!
//! No trigonometric function is needed at a node, every factor is positive, and the length
//! scales ε (the Rayleigh pole's peak at α = 0), k and 1/k (the peaks of Δ⁻³) are plain numbers:
//! the panels are graded geometrically about each, so the work grows like log(1/ε) + |log k|.
//!
//! **The pole in closed form** ([`quadrature`], [`contact_integrals`]; not the subtracted form
//! (48)). Every left integrand is n(s)/(s + ε²), s = w², with n analytic near [0, 1]; with
//! s0 = −ε² (t = 1),
//!
//! ```text
//! ∫_0^1 n(s)/(s + ε²) dw = n(s0)·atan(1/ε)/ε + ∫_0^1 (n(s) − n(s0))/(s − s0) dw,
//! ```
//!
//! the divided difference formed by the product rule without cancellation, so that no panel is
//! graded about ε (taken where ε ≤ 1/2 and kε ≤ 1/2).

use super::{beyond_exponent_range, AxisRatio, Evaluation, Route};
use crate::error::{Error, Result};
use crate::estimate::RelError;
use crate::numerics::elliptic::{ellipbd_mc, heuman_lambda_c_mc};
use crate::numerics::quadrature::{integrate_vec, integrate_vec_plus, Limits, VecQuadrature};
use crate::physics::{GreenFunction, Speed};
use crate::scalar::{short, Real};

/// The constants of the integrands for one (material, speed, axis ratio).
#[derive(Clone, Debug)]
pub struct DirectSetup<T: Real> {
    green: GreenFunction<T>,
    /// M_R².
    mr2: T,
    /// ε² = 1 − M_R².
    eps2: T,
    /// ε = √(1 − M_R²).
    eps: T,
    /// M_R.
    mr: T,
    k: T,
    k2: T,
    two_pi: T,
}

impl<T: Real> DirectSetup<T> {
    /// The constants of (46)–(48) (ε² = 1 − M_R², k², G's constants), each to a few ε.
    pub fn new(speed: &Speed<T>, axes: &AxisRatio<T>) -> Self {
        let p = speed.mr().prec();
        DirectSetup {
            green: GreenFunction::new(speed.material()),
            mr2: speed.mr2().clone(),
            eps2: speed.one_minus_mr2().clone(),
            eps: speed.one_minus_mr2().clone().sqrt(),
            mr: speed.mr().clone(),
            k: axes.k.clone(),
            k2: axes.k2.clone(),
            two_pi: T::pi(p).mul_pow2(1),
        }
    }

    /// G(M_R²), the value subtracted in (48).
    pub fn g_at_speed(&self) -> T {
        self.green.g_regular(&self.mr2)
    }

    /// At a left node w: w², 1 + w², t = M_R²/(1 + w²) and u = 1 + k²w².
    fn left_node(&self, w: &T) -> [T; 4] {
        let one = T::one(w.prec());
        let w2 = w.square();
        let opw2 = one.clone() + &w2;
        let t = self.mr2.clone() / &opw2;
        let u = one + self.k2.clone() * &w2;
        [w2, opw2, t, u]
    }

    /// At a right node v: v², 1 + v², t = M_R²v²/(1 + v²) and h = v² + k².
    fn right_node(&self, v: &T) -> [T; 4] {
        let v2 = v.square();
        let opv2 = T::one(v.prec()) + &v2;
        let t = self.mr2.clone() * &v2 / &opv2;
        let h = v2.clone() + &self.k2;
        [v2, opv2, t, h]
    }

    /// 2πG(t)√(1 + w²)/(ε² + w²) = F_L·u^{3/2}: the left integrand without the kernel.
    fn left_factor(&self, [w2, opw2, t, _]: &[T; 4]) -> T {
        let g = self.green.g_regular(t);
        self.two_pi.clone() * g * opw2.clone().sqrt() / (self.eps2.clone() + w2)
    }

    /// 2πG(t)√(1 + v²)/(1 + ε²v²) = F_R·h^{3/2}: the right integrand without the kernel.
    fn right_factor(&self, [v2, opv2, t, _]: &[T; 4]) -> T {
        let g = self.green.g_regular(t);
        let one = T::one(v2.prec());
        self.two_pi.clone() * g * opv2.clone().sqrt() / (one + self.eps2.clone() * v2)
    }

    /// F_L(w), the integrand of (46)–(47) on α ≤ π/4, w = tan α; a few ε relative.
    pub fn left(&self, w: &T) -> T {
        let n = self.left_node(w);
        let u = &n[3];
        self.left_factor(&n) / (u.clone() * u.clone().sqrt())
    }

    /// F_R(v), the integrand of (46)–(47) on α ≥ π/4, v = cot α; a few ε relative.
    pub fn right(&self, v: &T) -> T {
        let n = self.right_node(v);
        let h = &n[3];
        self.right_factor(&n) / (h.clone() * h.clone().sqrt())
    }

    /// The left half's pole at w = iε, when it is taken out of the contact integrands
    /// ([`contact_integrals`]): where ε ≤ 1/2 and kε ≤ 1/2 (so that 1 − k²ε² ≥ 3/4 keeps the
    /// pole away from the branch points w = ±i/k of the kernels).
    fn left_pole(&self) -> Option<LeftPole<T>> {
        let p = self.k.prec();
        let one = T::one(p);
        let half = one.clone().mul_pow2(-1);
        if self.eps > half || self.k.clone() * &self.eps > half {
            return None;
        }
        let s0 = -self.eps2.clone();
        let u0 = one.clone() - self.k2.clone() * &self.eps2;
        let su0 = u0.clone().sqrt();
        let g1 = self.green.g_regular(&one);
        let b0 = self.two_pi.clone() * &g1 * &self.mr;
        let phi1 = su0.clone().recip();
        let phi3 = phi1.clone() / &u0;
        let phi5 = phi3.clone() / &u0;
        let m3k = -self.k.clone().mul_i64(3);
        let kernels = [
            s0.clone() * &phi3,
            phi3,
            phi1,
            m3k.clone() * &s0 * &s0 * &phi5,
            m3k * &s0 * phi5,
        ];
        // n_c(s0)·∫_0^1 dw/(w² + ε²), the integral being atan(1/ε)/ε.
        let pole_integral = one.clone().atan2(&self.eps) / &self.eps;
        let parts = kernels.map(|c| c * &b0 * &pole_integral);
        Some(LeftPole {
            s0,
            u0,
            su0,
            b0,
            g1,
            one,
            parts,
        })
    }

    /// The parts of the left integrands with the pole taken out (see [`LeftPole`]): at s = w²,
    /// the numerators are n_c = B·K_c with B = 2πG(M_R²/(1 + s))√(1 + s) and kernels
    /// K = (s φ3, φ3, φ1, −3k s² φ5, −3k s φ5), φ_m = u^{−m/2}, u = 1 + k²s. Returns s,
    /// D[B] = (B(s) − B(s0))/(s − s0) with t − 1 = −(s − s0)/(1 + s) (so that
    /// D[G(t)] = −DG(t, 1)/(1 + s)) and D[√(1 + s)] = 1/(√(1 + s) + M_R), the φ_m and
    /// D[φ_m] = k²(φ_m(u) − φ_m(u0))/(u − u0) with the difference of powers of √u rationalised
    /// (m = 1, 3, 5). No term cancels; a few ε relative each.
    fn left_pole_parts(&self, pole: &LeftPole<T>, w: &T) -> (T, T, [T; 3], [T; 3]) {
        let [s, ops, t, u] = self.left_node(w);
        let r = ops.clone().sqrt();
        let dg = self.green.g_divided_difference(&t, &pole.one);
        let db = self.two_pi.clone() * (pole.g1.clone() / (r.clone() + &self.mr) - dg * r / ops);
        let su = u.clone().sqrt();
        let q = su.clone() * &pole.su0;
        let uu0 = u.clone() * &pole.u0;
        let base = -(self.k2.clone() / (q.clone() * (su.clone() + &pole.su0)));
        let phi1 = su.recip();
        let phi3 = phi1.clone() / &u;
        let phi5 = phi3.clone() / &u;
        let d3 = base.clone() * (pole.u0.clone() + &q + &u) / &uu0;
        let sq = pole.u0.clone().square() + pole.u0.clone() * &u + u.clone().square();
        let d5 = base.clone() * (sq + q * (pole.u0.clone() + &u)) / uu0.square();
        (s, db, [phi1, phi3, phi5], [base, d3, d5])
    }

    /// The five left integrands of [`contact_integrals`] with the pole taken out:
    /// D_c = (n_c(s) − n_c(s0))/(s − s0) = D[B]·K_c(s) + B(s0)·D[K_c] (the product rule for
    /// divided differences), from [`DirectSetup::left_pole_parts`].
    fn left_divided(&self, pole: &LeftPole<T>, w: &T) -> [T; 5] {
        let (s, db, [phi1, phi3, phi5], [d1, d3, d5]) = self.left_pole_parts(pole, w);
        let s0 = &pole.s0;
        let m3k = -self.k.clone().mul_i64(3);
        let kern = [
            s.clone() * &phi3,
            phi3.clone(),
            phi1,
            m3k.clone() * &s * &s * &phi5,
            m3k.clone() * &s * &phi5,
        ];
        let dkern = [
            phi3 + s0.clone() * &d3,
            d3,
            d1,
            m3k.clone() * ((s + s0) * &phi5 + s0.clone() * s0 * &d5),
            m3k * (phi5 + s0.clone() * &d5),
        ];
        let mut out = dkern;
        for (o, kc) in out.iter_mut().zip(kern) {
            *o = db.clone() * kc + pole.b0.clone() * &*o;
        }
        out
    }

    /// The left-half integrand of I2 with G(t) replaced by G(t) − G(M_R²), written with the
    /// divided difference DG so that nothing cancels: since t − M_R² = −M_R² w²/(1 + w²),
    /// it is −2π M_R² DG · w² / (√(1 + w²)(ε² + w²)(1 + k²w²)^{3/2}) ≥ 0.
    /// The integral of (48), left half; a few ε relative (no cancellation).
    pub fn left_subtracted(&self, w: &T) -> T {
        let [w2, opw2, t, u] = self.left_node(w);
        let dg = self.green.g_divided_difference(&t, &self.mr2);
        let den = opw2.sqrt() * (self.eps2.clone() + &w2) * u.clone() * u.sqrt();
        // w²/den first: M_R²·w² alone underflows when both are tiny.
        -(self.two_pi.clone() * &self.mr2 * dg * (w2 / den))
    }

    /// The right-half integrand of I2 (v² F_R) with G(t) − G(M_R²): with
    /// t − M_R² = −M_R²/(1 + v²), it is −2π M_R² DG · v² / (√(1 + v²)(1 + ε²v²)(v² + k²)^{3/2}).
    /// The integral of (48), right half; a few ε relative (no cancellation).
    pub fn right_subtracted(&self, v: &T) -> T {
        let [v2, opv2, t, h] = self.right_node(v);
        let dg = self.green.g_divided_difference(&t, &self.mr2);
        let one = T::one(v.prec());
        let den = opv2.sqrt() * (one + self.eps2.clone() * &v2) * h.clone() * h.sqrt();
        -(self.two_pi.clone() * &self.mr2 * dg * (v2 / den))
    }

    /// Breakpoints on [0, 1] graded geometrically (ratio 4) about each scale in `scales` that
    /// lies inside (0, 1): about log₄(16/scale) panels a scale, each of which the quadrature
    /// evaluates 3n times before it refines any (n = `lim`'s Gauss order). Where that first pass
    /// would take more than a third of `lim`'s evaluation cap (the rest for refining), as for
    /// k or 1/k beyond about 2^(4.4·10⁵/n), [`Error::Domain`] before any evaluation, naming the
    /// input whose scale has the most panels: k, or 1 − M_R² (ε = √(1 − M_R²) is a scale where
    /// the Rayleigh pole is not taken out in closed form).
    fn breakpoints(&self, scales: &[T], lim: Limits) -> Result<Vec<T>> {
        let p = self.k.prec();
        let one = T::one(p);
        let inside = |s: &&T| s.is_positive() && **s < one;
        // The panels from the scales' binary exponents, before any is made: at most
        // (log₂(1/s) + 4)/2 + 1 about each scale s, one more for [0, 1] itself.
        let count = |s: &T| (4.0 - RelError::of(s).log2()) / 2.0 + 1.0;
        let panels: f64 = 1.0 + scales.iter().filter(inside).map(count).sum::<f64>();
        // The first pass within a third of the cap, the rest left for refining (at 256 bits
        // the pieces about 1/k took up to 2.1 times their first pass: k = 10²⁷⁰⁰ ran out).
        let first_pass = panels * (3 * lim.gauss_order(T::bits(p))) as f64;
        if first_pass > lim.max_evals as f64 / 3.0 {
            let widest = scales
                .iter()
                .filter(inside)
                .max_by(|a, b| count(a).total_cmp(&count(b)));
            return Err(if widest == Some(&self.eps) {
                Error::Domain {
                    name: "1 - M_R^2 for the adaptive route's panels about its square root",
                    value: short(&self.eps2),
                    bound: "log2(1/(1 - M_R^2)) < about 8.8e5/(bits/4 + 8) at the working \
                            precision (the evaluation cap)",
                }
            } else {
                Error::Domain {
                    name: "axis ratio k for the adaptive route",
                    value: short(&self.k),
                    bound: "|log2 k| < about 4.4e5/(bits/4 + 8) at the working precision (the \
                            evaluation cap; the fixed rules cover 0 < k <= 2^180)",
                }
            });
        }
        let mut pts = vec![T::zero(p), one.clone()];
        for s in scales {
            if !(s.is_positive() && *s < one) {
                continue;
            }
            // s/4^j down to s/16, s·4^j up to 1.
            let mut x = s.clone().mul_pow2(-4);
            while x < one && x.is_positive() {
                pts.push(x.clone());
                x = x.mul_pow2(2);
            }
        }
        pts.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
        pts.dedup_by(|a, b| *a == *b);
        Ok(pts)
    }

    /// The scales of the left half (w = tan α): ε (unless the pole at iε has been taken out,
    /// `pole`), and 1/k when k > 1.
    fn left_scales(&self, pole: bool) -> Vec<T> {
        let mut s = if pole { vec![] } else { vec![self.eps.clone()] };
        if self.k > T::one(self.k.prec()) {
            s.push(self.k.clone().recip());
        }
        s
    }

    /// The scales of the right half (v = cot α): k when k < 1.
    fn right_scales(&self) -> Vec<T> {
        vec![self.k.clone()]
    }
}

/// The left half's pole at w = iε (s0 = −ε², where t = 1): the constants of
/// [`DirectSetup::left_divided`], and the closed-form parts n_c(s0)·∫_0^1 dw/(w² + ε²).
struct LeftPole<T: Real> {
    s0: T,
    /// u0 = 1 − k²ε² and its square root.
    u0: T,
    su0: T,
    /// B(s0) = 2πG(1)M_R.
    b0: T,
    /// G(1).
    g1: T,
    one: T,
    parts: [T; 5],
}

/// Work limits for the direct route: the Gauss–Legendre rule size follows the accuracy asked
/// for (about bits/4 + 8 nodes per half panel, bits = min(working bits, log2(1/tol))), so that a
/// loose tolerance costs fewer evaluations.
fn limits<T: Real>(tol: &T) -> Limits {
    let p = tol.prec();
    let work_bits = T::bits(p) as f64;
    let t = tol.to_f64();
    let bits = if t > 0.0 {
        (-t.log2()).clamp(8.0, work_bits)
    } else {
        work_bits
    };
    Limits {
        max_evals: 2_000_000,
        gauss_nodes: ((bits / 4.0) as usize + 8).min(1024),
    }
}

/// I1, I2 by plain adaptive Gauss–Legendre quadrature of (46)–(47) (normalisation of (37)) to
/// relative tolerance `tol` (0 means the working precision's floor, a few ε).
///
/// Valid for every 0 ≤ M_R < 1 (tested to 1 − 10^-12), every k > 0 (tested 10^-6 … 10^6) and
/// −1 < ν ≤ 1/2; the reported error estimate bounds the true error in the tests. The left half's
/// Rayleigh pole is taken out in closed form where ε ≤ 1/2 and kε ≤ 1/2 (module docs; else its
/// panels are graded about ε), so that the work grows like |log k| panels, not with
/// log(1/(1 − M_R)) (`tests/unit/direct.rs`, to 1 − M_R = 10⁻¹⁰⁰⁰⁰⁰). Where the panels about k or
/// 1/k alone would take a third of the evaluation cap (|log₂ k| beyond about
/// 4.4·10⁵/(bits/4 + 8): about 6150 at 256 bits, 1670 at 1024 bits), [`Error::Domain`] naming k before
/// any evaluation (the same for [`contact_integrals`] and the subtracted route).
pub fn quadrature<T: Real>(
    speed: &Speed<T>,
    axes: &AxisRatio<T>,
    tol: &T,
) -> Result<Evaluation<T>> {
    let s = DirectSetup::new(speed, axes);
    integrate_halves(&s, false, tol, Route::Adaptive, None)
}

/// I1 and I2 as two half-range vector quadratures, each evaluating G once a node for both
/// integrands, optionally with G(M_R²) subtracted from I2's integrand and `extra_i2` added to I2.
fn integrate_halves<T: Real>(
    s: &DirectSetup<T>,
    subtract: bool,
    tol: &T,
    route: Route,
    extra_i2: Option<T>,
) -> Result<Evaluation<T>> {
    let p = tol.prec();
    let lim = limits(tol);
    // Each of the four pieces to tol/4 relative to itself; pieces are positive except the
    // subtracted ones, whose accuracy is judged against the whole I2 below.
    let t4 = tol.clone().div_i64(4);
    let rp = s.breakpoints(&s.right_scales(), lim)?;
    let right = |v: &T| {
        let r = s.right(v);
        let i2 = if subtract {
            s.right_subtracted(v)
        } else {
            v.square() * &r
        };
        [r, i2]
    };
    let right = integrate_vec(right, &rp, &t4, lim)?;
    let pole = if subtract { None } else { s.left_pole() };
    let left = match pole {
        Some(pole) => left_pair_without_pole(s, &pole, &t4, lim)?,
        None => {
            // The left half's panels about ε only where the pole stays in the integrand.
            let lp = s.breakpoints(&s.left_scales(false), lim)?;
            let left = |w: &T| {
                let l = s.left(w);
                let i2 = if subtract {
                    s.left_subtracted(w)
                } else {
                    l.clone()
                };
                [l * w.square(), i2]
            };
            integrate_vec(left, &lp, &t4, lim)?
        }
    };
    let i1 = left.values[0].clone() + &right.values[0];
    let mut i2 = left.values[1].clone() + &right.values[1];
    if let Some(x) = extra_i2 {
        i2 += &x;
    }
    if !(i1.is_finite() && i1.is_positive() && i2.is_finite() && i2.is_positive()) {
        return Err(beyond_exponent_range(&s.k));
    }
    let e1 = (left.errors[0].clone() + &right.errors[0]) / &i1;
    let e2 = (left.errors[1].clone() + &right.errors[1]) / &i2;
    // Rounding floor of the integrands themselves (a few ε per evaluation of G and the weights).
    let floor = T::epsilon(p).mul_i64(8);
    let work = left.evaluations + right.evaluations;
    Ok(Evaluation::pair(
        i1,
        i2,
        e1.max_of(e2) + &floor,
        route,
        work,
    ))
}

/// I1's and I2's left halves with the Rayleigh pole taken out (module docs): one vector
/// quadrature of the divided differences D_0, D_1 on panels not graded about ε, each judged
/// against its whole half (the closed part included). Same tolerance semantics as [`integrate`].
fn left_pair_without_pole<T: Real>(
    s: &DirectSetup<T>,
    pole: &LeftPole<T>,
    tol: &T,
    lim: Limits,
) -> Result<VecQuadrature<T, 2>> {
    let f = |w: &T| {
        let [d0, d1, ..] = s.left_divided(pole, w);
        [d0, d1]
    };
    let parts = [pole.parts[0].clone(), pole.parts[1].clone()];
    let pts = s.breakpoints(&s.left_scales(true), lim)?;
    integrate_vec_plus(f, &pts, &parts, tol, lim)
}

/// S of (49) by the closed form (53):
///
/// ```text
/// S = (K − E)/(1 − k²ε²) + M_R/(ε (1 − k²ε²)^{3/2}) · [π/2 − K E(β,k) − E F(β,k) + K F(β,k)],
/// ```
///
/// K = K(e), E = E(e) complete with parameter e² = 1 − k², the incomplete integrals with modulus
/// k (parameter k²), β = arccos M_R, ε² = 1 − M_R². The bracket is (π/2)(1 − Λ0(β | e²)) with
/// Heuman's Lambda, evaluated without cancellation; K − E = e²·D(e²) without cancellation.
/// Valid for k ≤ 1 (the Heuman form needs 0 ≤ e² ≤ 1) and k²ε² < 1; otherwise
/// [`Error::Domain`]. Accuracy: a few ε.
pub fn s_closed_form<T: Real>(speed: &Speed<T>, axes: &AxisRatio<T>) -> Result<T> {
    let p = speed.mr().prec();
    let one = T::one(p);
    if axes.k > one {
        return Err(Error::domain(
            "axis ratio k for the closed form (53)",
            short(&axes.k),
            "(0, 1]",
        ));
    }
    let eps2 = speed.one_minus_mr2().clone();
    let q = one - axes.k2.clone() * &eps2;
    // K − E = e² D(e²) with mc = k².
    let kme = axes.e2.clone() * ellipbd_mc(&axes.k2)?.1;
    let first = kme / &q;
    if speed.mr().is_zero() {
        return Ok(first);
    }
    let eps = eps2.sqrt();
    // β = arccos M_R = atan2(ε, M_R), accurate as M_R → 1.
    let beta = eps.clone().atan2(speed.mr());
    let bracket = T::pi(p).mul_pow2(-1) * heuman_lambda_c_mc(&beta, &axes.k2)?;
    let second = speed.mr().clone() * bracket / (eps * q.clone() * q.sqrt());
    Ok(first + second)
}

/// I1 by quadrature of (46), I2 by the subtraction (48) with S by (53); k ≤ 1, as [`quadrature`].
pub fn subtracted<T: Real>(
    speed: &Speed<T>,
    axes: &AxisRatio<T>,
    tol: &T,
) -> Result<Evaluation<T>> {
    let s = DirectSetup::new(speed, axes);
    let g0 = s.g_at_speed();
    let sing = s.two_pi.clone() * &g0 * s_closed_form(speed, axes)?;
    integrate_halves(&s, true, tol, Route::AdaptiveSubtracted, Some(sing))
}

/// The five integrals the contact solution needs, in the normalisation of (37): I1, I2 (34),
/// J0 of (32) and ∂I1/∂k, ∂I2/∂k (differentiated under the integral sign:
/// ∂/∂k (cos²α + k² sin²α)^{−3/2} = −3k sin²α (…)^{−5/2}), by one adaptive vector quadrature
/// (one evaluation of G a node serves all five) to relative tolerance `tol` (0: the precision's
/// floor), the pole and the panels as in [`quadrature`]. Accuracy as [`quadrature`]; J0 within
/// 16ε of mpmath and of its own bound (`tests/unit/direct.rs`).
pub fn contact_integrals<T: Real>(
    speed: &Speed<T>,
    axes: &AxisRatio<T>,
    tol: &T,
) -> Result<Evaluation<T>> {
    let s = DirectSetup::new(speed, axes);
    let p = tol.prec();
    let lim = limits(tol);
    let three_k = s.k.clone().mul_i64(3);
    // Per node: F·u^{3/2} (or h^{3/2}) from the shared factor, then the five integrands.
    let left = |w: &T| -> [T; 5] {
        let n = s.left_node(w);
        let f = s.left_factor(&n);
        let [w2, _, _, a] = n;
        let j0 = f / &a.clone().sqrt();
        let i2 = j0.clone() / &a;
        let i1 = i2.clone() * &w2;
        let d = -(three_k.clone() * &w2 / &a);
        [i1.clone(), i2.clone(), j0, i1 * &d, i2 * d]
    };
    let right = |v: &T| -> [T; 5] {
        let n = s.right_node(v);
        let f = s.right_factor(&n);
        let [v2, _, _, b] = n;
        let j0 = f / &b.clone().sqrt();
        let i1 = j0.clone() / &b;
        let i2 = i1.clone() * &v2;
        let d = -(three_k.clone() / &b);
        [i1.clone(), i2.clone(), j0, i1 * &d, i2 * d]
    };
    let t4 = tol.clone().div_i64(4);
    let l = match s.left_pole() {
        Some(pole) => {
            let div = |w: &T| s.left_divided(&pole, w);
            let pts = s.breakpoints(&s.left_scales(true), lim)?;
            integrate_vec_plus(div, &pts, &pole.parts, &t4, lim)?
        }
        None => integrate_vec(left, &s.breakpoints(&s.left_scales(false), lim)?, &t4, lim)?,
    };
    let r = integrate_vec(right, &s.breakpoints(&s.right_scales(), lim)?, &t4, lim)?;
    let v: [T; 5] = std::array::from_fn(|c| l.values[c].clone() + &r.values[c]);
    let mut est = T::zero(p);
    for ((le, re), vc) in l.errors.iter().zip(&r.errors).zip(&v) {
        est = est.max_of((le.clone() + re) / &vc.clone().abs());
    }
    for (c, x) in v.iter().enumerate() {
        if !x.is_finite() || (c < 3 && !x.is_positive()) {
            return Err(beyond_exponent_range(&s.k));
        }
    }
    let [i1, i2, j0, di1_dk, di2_dk] = v;
    let est = est + &T::epsilon(p).mul_i64(8);
    Ok(Evaluation {
        i1,
        i2,
        dk: Some([di1_dk, di2_dk]),
        j0: Some(j0),
        error_estimate: est.clone(),
        extra_error: est,
        route: Route::Adaptive,
        work: l.evaluations + r.evaluations,
    })
}

#[cfg(test)]
#[path = "../../tests/unit/direct.rs"]
mod reference_tests;
