//! Quadrature at the working precision: [`GaussLegendre`] rules (built beyond the working
//! precision and rounded once, cached per type, n and precision) and [`integrate`], adaptive
//! Gauss–Legendre with breakpoints (inside the crate `integrate_vec` does the same for `N`
//! integrands that share one call a node).
//!
//! Tolerances are relative; each driver also stops at the rounding floor `≈ ε·∫|f|` (a request
//! below it is met as well as the precision allows, and the error estimate says how well). Work
//! is bounded by [`Limits`]; exceeding it is [`Error::NoConvergence`]. The rule caches (one for
//! every rule of the crate) grow with every (type, n, precision) requested until
//! [`clear_rule_caches`]; no rule is built above [`MAX_RULE_BITS`].
//!
//! No item of this module implements a formula of the paper: they are the generic quadratures under
//! the integral routes ((34), (46)–(48)); each item states the error it reaches (the tolerance
//! asked, never below a few ε of the working precision, or a typed error).

use super::gauss_legendre;
use super::sum::CompSum;
use crate::error::{Error, Result};
use crate::scalar::{short, Real};
use std::any::{Any, TypeId};
use std::collections::hash_map::DefaultHasher;
use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::sync::{Arc, Mutex, OnceLock};

// ---------------------------------------------------------------------------------------------
// Rule cache

type Key = (TypeId, usize, u64);
type Cache = Mutex<HashMap<Key, Arc<dyn Any + Send + Sync>>>;

fn cache() -> &'static Cache {
    static CACHE: OnceLock<Cache> = OnceLock::new();
    CACHE.get_or_init(Default::default)
}

/// The rule of type `R` for (`index`, precision `p`), built once by `build` and shared.
///
/// The key holds a hash of the precision token; the stored rule's own token is compared on every
/// hit, so a hash collision costs a rebuild, never a rule at the wrong precision. `build` runs
/// outside the lock (two threads may both build a rule; the first one stored wins).
pub(crate) fn cached<R, P>(
    index: usize,
    p: P,
    prec_of: impl Fn(&R) -> P,
    build: impl FnOnce() -> Result<R>,
) -> Result<Arc<R>>
where
    R: Any + Send + Sync,
    P: Hash + Eq,
{
    let mut h = DefaultHasher::new();
    p.hash(&mut h);
    let key = (TypeId::of::<R>(), index, h.finish());
    let lookup = |map: &HashMap<Key, Arc<dyn Any + Send + Sync>>| {
        map.get(&key)
            .and_then(|any| any.clone().downcast::<R>().ok())
            .filter(|rule| prec_of(rule) == p)
    };
    // A poisoned lock only means another thread panicked while holding it; the map is intact.
    if let Some(rule) = lookup(&cache().lock().unwrap_or_else(|e| e.into_inner())) {
        return Ok(rule);
    }
    let rule = Arc::new(build()?);
    let mut map = cache().lock().unwrap_or_else(|e| e.into_inner());
    if let Some(existing) = lookup(&map) {
        return Ok(existing);
    }
    map.entry(key).or_insert_with(|| rule.clone());
    Ok(rule)
}

/// A slot for the rule of one fixed-precision type (`f64`, double-double), filled once from the
/// shared cache: later requests read it without the cache's lock or hash. Declared as a
/// `static` by each rule type that needs it (see [`fixed_slot`]).
pub(crate) type FixedSlot<R> = OnceLock<Result<Arc<R>>>;

/// The rule of a fixed-precision type from its `slot`, filled on first use by [`cached`] (so
/// that the shared cache holds it too). The rule lives as long as the process.
pub(crate) fn slotted<R, P>(
    slot: &'static FixedSlot<R>,
    index: usize,
    p: P,
    prec_of: impl Fn(&R) -> P,
    build: impl FnOnce() -> Result<R>,
) -> Result<&'static Arc<R>>
where
    R: Any + Send + Sync,
    P: Hash + Eq,
{
    match slot.get_or_init(|| cached(index, p, prec_of, build)) {
        Ok(rule) => Ok(rule),
        Err(e) => Err(e.clone()),
    }
}

