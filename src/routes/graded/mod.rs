//! The fast route's companion for k ≥ 1: I1, I2 of (34) (normalisation of (37)) and their
//! k-derivatives by composite Gauss–Legendre rules on panels graded towards α = 0, where the peak
//! of Δ⁻³ (width 1/k) meets the Rayleigh pole (width ε = √(1 − M_R²)). The derivation, the node
//! counts and the error argument: `docs/fixed-rules.md`. In short:
//!
//! - **Left half** (w = tan α): w = a sinh x sends every singularity (at heights ≥ a on the
//!   imaginary axis) to the edge of the strip |Im x| < π/2; the x-range is cut into panels of
//!   ℓ·ln 2, ℓ = 1…[`MAX_UNITS`], of [`left_nodes`] nodes each, the lengths picked by
//!   [`left_plan`] (fewest nodes), every e^{±x} a cached power of 2^{1/2} times 2^{±c}.
//! - **The Rayleigh pole**, when kε ≤ 1/4, is taken out in closed form and the panels stop at
//!   a ≤ min(1/k, δ), so that the work does not grow with log(1/ε); above, the panels reach ε.
//! - **Right half** (v = cot α): one panel of [`panel_nodes`] nodes.
//! - **Layouts** on a fixed grid in ln k ([`layout_cell`], about an octave), one
//!   [`GradedSetup`] a cell kept with the speed: a further k of the cell costs one square root and
//!   one division a node, and what an evaluation returns depends on k alone.
//! - **Domain** 1 ≤ k ≤ 2^180 ([`K_MAX_LOG2`]), else [`Error::Domain`]; **accuracy**: relative
//!   error of I1, I2 below [`BOUND_EPS`]·ε, checked against the adaptive route at 400 bits in
//!   `tests/unit/graded.rs`; measured worst errors in docs/calibration.md.

use super::guard::{run_guarded, GuardedJob};
use super::speed_consts::SpeedConsts;
use super::{AxisRatio, Evaluation, Route};
use crate::error::{Error, Result};
use crate::estimate::RelError;
use crate::numerics::quadrature::{cached, check_rule_bits, fixed_slot, slotted, GaussLegendre};
use crate::numerics::shares::{for_shares, map_on_threads, shares};
use crate::physics::Speed;
use crate::scalar::{short, Real};
use std::sync::{Arc, OnceLock};

mod plan;
mod sums;
pub use plan::{left_nodes, left_plan, MAX_UNITS};
use plan::{length_costs, pick_plan, plan_table, PLANNED};
pub(super) use sums::NodeTables;
use sums::{chunked_sums, kernel_powers, CHUNK};
pub(super) use sums::{dot, power_sums, Kernel};

/// The a-priori bound on the relative error of I1 and I2 in units of ε (docs/fixed-rules.md).
pub const BOUND_EPS: i64 = 32;

/// Nodes of the right half's single panel at a working precision of `bits` bits: 17 at `f64`,
/// ⌈0.33·bits⌉ + 1 above (36 at double-double, 86 at 256 bits): its nearest singularities
/// (v = ±i) allow ρ ≈ 3 in the worst case measured, ρ^{−2n} ≤ 2^{−bits} needs n ≥ 0.316·bits.
/// Node counts for (46)–(47); implements no equation.
pub fn panel_nodes(bits: u32) -> usize {
    let b = bits.max(24) as usize;
    if b <= 53 {
        17
    } else {
        (b * 33).div_ceil(100) + 1
    }
}

/// The route's largest k is 2^K_MAX_LOG2 (≈ 1.5·10⁵⁴): beyond it (k⁵ > 2⁹⁰⁰) the derivatives'
/// factors u^{−5/2} ~ k⁻⁵ approach 2⁻⁹⁶⁹, below which a double-double's low part is subnormal
/// and loses bits (at k = 10⁶⁰ dI/dk would be off by about 6·10⁷ε at double-double).
pub const K_MAX_LOG2: i32 = 180;

