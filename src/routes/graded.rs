//! The fast route's companion for k ≥ 1: I1, I2 of (34) (normalisation of (37)) and their
//! k-derivatives by composite Gauss–Legendre rules on panels graded towards α = 0.
//!
//! **Why a second route.** For k > 1 the peak of Δ⁻³ (width 1/k in w = tan α) moves to α = 0,
//! on top of the Rayleigh pole of G (width ε = √(1 − M_R²)), so the two closed-form subtractions
//! of [`crate::routes::fast`] (pole on the left half, Taylor polynomial against the k-peak on the
//! right half) no longer separate the scales, and a Taylor expansion of G about α = 0 has radius
//! only δ² (δ ≥ 0.3, G's branch point) in s = w².
//!
//! **Panels.** The variables of [`crate::routes::fast`]: the left half α ∈ [0, π/4] in w = tan α,
//! the right half in v = cot α. On the left every singularity of the integrand in the complex
//! w-plane lies at or beyond distance a₁ = min(1/k, ε) from the real axis near w = 0 (the branch
//! points ±i/k of u^{−3/2}, the poles ±iε, G's branch points ±iδ, ±i); the breakpoints are 0, a₁
//! and a geometric sequence from a₁ to 1 of ratio at most 4, i.e. 1 + ⌈log₄(1/a₁)⌉ panels. On a
//! panel [x, 4x] a singularity at any distance below x from 0 lies outside the Bernstein ellipse
//! of parameter ρ = 3 (ρ = 4.6 on the first panel [0, a₁]), so an n-point rule on each panel
//! converges like ρ^{−2n} whatever k and ε are: [`panel_nodes`] (17 at `f64`, 36 at
//! double-double, 86 at 256 bits). The right half, for k ≥ 1, has its nearest singularities at
//! v = ±i (the factor (1 + σ)^{−1/2} of b) and ±ik: one panel of the same rule. The integrands are
//! positive: no cancellation, rounding error a few ε.
//!
//! **Cost.** (2 + ⌈log₄(1/a₁)⌉)·n evaluations of G (two or three square roots and one division
//! each): 51 at `f64` for k ≤ 4 and M_R ≤ 0.97, 204 at k = 10⁶ (a₁ = 10⁻⁶); about 0.4–1.5 µs at
//! `f64`. The Gauss–Legendre rule comes from the shared cache (one lock per call).
//!
//! **Domain.** 0 ≤ M_R < 1, −1 < ν ≤ 1/2, 1 ≤ k ≤ 2^40, else [`Error::Domain`].
//!
//! **Accuracy.** Relative error of I1, I2 below [`BOUND_EPS`]·ε, reported as `error_estimate`;
//! checked against the adaptive route at 400 bits in `tests/graded.rs` over ν ∈ {−0.9, 0, 0.25,
//! 0.5}, M_R ∈ {0, 0.5, 0.9, 0.99, 0.9999, 1 − 10⁻⁸}, k ∈ {1, 1.5, 3, 10, 10³, 10⁶}, with the
//! derivatives: worst 3.4ε at `f64`, 1.5ε at double-double, 2.6ε and 3.7ε at MPFR 128 and 256
//! bits (derivatives, ≤ 128 bits: 3.6ε, 1.4ε, 2.3ε). The margin is thin where the node count
//! is tightest against the ρ = 3 estimate: 2 nodes a panel fewer (15 at `f64`) give 39ε, and
//! ⌈0.3·bits⌉ + 1 nodes (78 at 256 bits) gave 206ε at 256 bits.

use super::fast::{check_positive, IntegralsDk, SpeedConsts};
use super::{AxisRatio, Integrals, Method};
use crate::error::{Error, Result};
use crate::numerics::quadrature::GaussLegendre;
use crate::physics::{Material, Speed};
use crate::scalar::{short, Real};

/// The a-priori bound on the relative error of I1 and I2 in units of ε (see the module docs).
pub const BOUND_EPS: i64 = 32;