/// The [`FixedSlot`] of `$rule<T>` for `T` = `f64` or [`crate::scalar::Dd`], `None` for other types: expands to
/// a function `fn $name<T: Real>() -> Option<&'static FixedSlot<$rule<T>>>`.
macro_rules! fixed_slot {
    ($name:ident, $rule:ident) => {
        fn $name<T: $crate::scalar::Real>(
        ) -> Option<&'static $crate::numerics::quadrature::FixedSlot<$rule<T>>> {
            use std::any::{Any, TypeId};
            use $crate::numerics::quadrature::FixedSlot;
            static F64: FixedSlot<$rule<f64>> = std::sync::OnceLock::new();
            static DD: FixedSlot<$rule<$crate::scalar::Dd>> = std::sync::OnceLock::new();
            let any: &'static dyn Any = if TypeId::of::<T>() == TypeId::of::<f64>() {
                &F64
            } else if TypeId::of::<T>() == TypeId::of::<$crate::scalar::Dd>() {
                &DD
            } else {
                return None;
            };
            any.downcast_ref::<FixedSlot<$rule<T>>>()
        }
    };
}
pub(crate) use fixed_slot;

/// Forgets every rule of the shared cache and every Gauss–Legendre rule's raw values, so
/// that the next request builds them again (for measuring first-use costs in one process; the
/// rules of `f64` and double-double stay in their slots), or for giving back the memory of
/// rules built at a high precision that is no longer used. Rules already handed out stay valid.
pub fn clear_rule_caches() {
    cache().lock().unwrap_or_else(|e| e.into_inner()).clear();
    gauss_legendre::clear_store();
}

// ---------------------------------------------------------------------------------------------
// Gauss–Legendre rules

/// The highest working precision at which quadrature rules are built: 32768 bits. A rule of n
/// nodes costs about n²·bits/128 word operations to build (`docs/precision.md`), and the routes'
/// rules have n ∝ bits, so that the first call at p bits costs ∝ p³: at 32768 bits about 64
/// times the first call at 8192 bits (`crate_ellipse_cold` in `docs/data/precision_scaling.csv`),
/// a few minutes. Above it (MPFR allows up to 2^20 bits) every rule-based route refuses with
/// [`Error::Precision`].
pub const MAX_RULE_BITS: u32 = 32768;

/// [`Error::Precision`] naming `bits` when it exceeds [`MAX_RULE_BITS`]: every route that builds
/// quadrature rules checks it before any work.
pub fn check_rule_bits(bits: u32) -> Result<()> {
    if bits > MAX_RULE_BITS {
        return Err(Error::Precision {
            bits: bits as u64,
            min: crate::scalar::MpPrec::MIN_BITS,
            max: MAX_RULE_BITS,
        });
    }
    Ok(())
}

/// An n-point Gauss–Legendre rule on [−1, 1] at one precision: exact for polynomials of degree
/// `2n − 1`, error `O(ρ^(−2n))` for integrands analytic inside the Bernstein ellipse `ρ`.
///
/// Only the nonnegative half of the symmetric rule is stored: nodes `x₁ > x₂ > … ≥ 0` (the last
/// is `0` when `n` is odd) and their weights.
///
/// Accuracy: the rule is built at a guard precision (32 bits beyond the target) and rounded once, so every node and weight is the
/// working-precision number nearest to the exact one (within ε/2 relative, checked against
/// 200–400-bit rules by the tests); at `f64` the weights sum to 2 within ε/2.
///
/// Work: the first request for (n, precision) builds the rule (`numerics/gauss_legendre.rs`:
/// about n²·bits/128 word operations); later
/// requests are a cache lookup, or round down a rule of the same n built at a higher precision.
#[derive(Debug)]
pub struct GaussLegendre<T: Real> {
    n: usize,
    prec: T::Prec,
    nodes: Vec<T>,
    weights: Vec<T>,
}

