//! The fast route: I1, I2 of (34) (normalisation of (37)) and their derivatives with respect to
//! the axis ratio k, 0 < k ≤ 1, by fixed Gauss–Legendre rules after the two near singularities
//! of (46)–(47) have been taken out in closed form. No adaptivity, no trigonometric function at a
//! node, node counts fixed by the working precision ([`RuleSizes::for_bits`]); at `f64` and
//! double-double no allocation per call once the speed's set-up is built. The derivation, the
//! node counts and the error argument: `docs/fixed-rules.md`. In short, with the quarter
//! α ∈ [0, π/2] split at π/4 as in [`crate::routes::direct`]:
//!
//! - **Left half** (w = tan α, s = w²): the Rayleigh pole 1/(s + ε²), ε² = 1 − M_R², is
//!   subtracted with its exact integral atan(1/ε)/ε where ε ≤ 1/2 ([`SpeedConsts`]); the rest is
//!   analytic within δ ≥ 0.30 of [0, 1]: one rule in w up to double-double, the sinh-mapped
//!   panels of [`crate::routes::graded`] above ([`RuleSizes::left_sinh`]).
//! - **Right half** (v = cot α, σ = v²): the Taylor polynomial of J terms of the regular factor
//!   b(σ) is subtracted at the nodes and integrated against (σ + k²)^{−3/2} exactly through the
//!   moments N_j (`closed.rs`, 64 guard bits above double-double); above double-double, where
//!   cheaper, one octave of k at a time on sinh-mapped panels instead ([`sinh_octave`]).
//! - **Derivatives**: ∂/∂k under the integral sign on the same nodes (G once a node).
//! - **Many k**: [`FastSetup`] keeps the k-independent part (G at every node, the Taylor
//!   coefficients, the pole terms); a further k costs one square root and one division a node
//!   ([`graded::power_sums`]). Each speed keeps one, built on first use ([`SetupCache`]).
//! - **Accuracy**: relative error of I1, I2 below [`BOUND_EPS`]·ε and of the derivatives below
//!   [`DK_BOUND_EPS`]·ε on the whole domain (down to the smallest k [`AxisRatio`] admits),
//!   checked against the adaptive route at 400 bits (`tests/unit/fast.rs`) and at 1024 bits
//!   against it at 1088 bits (`tests/precision_scaling.rs`); measured worst errors in
//!   docs/calibration.md. For k > 1 this route returns [`Error::Domain`].

use super::graded::{self, dot};
use super::{AxisRatio, Evaluation, Route};
use crate::error::{Error, Result};
use crate::numerics::quadrature::{cached, check_rule_bits, fixed_slot, slotted, GaussLegendre};
use crate::numerics::shares::{for_shares, shares};
use crate::physics::Speed;
use crate::scalar::FieldOps;
use crate::scalar::{short, Mp, MpPrec, Real};
use std::ops::Deref;
use std::sync::{Arc, OnceLock};

mod closed;
mod rule;
mod sinh;
pub(crate) use super::speed_consts::SpeedConsts;
use closed::*;
pub use rule::*;
use sinh::*;

/// The a-priori bound on the relative error of I1 and I2 for the default sizes, in units of ε of
/// the working precision, valid on the whole domain of the route at every precision: the
/// truncation error of the default rules is below 1ε everywhere on the domain (docs/fixed-rules.md), the
/// rest is rounding (measured worst errors: docs/calibration.md, at most 4.8ε; the solved
/// references of `tests/references.rs` reach 6.9ε in I1 at `f64`, where k's own error enters).
///
/// A calibrated bound, not a count: the worst case of every rounding is larger. In units of
/// r = [`Real::ROUNDING`]·ε, a left term with the derivatives counts x = 1 + k²s (3: k², the
/// product, the sum), x^{−5/2} = 1/(x²√x) (x² 7, √x 2.5, the product and the reciprocal: 11.5),
/// the term and its chunk's [`graded::power_sums`] (1 + ⌈20/4⌉ + 2 + 1), the x^{−3/2} sums (2),
/// G's cleared form at the node with its weight and 1/(s + ε²) (about 23): some 45r, 22ε at
/// `f64` and 73ε at double-double (r = 1.625ε), against measured errors below 5ε. Lowering the
/// bound needs a sharper argument than this count; tests/references.rs keeps it within 10× of
/// the worst error at `f64` (I1: 6.9ε) and `tests/unit/fast.rs` asserts it on every grid case.
pub const BOUND_EPS: i64 = 16;