/// Nodes per panel at a working precision of `bits` bits: 17 at `f64`, ⌈0.33·bits⌉ + 1 above
/// (36 at double-double, 86 at 256 bits): ρ^{−2n} ≤ 2^{−bits} needs n ≥ 0.316·bits for ρ = 3.
pub fn panel_nodes(bits: u32) -> usize {
    let b = bits.max(24) as usize;
    if b <= 53 {
        17
    } else {
        (b * 33).div_ceil(100) + 1
    }
}

/// Sums over one panel of the left half [x0, x1] in w: I2, I1 and, with `dk`, ∫ s a/(u h),
/// ∫ s² a/(u h) (the k-derivatives divided by −3k).
#[allow(clippy::too_many_arguments)]
fn left_panel<T: Real>(
    gl: &GaussLegendre<T>,
    sc: &SpeedConsts<T>,
    k2: &T,
    x0: &T,
    x1: &T,
    dk: bool,
    acc: &mut [T; 4],
) {
    let p = x0.prec();
    let one = T::one(p);
    let c = (x0.clone() + x1).mul_pow2(-1);
    let r = (x1.clone() - x0).mul_pow2(-1);
    let mut part = [T::zero(p), T::zero(p), T::zero(p), T::zero(p)];
    for (x, w) in gl.nodes().iter().zip(gl.weights()) {
        let d = r.clone() * x;
        let mirrored = !x.is_zero();
        for node in [c.clone() + &d, c.clone() - &d] {
            let s = node.square();
            let pp = one.clone() + &s;
            let (e1, dd, qq) =
                sc.left_node(&s, &pp, &pp.clone().mul_i64(2), &pp.clone().mul_i64(4));
            let u = one.clone() + k2.clone() * &s;
            let h = s.clone() + &sc.eps2;
            // a/h = (2/m1) D' √(e1 u)/(Q' u² h).
            let g = w.clone() * &sc.two_over_m1 * dd * (e1 * &u).sqrt() / (qq * &u * &u * h);
            let sg = s.clone() * &g;
            if dk {
                let su = sg.clone() / &u;
                part[3] += &(s.clone() * &su);
                part[2] += &su;
            }
            part[0] += &g;
            part[1] += &sg;
            if !mirrored {
                break;
            }
        }
    }
    for (a, q) in acc.iter_mut().zip(part) {
        *a += &(q * &r);
    }
}

/// The right half in v ∈ [0, 1], one panel: I1, I2 and, with `dk`, ∫ b W5, ∫ σ b W5.
fn right_panel<T: Real>(
    gl: &GaussLegendre<T>,
    sc: &SpeedConsts<T>,
    k2: &T,
    dk: bool,
    acc: &mut [T; 4],
) {
    let p = k2.prec();
    let one = T::one(p);
    let half = T::from_ratio(1, 2, p);
    let mut part = [T::zero(p), T::zero(p), T::zero(p), T::zero(p)];
    for (x, w) in gl.nodes().iter().zip(gl.weights()) {
        let d = half.clone() * x;
        let mirrored = !x.is_zero();
        for node in [half.clone() + &d, half.clone() - &d] {
            let sg = node.square();
            let pp = one.clone() + &sg;
            let (f1, dd, e) = sc.right_node(
                &sg,
                &pp,
                &pp.clone().mul_i64(2),
                &pp.clone().mul_i64(4),
                &one,
            );
            let hq = sg.clone() + k2;
            // b W3 = (2/m1) √f1 D' / (E hq √hq).
            let bw3 = w.clone() * &sc.two_over_m1 * f1.sqrt() * dd / (e * &hq * hq.clone().sqrt());
            let sbw3 = sg.clone() * &bw3;
            if dk {
                part[2] += &(bw3.clone() / &hq);
                part[3] += &(sbw3.clone() / &hq);
            }
            part[0] += &bw3;
            part[1] += &sbw3;
            if !mirrored {
                break;
            }
        }
    }
    for (a, q) in acc.iter_mut().zip(part) {
        *a += &(q * &half);
    }
}

/// The number of geometric panels between a₁ and 1 (ratio ≤ 4), from a₁ in `f64`.
fn geometric_panels(a1: f64) -> usize {
    if !(a1 > 0.0 && a1 < 1.0) {
        return 0;
    }
    (-a1.ln() / 4f64.ln()).ceil().max(1.0) as usize
}