impl<T: Real> GaussLegendre<T> {
    /// Largest number of nodes [`GaussLegendre::get`] accepts.
    pub const MAX_NODES: usize = 4096;

    /// Largest number of nodes at precision `p`: [`GaussLegendre::MAX_NODES`] up to 2048 bits,
    /// twice the bits above (a rule of n nodes gains about 2n·log₂ρ bits, so that larger rules
    /// would only serve integrands with singularities within ρ < 2^(1/4) of the interval).
    pub fn max_nodes(p: T::Prec) -> usize {
        Self::MAX_NODES.max(2 * T::bits(p) as usize)
    }

    /// The n-point rule at precision `p`, computed on first use and cached for the life of the
    /// process (see the type's documentation for accuracy and cost).
    ///
    /// Errors: [`Error::Precision`] above [`MAX_RULE_BITS`] (checked first);
    /// [`Error::Domain`] unless `1 ≤ n ≤` [`GaussLegendre::max_nodes`]; [`Error::NoConvergence`]
    /// if a node's refinement fails (not observed for any `n` in range).
    pub fn get(n: usize, p: T::Prec) -> Result<Arc<Self>> {
        check_rule_bits(T::bits(p))?;
        if n == 0 || n > Self::max_nodes(p) {
            return Err(Error::domain(
                "Gauss-Legendre node count n",
                n.to_string(),
                "1 <= n <= max(4096, 2 x bits)",
            ));
        }
        cached(n, p, |r: &Self| r.prec, || Self::compute(n, p))
    }

    fn compute(n: usize, p: T::Prec) -> Result<Self> {
        // Computed beyond the target and rounded once (`numerics/gauss_legendre.rs`).
        let raw = gauss_legendre::raw_rule(n, T::bits(p))?;
        let round = |v: &[rug::Float]| v.iter().map(|f| T::from_float(f, p)).collect::<Vec<_>>();
        let (nodes, weights) = (round(&raw.nodes), round(&raw.weights));
        // Guard against Newton landing on a neighbouring root: nodes must decrease strictly
        // and every weight be positive and finite.
        let ordered = nodes.windows(2).all(|w| w[0] > w[1])
            && nodes.last().is_some_and(|x| !x.is_negative())
            && nodes.first().is_some_and(|x| *x < T::one(p))
            && weights.iter().all(|w| w.is_finite() && w.is_positive());
        if !ordered {
            return Err(Error::NoConvergence {
                what: "Gauss-Legendre nodes (out of order)",
                iterations: n,
                reached: "nodes not distinct".into(),
            });
        }
        Ok(GaussLegendre {
            n,
            prec: p,
            nodes,
            weights,
        })
    }

    /// The precision the rule was computed at.
    pub fn prec(&self) -> T::Prec {
        self.prec
    }

    /// The nonnegative nodes, decreasing (the rule also uses their negatives).
    pub fn nodes(&self) -> &[T] {
        &self.nodes
    }

    /// The weights of [`GaussLegendre::nodes`] (each shared with the mirrored node).
    pub fn weights(&self) -> &[T] {
        &self.weights
    }

    /// `∫_a^b f ≈ r Σ wᵢ (f(c + r xᵢ) + f(c − r xᵢ))` with `c = (a+b)/2`, `r = (b−a)/2`,
    /// summed with compensation.
    ///
    /// Accuracy: the rule's truncation error plus a few `ε·∫|f|`. Work: `n` evaluations of `f`
    /// and a handful of operations per node pair; no allocation besides the `T` values
    /// themselves. `a`, `b` must be at the rule's precision. Non-finite values of `f` propagate
    /// into the result.
    pub fn integrate<F: FnMut(&T) -> T>(&self, mut f: F, a: &T, b: &T) -> T {
        let c = (a.clone() + b).mul_pow2(-1);
        let r = (b.clone() - a).mul_pow2(-1);
        let mut acc = CompSum::new(self.prec);
        for (x, w) in self.nodes.iter().zip(&self.weights) {
            if x.is_zero() {
                acc.add(f(&c) * w);
                continue;
            }
            let d = r.clone() * x;
            let xp = c.clone() + &d;
            let xm = -(d - &c);
            acc.add((f(&xp) + f(&xm)) * w);
        }
        acc.total() * &r
    }
}