/// The bound on the relative error of the k-derivatives, in units of ε, asserted in
/// `tests/unit/fast.rs` (measured worst errors: docs/calibration.md).
pub const DK_BOUND_EPS: i64 = 128;

// ---------------------------------------------------------------------------------------------
// Scratch buffers: on the stack for f64 and double-double, on the heap for MPFR.

/// A slice of `n` values: inline (capacity `N`) for `f64` and double-double, on the heap for
/// MPFR (whose values allocate anyway) and for counts above `N`.
#[derive(Debug)]
enum Buf<T, const N: usize> {
    Inline([T; N], usize),
    Heap(Vec<T>),
}

impl<T: Real, const N: usize> Buf<T, N> {
    #[inline(always)]
    fn zeros(n: usize, p: T::Prec) -> Self {
        if n == 0 {
            Buf::Heap(Vec::new())
        } else if n <= N && T::bits(p) <= 106 {
            Buf::Inline(std::array::from_fn(|_| T::zero(p)), n)
        } else {
            Buf::Heap(vec![T::zero(p); n])
        }
    }
}

impl<T, const N: usize> Deref for Buf<T, N> {
    type Target = [T];
    #[inline(always)]
    fn deref(&self) -> &[T] {
        match self {
            Buf::Inline(a, n) => &a[..*n],
            Buf::Heap(v) => v,
        }
    }
}