fn run<T: Real>(
    mat: &Material<T>,
    speed: &Speed<T>,
    axes: &AxisRatio<T>,
    dk: bool,
) -> Result<IntegralsDk<T>> {
    let p = axes.k.prec();
    let one = T::one(p);
    if axes.k < one || axes.k > T::from_i64(1 << 40, p) {
        return Err(Error::Domain {
            name: "axis ratio k for the graded route",
            value: short(&axes.k),
            bound: "[1, 2^40]",
        });
    }
    let n = panel_nodes(T::bits(p));
    let gl = GaussLegendre::<T>::get(n, p)?;
    let sc = SpeedConsts::new(mat, speed);
    let eps = sc.eps2.clone().sqrt();
    let a1 = axes.k.clone().recip().min_of(eps);
    let mut left = [T::zero(p), T::zero(p), T::zero(p), T::zero(p)];
    let m = geometric_panels(a1.to_f64());
    let mut evaluations = 0;
    if m == 0 {
        left_panel(&gl, &sc, &axes.k2, &T::zero(p), &one, dk, &mut left);
        evaluations += n;
    } else {
        left_panel(&gl, &sc, &axes.k2, &T::zero(p), &a1, dk, &mut left);
        // x_i = a₁^{1 − i/m}: ratio a₁^{−1/m} ≤ 4.
        let step = (-a1.clone().ln()).div_i64(m as i64).exp();
        let mut x0 = a1;
        for i in 0..m {
            let x1 = if i + 1 == m {
                one.clone()
            } else {
                x0.clone() * &step
            };
            left_panel(&gl, &sc, &axes.k2, &x0, &x1, dk, &mut left);
            x0 = x1;
        }
        evaluations += n * (m + 1);
    }
    let mut right = [T::zero(p), T::zero(p), T::zero(p), T::zero(p)];
    right_panel(&gl, &sc, &axes.k2, dk, &mut right);
    evaluations += n;
    let [i2l, i1l, d2l, d1l] = left;
    let [i1r, i2r, d1r, d2r] = right;
    let i1 = i1l + &i1r;
    let i2 = i2l + &i2r;
    check_positive(["graded route: I1", "graded route: I2"], &i1, &i2)?;
    let (di1, di2) = if dk {
        let m3k = -axes.k.clone().mul_i64(3);
        ((d1l + &d1r) * &m3k, (d2l + &d2r) * &m3k)
    } else {
        (T::zero(p), T::zero(p))
    };
    Ok(IntegralsDk {
        integrals: Integrals {
            i1,
            i2,
            error_estimate: T::epsilon(p).mul_i64(BOUND_EPS),
            method: Method::Quadrature,
            work: evaluations,
        },
        di1_dk: di1,
        di2_dk: di2,
    })
}

/// I1, I2 of (34) in the normalisation of (37) for k ≥ 1 by graded fixed panels (module docs).
///
/// Domain: 0 ≤ M_R < 1, −1 < ν ≤ 1/2, 1 ≤ k ≤ 2^40, else [`Error::Domain`]. Accuracy: relative
/// error below [`BOUND_EPS`]·ε (the reported `error_estimate`). Work: (2 + ⌈log₄ 1/min(1/k, ε)⌉)
/// panels of [`panel_nodes`] nodes.
pub fn integrals<T: Real>(
    mat: &Material<T>,
    speed: &Speed<T>,
    axes: &AxisRatio<T>,
) -> Result<Integrals<T>> {
    run(mat, speed, axes, false).map(|r| r.integrals)
}

/// [`integrals`] with dI1/dk, dI2/dk differentiated under the integral sign on the same nodes
/// (∂Δ⁻³/∂k = −3k sin²α Δ⁻⁵); their relative error is of the same order (positive integrands).
pub fn integrals_with_dk<T: Real>(
    mat: &Material<T>,
    speed: &Speed<T>,
    axes: &AxisRatio<T>,
) -> Result<IntegralsDk<T>> {
    run(mat, speed, axes, true)
}