// ---------------------------------------------------------------------------------------------
// Common driver pieces

/// Work bounds for [`integrate`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Cap on evaluations of the integrand over all sub-intervals.
    pub max_evals: usize,
    /// Nodes of the Gauss–Legendre rule used by [`integrate`] per panel; `0` chooses
    /// `min(bits/4 + 8, 1024)` (21 at `f64`, 34 at double-double, 264 at 1024 bits).
    /// With the panel halving, a rule of n nodes gains about `2n` bits per halving of the panel
    /// for analytic integrands, so this order resolves a panel at the working precision once it
    /// is a few times narrower than the distance to the nearest singularity.
    pub gauss_nodes: usize,
}

impl Limits {
    /// The Gauss–Legendre order per panel at `bits` bits: [`Limits::gauss_nodes`], or when it
    /// is 0, `min(bits/4 + 8, 1024)`.
    pub fn gauss_order(&self, bits: u32) -> usize {
        if self.gauss_nodes > 0 {
            self.gauss_nodes
        } else {
            (bits as usize / 4 + 8).min(1024)
        }
    }
}

impl Default for Limits {
    /// 500 000 evaluations, automatic Gauss–Legendre order.
    fn default() -> Self {
        Limits {
            max_evals: 500_000,
            gauss_nodes: 0,
        }
    }
}

/// The result of a quadrature driver.
#[derive(Clone, Debug, PartialEq)]
pub struct Quadrature<T> {
    /// The integral.
    pub value: T,
    /// Estimated absolute error of `value`, rounding allowance included (how it is formed, and
    /// when it is conservative, is described with each driver).
    pub error: T,
    /// Evaluations of the integrand spent.
    pub evaluations: usize,
}

/// Checks the breakpoints and tolerance; returns the increasing sub-intervals and whether the
/// breakpoints were decreasing (the integral then changes sign).
fn setup<T: Real>(points: &[T], tol: &T) -> Result<(Vec<(T, T)>, bool)> {
    if points.len() < 2 {
        return Err(Error::domain(
            "quadrature breakpoints",
            format!("{} point(s)", points.len()),
            "at least two points (the endpoints)",
        ));
    }
    for x in points {
        crate::scalar::check_finite("quadrature breakpoint", x)?;
    }
    crate::scalar::check_finite("quadrature tolerance", tol)?;
    if tol.is_negative() {
        return Err(Error::domain(
            "quadrature tolerance",
            crate::scalar::short(tol),
            "tol >= 0",
        ));
    }
    let reversed = points[0] > points[points.len() - 1];
    let monotone = points
        .windows(2)
        .all(|w| if reversed { w[0] > w[1] } else { w[0] < w[1] });
    if !monotone {
        return Err(Error::domain(
            "quadrature breakpoints",
            points.iter().map(short).collect::<Vec<_>>().join(", "),
            "strictly increasing or strictly decreasing",
        ));
    }
    let mut iv: Vec<(T, T)> = points
        .windows(2)
        .map(|w| (w[0].clone(), w[1].clone()))
        .collect();
    if reversed {
        iv = iv.into_iter().rev().map(|(a, b)| (b, a)).collect();
    }
    Ok((iv, reversed))
}

/// The name of a non-finite integrand value in [`Error::NotFinite`]: a value internal to the
/// caller, which [`name_the_input`] replaces by the caller's refusal of the input that led there.
const INTEGRAND: &str = "integrand";

