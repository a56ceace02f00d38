//! Gauss–Legendre nodes and weights at any precision: the construction behind
//! [`crate::numerics::quadrature::GaussLegendre`], each node in three stages, the precision
//! rising:
//!
//! 1. *`f64`*: an asymptotic initial value (`seed`: the Bessel-zero formula of Gatteschi and
//!    Pittaluga near the ends, Tricomi's expansion in the interior), Newton on the recurrence in
//!    `f64` (about 2⁻⁵² absolute), then one Newton step in double-double (about 2⁻⁸⁰ or better).
//! 2. *A short point, every bit of the target*: the double-double node rounded to a multiple of
//!    2⁻¹¹², x̃ = X/2¹¹². P_n(x̃) and P_{n−1}(x̃) come from Bonnet's recurrence in fixed point
//!    (`legendre_fixed`), scaled as Q_k = k!·P_k so that no step divides:
//!    Q_{k+1} = (2k + 1) x̃ Q_k − k² Q_{k−1}. Since x̃ has 128 bits, a step is a product of a
//!    p-bit integer by a two-limb one ((2k + 1)X < 2¹²⁸), a shift and a multiply-subtract by the
//!    machine word k²:
//!    `O(p)` word operations instead of a p-bit product. This is the only `O(n)` part per node.
//! 3. *The Taylor expansion at x̃*: with s = 1 − x̃² and u_m = s^m P_n^{(m)}(x̃), Legendre's
//!    equation gives u_{m+2} = 2(m + 1) x̃ u_{m+1} − (n − m)(n + m + 1) s u_m (again products by
//!    short numbers only), and P_n(x̃ + sη) = f(η) = Σ u_m η^m/m!. The node is x̃ + sη* with
//!    f(η*) = 0, found by Newton's method on f at doubling precision from η = −u_0/u_1; since
//!    |sη| ≲ 2⁻⁸⁰ each term is some 2⁻⁶⁰ or less below the one before, so the sums are evaluated
//!    with the precision falling term by term. The weight follows from the same expansion,
//!    w = 2/((1 − x²) P_n'(x)²) with P_n'(x̃ + sη*) = f'(η*)/s.
//!
//! A rule of n nodes at p bits costs n²/2 fixed-point steps of `O(p/64)` word operations and
//! `O(n·p/80)` products at falling precision, against `O(n²)` p-bit products for Newton on the
//! recurrence at the target precision (the unit tests' reference construction). The nodes are
//! independent and built on every core
//! (`numerics::shares::map_on_threads`); rules are kept per (n, precision) (`raw_rule`), and one
//! built at a higher precision is rounded down for a lower one. The values are computed `GUARD`
//! bits beyond the target and rounded once by the caller: every node and weight correctly
//! rounded or one ulp off (`tests/unit/gauss_legendre.rs`, against Newton on the recurrence at
//! the guard precision, at `f64` and 256 to 8192 bits).
//! No item of this module implements a formula of the paper.

use crate::error::{Error, Result};
use crate::numerics::shares::map_on_threads;
use crate::scalar::FieldOps;
use crate::scalar::{short, Dd, Field, Real};
use rug::{Assign, Float, Integer};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Bits beyond the target precision at which a rule is computed (then rounded once).
pub(crate) const GUARD: u32 = 32;

// ---------------------------------------------------------------------------------------------
// The recurrence in a generic real type (seeds, double-double, the reference construction)

/// `(P_n(x), P_{n−1}(x))` by the three-term recurrence
/// `(k+1) P_{k+1} = (2k+1) x P_k − k P_{k−1}`, which is stable upward on [−1, 1]. `n ≥ 1`.
fn legendre<U: Real>(n: usize, x: &U) -> (U, U) {
    let mut p0 = U::one(x.prec());
    let mut p1 = x.clone();
    for k in 1..n as i64 {
        let p2 = ((x.clone() * &p1).mul_i64(2 * k + 1) - p0.mul_i64(k)).div_i64(k + 1);
        p0 = std::mem::replace(&mut p1, p2);
    }
    (p1, p0)
}

