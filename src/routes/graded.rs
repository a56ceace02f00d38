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
//! `f64`. [`GradedSetup`] keeps the layout and G at its nodes for every k up to 5/4 of the k it
//! was laid out for, so that a further k costs one square root and one division a node (the
//! ellipse solve's Newton iterates). The Gauss–Legendre rule comes from the shared cache.
//!
//! **Domain.** 0 ≤ M_R < 1, −1 < ν ≤ 1/2, 1 ≤ k ≤ 2^40, else [`Error::Domain`].
//!
//! **Accuracy.** Relative error of I1, I2 below [`BOUND_EPS`]·ε, reported as `error_estimate`;
//! checked against the adaptive route at 400 bits in `tests/graded.rs` over ν ∈ {−0.9, 0, 0.25,
//! 0.5}, M_R ∈ {0, 0.5, 0.9, 0.99, 0.9999, 1 − 10⁻⁸}, k ∈ {1, 1.5, 3, 10, 10³, 10⁶}, with the
//! derivatives: worst 3.2ε at `f64`, 1.5ε at double-double, 3.1ε and 4.1ε at MPFR 128 and 256
//! bits (derivatives, ≤ 128 bits: 3.9ε, 1.9ε, 2.5ε); a layout for another k_ref (k at 5/4 of
//! it, or 16 times below it): 3.7ε, 1.9ε, 3.5ε, 3.3ε. The margin is thin where the node count
//! is tightest against the ρ = 3 estimate: 2 nodes a panel fewer (15 at `f64`) give 39ε, and
//! ⌈0.3·bits⌉ + 1 nodes (78 at 256 bits) gave 206ε at 256 bits.

use super::fast::{IntegralsDk, SpeedConsts};
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

/// Calls `node(x², weight)` for each node of one panel [x0, x1] in w (or v).
fn for_panel_nodes<T: Real>(gl: &GaussLegendre<T>, x0: &T, x1: &T, mut node: impl FnMut(T, &T)) {
    let c = (x0.clone() + x1).mul_pow2(-1);
    let r = (x1.clone() - x0).mul_pow2(-1);
    for (x, w) in gl.nodes().iter().zip(gl.weights()) {
        let d = r.clone() * x;
        let wr = w.clone() * &r;
        node((c.clone() + &d).square(), &wr);
        if !x.is_zero() {
            node((c.clone() - &d).square(), &wr);
        }
    }
}

/// The number of geometric panels between a₁ and 1 (ratio ≤ 4), from a₁ in `f64`.
fn geometric_panels(a1: f64) -> usize {
    if !(a1 > 0.0 && a1 < 1.0) {
        return 0;
    }
    (-a1.ln() / 4f64.ln()).ceil().max(1.0) as usize
}

fn check_k<T: Real>(k: &T) -> Result<()> {
    let p = k.prec();
    if *k < T::one(p) || *k > T::from_i64(1 << 40, p) {
        return Err(Error::Domain {
            name: "axis ratio k for the graded route",
            value: short(k),
            bound: "[1, 2^40]",
        });
    }
    Ok(())
}

/// The k-independent part of the graded route for one material and speed: panels laid out for
/// an axis ratio `k_ref`, G at every node. It serves every 1 ≤ k ≤ (5/4)·k_ref with the same
/// accuracy bound (module docs: a first panel [0, a₁] with k·a₁ ≤ 5/4 keeps ρ ≥ 3.9, the next
/// ρ ≥ 3.2; smaller k only moves the singularities away), so that Newton's method on (33)
/// pays the square roots and the division of G once and then one square root and one division
/// a node per k.
///
/// Stored per node, weights included: on the left (w = tan α, s = w²) f = (2/m1) D′ √e1/(Q′ h)
/// with a/h = f·u^{−3/2}, u = 1 + k²s, h = s + ε², and s·f, s²·f; on the right (σ = v²)
/// f = (2/m1) √f1 D′/E with b W3 = f·(σ + k²)^{−3/2}, and σ·f. An evaluation forms u^{−3/2}
/// (and u^{−5/2} for the derivatives) at the nodes, then weighted sums panel by panel.
#[derive(Clone, Debug)]
pub struct GradedSetup<T: Real> {
    k_max: T,
    left_s: Vec<T>,
    left_f: [Vec<T>; 3],
    /// The end of each left panel in the node lists.
    panel_ends: Vec<usize>,
    right_s: Vec<T>,
    right_f: [Vec<T>; 2],
}

