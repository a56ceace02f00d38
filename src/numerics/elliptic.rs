//! The elliptic integrals of the paper's (42)–(43), (A.8) and (52)–(53) at any precision: K(e)
//! and E(e), L₁ = (K − E)/e² and M₁ = (E − k²K)/e² as D and B, and the bracket of (52)–(53)
//! as 1 − Λ₀ ([`heuman_lambda_c_mc`]).
//!
//! Every function takes the **complementary parameter** `mc = 1 − m` (DLMF §19's `m = k²`): in
//! the application `mc = k_axis²` for the axis ratio `k_axis ∈ [10⁻⁶, 10⁶]`, and forming it as
//! `1 − m` would lose every digit when `k_axis` is tiny.
//!
//! Complete integrals by Bulirsch's cel (Numer. Math. 13 (1969) 305–315), which adds only
//! positive quantities; Heuman's Lambda by Carlson's R_F and R_D (DLMF
//! 19.25.5, 19.25.10) with the duplication theorem and a Taylor series of an order chosen from
//! the working precision. Tolerances come from the working precision and every loop has a cap
//! ([`Error::NoConvergence`]). Each function is within 8 ε of the working precision (16 ε at
//! double-double) against mpmath (`tests/elliptic.rs`; the measured worst errors in
//! `docs/calibration.md`).

use crate::error::{Error, Result};
use crate::scalar::{check_finite, short, Real};
use rug::float::Constant;
use rug::Float;

fn domain<T: Real>(name: &'static str, x: &T, bound: &'static str) -> Error {
    Error::domain(name, short(x), bound)
}

/// Guards against a silent ∞/NaN from an intermediate overflow at extreme arguments.
fn finite_out<T: Real>(what: &'static str, x: T) -> Result<T> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Error::Unreachable {
            what,
            tolerance: short(&T::epsilon(x.prec())),
            reason: "an intermediate quantity left the exponent range of the backend".into(),
        })
    }
}

/// Iteration cap of the AGM-type loops: they converge quadratically once the two means agree to
/// a factor 2, which takes log₂|log₂ kc| steps; log₂(bits) more reach the precision.
fn agm_cap(bits: u32) -> usize {
    64 + 2 * bits.ilog2() as usize
}

// ---------------------------------------------------------------------------------------------
// Complete integrals
// ---------------------------------------------------------------------------------------------

/// Bulirsch's general complete elliptic integral with `p = 1`,
///
/// `cel(kc, 1, a, b) = ∫₀^{π/2} (a cos²θ + b sin²θ) / √(cos²θ + kc² sin²θ) dθ = a B + b D`
///
/// (m = 1 − kc²), for several pairs `(a, b)` sharing `kc > 0` (cel is linear in `(a, b)`, and
/// the AGM part of the iteration depends on `kc` only).
///
/// The iteration is the one of Bulirsch (1969) as printed in Numerical Recipes, with the
/// quantities `em = 2ⁿ aₙ`, `qc = 2ⁿ bₙ` (AGM means scaled by exact powers of two). For
/// `a, b ≥ 0` it adds only positive quantities. It stops when the relative AGM gap is below √ε
/// of the working precision: the other sequences converge at the same quadratic rate, so the
/// result is then complete to O(ε).
fn cel_core<T: Real, const N: usize>(kc: T, mut ab: [(T, T); N]) -> Result<[T; N]> {
    let pr = kc.prec();
    let one = T::one(pr);
    let mut p = one.clone();
    let tol = T::epsilon_root(pr, 2);
    let two = T::from_i64(2, pr);
    let (mut qc, mut e, mut em) = (kc.clone(), kc, one);
    let mut prev: Option<T> = None;
    let cap = agm_cap(T::bits(pr));
    for _ in 0..cap {
        let ip = p.clone().recip();
        let g = e.clone() * &ip;
        for (a, b) in ab.iter_mut() {
            let f = a.clone();
            *a += b.clone() * &ip;
            let nb = (b.clone() + f * &g) * &two;
            *b = nb;
        }
        p += &g;
        let g = em.clone();
        em += &qc;
        let gap = (g.clone() - &qc).abs();
        // Tolerance reached, or no progress: the scaled gap 2ⁿ|aₙ − bₙ| never grows in exact
        // arithmetic (it may stay equal to rounding while kc ≪ 1, so only growth counts).
        if gap <= tol.clone() * &g || prev.as_ref().is_some_and(|x| gap > *x) {
            let half_pi = T::pi(pr).div_i64(2);
            let den = em.clone() * (em.clone() + &p);
            return Ok(ab.map(|(a, b)| half_pi.clone() * (b + a * &em) / &den));
        }
        qc = e.sqrt() * &two;
        e = qc.clone() * &em;
        prev = Some(gap);
    }
    Err(Error::NoConvergence {
        what: "Bulirsch cel",
        iterations: cap,
        reached: prev.map_or_else(String::new, |g| short(&g)),
    })
}