/// `(1 − x²) P_n'(x) = n (P_{n−1} − x P_n)`, and `1 − x² = (1 − x)(1 + x)` (no cancellation
/// near ±1). Returns `(P_n, n (P_{n−1} − x P_n), 1 − x²)`.
fn legendre_scaled<U: Real>(n: usize, x: &U) -> (U, U, U) {
    let (pn, pn1) = legendre(n, x);
    let one = U::one(x.prec());
    let omx2 = (one.clone() - x) * &(one + x);
    let d = (pn1 - &(x.clone() * &pn)).mul_i64(n as i64);
    (pn, d, omx2)
}

/// Newton's method for a root of `P_n` from `x`: `dx = P_n/P_n' = P_n (1 − x²) / (n (P_{n−1} − x
/// P_n))`. Stops when the step is below `ε` (absolute: nodes lie in [−1, 1], and convergence is
/// quadratic, so the next error is far smaller), when the step stops shrinking (rounding noise;
/// accepted only if the previous step was already below `√ε`), or after `cap` steps.
fn polish_node<U: Real>(n: usize, mut x: U, cap: usize) -> Result<U> {
    let p = x.prec();
    let eps = U::epsilon(p);
    let noise = U::epsilon_root(p, 2);
    let mut last: Option<U> = None;
    let fail = |it: usize, dx: &U| Error::NoConvergence {
        what: "Gauss-Legendre node (Newton on P_n)",
        iterations: it,
        reached: short(dx),
    };
    for it in 0..cap {
        let (pn, d, omx2) = legendre_scaled(n, &x);
        let dx = pn * &omx2 / d;
        let adx = dx.clone().abs();
        if !adx.is_finite() {
            return Err(fail(it, &adx));
        }
        if let Some(prev) = &last {
            if adx >= *prev {
                return if *prev <= noise {
                    Ok(x)
                } else {
                    Err(fail(it, prev))
                };
            }
        }
        x -= dx;
        if adx <= eps {
            return Ok(x);
        }
        last = Some(adx);
    }
    Err(fail(cap, &last.unwrap_or_else(|| U::one(p))))
}

/// The first five zeros of the Bessel function J_0 (DLMF Table 10.21.1, rounded to `f64`).
const J0_ZEROS: [f64; 5] = [
    2.404_825_557_695_773,
    5.520_078_110_286_311,
    8.653_727_912_911_012,
    11.791_534_439_014_281,
    14.930_917_708_487_787,
];

/// The k-th zero of J_0 (k ≥ 1): the table, then McMahon's expansion (DLMF 10.21.19) with
/// β = (k − 1/4)π, j ≈ β + 1/(8β) − 124/(3(8β)³) + 120928/(15(8β)⁵), within 10⁻¹⁰ from k = 6.
fn bessel_j0_zero(k: usize) -> f64 {
    if let Some(j) = J0_ZEROS.get(k.wrapping_sub(1)) {
        return *j;
    }
    let b = (k as f64 - 0.25) * std::f64::consts::PI;
    let e = 8.0 * b;
    b + 1.0 / e - 124.0 / (3.0 * e.powi(3)) + 120_928.0 / (15.0 * e.powi(5))
}

/// An `f64` initial value for the k-th largest node of the n-point rule (k = 1 … ⌈n/2⌉).
///
/// Near the end (θ = arccos x ≤ 1/2) Gatteschi and Pittaluga's formula
/// θ ≈ ψ + (ψ cot ψ − 1)/(8ψρ²), ψ = j_{0,k}/ρ, ρ = n + 1/2 (error O(ρ⁻⁴)); in the interior
/// Tricomi's expansion x ≈ (1 − (n−1)/(8n³) − (39 − 28/sin²θ)/(384n⁴)) cos θ,
/// θ = π(4k − 1)/(4n + 2) (error O(n⁻⁵)). Both are refined by Newton's method afterwards.
pub(crate) fn seed(n: usize, k: usize) -> f64 {
    let nf = n as f64;
    let rho = nf + 0.5;
    let psi = bessel_j0_zero(k) / rho;
    if psi <= 0.5 {
        let theta = psi + (psi / psi.tan() - 1.0) / (8.0 * psi * rho * rho);
        return theta.cos();
    }
    let th = std::f64::consts::PI * (4 * k - 1) as f64 / (4.0 * nf + 2.0);
    let s2 = th.sin().powi(2);
    (1.0 - (nf - 1.0) / (8.0 * nf.powi(3)) - (39.0 - 28.0 / s2) / (384.0 * nf.powi(4))) * th.cos()
}