fn not_finite<T: Real>(v: &T) -> Error {
    Error::NotFinite {
        name: INTEGRAND,
        value: crate::scalar::short(v),
    }
}

/// `e`, or `refusal()` where `e` is a quadrature's refusal of a non-finite integrand value: an
/// internal value means nothing to a user, so each public caller names the input that led
/// there (the axis ratio k for the routes to I1, I2, the field point for the convolution).
pub(crate) fn name_the_input(e: Error, refusal: impl FnOnce() -> Error) -> Error {
    match e {
        Error::NotFinite { name, .. } if name == INTEGRAND => refusal(),
        e => e,
    }
}

// ---------------------------------------------------------------------------------------------
// Adaptive Gauss–Legendre

/// Values and error estimates of `N` integrals from [`integrate_vec`].
#[derive(Clone, Debug)]
pub(crate) struct VecQuadrature<T, const N: usize> {
    /// The integrals.
    pub values: [T; N],
    /// Absolute error estimates (panel discrepancies plus a rounding allowance ε·Σ|panel|).
    pub errors: [T; N],
    /// Calls of `f`.
    pub evaluations: usize,
}

/// A panel [a, b]: the rule on its two halves and, per component, the discrepancy with the
/// one-panel rule, `|G(a,b) − G(a,m) − G(m,b)|`, a (very) conservative bound for the error of
/// the two-half value.
struct Panel<T, const N: usize> {
    a: T,
    b: T,
    left: [T; N],
    right: [T; N],
    err: [T; N],
}

impl<T: Real, const N: usize> Panel<T, N> {
    fn value(&self, c: usize) -> T {
        self.left[c].clone() + &self.right[c]
    }
}

/// A panel too narrow to halve, kept for good: its value and error per component.
type Frozen<T, const N: usize> = ([T; N], [T; N]);

/// Midpoint of `[a, b]`, or `None` when it is not strictly inside (the panel is as narrow as the
/// precision allows).
fn midpoint<T: Real>(a: &T, b: &T) -> Option<T> {
    let m = (a.clone() + b).mul_pow2(-1);
    (m > *a && m < *b).then_some(m)
}

/// Adaptive Gauss–Legendre quadrature of `f` over the breakpoints `points` (endpoints plus any
/// interior kinks or peaks, strictly monotone; decreasing points give the negated integral) to
/// relative tolerance `tol`, whose precision `points` must share (`integrate_vec` with one
/// component).
///
/// Each panel is integrated by the n-point rule ([`Limits::gauss_nodes`]) on its two halves, its
/// error estimated by the discrepancy with the one-panel rule (for analytic `f` about `2^(2n−1)`
/// times the error of the two-half value); the worst panel is split (4n evaluations) until the
/// total estimate is at most `max(tol·|I|, 4ε·Σ|I_panel|) + min_positive` (`tol = 0`: as
/// accurate as the precision allows). The reported error adds a rounding allowance `ε·Σ|I_panel|`.
///
/// Accuracy: for `f` analytic on each panel the reported error bounds the true one, usually by
/// orders of magnitude; at an endpoint singularity `x^α` (−1 < α < 0) it underestimates it by
/// up to `2^(−1−α)/(1 − 2^(−1−α))` (×2.4 for `x^(−1/2)`).
/// Work: at most `limits.max_evals` evaluations of `f`, plus `O(panels)` bookkeeping per split.
///
/// Errors: [`Error::Domain`] for fewer than two or non-monotone breakpoints or a negative `tol`;
/// [`Error::NotFinite`] for non-finite breakpoints, tolerance or integrand values;
/// [`Error::NoConvergence`] (with evaluations spent and the relative estimate reached) when the
/// evaluation cap is hit or a panel with a non-negligible estimate is too narrow to split.
pub fn integrate<T: Real, F: FnMut(&T) -> T>(
    mut f: F,
    points: &[T],
    tol: &T,
    limits: Limits,
) -> Result<Quadrature<T>> {
    let q = integrate_vec(|x: &T| [f(x)], points, tol, limits)?;
    let ([value], [error]) = (q.values, q.errors);
    Ok(Quadrature {
        value,
        error,
        evaluations: q.evaluations,
    })
}