fn check_mc<T: Real>(mc: &T, strict: bool) -> Result<()> {
    check_finite("mc", mc)?;
    if mc.is_negative() || (strict && mc.is_zero()) {
        return Err(domain("mc", mc, if strict { "mc > 0" } else { "mc >= 0" }));
    }
    Ok(())
}

/// `[B(mc), D(mc)]` in one iteration (`mc > 0`).
fn bd_mc<T: Real>(mc: &T) -> Result<[T; 2]> {
    let p = mc.prec();
    let (z, o) = (T::zero(p), T::one(p));
    cel_core(mc.clone().sqrt(), [(o.clone(), z.clone()), (z, o)])
}

/// K(m) and E(m) together from `mc = 1 − m > 0`, in one iteration: K = B + D and
/// E = B + mc·D with B, D as in [`ellipbd_mc`] (sums of positive terms, a few ε).
pub fn ellipke_mc<T: Real>(mc: &T) -> Result<(T, T)> {
    check_mc(mc, true)?;
    let [b, d] = bd_mc(mc)?;
    let k = b.clone() + &d;
    let e = b + d * mc;
    Ok((finite_out("K(m)", k)?, finite_out("E(m)", e)?))
}

/// B(m) = ∫₀^{π/2} cos²θ / √(1 − m sin²θ) dθ = (E − mc·K)/m and
/// D(m) = ∫₀^{π/2} sin²θ / √(1 − m sin²θ) dθ = (K − E)/m (DLMF 19.2.6) together from
/// `mc = 1 − m > 0`, in one `cel` iteration: `cel(√mc, 1, 1, 0)` and `cel(√mc, 1, 0, 1)`, with
/// no cancellation as `m → 0`, each a few ε. The paper's M₁ and L₁ of (42)/(A.8) are B(e²)
/// and D(e²). Every complete integral of (42) follows from the pair without
/// cancellation: K = B + D, E = B + mc·D, E/mc = B/mc + D.
pub fn ellipbd_mc<T: Real>(mc: &T) -> Result<(T, T)> {
    check_mc(mc, true)?;
    let [b, d] = bd_mc(mc)?;
    Ok((finite_out("B(m)", b)?, finite_out("D(m)", d)?))
}

// ---------------------------------------------------------------------------------------------
// Carlson's symmetric integrals
// ---------------------------------------------------------------------------------------------