/// The `f64` node: [`seed`] polished by Newton's method in `f64`.
fn node_f64(n: usize, k: usize) -> Result<f64> {
    polish_node::<f64>(n, seed(n, k), 40)
}

// ---------------------------------------------------------------------------------------------
// Fixed-point Legendre recurrence at a short point

/// Binary digits of the short point: x̃ = X/2^XBITS.
const XBITS: u32 = 112;

/// `(Q_n, Q_{n−1}, e)` with `Q_k·2^e = k!·P_k(x̃)`, x̃ = `x`/2^[`XBITS`], by
/// Q_{k+1} = (2k + 1) x̃ Q_k − k² Q_{k−1} in integers with `frac` fraction bits (Q_0 = 2^frac,
/// e = −frac), both shifted right by a limb whenever they outgrow `frac` + 64 bits (the k! growth).
/// Each step truncates by less than one unit of the current scale, so the absolute error of
/// P_k relative to max(|P_k|, |P_{k−1}|) stays below about k·2^−frac (the recurrence is stable
/// upward on [−1, 1]). A step costs one product by the short factor (2k + 1)X, one shift and
/// one multiply-subtract by the machine word k².
fn legendre_fixed(n: usize, x: &Integer, frac: u32) -> (Integer, Integer, i64) {
    let mut e = -(frac as i64);
    let mut q0 = Integer::from(1) << frac;
    let mut q1 = Integer::from(x << frac) >> XBITS;
    let cap = frac + 64;
    let mut t = Integer::with_capacity(cap as usize + 2 * XBITS as usize);
    let mut y = Integer::with_capacity(2 * XBITS as usize);
    for k in 1..n as u64 {
        y.assign(x * (2 * k + 1));
        t.assign(&q1 * &y);
        t >>= XBITS;
        // k² < 2^64 for every n a rule can have.
        t -= &q0 * (k * k);
        std::mem::swap(&mut q0, &mut q1);
        std::mem::swap(&mut q1, &mut t);
        if q1.significant_bits().max(q0.significant_bits()) > cap {
            q1 >>= 64;
            q0 >>= 64;
            e += 64;
        }
    }
    (q1, q0, e)
}

// ---------------------------------------------------------------------------------------------
// The Taylor expansion at the short point

/// The constants of one rule's refinement.
struct Refine {
    n: usize,
    /// Working precision of the expansion (target + [`GUARD`] + 24).
    w: u32,
    /// Fraction bits of the fixed-point recurrence.
    frac: u32,
    /// (n!)² at precision `w`.
    nfact2: Float,
}

/// A value's binary exponent as `f64` (−∞ for zero): |v| ∈ [2^(e−1), 2^e).
fn lg(v: &Float) -> f64 {
    v.get_exp().map_or(f64::NEG_INFINITY, f64::from)
}

/// log₂|v| (−∞ for zero): from the exponent and the leading digits, within 10⁻¹⁵ bits.
fn log2_abs(v: &Float) -> f64 {
    match v.get_exp() {
        None => f64::NEG_INFINITY,
        Some(e) => {
            let m = Float::with_val(53, v >> e).abs().to_f64();
            f64::from(e) + m.log2()
        }
    }
}

/// The Taylor coefficients v_m = s^m P_n^{(m)}(x̃)/m! (up to the common factor 2^e/n!) with
/// the binary size τ_m of each term v_m η^m of f, for the first-order |η|, until two consecutive
/// terms fall 2^(w + 24) below the first-order term; and those of f′, d_m = (m + 1) v_{m+1},
/// with the sizes τ′_m of d_m η^m. The factorials are divided out once here, so that each
/// evaluation of f or f′ (Newton's steps, the weight) costs one product and one sum a term.
struct Expansion {
    v: Vec<Float>,
    tau: Vec<f64>,
    d: Vec<Float>,
    tau_d: Vec<f64>,
}

impl Refine {
    fn new(n: usize, raw_bits: u32) -> Refine {
        let w = raw_bits + 24;
        let lgn = usize::BITS - n.leading_zeros();
        let frac = w + 2 * lgn + 32;
        let f = Integer::from(Integer::factorial(n as u32));
        Refine {
            n,
            w,
            frac,
            nfact2: Float::with_val(w, f.square()),
        }
    }