/// [`integrate`] of the `N` components of `f` at once, for integrands that share their
/// expensive part (several integrals of the same Green's function against different weights):
/// one call of `f` a node returns all `N` values. Each component meets its own threshold
/// `max(tol·|I_c|, 4ε·Σ|I_c,panel|) + min_positive`; the panel split next is the one whose
/// worst component, relative to its threshold, is largest. Accuracy, work and errors as
/// [`integrate`].
pub(crate) fn integrate_vec<T: Real, const N: usize, F: FnMut(&T) -> [T; N]>(
    f: F,
    points: &[T],
    tol: &T,
    limits: Limits,
) -> Result<VecQuadrature<T, N>> {
    let zero = std::array::from_fn(|_| T::zero(tol.prec()));
    integrate_vec_plus(f, points, &zero, tol, limits)
}

/// `c_c + ∫f_c` for each component by [`integrate_vec`], each threshold judged against the
/// sum, `max(tol·|c_c + I_c|, 4ε·(|c_c| + Σ|I_c,panel|)) + min_positive`: for a remainder
/// integrand after a part `c_c` has been taken out in closed form, whose accuracy matters
/// relative to the whole. The returned values include the `c_c`, the errors are the
/// quadrature's (`c_c`'s rounding is the caller's).
pub(crate) fn integrate_vec_plus<T: Real, const N: usize, F: FnMut(&T) -> [T; N]>(
    mut f: F,
    points: &[T],
    offsets: &[T; N],
    tol: &T,
    limits: Limits,
) -> Result<VecQuadrature<T, N>> {
    let (iv, reversed) = setup(points, tol)?;
    let p = tol.prec();
    let n = limits.gauss_order(T::bits(p));
    let rule = GaussLegendre::<T>::get(n, p)?;
    let mut evals = 0usize;
    let mut panels: Vec<Panel<T, N>> = Vec::new();
    let mut frozen: Vec<Frozen<T, N>> = Vec::new();
    for (a, b) in iv {
        if evals + 3 * n > limits.max_evals {
            return Err(Error::NoConvergence {
                what: "adaptive Gauss-Legendre quadrature (too many breakpoints for the cap)",
                iterations: evals,
                reached: "1".into(),
            });
        }
        match make_panel(&rule, &mut f, a, b, None, &mut evals)? {
            Ok(panel) => panels.push(panel),
            Err(vf) => frozen.push(vf),
        }
    }
    let mut totals = Totals::of(&panels, &frozen, offsets, reversed, tol);
    loop {
        if totals.converged() {
            // Running totals drift by rounding; confirm with an exact recount.
            totals = Totals::of(&panels, &frozen, offsets, reversed, tol);
            if totals.converged() {
                return Ok(totals.result(evals));
            }
        }
        let stalled = totals.stalled();
        let pick = totals.worst(&panels);
        let Some(idx) = pick.filter(|_| !stalled && evals + 4 * n <= limits.max_evals) else {
            return Err(Error::NoConvergence {
                what: if stalled {
                    "adaptive Gauss-Legendre quadrature (panel at rounding width)"
                } else {
                    "adaptive Gauss-Legendre quadrature"
                },
                iterations: evals,
                reached: totals.reached(),
            });
        };
        let q = panels.swap_remove(idx);
        let m = (q.a.clone() + &q.b).mul_pow2(-1);
        let lo = make_panel(
            &rule,
            &mut f,
            q.a.clone(),
            m.clone(),
            Some(q.left.clone()),
            &mut evals,
        )?;
        let hi = make_panel(
            &rule,
            &mut f,
            m,
            q.b.clone(),
            Some(q.right.clone()),
            &mut evals,
        )?;
        if let (Ok(lo), Ok(hi)) = (lo, hi) {
            totals.replace(&q, [&lo, &hi]);
            panels.extend([lo, hi]);
        } else {
            // A half is too narrow to halve: keep the panel as it is (its totals stay counted).
            totals.freeze(&q.err);
            frozen.push((std::array::from_fn(|c| q.value(c)), q.err));
        }
    }
}