/// One left panel's fixed table: with t the Gauss–Legendre node on [−1, 1] and ℓ the panel's
/// length in units of ln 2, e^{x − x0} = 2^{(1+t)ℓ/2} (`ep`), e^{−(x − x0)} = 2^{−(1+t)ℓ/2}
/// (`em`) and the weight times ℓ ln 2/2 (`lw`), so that e^{±x} on a panel starting at
/// x0 = c ln 2 is a product by 2^{±c} (exact).
struct LeftRule<T: Real> {
    ep: Vec<T>,
    em: Vec<T>,
    lw: Vec<T>,
}

/// The fixed tables of the graded route at one precision, cached per precision: a
/// [`LeftRule`] for each panel length 1…[`plan::max_units`] (units of ln 2), each built the first time
/// a plan uses it (a Gauss–Legendre rule costs O(n²) operations to build), the plans, and, for
/// the right half's single panel [0, 1] in v, σ = v² and the weights (also built on first use:
/// the fixed rule's right half above double-double uses the panel tables alone).
struct Rules<T: Real> {
    prec: T::Prec,
    left: Vec<OnceLock<LeftRule<T>>>,
    /// `plans[c]`: the [`left_plan`] for c units, c < [`PLANNED`] − [`MAX_UNITS`].
    plans: Vec<Vec<usize>>,
    /// The right half's σ and weights, built on first use.
    right: OnceLock<(Vec<T>, Vec<T>)>,
}

fixed_slot!(rules_slot, Rules);

impl<T: Real> Rules<T> {
    /// The tables of precision `p` from the shared rule cache (for `f64` and double-double
    /// through their static slots, without the cache's lock).
    fn get(p: T::Prec) -> Result<Arc<Self>> {
        check_rule_bits(T::bits(p))?;
        let prec_of = |r: &Self| r.prec;
        match rules_slot::<T>() {
            Some(slot) => slotted(slot, 0, p, prec_of, || Self::build(p)).cloned(),
            None => cached(0, p, prec_of, || Self::build(p)),
        }
    }

    fn build(p: T::Prec) -> Result<Self> {
        let table = plan_table(&length_costs(T::bits(p)), PLANNED);
        Ok(Rules {
            prec: p,
            left: (0..MAX_UNITS).map(|_| OnceLock::new()).collect(),
            plans: (0..PLANNED - MAX_UNITS)
                .map(|c| pick_plan(&table, c))
                .collect(),
            right: OnceLock::new(),
        })
    }

    /// The right half's single panel [0, 1] in v: σ = v² and the weights ([`panel_nodes`]).
    fn right(&self) -> Result<&(Vec<T>, Vec<T>)> {
        if let Some(r) = self.right.get() {
            return Ok(r);
        }
        let p = self.prec;
        let gl = GaussLegendre::<T>::get(panel_nodes(T::bits(p)), p)?;
        let (mut right_s, mut right_w) = (Vec::new(), Vec::new());
        for_panel_nodes(&gl, &T::zero(p), &T::one(p), |v, w| {
            right_s.push(v.square());
            right_w.push(w.clone());
        });
        Ok(self.right.get_or_init(|| (right_s, right_w)))
    }