    /// Precision for a term of binary size `tau` when the sum needs `q` bits relative to 2^`r`.
    fn prec_for(q: u32, r: f64, tau: f64) -> u32 {
        let drop = (r - tau).max(0.0).min(q as f64) as u32;
        (q + 16 - drop).max(64)
    }

    /// The coefficients v_0 … v_J from u_{m+2} = 2(m + 1) x̃ u_{m+1} − (n − m)(n + m + 1) s u_m
    /// divided by (m + 2)!: v_{m+2} = (2(m + 1)² x̃ v_{m+1} − (n − m)(n + m + 1) s v_m)/((m + 1)(m + 2)),
    /// each at the precision its term needs.
    fn expansion(
        &self,
        u0: Float,
        u1: Float,
        xt: &Float,
        s: &Float,
        lg_eta: f64,
    ) -> Result<Expansion> {
        let n = self.n as i64;
        let r = lg(&u1) + lg_eta;
        let floor = r - self.w as f64 - 24.0;
        let mut tau = vec![lg(&u0), r];
        let mut v = vec![u0, u1];
        let cap = 4 * self.w as usize + 64;
        let mut m = 0usize;
        while !(tau[m] < floor && tau[m + 1] < floor) {
            if m >= cap {
                return Err(Error::NoConvergence {
                    what: "Gauss-Legendre node (Taylor expansion at the short point)",
                    iterations: m,
                    reached: format!("2^{}", tau[m + 1] - r),
                });
            }
            // The next coefficient's term is about as large as these two or smaller (a margin
            // of 32 bits for one that happens to be small).
            let prec = Self::prec_for(self.w, r, tau[m].max(tau[m + 1]) + 32.0);
            let m1 = m as u64 + 1;
            // Both factors exact: x̃ has 114 bits and 2(m + 1)² < 2⁶⁴, s 232 bits.
            let a = Float::with_val(xt.prec() + 64, xt * (2 * m1 * m1));
            let b = Float::with_val(s.prec() + 64, s * ((n - m as i64) * (n + m as i64 + 1)));
            let mut next = Float::with_val(prec, &a * &v[m + 1]);
            next -= Float::with_val(prec, &b * &v[m]);
            next /= m1 * (m1 + 1);
            tau.push(lg(&next) + (m + 2) as f64 * lg_eta);
            v.push(next);
            m += 1;
        }
        // f′ = Σ (m + 1) v_{m+1} η^m: each product exact (the factor has at most 32 bits).
        let d = (1..v.len())
            .map(|i| Float::with_val(v[i].prec() + 32, &v[i] * i as u64))
            .collect();
        let tau_d = (1..v.len())
            .map(|i| tau[i] - lg_eta + (i as f64).log2())
            .collect();
        Ok(Expansion { v, tau, d, tau_d })
    }

    /// Σ_m c_m η^m by Horner from the top, each partial sum at the precision of its term, to
    /// about 2^−q relative to 2^r: f(η) = Σ v_m η^m relative to the first-order term, f′(η) =
    /// Σ d_m η^m relative to |d_0| = |u_1|.
    fn horner(c: &[Float], tau: &[f64], eta: &Float, q: u32, r: f64) -> Float {
        let floor = r - q as f64 - 24.0;
        let top = (0..c.len()).rev().find(|&m| tau[m] >= floor).unwrap_or(0);
        let mut acc = Float::with_val(Self::prec_for(q, r, tau[top]), &c[top]);
        // The partial sum from m on carries every term above m: its precision follows the
        // largest of them (a coefficient that happens to be small does not lower it).
        let mut big = tau[top];
        for m in (0..top).rev() {
            big = big.max(tau[m]);
            let prec = Self::prec_for(q, r, big);
            // η as it is when it is no longer than the partial sum (the same value), else
            // rounded to it.
            let short_eta;
            let e = if eta.prec() <= prec {
                eta
            } else {
                short_eta = Float::with_val(prec, eta);
                &short_eta
            };
            let mut t = Float::with_val(prec, e * &acc);
            t += &c[m];
            acc = t;
        }
        acc
    }