/// Order `N` of the Taylor series used after duplication, and the threshold `2^-k` on
/// δ = max|Zⱼ| below which the series truncated after order `N` is exact to ε/2.
///
/// The coefficient of order n of the series of `R_{-a}` is bounded by `(a)ₙ/n! δⁿ`
/// (≤ δⁿ for R_F, ≤ 1.13 √n δⁿ for R_D), so the tail after order N is below
/// `2.3 √(N+1) δ^(N+1)` for δ ≤ 1/2; `k (N+1) ≥ bits + 4 + log₂(N+1)` makes it < 2^-bits.
/// Each duplication divides δ by 4 and costs three square roots; the series costs O(N²)
/// multiplications, so `N ≈ (4·bits)^(1/3)` balances the two (N = 6 at f64, 32 at 8192 bits).
fn series_plan<T: Real>(p: T::Prec) -> (usize, T) {
    let bits = T::bits(p);
    let mut n = 6u32;
    while (n + 1).pow(3) <= 4 * bits && n < 64 {
        n += 1;
    }
    let k = (bits + 4 + (n + 1).ilog2()).div_ceil(n + 1);
    (n as usize, T::one(p).mul_pow2(-(k as i32)))
}

/// `Σₙ (a)ₙ/(c)ₙ Tₙ(b; Z)`: the series of Carlson's `R_{-a}(b; z)` about the weighted mean A
/// (DLMF 19.19.7 with `Zⱼ = 1 − zⱼ/A`, `Σ bⱼ Zⱼ = 0`), where Tₙ are the Taylor coefficients of
/// `Πⱼ (1 − t Zⱼ)^(−bⱼ)`. From the weighted power sums `Pₖ = Σ bⱼ Zⱼᵏ` (P₁ = 0) they follow by
/// `n Tₙ = Σₖ Pₖ Tₙ₋ₖ` (logarithmic derivative). Weights are passed doubled: `w2 = 2b`,
/// `a2 = 2a`, `c2 = 2c`. For R_F this reproduces DLMF 19.36.1 term by term.
fn carlson_series<T: Real>(z: [T; 3], w2: [i64; 3], a2: i64, c2: i64, order: usize) -> T {
    let p = z[0].prec();
    let mut pw = z.clone();
    let mut ps: Vec<T> = Vec::with_capacity(order + 1); // ps[k] = 2 Pₖ
    ps.push(T::zero(p));
    ps.push(T::zero(p));
    for _ in 2..=order {
        let mut s = T::zero(p);
        for j in 0..3 {
            pw[j] *= &z[j];
            s += pw[j].clone().mul_i64(w2[j]);
        }
        ps.push(s);
    }
    let mut t: Vec<T> = Vec::with_capacity(order + 1);
    t.push(T::one(p));
    t.push(T::zero(p));
    let mut r = T::from_ratio(a2, c2, p); // (a)ₙ/(c)ₙ at n = 1
    let mut sum = T::one(p);
    for n in 2..=order {
        let n2 = 2 * n as i64;
        r = r.mul_i64(a2 + n2 - 2).div_i64(c2 + n2 - 2);
        let mut acc = T::zero(p);
        for k in 2..=n {
            acc += ps[k].clone() * &t[n - k];
        }
        let tn = acc.div_i64(n2);
        sum += r.clone() * &tn;
        t.push(tn);
    }
    sum
}