    /// The table of a left panel of length `l`·ln 2 (1 ≤ l ≤ [`plan::max_units`]), built on first use.
    fn left_rule(&self, l: usize) -> Result<&LeftRule<T>> {
        let cell = &self.left[l - 1];
        if let Some(rule) = cell.get() {
            return Ok(rule);
        }
        let p = self.prec;
        let gl = GaussLegendre::<T>::get(left_nodes(T::bits(p), l), p)?;
        // The weight's factor ℓ ln 2/2.
        let half = T::ln2(p) * &T::from_ratio(l as i64, 2, p);
        let (mut ep, mut em, mut lw) = (Vec::new(), Vec::new(), Vec::new());
        // The nodes come in pairs x± = (1 ± t)·ℓ ln 2/2 with x₊ + x₋ = ℓ ln 2, so that one
        // exponential and one reciprocal serve both: e^{x₋} = 2^ℓ e^{−x₊}, e^{−x₋} = 2^{−ℓ} e^{x₊}
        // (exact scalings). The middle node of an odd rule is its own pair.
        let exps = run_guarded(
            p,
            exp_guard::<T>(p),
            PanelExps {
                nodes: gl.nodes(),
                l,
            },
        )?;
        let l2 = l as i32;
        for ((t, w), (e, r)) in gl.nodes().iter().zip(gl.weights()).zip(exps) {
            let wh = w.clone() * &half;
            ep.push(e.clone());
            em.push(r.clone());
            lw.push(wh.clone());
            if !t.is_zero() {
                ep.push(r.mul_pow2(l2));
                em.push(e.mul_pow2(-l2));
                lw.push(wh);
            }
        }
        // Another thread may have built it meanwhile: the first one stored wins.
        Ok(cell.get_or_init(|| LeftRule { ep, em, lw }))
    }
}

/// The guard bits of a panel's exponentials: those of [`Real::Wide`] up to double-double (a
/// fixed type there), 64 above, where `Real::Wide` has twice the precision and an exponential
/// there costs about three times one at p + 64 bits (4096 bits).
fn exp_guard<T: Real>(p: T::Prec) -> u32 {
    let bits = T::bits(p);
    if bits > 106 {
        64
    } else {
        <T::Wide as Real>::bits(T::wide_prec(p)).saturating_sub(bits)
    }
}

/// e^{x₊} and e^{−x₊} at each node t of a panel's rule, x₊ = (1 + t)·ℓ ln 2/2, formed at the
/// guarded precision and rounded once (so within an ulp or so of the working precision). The
/// exponentials are independent: at MPFR precisions they are formed on every core above a few
/// dozen nodes.
struct PanelExps<'a, T> {
    nodes: &'a [T],
    l: usize,
}

/// Double-double's bits: the panel exponentials above it are MPFR's.
const MPFR_ABOVE_BITS: u32 = 106;

impl<T: Real> GuardedJob<T> for PanelExps<'_, T> {
    type Output = Vec<(T, T)>;
    fn run<W: Real>(
        self,
        pw: W::Prec,
        up: &dyn Fn(&T) -> W,
        down: &dyn Fn(&W) -> T,
    ) -> Result<Vec<(T, T)>> {
        let half = W::ln2(pw) * &W::from_ratio(self.l as i64, 2, pw);
        let x: Vec<W> = self
            .nodes
            .iter()
            .map(|t| (W::one(pw) + &up(t)) * &half)
            .collect();
        let exp_pair = |i: usize| {
            let e = x[i].clone().exp();
            let r = e.clone().recip();
            Ok((e, r))
        };
        // On every core at MPFR precisions, where an exponential costs microseconds; in `f64`
        // and double-double it costs less than handing work to another thread.
        let exps = if W::bits(pw) > MPFR_ABOVE_BITS {
            map_on_threads(x.len(), &exp_pair)?
        } else {
            (0..x.len()).map(exp_pair).collect::<Result<Vec<_>>>()?
        };
        Ok(exps.iter().map(|(e, r)| (down(e), down(r))).collect())
    }
}

/// Calls `node(x, weight)` for each node of one panel [x0, x1].
fn for_panel_nodes<T: Real>(gl: &GaussLegendre<T>, x0: &T, x1: &T, mut node: impl FnMut(T, &T)) {
    let c = (x0.clone() + x1).mul_pow2(-1);
    let r = (x1.clone() - x0).mul_pow2(-1);
    for (x, w) in gl.nodes().iter().zip(gl.weights()) {
        let d = r.clone() * x;
        let wr = w.clone() * &r;
        node(c.clone() + &d, &wr);
        if !x.is_zero() {
            node(c.clone() - &d, &wr);
        }
    }
}