    /// The node nearest the short point x̃ = `xn`/2^112 and its weight, rounded to `raw` bits.
    fn node(&self, xn: &Integer, raw: u32) -> Result<(Float, Float)> {
        let n = self.n;
        let (qn, qn1, e) = legendre_fixed(n, xn, self.frac);
        let xt = Float::with_val(XBITS + 2, xn) >> XBITS;
        let one_m = Float::with_val(XBITS + 2, 1 - &xt);
        let one_p = Float::with_val(XBITS + 2, 1 + &xt);
        let s = Float::with_val(2 * XBITS + 8, &one_m * &one_p);
        // u_0 = Q_n, u_1 = n (n Q_{n−1} − x̃ Q_n) = s P_n'(x̃), both times n!/2^e.
        let mut u1i = Integer::from(&qn1 * (n as u64)) << XBITS;
        u1i -= Integer::from(xn * &qn);
        u1i *= n as u64;
        let w = self.w;
        let u0 = Float::with_val(w + 16, &qn);
        let u1 = Float::with_val(w + 16, &u1i) >> XBITS;
        let fail = |what: &'static str| Error::Internal { what };
        if u1.is_zero() || !u1.is_finite() {
            return Err(fail("Gauss-Legendre node (P_n' = 0 at the short point)"));
        }
        let (eta, dfull) = if u0.is_zero() {
            (Float::with_val(w, 0), u1.clone())
        } else {
            // log₂|η| to a small fraction of a bit (the m-th term carries m times its error).
            let lg_eta = log2_abs(&Float::with_val(64, &u0 / &u1));
            let ex = self.expansion(u0, u1, &xt, &s, lg_eta)?;
            // The first-order step −u_0/u_1 is good to about r − τ_2 bits; Newton doubles them.
            let r = ex.tau[1];
            let first = (r - ex.tau.get(2).copied().unwrap_or(f64::NEG_INFINITY)).min(w as f64);
            if first < 8.0 {
                return Err(fail(
                    "Gauss-Legendre node (short point too far from the root)",
                ));
            }
            // The node x̃ + sη needs sη to 2^−w relative to x̃, i.e. η to `need` bits relative:
            // u_0 = P_n(x̃) is |sη|·|P_n'| small, and holds only that many bits beyond the
            // fixed-point recurrence's absolute accuracy.
            let need = (w as f64 + 8.0 + lg(&s) + lg_eta - lg(&xt)).clamp(16.0, (w + 8) as f64);
            let need = need as u32;
            let mut good = (first as u32 - 4).min(need);
            let p0 = (2 * good + 32).min(need + 16);
            let mut eta = Float::with_val(p0, -(Float::with_val(p0, &ex.v[0]) / &ex.v[1]));
            // Each Newton step must land within 2^−(good − 4) of η (relative): quadratic
            // convergence from a first step good to `first` bits.
            while good < need {
                let next = (2 * good).saturating_sub(8).min(need + 8);
                let fv = Self::horner(&ex.v, &ex.tau, &eta, next, r);
                let dv = Self::horner(&ex.d, &ex.tau_d, &eta, good + 16, ex.tau_d[0]);
                let step = Float::with_val(next + 16, &fv / &dv);
                if lg(&step) > lg(&eta) - good as f64 + 4.0 {
                    return Err(fail("Gauss-Legendre node (Newton on the Taylor expansion)"));
                }
                eta = Float::with_val(next + 16, &eta - &step);
                if next <= good {
                    break;
                }
                good = next;
            }
            let dfull = Self::horner(&ex.d, &ex.tau_d, &eta, w + 16, ex.tau_d[0]);
            (eta, dfull)
        };
        let x = Float::with_val(w, &xt + Float::with_val(w, &s * &eta));
        // 1 − x² = (1 − x)(1 + x), 1 − x = (1 − x̃) − sη (no cancellation: |sη| ≪ 1 − x̃).
        let sn = Float::with_val(w, &s * &eta);
        let omx = Float::with_val(w, &one_m - &sn);
        let opx = Float::with_val(w, &one_p + &sn);
        // w = 2/((1 − x²) P_n'(x)²) with P_n'(x) = f'(η*)·2^e/(n!·s) (f' in the units of u_m):
        // w = 2 s² (n!)² 2^(−2e)/((1 − x²) f'²).
        let mut wt = Float::with_val(w, &s * &s);
        wt *= &self.nfact2;
        wt /= Float::with_val(w, &omx * &opx);
        wt /= Float::with_val(w, dfull.square_ref());
        wt <<= 1 - 2 * e as i32;
        if !x.is_finite() || !wt.is_finite() {
            return Err(fail("Gauss-Legendre node (non-finite node or weight)"));
        }
        Ok((Float::with_val(raw, &x), Float::with_val(raw, &wt)))
    }
}