impl<T, const N: usize> std::ops::DerefMut for Buf<T, N> {
    #[inline(always)]
    fn deref_mut(&mut self) -> &mut [T] {
        match self {
            Buf::Inline(a, n) => &mut a[..*n],
            Buf::Heap(v) => v,
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The result and the k-dependent constants

/// The k-dependent constants shared by both evaluation paths.
struct KConsts<T: Real> {
    k: T,
    k2: T,
    /// a0 = g0 (1 − k²ε²)^{−3/2}, and e0 = ε² a0/(1 − k²ε²) (the pole value of the k-derivative
    /// of the left integrand, divided by 3k).
    a0: T,
    e0: T,
}

/// The domain of the route in k: (0, 1].
fn check_axes<T: Real>(axes: &AxisRatio<T>) -> Result<()> {
    let p = axes.k.prec();
    if axes.k > T::one(p) {
        return Err(Error::Domain {
            name: "axis ratio k for the fast route",
            value: short(&axes.k),
            bound: "(0, 1]",
        });
    }
    Ok(())
}

impl<T: Real> KConsts<T> {
    fn new(sc: &SpeedConsts<T>, axes: &AxisRatio<T>) -> Self {
        // u0 = 1 − k²ε² ≥ 3/4 here (k ≤ 1, ε² ≤ 1/4).
        let (a0, e0) = sc.pole_values(&axes.k2);
        KConsts {
            k: axes.k.clone(),
            k2: axes.k2.clone(),
            a0,
            e0,
        }
    }
}

/// The left half: I1_L, I2_L and, with `dk`, dI1_L/dk, dI2_L/dk (zero without), from the
/// weighted power sums [A, B, C, D] = [Σ F1 v3, Σ F2 v3, Σ F2 v5, Σ F3 v5] (v_m = u^{−m/2},
/// F1 = ω L/(Q'(s + ε²)), F2 = s F1, F3 = s F2: [`FastSetup`]'s left tables) and the pole terms
/// less their values on the rule ([`FastSetup`]'s `left_pole`).
fn left_parts<T: Real>(pole: &[T; 2], kc: &KConsts<T>, sums: [T; 4], dk: bool) -> [T; 4] {
    let p = kc.k.prec();
    let [a, b, c, d] = sums;
    // I2_L = a0 (atan(1/ε)/ε − Σω/(s + ε²)) + A, I1_L = a0 (1 − ε atan(1/ε) − Σωs/(s + ε²)) + B.
    let i2l = kc.a0.clone() * &pole[0] + &a;
    let i1l = kc.a0.clone() * &pole[1] + &b;
    if !dk {
        return [i1l, i2l, T::zero(p), T::zero(p)];
    }
    // dI2_L = 3k (e0 (atan(1/ε)/ε − Σω/(s + ε²)) − C), dI1_L = 3k (e0 (1 − ε atan(1/ε) −
    // Σωs/(s + ε²)) − D).
    let three_k = kc.k.clone().mul_i64(3);
    let d2l = (kc.e0.clone() * &pole[0] - &c) * &three_k;
    let d1l = (kc.e0.clone() * &pole[1] - &d) * &three_k;
    [i1l, i2l, d1l, d2l]
}

/// The right half by the Taylor subtraction: I1_R = ∫ P W3 + Σω r W3, I2_R = ∫ σ P W3 +
/// Σωσ r W3 (P the Taylor polynomial, r = b − P at the nodes, kept as ωr and ωσr in `t`) and,
/// with `dk`, S1 = ∫ P W5 + Σω r W5, S2 (with σ), so that dI_R/dk = −3k S.
fn taylor_right_parts<T: Real>(
    rule: &FastRule<T>,
    r: &Half<T>,
    kc: &KConsts<T>,
    t: &TaylorRight<T>,
    dk: bool,
) -> [T; 4] {
    let [s1, s2, sd1, sd2] = right_closed_forms_guarded(rule, &t.b, kc, dk);
    let g = [&t.f[..], &t.sf[..], &t.ssf[..]];
    let right = graded::Kernel::Right { k2: &kc.k2 };
    let ([a, b], [c, d, _]) = graded::power_sums(&r.s, g, dk, right);
    [a + &s1, b + &s2, c + &sd1, d + &sd2]
}

/// I1 = I1_L + I1_R, I2 = I2_L + I2_R and, with `dk`, dI/dk = dI_L/dk − 3k S_R, from
/// [`left_parts`] and the right half's parts ([`taylor_right_parts`] or [`right_sinh`]'s sums);
/// `work` is the number of nodes.
fn combine<T: Real>(
    [i1l, i2l, d1l, d2l]: [T; 4],
    [i1r, i2r, s1, s2]: [T; 4],
    kc: &KConsts<T>,
    dk: bool,
    work: usize,
) -> Result<Evaluation<T>> {
    let i1 = i1l + &i1r;
    let i2 = i2l + &i2r;
    let dks = dk.then(|| {
        let three_k = kc.k.clone().mul_i64(3);
        [d1l - &(s1 * &three_k), d2l - &(s2 * &three_k)]
    });
    Evaluation::from_rule(
        &kc.k,
        [i1, i2],
        dks,
        [BOUND_EPS, DK_BOUND_EPS],
        Route::FixedRule,
        work,
    )
}

/// The Taylor polynomial Σ_{j<J} b_j σ^j at every node (Horner, one pass per coefficient so that
/// the inner loop runs over the nodes).
fn taylor_poly<T: Real>(b: &[T], s: &[T], out: &mut [T]) {
    let Some((last, rest)) = b.split_last() else {
        return;
    };
    for o in out.iter_mut() {
        *o = last.clone();
    }
    for bj in rest.iter().rev() {
        for (o, x) in out.iter_mut().zip(s) {
            *o = o.clone() * x + bj;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The k-independent part, kept for many axis ratios

/// The part of the fast route that does not depend on the axis ratio k, for one material and
/// speed: G at every node (as the factors below), the Taylor coefficients of b and the right
/// remainders. Each further k then costs one square root and one division per node and the
/// closed forms (one logarithm): the evaluation Newton's method on the ellipse equation (33)
/// repeats. [`crate::Evaluator`] runs the one the speed keeps ([`SetupCache`]): the route has
/// one integrand, this one.
#[derive(Debug)]
pub struct FastSetup<T: Real + 'static> {
    rule: Arc<FastRule<T>>,
    sc: SpeedConsts<T>,
    /// Left: F1 = ω L/(Q'(s + ε²)) with L = (2/m1) D' √(p − γc) (so that a(s) = (L/Q') u^{−3/2}),
    /// F2 = s F1 and F3 = s F2, so that I2_L = a0 (atan(1/ε)/ε − Σω/(s + ε²)) + Σ F1 u^{−3/2}
    /// and the rest alike ([`left_parts`]): a k costs a square root and a division a node.
    left_f: Buf<T, SETUP_INLINE>,
    left_sf: Buf<T, SETUP_INLINE>,
    left_ssf: Buf<T, SETUP_INLINE>,
    /// The pole terms less their values on the rule: atan(1/ε)/ε − Σω/(s + ε²) and
    /// 1 − ε atan(1/ε) − Σωs/(s + ε²) (zero where the pole is not subtracted; then a0 = 0).
    left_pole: [T; 2],
    /// The right half by the Taylor subtraction (built with the set-up at `f64` and
    /// double-double, on first use above).
    taylor: TaylorCell<T>,
    /// The right half on sinh-mapped panels, per octave of k (above double-double; empty below).
    sinh: Vec<OnceLock<Result<graded::NodeTables<T>>>>,
}

/// The fixed rule's k-independent part for one speed ([`FastSetup`]), built on first use and
/// shared by the speed's clones: every evaluator and ellipse solve at that speed reuses it, so
/// that a solve at a speed met before costs its evaluations only.
#[derive(Clone)]
pub(crate) struct SetupCache<T: Real + 'static>(Arc<OnceLock<Result<Box<FastSetup<T>>>>>);

impl<T: Real> SetupCache<T> {
    /// An empty cache.
    pub(crate) fn new() -> Self {
        SetupCache(Arc::new(OnceLock::new()))
    }

    /// The set-up for `speed` (the speed that holds this cache), built on first use.
    pub(crate) fn get(&self, speed: &Speed<T>) -> &Result<Box<FastSetup<T>>> {
        self.0.get_or_init(|| FastSetup::boxed(speed))
    }
}

impl<T: Real> std::fmt::Debug for SetupCache<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let state = if self.0.get().is_some() {
            "built"
        } else {
            "empty"
        };
        write!(f, "SetupCache({state})")
    }
}

/// The Taylor subtraction's tables of a [`FastSetup`]: built with it, in place, at `f64` and
/// double-double (where every k ≤ 1 uses them; no `OnceLock` to pass through), on first use
/// above (where most octaves of k use the sinh-mapped panels instead).
#[derive(Debug)]
enum TaylorCell<T> {
    Built(Result<TaylorRight<T>>),
    Lazy(OnceLock<Result<TaylorRight<T>>>),
}

/// The k-independent part of the right half by the Taylor subtraction: the Taylor coefficients
/// b_j of b and the remainders r = b(σ) − Σ_{j<J} b_j σ^j at the nodes, weighted: f = ωr, σf
/// and σ²f ([`graded::power_sums`]' factors).
#[derive(Debug)]
struct TaylorRight<T> {
    b: Buf<T, TAYLOR_INLINE>,
    f: Buf<T, RIGHT_INLINE>,
    sf: Buf<T, RIGHT_INLINE>,
    ssf: Buf<T, RIGHT_INLINE>,
}

impl<T: Real> TaylorRight<T> {
    fn new(rule: &FastRule<T>, sc: &SpeedConsts<T>) -> Result<Self> {
        let mut t = TaylorRight::zeros(rule)?;
        t.fill(rule, sc)?;
        Ok(t)
    }

    /// The tables sized for `rule`, zero.
    fn zeros(rule: &FastRule<T>) -> Result<Self> {
        let p = rule.prec;
        let h = rule.right_half()?;
        Ok(TaylorRight {
            b: Buf::zeros(rule.sizes.taylor, p),
            f: Buf::zeros(h.len(), p),
            sf: Buf::zeros(h.len(), p),
            ssf: Buf::zeros(h.len(), p),
        })
    }

    /// Fills the tables in place.
    fn fill(&mut self, rule: &FastRule<T>, sc: &SpeedConsts<T>) -> Result<()> {
        let one = T::one(rule.prec);
        taylor_b(sc, rule, &mut self.b);
        let h = rule.right_half()?;
        taylor_poly(&self.b, &h.s, &mut self.f);
        let nodes = h.nodes().zip(h.w.iter().zip(&h.ws));
        for (((sg, pp, two_p, four_p), (w, ws)), (f, sf)) in
            nodes.zip(self.f.iter_mut().zip(&mut *self.sf))
        {
            let (f1, dd, e) = sc.right_node(sg, pp, two_p, four_p, &one);
            let r = sc.two_over_m1.clone() * dd * f1.sqrt_div(&e) - &*f;
            *sf = ws.clone() * &r;
            *f = w.clone() * r;
        }
        for ((ssf, sf), sg) in self.ssf.iter_mut().zip(&*self.sf).zip(&h.s) {
            *ssf = sg.clone() * sf;
        }
        Ok(())
    }
}

/// Values a [`FastSetup`] holds inline per table, sized for the default `f64` rule
/// ([`RuleSizes::for_bits`]: 20 left nodes, 12 right nodes, 8 Taylor terms), so that an `f64`
/// set-up (one per solve) allocates nothing beyond its box and moves little. Double-double's
/// tables (44, 26, 14) are on the heap: four allocations cost that set-up less than moving
/// tables sized for them would cost every `f64` set-up (docs/calibration.md).
const SETUP_INLINE: usize = 20;
const RIGHT_INLINE: usize = 12;
const TAYLOR_INLINE: usize = 8;

impl<T: Real> FastSetup<T> {
    /// Precomputes the k-independent part for `speed` (and its material) with the default rule
    /// of the working precision (cost about that of one evaluation), built in its box: the
    /// inline tables are filled where they stay, not moved (a speed keeps its set-up boxed,
    /// [`SetupCache`]). Above double-double the right half is laid out on first use for each
    /// octave of k ([`sinh_octave`]). Implements the k-independent part of (46)–(47).
    pub(crate) fn boxed(speed: &Speed<T>) -> Result<Box<Self>> {
        Self::with_rule(speed, FastRule::<T>::get(speed.mr().prec())?, true)
    }

    /// [`FastSetup::boxed`] on `rule`; `sinh`: whether the right half may take the sinh-mapped
    /// panels above double-double ([`sinh_octave`]; not for a rule of explicit sizes).
    fn with_rule(speed: &Speed<T>, rule: Arc<FastRule<T>>, sinh: bool) -> Result<Box<Self>> {
        let p = speed.mr().prec();
        let n = rule.left.len();
        let eager = T::bits(p) <= 106 || !sinh;
        let (taylor, sinh) = if eager {
            (TaylorCell::Built(TaylorRight::zeros(&rule)), Vec::new())
        } else {
            let octaves = (0..OCTAVES).map(|_| OnceLock::new()).collect();
            (TaylorCell::Lazy(OnceLock::new()), octaves)
        };
        // Written straight into its allocation: `Box::new` would build the value on the stack
        // and copy it (its cost: docs/calibration.md, `SETUP_INLINE`).
        let mut setup = Box::write(
            Box::new_uninit(),
            FastSetup {
                sc: SpeedConsts::new(speed),
                left_f: Buf::zeros(n, p),
                left_sf: Buf::zeros(n, p),
                left_ssf: Buf::zeros(n, p),
                left_pole: [T::zero(p), T::zero(p)],
                taylor,
                sinh,
                rule,
            },
        );
        let FastSetup {
            rule,
            sc,
            left_f,
            left_sf,
            left_ssf,
            left_pole,
            taylor,
            ..
        } = &mut *setup;
        let (rule, sc) = (&*rule, &*sc);
        // F1 = ω L/(Q'(s + ε²)) and 1/(s + ε²) node by node (F1 in `left_f`, 1/(s + ε²) in
        // `left_ssf` until the sums below).
        for_shares(
            shares(T::bits(p), n),
            left_f,
            left_ssf,
            &|start, fs, ihs| {
                let range = start..start + fs.len();
                let nodes = rule.left.nodes_in(range.clone());
                let w = &rule.left.w[range];
                for (((s, pp, two_p, four_p), w), (f, ih)) in
                    nodes.zip(w).zip(fs.iter_mut().zip(ihs))
                {
                    let (e1, dd, qq) = sc.left_node(s, pp, two_p, four_p);
                    *ih = (s.clone() + &sc.eps2).recip();
                    *f = sc.two_over_m1.clone() * dd * e1.sqrt_div(&qq) * w * &*ih;
                }
            },
        );
        // The pole terms less the rule's Σω/(s + ε²), Σωs/(s + ε²) (where the pole is
        // subtracted), then F2 = s F1, F3 = s F2.
        if !sc.g0.is_zero() {
            let l = &rule.left;
            *left_pole = [
                sc.pole_t.clone() - &dot(&l.w, left_ssf),
                sc.pole_1.clone() - &dot(&l.ws, left_ssf),
            ];
        }
        for (((f, sf), ssf), s) in left_f
            .iter()
            .zip(left_sf.iter_mut())
            .zip(left_ssf.iter_mut())
            .zip(&rule.left.s)
        {
            *sf = s.clone() * f;
            *ssf = s.clone() * &*sf;
        }
        if let TaylorCell::Built(t) = taylor {
            if let Some(Err(e)) = t.as_mut().ok().map(|tr| tr.fill(rule, sc)) {
                *t = Err(e);
            }
        }
        Ok(setup)
    }

    /// I1, I2 of (34) in the normalisation of (37) at the axis ratio `axes` by the fast route
    /// (docs/fixed-rules.md) and, with `dk`, dI1/dk, dI2/dk differentiated under the integral sign on the
    /// same nodes (a few products more a node). Domain: 0 < k ≤ 1, else [`Error::Domain`].
    /// Accuracy: relative error of I1 and I2 below [`BOUND_EPS`]·ε = 16ε, reported as
    /// `error_estimate`, of the derivatives below [`DK_BOUND_EPS`]·ε = 128ε. Work: a square root
    /// and a division a node and the closed forms; no allocation at `f64` and double-double;
    /// above double-double the right half's sinh-mapped panels where they are cheaper (module
    /// docs). The route reported is [`Route::FixedRule`]. Implements (46)–(47).
    pub(crate) fn run(&self, axes: &AxisRatio<T>, dk: bool) -> Result<Evaluation<T>> {
        check_axes(axes)?;
        let rule = &*self.rule;
        let p = rule.prec;
        let kc = KConsts::new(&self.sc, axes);
        let one = T::one(p);
        let nl = rule.left.len();
        // Σ F1 u^{−3/2}, Σ F2 u^{−3/2} and, with `dk`, Σ F2 u^{−5/2}, Σ F3 u^{−5/2}, u = 1 + k²s.
        let (f, sf, ssf) = (&self.left_f[..], &self.left_sf[..], &self.left_ssf[..]);
        let ([a, b], [_, c, d]) = graded::power_sums(
            &rule.left.s,
            [f, sf, ssf],
            dk,
            graded::Kernel::Left {
                k2: &kc.k2,
                one: &one,
            },
        );
        let sums = [a, b, c, d];
        let lp = left_parts(&self.left_pole, &kc, sums, dk);
        // No octaves kept: a set-up built without the sinh-mapped panels.
        if let Some(j) = sinh_octave(rule, &axes.k).filter(|_| !self.sinh.is_empty()) {
            let rs = self.sinh[j]
                .get_or_init(|| right_sinh(&self.sc, p, j))
                .as_ref()
                .map_err(Clone::clone)?;
            let ([a, b], [c, d, _]) = rs.sums(dk, graded::Kernel::Right { k2: &kc.k2 });
            return combine(lp, [a, b, c, d], &kc, dk, nl + rs.len());
        }
        let t = match &self.taylor {
            TaylorCell::Built(t) => t,
            TaylorCell::Lazy(cell) => cell.get_or_init(|| TaylorRight::new(rule, &self.sc)),
        };
        let t = t.as_ref().map_err(Clone::clone)?;
        let rp = taylor_right_parts(rule, rule.right_half()?, &kc, t, dk);
        combine(lp, rp, &kc, dk, rule.sizes.nodes())
    }
}

#[cfg(test)]
#[path = "../../../tests/unit/fast_internals.rs"]
mod tests;

#[cfg(test)]
#[path = "../../../tests/unit/fast.rs"]
mod reference_tests;