/// The panels of w = a sinh x over x ∈ [0, C ln 2] (so that w runs over [0, 1]): the
/// [`left_plan`] for the C units of ln 2 that a scale of at most `a_max` needs, with
/// a = 1/sinh(C ln 2). Serves the graded route's left half (w = tan α, k ≥ 1) and the fixed
/// rule's right half above double-double (v = cot α, k < 1: [`crate::routes::fast`]).
pub(super) struct SinhLayout<'r, T: Real> {
    rules: &'r Rules<T>,
    /// The plan, when C lies beyond the plans kept in [`Rules`].
    far: Option<Vec<usize>>,
    units: usize,
}

/// The units of ln 2 that a scale of at most `a_max` needs: ⌈asinh(1/a_max)/ln 2⌉, at least 1.
fn units_for(a_max: f64) -> usize {
    units_for_log2(-a_max.log2())
}

/// [`units_for`] from l = log₂(1/a_max), so that a scale below the `f64` range still counts:
/// asinh(2^l)/ln 2 < l + 1, which is used for l ≥ 60 (where the two differ by < 2^-120).
/// Finite l only: at most about 183 is asked for (k ≤ 2^180, and ε enters only while kε > 1/4).
fn units_for_log2(l: f64) -> usize {
    let u = if l < 60.0 {
        l.exp2().asinh() / std::f64::consts::LN_2
    } else {
        l + 1.0
    };
    u.ceil().max(1.0) as usize
}

/// The number of nodes of the sinh layout for a scale of at most `a_max` at `bits` bits (from
/// the plan alone: no table is built).
pub(super) fn sinh_node_count(bits: u32, a_max: f64) -> usize {
    left_plan(bits, units_for(a_max))
        .iter()
        .map(|&l| left_nodes(bits, l))
        .sum()
}

impl<'r, T: Real> SinhLayout<'r, T> {
    fn new(rules: &'r Rules<T>, a_max: f64) -> Self {
        Self::for_units(rules, units_for(a_max))
    }

    fn for_units(rules: &'r Rules<T>, units: usize) -> Self {
        let far = (units >= rules.plans.len()).then(|| left_plan(T::bits(rules.prec), units));
        SinhLayout { rules, far, units }
    }

    fn plan(&self) -> &[usize] {
        match &self.far {
            Some(plan) => plan,
            None => &self.rules.plans[self.units],
        }
    }

    /// The number of nodes.
    pub(super) fn nodes(&self) -> Result<usize> {
        self.plan()
            .iter()
            .map(|&l| self.rules.left_rule(l).map(|r| r.ep.len()))
            .sum()
    }

    /// w² and the weights (dw/dx)·(panel weight)·`scale` at the layout's nodes, panel by panel
    /// from x = 0.
    pub(super) fn fill(&self, scale: &T) -> Result<(Vec<T>, Vec<T>)> {
        let n = self.nodes()?;
        let (mut s, mut wt) = (
            vec![T::zero(scale.prec()); n],
            vec![T::zero(scale.prec()); n],
        );
        let plan = self.plan();
        let total: usize = plan.iter().sum();
        // a/2 = 1/(2^C − 2^−C), C = the panels' total length in units of ln 2.
        let two_c = T::one(self.rules.prec).mul_pow2(total as i32);
        let half_a = (two_c.clone() - two_c.recip()).recip();
        let half_a_g = half_a.clone() * scale;
        let (mut start, mut i0) = (0i32, 0usize);
        for &l in plan {
            // e^{±x} on a panel from x0 = c ln 2: the cached 2^{±(1+t)ℓ/2} times 2^{±c},
            // exactly.
            let rule = self.rules.left_rule(l)?;
            let range = i0..i0 + rule.ep.len();
            let nodes = s[range.clone()].iter_mut().zip(&mut wt[range]);
            for ((s, f), ((ep, em), w)) in nodes.zip(rule.ep.iter().zip(&rule.em).zip(&rule.lw)) {
                let ex = ep.clone().mul_pow2(start);
                let emx = em.clone().mul_pow2(-start);
                *s = ((ex.clone() - &emx) * &half_a).square();
                *f = (ex + emx) * &half_a_g * w;
            }
            start += l as i32;
            i0 += rule.ep.len();
        }
        Ok((s, wt))
    }
}