/// Running totals of [`integrate_vec_plus`] per component: the panels' value (unsigned, offsets
/// apart), estimated error and Σ|value|, and the frozen panels' error.
struct Totals<'a, T: Real, const N: usize> {
    value: [T; N],
    err: [T; N],
    l1: [T; N],
    frozen_err: [T; N],
    offsets: &'a [T; N],
    reversed: bool,
    tol: &'a T,
}

impl<'a, T: Real, const N: usize> Totals<'a, T, N> {
    /// Exact totals over all panels, compensated.
    fn of(
        panels: &[Panel<T, N>],
        frozen: &[Frozen<T, N>],
        offsets: &'a [T; N],
        reversed: bool,
        tol: &'a T,
    ) -> Self {
        let p = tol.prec();
        let sums = || -> [CompSum<T>; N] { std::array::from_fn(|_| CompSum::new(p)) };
        let (mut v, mut e, mut l1, mut fe) = (sums(), sums(), sums(), sums());
        let live = panels
            .iter()
            .map(|q| (std::array::from_fn(|c| q.value(c)), &q.err));
        for (val, err) in live.chain(frozen.iter().map(|(a, b)| (a.clone(), b))) {
            for c in 0..N {
                v[c].add(val[c].clone());
                e[c].add(err[c].clone());
                l1[c].add(val[c].clone().abs());
            }
        }
        for (_, err) in frozen {
            for c in 0..N {
                fe[c].add(err[c].clone());
            }
        }
        let total = |s: [CompSum<T>; N]| s.map(|x| x.total());
        Totals {
            value: total(v),
            err: total(e),
            l1: total(l1),
            frozen_err: total(fe),
            offsets,
            reversed,
            tol,
        }
    }

    /// The integral of component `c`, its offset included.
    fn whole(&self, c: usize) -> T {
        let v = &self.value[c];
        self.offsets[c].clone() + &(if self.reversed { -v.clone() } else { v.clone() })
    }

    /// `max(tol·|c + I|, 4ε·(Σ|I_panel| + |c|)) + min_positive` for component `c`.
    fn threshold(&self, c: usize) -> T {
        let p = self.tol.prec();
        let floor =
            (self.l1[c].clone() + &self.offsets[c].clone().abs()).mul_i64(4) * &T::epsilon(p);
        (self.tol.clone() * &self.whole(c).abs()).max_of(floor) + &T::min_positive(p)
    }

    fn converged(&self) -> bool {
        (0..N).all(|c| self.err[c] <= self.threshold(c))
    }

    /// The frozen panels alone break a threshold: splitting cannot help.
    fn stalled(&self) -> bool {
        (0..N).any(|c| self.frozen_err[c] > self.threshold(c))
    }

    /// The panel whose worst component, relative to its threshold, is largest.
    fn worst(&self, panels: &[Panel<T, N>]) -> Option<usize> {
        let inv: [T; N] = std::array::from_fn(|c| self.threshold(c).recip());
        let score = |q: &Panel<T, N>| {
            (1..N).fold(q.err[0].clone() * &inv[0], |m, c| {
                m.max_of(q.err[c].clone() * &inv[c])
            })
        };
        let mut best: Option<(usize, T)> = None;
        for (i, q) in panels.iter().enumerate() {
            let s = score(q);
            if best.as_ref().is_none_or(|(_, b)| s > *b) {
                best = Some((i, s));
            }
        }
        best.map(|(i, _)| i)
    }