impl<T: Real> GradedSetup<T> {
    /// Lays out the panels for `k_ref` (1 ≤ k_ref ≤ 2^40, else [`Error::Domain`]) and evaluates
    /// G at their nodes: (3 + ⌈log₄ 1/min(1/k_ref, ε)⌉)·[`panel_nodes`] evaluations of G.
    pub fn new(mat: &Material<T>, speed: &Speed<T>, k_ref: &T) -> Result<Self> {
        check_k(k_ref)?;
        let p = k_ref.prec();
        let one = T::one(p);
        let zero = T::zero(p);
        let n = panel_nodes(T::bits(p));
        let gl = GaussLegendre::<T>::get(n, p)?;
        let sc = SpeedConsts::new(mat, speed);
        let eps = sc.eps2.clone().sqrt();
        let a1 = k_ref.clone().recip().min_of(eps);
        let m = geometric_panels(a1.to_f64());
        // Breakpoints 0, a₁, a₁^{1 − i/m} (ratio a₁^{−1/m} ≤ 4), 1; or 0, 1.
        let mut breaks = vec![zero.clone()];
        if m > 0 {
            let step = (-a1.clone().ln()).div_i64(m as i64).exp();
            let mut x = a1;
            for _ in 0..m {
                breaks.push(x.clone());
                x *= &step;
            }
        }
        breaks.push(one.clone());
        // The nodes (x², weight), then G at them with the weights: left f, s·f, s²·f; right f,
        // σ·f.
        let nl = n * (breaks.len() - 1);
        let (mut left_s, mut left_w) = (Vec::with_capacity(nl), Vec::with_capacity(nl));
        let mut panel_ends = Vec::with_capacity(breaks.len() - 1);
        for pair in breaks.windows(2) {
            for_panel_nodes(&gl, &pair[0], &pair[1], |s, w| {
                left_s.push(s);
                left_w.push(w.clone());
            });
            panel_ends.push(left_s.len());
        }
        let lf = chunked_map(&left_s, &left_w, |s, w| {
            let pp = one.clone() + s;
            let (e1, dd, qq) = sc.left_node(s, &pp, &pp.clone().mul_i64(2), &pp.clone().mul_i64(4));
            let h = s.clone() + &sc.eps2;
            w.clone() * &sc.two_over_m1 * dd * e1.sqrt() / (qq * h)
        });
        let lsf = chunked_map(&left_s, &lf, |s, f| s.clone() * f);
        let lssf = chunked_map(&left_s, &lsf, |s, f| s.clone() * f);
        let (mut right_s, mut right_w) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for_panel_nodes(&gl, &zero, &one, |sg, w| {
            right_s.push(sg);
            right_w.push(w.clone());
        });
        let rf = chunked_map(&right_s, &right_w, |sg, w| {
            let pp = one.clone() + sg;
            let (f1, dd, e) = sc.right_node(
                sg,
                &pp,
                &pp.clone().mul_i64(2),
                &pp.clone().mul_i64(4),
                &one,
            );
            w.clone() * &sc.two_over_m1 * f1.sqrt() * dd / e
        });
        let rsf = chunked_map(&right_s, &rf, |sg, f| sg.clone() * f);
        let (left_f, right_f) = ([lf, lsf, lssf], [rf, rsf]);
        Ok(GradedSetup {
            k_max: k_ref.clone() * &T::from_ratio(5, 4, p),
            left_s,
            left_f,
            panel_ends,
            right_s,
            right_f,
        })
    }

    /// Whether `k` lies in the range this layout serves, 1 ≤ k ≤ (5/4)·k_ref.
    pub fn covers(&self, k: &T) -> bool {
        *k >= T::one(k.prec()) && *k <= self.k_max
    }

    /// I1, I2 at `axes` ([`integrals`]' accuracy); [`Error::Domain`] outside [`Self::covers`].
    pub fn integrals(&self, axes: &AxisRatio<T>) -> Result<Integrals<T>> {
        self.eval(axes, false).map(|r| r.integrals)
    }

    /// I1, I2, dI1/dk, dI2/dk at `axes` ([`integrals_with_dk`]' accuracy).
    pub fn integrals_with_dk(&self, axes: &AxisRatio<T>) -> Result<IntegralsDk<T>> {
        self.eval(axes, true)
    }