/// The sinh layout for a scale of at most `a_max` at precision `p`, with `f(layout)` run on it
/// (the tables of the precision from the shared cache).
pub(super) fn with_sinh_layout<T: Real, R>(
    p: T::Prec,
    a_max: f64,
    f: impl FnOnce(&SinhLayout<'_, T>) -> Result<R>,
) -> Result<R> {
    let rules = Rules::<T>::get(p)?;
    f(&SinhLayout::new(&rules, a_max))
}

fn check_k<T: Real>(k: &T) -> Result<()> {
    let p = k.prec();
    if *k < T::one(p) || *k > T::one(p).mul_pow2(K_MAX_LOG2) {
        return Err(Error::Domain {
            name: "axis ratio k for the graded route",
            value: short(k),
            bound: "[1, 2^180]",
        });
    }
    Ok(())
}

/// The k-independent part of the graded route for one material and speed: panels laid out for
/// axis ratios up to `k_max`, G at every node. It serves every 1 ≤ k ≤ k_max with the same
/// accuracy bound (docs/fixed-rules.md: the map's scale a is at most 1/k_max, so every branch point
/// of u^{−3/2} stays at |Im x| ≥ π/2; smaller k only moves them away), so that Newton's method on
/// (33) pays the square roots and the division of G once and then one square root and one
/// division a node per k.
///
/// Stored per node, weights included: on the left (w = a sinh x, s = w²) f = (2/m1) D′ √e1/(Q′ h)
/// times dw/dx with a/h = f·u^{−3/2}, u = 1 + k²s, h = s + ε², and s·f, s²·f (or, with the pole
/// subtracted, a·u^{3/2}, 1/h and the weight apart: docs/fixed-rules.md); on the right
/// (σ = v²) f = (2/m1) √f1 D′/E with b W3 = f·(σ + k²)^{−3/2}, σ·f and σ²·f. An evaluation forms
/// u^{−3/2} (and u^{−5/2} for the derivatives) at the nodes, then weighted sums panel by panel.
#[derive(Clone, Debug)]
pub struct GradedSetup<T: Real> {
    k_max: T,
    body: GradedBody<T>,
}

/// The node values of a [`GradedSetup`].
#[derive(Clone, Debug)]
struct GradedBody<T: Real> {
    left: LeftHalf<T>,
    /// The right nodes' σ, f, σ·f, σ²·f.
    right: NodeTables<T>,
}

/// The left half's node values: with the Rayleigh pole resolved by the panels, or subtracted.
#[derive(Clone, Debug)]
enum LeftHalf<T: Real> {
    /// s, f, s·f, s²·f: the panels reach down to ε.
    Resolved(NodeTables<T>),
    /// s, F = (2/m1) D′ √e1/Q′ (so that a = F·u^{−3/2}), 1/h and the weight, with the pole's
    /// closed-form constants: the panels stop at min(1/k_max, δ), below which only the
    /// subtracted pole lies (docs/fixed-rules.md).
    Subtracted {
        tables: [Vec<T>; 4],
        /// The speed's constants: ε², the pole's strength and atan(1/ε)/ε among them.
        sc: Box<SpeedConsts<T>>,
    },
}

/// e1, D′ and Q′ at a left node s (p = 1 + s), the parts of G of (45) in the forms of
/// [`crate::routes::fast`].
fn left_parts<T: Real>(sc: &SpeedConsts<T>, s: &T, one: &T) -> (T, T, T) {
    let pp = one.clone() + s;
    sc.left_node(s, &pp, &pp.clone().mul_pow2(1), &pp.clone().mul_pow2(2))
}

/// The left half with the pole resolved by the panels: s, f, s·f, s²·f (f = weight·a/h·u^{3/2},
/// with G's constant factor 2/m1 folded into the weight).
fn resolved_left<T: Real>(layout: &SinhLayout<'_, T>, sc: &SpeedConsts<T>) -> Result<LeftHalf<T>> {
    let p = sc.c.prec();
    let one = T::one(p);
    let (s, mut f) = layout.fill(&sc.two_over_m1)?;
    node_map(p, &s, &mut f, |s, w| {
        let (e1, dd, qq) = left_parts(sc, s, &one);
        let h = s.clone() + &sc.eps2;
        w.clone() * dd * e1.sqrt_div(&(qq * h))
    });
    Ok(LeftHalf::Resolved(NodeTables::new(s, f, p)))
}

/// The left half with the pole subtracted: s, F (with G's constant factor 2/m1), 1/h and the
/// weight.
fn subtracted_left<T: Real>(
    layout: &SinhLayout<'_, T>,
    sc: &SpeedConsts<T>,
) -> Result<LeftHalf<T>> {
    let p = sc.c.prec();
    let one = T::one(p);
    let (s, w) = layout.fill(&one)?;
    let (mut f, mut ih) = (s.clone(), s.clone());
    node_map(p, &s, &mut f, |s, _| {
        let (e1, dd, qq) = left_parts(sc, s, &one);
        sc.two_over_m1.clone() * dd * e1.sqrt_div(&qq)
    });
    node_map(p, &s, &mut ih, |s, _| (s.clone() + &sc.eps2).recip());
    Ok(LeftHalf::Subtracted {
        tables: [s, f, ih, w],
        sc: Box::new(sc.clone()),
    })
}

impl<T: Real> GradedSetup<T> {
    /// The layout of [`layout_cell`] `cell`, serving 1 ≤ k ≤ sinh(`cell`·ln 2): a function of
    /// the cell alone. The k-independent part of (46)–(47), G of (45) to a few ε at each node.
    pub(crate) fn for_cell(speed: &Speed<T>, cell: usize) -> Result<Self> {
        Self::laid_out(speed, cell_top(cell, speed.mr().prec()), cell)
    }

    /// The layout serving 1 ≤ k ≤ `k_max` ≤ sinh(`k_units`·ln 2), the pole subtracted when
    /// k_max·ε ≤ 1/4: the [`left_plan`] for max(`k_units`, ⌈asinh(1/min(ε, δ))/ln 2⌉) units of
    /// ln 2 on the left (without ε when the pole is subtracted), [`panel_nodes`] on the right,
    /// G at the nodes. The k-independent part of (46)–(47), G of (45) to a few ε at each node.
    pub(crate) fn laid_out(speed: &Speed<T>, k_max: T, k_units: usize) -> Result<Self> {
        let p = k_max.prec();
        let rules = Rules::<T>::get(p)?;
        let (eps2, d2) = (speed.one_minus_mr2(), T::one(p) - speed.m2sq());
        // a of w = a sinh x at most the lowest singularity height (±i/k, ±iε, ±iδ); log₂(1/a)
        // from the exponents: ε² and δ² can lie below the f64 range at MPFR.
        let subtract = (k_max.square() * eps2).mul_pow2(4) <= T::one(p);
        let lg = |x: &T| RelError::of(x).log2();
        let pole_scale = if subtract { 0.0 } else { -lg(eps2) / 2.0 };
        let other = pole_scale.max(-lg(&d2) / 2.0);
        let units = k_units.max(units_for_log2(other));
        let body = GradedBody::new(&rules, &SpeedConsts::new(speed), units, subtract, p)?;
        Ok(GradedSetup { k_max, body })
    }
}

/// The top of layout cell `c`: sinh(c ln 2) = 2^(c−1) − 2^(−c−1) (exact up to c = 26 at
/// `f64`; rounded once beyond).
fn cell_top<T: Real>(c: usize, p: T::Prec) -> T {
    let one = T::one(p);
    one.clone().mul_pow2(c as i32 - 1) - &one.mul_pow2(-(c as i32) - 1)
}

/// The layout cell of `k` (1 ≤ k ≤ 2^180, else [`Error::Domain`]): the least c ≥ 2 with
/// k ≤ sinh(c ln 2) (a = 1/sinh(c ln 2) ≤ 1/k: docs/fixed-rules.md), ⌊log₂ k⌋ + 2 or one more just
/// below a power of 2, by exact comparisons: a fixed grid in ln k.
pub(crate) fn layout_cell<T: Real>(k: &T) -> Result<usize> {
    check_k(k)?;
    // ⌊log₂ k⌋ from k's nearest f64 (off by one only where it rounds up to a power of 2).
    let mut c = ((k.to_f64().to_bits() >> 52) as i32 - 1021).max(2) as usize;
    if c > 2 && *k <= cell_top(c - 1, k.prec()) {
        c -= 1;
    }
    if *k > cell_top(c, k.prec()) {
        c += 1;
    }
    Ok(c)
}

impl<T: Real> GradedBody<T> {
    /// The left and right node values for a plan of `units` (the pole `subtract`ed or not).
    fn new(
        rules: &Rules<T>,
        sc: &SpeedConsts<T>,
        units: usize,
        subtract: bool,
        p: T::Prec,
    ) -> Result<Self> {
        let one = T::one(p);
        let layout = SinhLayout::for_units(rules, units);
        let left = if subtract {
            subtracted_left(&layout, sc)?
        } else {
            resolved_left(&layout, sc)?
        };
        // Right: σ, f, σ·f, σ²·f.
        let (right_s, right_w) = rules.right()?;
        let mut f = right_w.clone();
        node_map(p, right_s, &mut f, |sg, w| {
            let (f1, dd, e) = sc.right_at(sg, &one);
            w.clone() * &sc.two_over_m1 * dd * f1.sqrt_div(&e)
        });
        let right = NodeTables::new(right_s.clone(), f, p);
        Ok(GradedBody { left, right })
    }
}

impl<T: Real> GradedSetup<T> {
    /// I1, I2 of (34) in the normalisation of (37) at `axes` by graded fixed panels (module
    /// docs) and, with `dk`, dI1/dk, dI2/dk differentiated under the integral sign on the same
    /// nodes (∂Δ⁻³/∂k = −3k sin²α Δ⁻⁵); [`Error::Domain`] above the layout's k_max. Accuracy:
    /// relative error below [`BOUND_EPS`]·ε (the reported `error_estimate`), the derivatives'
    /// of the same order (positive integrands). Work: the [`left_plan`] for x up to
    /// asinh(1/min(1/k_max, ε, δ)) plus [`panel_nodes`] nodes. Implements (46)–(47).
    pub(crate) fn eval(&self, axes: &AxisRatio<T>, dk: bool) -> Result<Evaluation<T>> {
        check_k(&axes.k)?;
        if axes.k > self.k_max {
            return Err(Error::Domain {
                name: "axis ratio k for this graded layout",
                value: short(&axes.k),
                bound: "[1, the top of the layout's cell]",
            });
        }
        let p = axes.k.prec();
        let (left, nl) = (self.body.left.sums(axes, dk, p), self.body.left.nodes());
        // Right: Σ f h^{−3/2}, Σ σ f h^{−3/2} and, with dk, the same with h^{−5/2}, h = σ + k².
        let nr = self.body.right.len();
        let right = Kernel::Right { k2: &axes.k2 };
        let ([i1r, i2r], [d1r, d2r, _]) = self.body.right.sums(dk, right);
        let [i2l, i1l, d2l, d1l] = left;
        let i1 = i1l + &i1r;
        let i2 = i2l + &i2r;
        let dks = dk.then(|| {
            let m3k = -axes.k.clone().mul_i64(3);
            [(d1l + &d1r) * &m3k, (d2l + &d2r) * &m3k]
        });
        Evaluation::from_rule(
            &axes.k,
            [i1, i2],
            dks,
            [BOUND_EPS, BOUND_EPS],
            Route::GradedRule,
            nl + nr,
        )
    }
}

impl<T: Real> LeftHalf<T> {
    fn nodes(&self) -> usize {
        match self {
            LeftHalf::Resolved(t) => t.len(),
            LeftHalf::Subtracted { tables, .. } => tables[0].len(),
        }
    }

    /// I2_L, I1_L and, with `dk`, d2, d1 with dI_L/dk = −3k·d (zero without), u = 1 + k²s.
    fn sums(&self, axes: &AxisRatio<T>, dk: bool, p: T::Prec) -> [T; 4] {
        let one = T::one(p);
        let nl = self.nodes();
        match self {
            // Σ f u^{−3/2}, Σ s f u^{−3/2} and, with dk, Σ s f u^{−5/2}, Σ s² f u^{−5/2}.
            LeftHalf::Resolved(t) => {
                let left = Kernel::Left {
                    k2: &axes.k2,
                    one: &one,
                };
                let ([a, b], [_, c, d]) = t.sums(dk, left);
                [a, b, c, d]
            }
            LeftHalf::Subtracted { tables, sc } => {
                let [ls, lf, lih, lw] = tables;
                // u0 = 1 − k²ε² ≥ 15/16 here.
                let (a0, e0) = sc.pole_values(&axes.k2);
                let (eps2, pole_t) = (&sc.eps2, &sc.pole_t);
                // Σω (a − a0)/h, Σω a and, with dk, Σω (s F u^{−5/2} + e0)/h, Σω s F u^{−5/2}.
                let buffer = || [(); CHUNK].map(|_| T::zero(p));
                let scratch = || (buffer(), buffer());
                let [sr, sa, srd, sb] = chunked_sums(nl, p, scratch, |i0, (t3, t5)| {
                    let m = CHUNK.min(nl - i0);
                    let xs = &ls[i0..i0 + m];
                    kernel_powers(xs, &mut t3[..m], &mut t5[..m], dk, &|s: &T| {
                        one.clone() + axes.k2.clone() * s
                    });
                    let mut part = [(); 4].map(|_| T::zero(p));
                    for j in 0..m {
                        let (f, ih, w) = (&lf[i0 + j], &lih[i0 + j], &lw[i0 + j]);
                        let a = f.clone() * &t3[j];
                        part[0] += &((a.clone() - &a0) * ih * w);
                        part[1] += &(a * w);
                        if dk {
                            let b = xs[j].clone() * f * &t5[j];
                            part[2] += &((b.clone() + &e0) * ih * w);
                            part[3] += &(b * w);
                        }
                    }
                    part
                });
                // I2_L = a0 atan(1/ε)/ε + Σω (a − a0)/h; I1_L = ∫ a dw − ε² I2_L.
                let i2l = a0 * pole_t + &sr;
                let i1l = sa - eps2.clone() * &i2l;
                let d2l = srd - e0 * pole_t;
                let d1l = sb - eps2.clone() * &d2l;
                [i2l, i1l, d2l, d1l]
            }
        }
    }
}

/// `out[i] = g(x[i], out[i])` for every node, on the cores above
/// [`crate::numerics::shares::PARALLEL_ABOVE_BITS`]: no dependence between nodes.
#[inline(always)]
pub(super) fn node_map<T: Real>(
    p: T::Prec,
    xs: &[T],
    out: &mut [T],
    g: impl Fn(&T, &T) -> T + Sync,
) {
    for_shares(
        shares(T::bits(p), xs.len()),
        out,
        &mut [] as &mut [T],
        &|start, os, _| {
            for (o, x) in os.iter_mut().zip(&xs[start..]) {
                *o = g(x, o);
            }
        },
    );
}

#[cfg(test)]
#[path = "../../../tests/unit/graded.rs"]
mod reference_tests;