/// The double-double node: one Newton step from the `f64` node (error ≈ (n²/(1 − x²))·2⁻¹⁰⁶
/// or less, below 2⁻⁸⁰; the Taylor stage needs only a few bits, and a closer point only saves
/// terms).
fn node_dd(n: usize, x: f64) -> Dd {
    const DD_STEPS: usize = 1;
    let mut x = Dd::from_f64(x, ());
    for _ in 0..DD_STEPS {
        let (pn, d, omx2) = legendre_scaled(n, &x);
        let dx = pn * omx2 / d;
        if !dx.is_finite() {
            break;
        }
        x -= dx;
    }
    x
}

/// The rule's nonnegative nodes (decreasing) and weights at `raw` bits, by the three stages of
/// the module docs. The nodes are independent of one another: they are built on every core
/// ([`map_on_threads`]; the same values whatever the number of threads).
pub(crate) fn build_fast(n: usize, raw: u32) -> Result<RawRule> {
    let m = n.div_ceil(2);
    let refine = Refine::new(n, raw);
    let pairs = map_on_threads(m, &|i: usize| build_node(&refine, n, i + 1, raw))?;
    let (nodes, weights) = pairs.into_iter().unzip();
    Ok(RawRule {
        bits: raw,
        nodes,
        weights,
    })
}

/// The k-th nonnegative node (k = 1 the largest) of the n-point rule and its weight at `raw` bits.
fn build_node(refine: &Refine, n: usize, k: usize, raw: u32) -> Result<(Float, Float)> {
    let xn = if 2 * k - 1 == n {
        Integer::new()
    } else {
        let xd = node_dd(n, node_f64(n, k)?);
        if !(xd.is_positive() && xd < Dd::one(())) {
            return Err(Error::NoConvergence {
                what: "Gauss-Legendre node (double-double Newton left (0, 1))",
                iterations: k,
                reached: short(&xd),
            });
        }
        let f = xd.to_float(2 * XBITS) << XBITS;
        f.to_integer().unwrap_or_default()
    };
    refine.node(&xn, raw)
}

// ---------------------------------------------------------------------------------------------
// The store of rules by node count

/// A rule's nonnegative nodes (decreasing) and their weights as MPFR numbers at `bits` bits
/// (a target precision plus [`GUARD`]).
#[derive(Debug)]
pub(crate) struct RawRule {
    pub(crate) bits: u32,
    pub(crate) nodes: Vec<Float>,
    pub(crate) weights: Vec<Float>,
}

type Store = Mutex<HashMap<usize, Arc<RawRule>>>;

fn store() -> &'static Store {
    static STORE: OnceLock<Store> = OnceLock::new();
    STORE.get_or_init(Default::default)
}

/// The n-point rule for targets of `target_bits` bits: the most precise one built so far
/// for n if it is at least as precise as `target_bits` + [`GUARD`] (a higher precision rounds
/// down), else a new one by [`build_fast`], kept in its place.
pub(crate) fn raw_rule(n: usize, target_bits: u32) -> Result<Arc<RawRule>> {
    let raw = target_bits + GUARD;
    let lock = || store().lock().unwrap_or_else(|e| e.into_inner());
    if let Some(r) = lock().get(&n).filter(|r| r.bits >= raw) {
        return Ok(r.clone());
    }
    let rule = Arc::new(build_fast(n, raw)?);
    let mut map = lock();
    match map.get(&n) {
        Some(r) if r.bits >= raw => Ok(r.clone()),
        _ => {
            map.insert(n, rule.clone());
            Ok(rule)
        }
    }
}

/// Forgets every rule of the store (for measuring first-use costs).
pub(crate) fn clear_store() {
    store().lock().unwrap_or_else(|e| e.into_inner()).clear();
}

#[cfg(test)]
#[path = "../../tests/unit/gauss_legendre.rs"]
mod tests;