/// Carlson's duplication (Carlson 1995, Numer. Algorithms 10, 13–26) for R_F (`rd = false`) or
/// R_D (`rd = true`), followed by [`carlson_series`]. Arguments are checked by the callers.
///
/// Stops when δ = 4⁻ⁿ max|A₀ − zⱼ| / Aₙ (a rigorous bound on max|Zⱼ|) is below the threshold of
/// [`series_plan`], when a step leaves x, y, z unchanged, or at a cap. While the arguments
/// differ by many orders of magnitude, δ stays put but the ratio r of the smallest to the
/// largest goes to about 2√r per step, so this phase lasts log₂ log₂(1/r) steps (about 30 for
/// the MPFR exponent range); the others divide δ by 4. The cap, 100 + bits, is far above both.
fn carlson<T: Real>(x: T, y: T, z: T, rd: bool) -> Result<T> {
    let p = x.prec();
    let (order, thr) = series_plan::<T>(p);
    let a0 = if rd {
        (x.clone() + &y + z.clone().mul_i64(3)).div_i64(5)
    } else {
        (x.clone() + &y + &z).div_i64(3)
    };
    let (dx, dy) = (a0.clone() - &x, a0.clone() - &y);
    let q = dx
        .clone()
        .abs()
        .max_of(dy.clone().abs())
        .max_of((a0.clone() - &z).abs());
    let (mut x, mut y, mut z, mut a) = (x, y, z, a0);
    let mut fac = T::one(p);
    let mut sum = T::zero(p);
    let quarter = T::from_ratio(1, 4, p);
    let cap = 100 + T::bits(p) as usize;
    let mut n = 0usize;
    while q.clone() * &fac > thr.clone() * &a {
        if n == cap {
            return Err(Error::NoConvergence {
                what: if rd {
                    "Carlson R_D duplication"
                } else {
                    "Carlson R_F duplication"
                },
                iterations: n,
                reached: short(&(q * &fac / &a)),
            });
        }
        let (sx, sy, sz) = (x.clone().sqrt(), y.clone().sqrt(), z.clone().sqrt());
        let lam = sx * (sy.clone() + &sz) + sy * &sz;
        if rd {
            sum += fac.clone() / (sz * (z.clone() + &lam));
        }
        let xn = (x.clone() + &lam) * &quarter;
        let yn = (y.clone() + &lam) * &quarter;
        let zn = (z.clone() + &lam) * &quarter;
        if xn == x && yn == y && zn == z {
            break; // a fixed point of the rounded iteration: no more progress
        }
        (x, y, z) = (xn, yn, zn);
        a = (a + &lam) * &quarter;
        fac *= &quarter;
        n += 1;
    }
    // Zⱼ = (A₀ − zⱼ)/(4ⁿ Aₙ): exact differences of the inputs, not of the iterates.
    let s = fac.clone() / &a;
    let (xx, yy) = (dx * &s, dy * &s);
    if rd {
        let zz = -(xx.clone() + &yy).div_i64(3);
        let ser = carlson_series([xx, yy, zz], [1, 1, 3], 3, 5, order);
        Ok(sum.mul_i64(3) + fac * ser / (a.clone() * a.sqrt()))
    } else {
        let zz = -(xx.clone() + &yy);
        Ok(carlson_series([xx, yy, zz], [1, 1, 1], 1, 3, order) / a.sqrt())
    }
}

// ---------------------------------------------------------------------------------------------
// Heuman's Lambda
// ---------------------------------------------------------------------------------------------

/// An amplitude reduced to `φ = jπ + φ'`, `|φ'| ≤ π/2`.
enum Amplitude<T> {
    /// `|φ| > 2^(bits+8)`: the periodic part is below ε of the result, Λ₀ = 2φ/π.
    Huge,
    /// `j` (None for 0), `sin φ'` and `|cos φ'|`.
    Reduced(Option<T>, T, T),
}

/// Reduces `φ` modulo π and returns `sin φ'`, `|cos φ'|`. For `|φ| > π/2` the reduction and
/// the sine and cosine are carried out in MPFR with `bits + exponent(φ) + 64` bits and rounded
/// once: rounding φ' itself to the working precision would cost an absolute error ulp(π/2) in
/// φ', fatal next to ±π/2 where Λ₀ is steep.
fn reduce<T: Real>(phi: &T) -> Amplitude<T> {
    let p = phi.prec();
    if phi.clone().abs() <= T::pi(p).mul_pow2(-1) {
        let (s, c) = phi.clone().sin_cos();
        return Amplitude::Reduced(None, s, c.abs());
    }
    let bits = T::bits(p);
    let f = phi.to_float(bits + 64);
    let ex = f.get_exp().unwrap_or(0);
    if ex > bits as i32 + 8 {
        return Amplitude::Huge;
    }
    let w = bits + 64 + ex.max(0) as u32;
    let pi = Float::with_val(w, Constant::Pi);
    let j = Float::with_val(w, &f / &pi).round();
    let r = Float::with_val(w, &f - Float::with_val(w, &j * &pi));
    let (s, c) = r.sin_cos(Float::new(w));
    Amplitude::Reduced(
        Some(T::from_float(&j, p)),
        T::from_float(&s, p),
        T::from_float(&c.abs(), p),
    )
}