    fn eval(&self, axes: &AxisRatio<T>, dk: bool) -> Result<IntegralsDk<T>> {
        check_k(&axes.k)?;
        if axes.k > self.k_max {
            return Err(Error::Domain {
                name: "axis ratio k for this graded layout",
                value: short(&axes.k),
                bound: "[1, 5/4 k_ref]",
            });
        }
        let p = axes.k.prec();
        let one = T::one(p);
        // Left, panel by panel: Σ f u^{−3/2}, Σ s f u^{−3/2} and, with dk, Σ s f u^{−5/2},
        // Σ s² f u^{−5/2}, u = 1 + k²s.
        let [lf, lsf, lssf] = &self.left_f;
        let mut left = [T::zero(p), T::zero(p), T::zero(p), T::zero(p)];
        let mut start = 0;
        for &end in &self.panel_ends {
            let r = start..end;
            let factors = [
                &lf[r.clone()],
                &lsf[r.clone()],
                &lsf[r.clone()],
                &lssf[r.clone()],
            ];
            let part = power_sums(&self.left_s[r], factors, dk, p, |s| {
                one.clone() + axes.k2.clone() * s
            });
            for (a, q) in left.iter_mut().zip(part) {
                *a += &q;
            }
            start = end;
        }
        // Right: Σ f h^{−3/2}, Σ σ f h^{−3/2} and, with dk, the same with h^{−5/2}, h = σ + k².
        let [rf, rsf] = &self.right_f;
        let right = power_sums(&self.right_s, [rf, rsf, rf, rsf], dk, p, |sg| {
            sg.clone() + &axes.k2
        });
        let [i2l, i1l, d2l, d1l] = left;
        let [i1r, i2r, d1r, d2r] = right;
        let i1 = i1l + &i1r;
        let i2 = i2l + &i2r;
        let (di1, di2) = if dk {
            let m3k = -axes.k.clone().mul_i64(3);
            ((d1l + &d1r) * &m3k, (d2l + &d2r) * &m3k)
        } else {
            (T::zero(p), T::zero(p))
        };
        IntegralsDk::from_rule(
            "graded route: I1 and I2 (finite, positive)",
            [i1, i2],
            [di1, di2],
            BOUND_EPS,
            Method::Quadrature,
            self.left_s.len() + self.right_s.len(),
        )
    }
}

/// `[g(x₀, y₀), g(x₁, y₁), …]`, evaluated in chunks of [`CHUNK`] into a stack buffer before being
/// appended (no dependence between nodes: vectorised at `f64`, like [`power_sums`]).
#[inline(always)]
fn chunked_map<T: Real>(xs: &[T], ys: &[T], g: impl Fn(&T, &T) -> T) -> Vec<T> {
    let mut out = Vec::with_capacity(xs.len());
    let Some(first) = xs.first() else {
        return out;
    };
    let mut buf = [(); CHUNK].map(|_| T::zero(first.prec()));
    for (cx, cy) in xs.chunks(CHUNK).zip(ys.chunks(CHUNK)) {
        for ((b, x), y) in buf.iter_mut().zip(cx).zip(cy) {
            *b = g(x, y);
        }
        out.extend(buf[..cx.len()].iter().cloned());
    }
    out
}

/// Nodes a chunk in the node loops of [`chunked_map`] and [`power_sums`].
const CHUNK: usize = 32;

/// Σ a x^{−3/2}, Σ b x^{−3/2} and, with `dk`, Σ c x^{−5/2}, Σ d x^{−5/2} over the nodes, with
/// x = shift(node) and [a, b, c, d] = `factors` (one square root and one division a node).
#[inline(always)]
fn power_sums<T: Real>(
    nodes: &[T],
    [a, b, c, d]: [&[T]; 4],
    dk: bool,
    p: T::Prec,
    shift: impl Fn(&T) -> T,
) -> [T; 4] {
    // Node values first, sums after: the node loop carries no dependence, so that at f64 the
    // compiler packs two nodes into one SSE2 square root and division.
    let zero = || [T::zero(p), T::zero(p), T::zero(p), T::zero(p)];
    let mut acc = zero();
    let mut t3 = [(); CHUNK].map(|_| T::zero(p));
    let mut t5 = [(); CHUNK].map(|_| T::zero(p));
    let mut i0 = 0;
    while i0 < nodes.len() {
        let m = CHUNK.min(nodes.len() - i0);
        if dk {
            for j in 0..m {
                let x = shift(&nodes[i0 + j]);
                let v = (x.clone() * &x * x.clone().sqrt()).recip();
                t3[j] = v.clone() * x;
                t5[j] = v;
            }
        } else {
            for j in 0..m {
                let x = shift(&nodes[i0 + j]);
                t3[j] = (x.clone() * x.sqrt()).recip();
            }
        }
        for j in 0..m {
            let i = i0 + j;
            acc[0] += &(a[i].clone() * &t3[j]);
            acc[1] += &(b[i].clone() * &t3[j]);
            if dk {
                acc[2] += &(c[i].clone() * &t5[j]);
                acc[3] += &(d[i].clone() * &t5[j]);
            }
        }
        i0 += m;
    }
    acc
}

fn run<T: Real>(
    mat: &Material<T>,
    speed: &Speed<T>,
    axes: &AxisRatio<T>,
    dk: bool,
) -> Result<IntegralsDk<T>> {
    GradedSetup::new(mat, speed, &axes.k)?.eval(axes, dk)
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