    /// Panel `q` split into `halves`.
    fn replace(&mut self, q: &Panel<T, N>, halves: [&Panel<T, N>; 2]) {
        for c in 0..N {
            let v = q.value(c);
            self.value[c] -= &v;
            self.err[c] -= &q.err[c];
            self.l1[c] -= &v.abs();
            for h in halves {
                let v = h.value(c);
                self.value[c] += &v;
                self.err[c] += &h.err[c];
                self.l1[c] += &v.abs();
            }
        }
    }

    /// A panel of these errors frozen (its totals stay counted).
    fn freeze(&mut self, err: &[T; N]) {
        for (total, e) in self.frozen_err.iter_mut().zip(err) {
            *total += e;
        }
    }

    /// The estimate reached, relative to the worst component's integral, for reports.
    fn reached(&self) -> String {
        let p = self.tol.prec();
        let worst = (0..N)
            .map(|c| self.err[c].clone() / &(self.whole(c).abs() + &T::min_positive(p)))
            .fold(T::zero(p), |m, x| m.max_of(x));
        short(&worst)
    }

    /// The result: values with offsets, errors with the rounding allowance ε·Σ|I_panel| (the
    /// panel discrepancies do not see the rounding common to both rules, about ε per panel
    /// value, nor that of the final sum).
    fn result(self, evaluations: usize) -> VecQuadrature<T, N> {
        let eps = T::epsilon(self.tol.prec());
        VecQuadrature {
            values: std::array::from_fn(|c| self.whole(c)),
            errors: std::array::from_fn(|c| self.err[c].clone() + &(self.l1[c].clone() * &eps)),
            evaluations,
        }
    }
}

/// The n-point `rule` on [a, b] for every component, counted, refused when not finite.
fn rule_on<T: Real, const N: usize, F: FnMut(&T) -> [T; N]>(
    rule: &GaussLegendre<T>,
    f: &mut F,
    a: &T,
    b: &T,
    evals: &mut usize,
) -> Result<[T; N]> {
    *evals += rule.n;
    let p = a.prec();
    let half = (b.clone() - a).mul_pow2(-1);
    let mid = (b.clone() + a).mul_pow2(-1);
    let mut acc: [T; N] = std::array::from_fn(|_| T::zero(p));
    for (x, w) in rule.nodes().iter().zip(rule.weights()) {
        let mut add = |v: [T; N]| {
            for (s, vi) in acc.iter_mut().zip(v) {
                *s += vi * w;
            }
        };
        if x.is_zero() {
            add(f(&mid));
        } else {
            let dx = half.clone() * x;
            add(f(&(mid.clone() - &dx)));
            add(f(&(mid.clone() + &dx)));
        }
    }
    for s in acc.iter_mut() {
        *s *= &half;
        if !s.is_finite() {
            return Err(not_finite(s));
        }
    }
    Ok(acc)
}

/// The panel [a, b] given its one-panel value `whole` (computed here if `None`): the rule on
/// both halves and the discrepancy. `Err` holds the value and error of a panel too narrow to
/// halve.
fn make_panel<T: Real, const N: usize, F: FnMut(&T) -> [T; N]>(
    rule: &GaussLegendre<T>,
    f: &mut F,
    a: T,
    b: T,
    whole: Option<[T; N]>,
    evals: &mut usize,
) -> Result<std::result::Result<Panel<T, N>, Frozen<T, N>>> {
    let whole = match whole {
        Some(w) => w,
        None => rule_on(rule, f, &a, &b, evals)?,
    };
    let Some(m) = midpoint(&a, &b) else {
        let e = whole.clone().map(|w| w.abs());
        return Ok(Err((whole, e)));
    };
    let left = rule_on(rule, f, &a, &m, evals)?;
    let right = rule_on(rule, f, &m, &b, evals)?;
    let err = std::array::from_fn(|c| (whole[c].clone() - &left[c] - &right[c]).abs());
    Ok(Ok(Panel {
        a,
        b,
        left,
        right,
        err,
    }))
}