/// `1 − Λ₀(φ | m)` from `mc = 1 − m ∈ [0, 1]`, where Heuman's Lambda function is
/// `Λ₀(φ | m) = (2/π)[E(m) F(φ | mc) + K(m) E(φ | mc) − K(m) F(φ | mc)]` (Byrd & Friedman
/// 150.03), without the cancellation of `1 − Λ₀` as φ → π/2.
///
/// The bracket of the paper's (52)–(53),
/// `π/2 − K(e) E(β, k) − E(e) F(β, k) + K(e) F(β, k)`, equals
/// `(π/2) · heuman_lambda_c_mc(β, k²)` with `e² = 1 − k²` (k the axis ratio, `k ≤ 1`).
/// Accuracy: a few ε for every real φ, including φ next to π/2.
///
/// On `0 ≤ u ≤ π/2`, with `s = sin u`, `c = cos u`, it follows from
/// `dΛ₀/du = (2/π)(m B + mc K cos²u)/Δ'`, `Δ'² = c² + m s²` (Byrd & Friedman 710.11, with
/// E − mc K sin²u rewritten as m B + mc K cos²u ≥ 0) and DLMF 19.25.5, 19.25.10 as the sum of
/// positive terms `1 − Λ₀(u) = (2/π) m [B c R_F(m s², m s² + c², m) + mc K (c³/3) R_D(m s²,
/// m s² + c², m)]`. For any real φ = jπ ± u, `1 − Λ₀ = (1 ∓ 1 − 2j) ± (1 − Λ₀(u))`, where the
/// integer part is 0 or at least 2 in size.
pub fn heuman_lambda_c_mc<T: Real>(phi: &T, mc: &T) -> Result<T> {
    check_finite("phi", phi)?;
    check_mc(mc, false)?;
    let p = phi.prec();
    let one = T::one(p);
    if *mc > one {
        return Err(domain("mc", mc, "0 <= mc <= 1"));
    }
    let m = one.clone() - mc;
    let (j, s, c) = match reduce(phi) {
        // Λ₀(φ) = 2φ/π + O(1), the O(1) below ε of the result.
        Amplitude::Huge => return Ok(one - phi.clone().mul_pow2(1) / T::pi(p)),
        Amplitude::Reduced(j, s, c) => (j, s, c),
    };
    let neg = s.is_negative();
    let s = s.abs();
    let v = if m.is_zero() {
        // Λ₀(u | 0) = sin u; 1 − sin u = cos²u / (1 + sin u).
        c.square() / (one.clone() + &s)
    } else {
        // B(m) and mc·K(m) (→ 1 and 0 as mc → 0).
        let (b, mck) = if mc.is_zero() {
            (one.clone(), T::zero(p))
        } else {
            let [b, d] = bd_mc(mc)?;
            (b.clone(), mc.clone() * (b + d))
        };
        let x = m.clone() * s.square();
        let y = x.clone() + c.square();
        let rf = carlson(x.clone(), y.clone(), m.clone(), false)?;
        let rd = carlson(x, y, m.clone(), true)?;
        let c3 = c.square() * &c;
        let two_over_pi = T::from_i64(2, p) / T::pi(p);
        two_over_pi * m * (b * &c * rf + mck * c3 * rd / T::from_i64(3, p))
    };
    let two_j = j.map_or_else(|| T::zero(p), |j| j.mul_pow2(1));
    let r = if neg {
        one.mul_pow2(1) - two_j - v
    } else {
        v - two_j
    };
    finite_out("Heuman Lambda", r)
}
