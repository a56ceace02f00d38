//! The moments of section 5 and the appendix, as functions of the complementary parameter
//! `mc = k²` (exact input, as in [`crate::numerics::elliptic`]):
//!
//! ```text
//! L_n = ∫_0^{π/2} cos^{2n}α / Δ³ dα   (39),      M_n = ∫_0^{π/2} cos^{2n}α / Δ dα   (41),
//! Δ² = cos²α + k² sin²α,   e² = 1 − k²  (negative when k > 1),
//! ```
//!
//! and the differences D_n = L_n − L_{n+1} that the series (37) for I1 needs. `docs/theory.md`
//! states the recursion (40) and its starting values (42); `docs/series.md` its stability (forward
//! for e² > 1/2, backward below), the three [`MomentMethod`]s, the default's choice ([`plan`]),
//! the guard bits and the measured accuracy (every M_n, L_n, D_n within 8 ε, `tests/moments.rs`).
//! [`KeForm`] runs (40) on the coefficients of K and E, exactly over `rug::Rational`;
//! [`ke_condition_bits`] is the condition number of any evaluation in that basis.

use super::guard::{ceil_log2, run_guarded, GuardedJob};
use crate::error::{Error, Result};
use crate::numerics::elliptic::{ellipbd_mc, ellipke_mc};
use crate::numerics::series::sum_series_with_tail;
use crate::scalar::{check_positive, short, FieldOps, Real};
use rug::float::Constant;
use rug::{Float, Integer};

/// Largest table index accepted (n_max ≤ 10⁶).
pub(crate) const MAX_INDEX: usize = 1_000_000;
/// Cap on the terms of a top-value series ([`Error::TermCap`] beyond).
pub(crate) const MAX_TOP_TERMS: usize = 20_000_000;

/// How the moment table is computed (`docs/series.md`, "The default").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum MomentMethod {
    /// The forward recursion (40) from (42) (via cel); stable for e² > 1/2 only.
    Forward,
    /// Backward recursion (40) from top values by the hypergeometric series in e²
    /// (|e²| < 1; stable for e² < 1/2).
    BackwardGauss,
    /// Backward recursion (40) from top values by the cos² expansion in t = −e²/k²
    /// (e² < 1/2; stable there; slow as k → ∞ or e² → 1/2).
    BackwardPfaff,
}

impl MomentMethod {
    /// `forward`, `backward-gauss`, `backward-pfaff`. Names a method for (40); exact.
    pub fn label(&self) -> &'static str {
        match self {
            MomentMethod::Forward => "forward",
            MomentMethod::BackwardGauss => "backward-gauss",
            MomentMethod::BackwardPfaff => "backward-pfaff",
        }
    }
}

/// The default's choice for one (k², n_max, precision): method, guard bits and the estimated
/// number of terms of each top-value series.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MomentPlan {
    /// The method.
    pub method: MomentMethod,
    /// Guard bits added to the working precision.
    pub guard_bits: u32,
    /// Estimated terms of each top-value series (0 for the forward recursion).
    pub top_terms: u64,
}

/// Guard bits every method gets: accumulation over n steps and the cancellation in D_n.
fn base_guard(n_max: usize) -> u32 {
    2 * ceil_log2(n_max as f64 + 2.0) + 12
}

/// log₂|r| = log₂(k²/|e²|) for e² < 0, from k² = mc > 1 (accurate for huge mc).
fn growth_bits_per_step(mc: f64) -> f64 {
    -(-1.0 / mc).ln_1p() / std::f64::consts::LN_2
}

/// Terms of the Gauss top series at index `n` for `bits` bits (simulated in f64).
fn gauss_terms(e2: f64, n: usize, bits: u32) -> u64 {
    let target = (-(bits as f64) * std::f64::consts::LN_2).exp().max(1e-300);
    let (mut t, mut j) = (1.0f64, 0u64);
    while t > target && j < MAX_TOP_TERMS as u64 {
        let jf = j as f64;
        t *= e2.abs() * (2.0 * jf + 3.0) * (2.0 * jf + 1.0)
            / (4.0 * (jf + 1.0) * (n as f64 + 1.0 + jf));
        j += 1;
        if t == 0.0 {
            break;
        }
    }
    j + 2
}

/// The default's method and guard bits for k² = `mc`, indices up to `n_max` (the table holds
/// M_n, L_n to n_max + 1), at `bits` bits of working precision.
///
/// Forward for e² ≥ 1/2; Gauss-backward for −3/4 ≤ e² < 1/2; for e² < −3/4 the cheaper (by a
/// cost model: operations × (1 + bits/64)) of forward with n_max·log₂(k²/|e²|) extra guard bits
/// and Pfaff-backward with about bits/log₂(k²/|e²|) series terms.
/// The method for (40) with (42) or the series top values; implements no equation.
pub fn plan(mc: f64, n_max: usize, bits: u32) -> MomentPlan {
    let e2 = 1.0 - mc;
    let base = base_guard(n_max);
    let top = n_max + 1;
    if e2 >= 0.5 {
        return MomentPlan {
            method: MomentMethod::Forward,
            guard_bits: base,
            top_terms: 0,
        };
    }
    if e2 >= -0.75 {
        let j = gauss_terms(e2, top.saturating_sub(1), bits + base);
        return MomentPlan {
            method: MomentMethod::BackwardGauss,
            guard_bits: base + ceil_log2(j as f64),
            top_terms: j,
        };
    }
    let lambda = growth_bits_per_step(mc);
    let g_fwd = base as f64 + (top as f64 * lambda).ceil() + 2.0;
    let j = ((bits + base) as f64 / lambda).ceil() + 16.0;
    let g_bwd = base as f64 + j.log2().ceil();
    let cost = |ops: f64, g: f64| ops * (1.0 + (bits as f64 + g) / 64.0);
    let fwd = cost(12.0 * top as f64, g_fwd);
    let bwd = cost(14.0 * top as f64 + 20.0 * j, g_bwd);
    let fwd_ok = g_fwd + bits as f64 <= crate::scalar::MpPrec::MAX_BITS as f64;
    if (fwd <= bwd && fwd_ok) || j > MAX_TOP_TERMS as f64 {
        MomentPlan {
            method: MomentMethod::Forward,
            guard_bits: g_fwd.min(u32::MAX as f64) as u32,
            top_terms: 0,
        }
    } else {
        MomentPlan {
            method: MomentMethod::BackwardPfaff,
            guard_bits: g_bwd as u32,
            top_terms: j as u64,
        }
    }
}

/// A table of moments: M_n and L_n for n = 0 … n_max + 1, D_n = L_n − L_{n+1} for
/// n = 0 … n_max, all at the precision of the input.
#[derive(Clone, Debug)]
pub struct Moments<T> {
    m: Vec<T>,
    l: Vec<T>,
    d: Vec<T>,
    /// The method used.
    pub method: MomentMethod,
    /// Guard bits the computation ran with (0: at the working precision).
    pub guard_bits: u32,
    /// Terms of the longest top-value series (0 for the forward recursion).
    pub top_terms: usize,
}

impl<T> Moments<T> {
    /// The largest n of D_n, the top index of (38)–(41) (the table of M and L goes one further).
    pub fn n_max(&self) -> usize {
        self.d.len() - 1
    }
    /// M_0 … M_{n_max+1} (41).
    pub fn m(&self) -> &[T] {
        &self.m
    }
    /// L_0 … L_{n_max+1} (39).
    pub fn l(&self) -> &[T] {
        &self.l
    }
    /// D_n = L_n − L_{n+1} = ∫cos^{2n}α sin²α/Δ³ dα for n = 0 … n_max.
    /// The differences of (39) entering (37); each within 8ε ([`moments`]).
    pub fn d(&self) -> &[T] {
        &self.d
    }
}

fn check_inputs<T: Real>(mc: &T, n_max: usize) -> Result<()> {
    check_positive("k^2 (moments)", mc)?;
    if n_max > MAX_INDEX {
        return Err(Error::domain(
            "n_max (moments)",
            n_max.to_string(),
            "n_max <= 1000000",
        ));
    }
    Ok(())
}

/// M_n, L_n (n ≤ n_max + 1) and D_n (n ≤ n_max) for k² = `mc` > 0, each within 8 ε of the working
/// precision (`docs/series.md`: the measured accuracy; the method chosen by [`plan`]).
///
/// Work: O(n_max) operations at the working precision plus the guard bits of the plan, plus the
/// top-value series (at most 2·10⁷ terms), plus one cel.
///
/// Errors: [`Error::Domain`] for k² ≤ 0 or n_max > 10⁶, [`Error::NotFinite`],
/// [`Error::TermCap`] if a top-value series exceeds its cap, [`Error::Precision`] if the
/// guard bits exceed the MPFR maximum; errors of the elliptic integrals.
/// Implements (38)–(42) (recursion (40) from (42), or backwards from series top values).
pub fn moments<T: Real>(mc: &T, n_max: usize) -> Result<Moments<T>> {
    check_inputs(mc, n_max)?;
    let pl = plan(mc.to_f64(), n_max, T::bits(mc.prec()));
    moments_with(mc, n_max, pl.method, pl.guard_bits)
}

/// The moment table by a chosen method, at the working precision plus `guard_bits` (0: the
/// working precision itself, as the paper's recursion would run). D_n is formed before the final
/// rounding.
///
/// Implements (38)–(42). Accuracy (`docs/series.md`): stable methods hold a few ε·n before
/// guarding; [`MomentMethod::Forward`] for e² < 1/2 loses log₂|k²/e²| bits per step.
///
/// Errors: as [`moments`]; also [`Error::Domain`] for the forward recursion at e² = 0 (it divides
/// by e²), for Gauss top values with |e²| ≥ 1 and Pfaff top values with e² ≥ 1/2 (divergent).
pub fn moments_with<T: Real>(
    mc: &T,
    n_max: usize,
    method: MomentMethod,
    guard_bits: u32,
) -> Result<Moments<T>> {
    check_inputs(mc, n_max)?;
    run_guarded(
        mc.prec(),
        guard_bits,
        MomentsJob {
            mc,
            n_max,
            method,
            guard_bits,
        },
    )
}

struct MomentsJob<'a, T> {
    mc: &'a T,
    n_max: usize,
    method: MomentMethod,
    guard_bits: u32,
}

impl<T: Real> GuardedJob<T> for MomentsJob<'_, T> {
    type Output = Moments<T>;
    fn run<W: Real>(
        self,
        _pw: W::Prec,
        up: &dyn Fn(&T) -> W,
        down: &dyn Fn(&W) -> T,
    ) -> Result<Moments<T>> {
        let mcw = up(self.mc);
        let t = table_at(&mcw, self.n_max + 1, self.method)?;
        let d = (0..=self.n_max).map(|n| down(&t.d(n, &mcw))).collect();
        Ok(Moments {
            m: t.m.iter().map(down).collect(),
            l: t.l.iter().map(down).collect(),
            d,
            method: self.method,
            guard_bits: self.guard_bits,
            top_terms: t.top_terms,
        })
    }
}

/// M_n, L_n for n = 0 … top at the working precision of `mc`.
pub(crate) struct Table<W> {
    pub(crate) m: Vec<W>,
    pub(crate) l: Vec<W>,
    pub(crate) top_terms: usize,
}

impl<W: Real> Table<W> {
    /// D_n = L_n − L_{n+1} for k² ≤ 1, and (M_n − L_{n+1})/k² for k² > 1 (the same integral, by
    /// k² sin²α = Δ² − cos²α). Either difference cancels by at most a factor ≈ 2n + ln k, where
    /// L_n − L_{n+1} would lose a factor ≈ k²/ln k for large k.
    pub(crate) fn d(&self, n: usize, mc: &W) -> W {
        if *mc > W::one(mc.prec()) {
            (self.m[n].clone() - &self.l[n + 1]) / mc
        } else {
            self.l[n].clone() - &self.l[n + 1]
        }
    }
}

/// One forward step of the recursion (40) = (A.2), (A.7), for n ≥ 2, with c = 2e² − 1:
///
/// ```text
/// (2n−1)e² M_n = 2(n−1)c M_{n−1} + (2n−3)k² M_{n−2},
/// (2n−1)e² L_n = 4(n−1)M_{n−1} − 2(2n−3)M_{n−2} + 2(n−1)c L_{n−1} + (2n−3)k² L_{n−2}.
/// ```
///
/// Written once over [`FieldOps`]: the forward table ([`moments_with`]), the exact and symbolic
/// K, E form ([`KeForm`]) and [`crate::symbolic`] all run this code. Each step rounds about ten
/// times; whether the errors grow is the direction's stability (`docs/series.md`).
#[derive(Clone, Debug)]
pub(crate) struct ForwardStep<F: FieldOps> {
    mc: F,
    c: F,
    inv_e2: F,
}

impl<F: FieldOps> ForwardStep<F> {
    /// The step for k² = `mc` (e² = 1 − k² must be nonzero: the callers check it).
    pub(crate) fn new(mc: F) -> Self {
        let e2 = F::one(mc.prec()) - &mc;
        ForwardStep {
            c: e2.clone() - &mc,
            inv_e2: e2.recip(),
            mc,
        }
    }

    /// (M_n, L_n) from `m` = [M_{n−1}, M_{n−2}] and `l` = [L_{n−1}, L_{n−2}].
    #[inline(always)]
    pub(crate) fn apply(&self, n: usize, m: [&F; 2], l: [&F; 2]) -> (F, F) {
        let (n1, n3, n2m1) = (2 * n as i64 - 2, 2 * n as i64 - 3, 2 * n as i64 - 1);
        // (2n−1)e² M_n = 2(n−1)c M_{n−1} + (2n−3)k² M_{n−2}
        let mn = (self.c.clone() * m[0]).mul_i64(n1) + (self.mc.clone() * m[1]).mul_i64(n3);
        // (2n−1)e² L_n = 4(n−1)M_{n−1} − 2(2n−3)M_{n−2} + 2(n−1)c L_{n−1} + (2n−3)k² L_{n−2}
        let ln = m[0].clone().mul_i64(2 * n1) - m[1].clone().mul_i64(2 * n3)
            + (self.c.clone() * l[0]).mul_i64(n1)
            + (self.mc.clone() * l[1]).mul_i64(n3);
        (
            (mn * &self.inv_e2).div_i64(n2m1),
            (ln * &self.inv_e2).div_i64(n2m1),
        )
    }
}

/// The moment table to index `top` ≥ 1 by `method`, at the working precision (no guard).
pub(crate) fn table_at<W: Real>(mc: &W, top: usize, method: MomentMethod) -> Result<Table<W>> {
    let p = mc.prec();
    let top = top.max(1);
    let e2 = W::one(p) - mc;
    let c = e2.clone() - mc; // 2e² − 1
    let (mut m, mut l) = (vec![W::zero(p); top + 1], vec![W::zero(p); top + 1]);
    match method {
        MomentMethod::Forward => {
            if e2.is_zero() {
                return Err(Error::domain(
                    "e^2 = 1 - k^2 (forward recursion (40) divides by e^2)",
                    "0".into(),
                    "e^2 != 0",
                ));
            }
            let (b, d) = ellipbd_mc(mc)?;
            m[0] = b.clone() + &d;
            l[0] = b.clone() / mc + &d;
            m[1] = b;
            l[1] = d;
            let step = ForwardStep::new(mc.clone());
            for n in 2..=top {
                let (mn, ln) = step.apply(n, [&m[n - 1], &m[n - 2]], [&l[n - 1], &l[n - 2]]);
                m[n] = mn;
                l[n] = ln;
            }
            Ok(Table { m, l, top_terms: 0 })
        }
        MomentMethod::BackwardGauss | MomentMethod::BackwardPfaff => {
            let (mt, lt, j1) = top_values(&e2, mc, top, method)?;
            let (mt1, lt1, j2) = top_values(&e2, mc, top - 1, method)?;
            m[top] = mt;
            l[top] = lt;
            m[top - 1] = mt1;
            l[top - 1] = lt1;
            let inv_mc = mc.clone().recip();
            for n in (2..=top).rev() {
                let (n1, n3, n2m1) = (2 * n as i64 - 2, 2 * n as i64 - 3, 2 * n as i64 - 1);
                // (2n−3)k² M_{n−2} = (2n−1)e² M_n − 2(n−1)c M_{n−1}
                let mm = (e2.clone() * &m[n]).mul_i64(n2m1) - (c.clone() * &m[n - 1]).mul_i64(n1);
                let mm = (mm * &inv_mc).div_i64(n3);
                // (2n−3)k² L_{n−2} = (2n−1)e² L_n − 4(n−1)M_{n−1} − 2(n−1)c L_{n−1} + 2(2n−3)M_{n−2}
                let ll = (e2.clone() * &l[n]).mul_i64(n2m1)
                    - m[n - 1].clone().mul_i64(2 * n1)
                    - (c.clone() * &l[n - 1]).mul_i64(n1)
                    + mm.clone().mul_i64(2 * n3);
                l[n - 2] = (ll * &inv_mc).div_i64(n3);
                m[n - 2] = mm;
            }
            Ok(Table {
                m,
                l,
                top_terms: j1.max(j2),
            })
        }
    }
}

/// W_n = ∫_0^{π/2} cos^{2n}α dα = (π/2)·C(2n, n)/4^n, rounded once (the binomial is exact);
/// n ≤ [`MAX_INDEX`] + 1 (checked by the callers).
pub(crate) fn wallis<W: Real>(n: usize, p: W::Prec) -> W {
    let bits = W::bits(p) + 32;
    let c = Integer::from(Integer::binomial_u(2 * n as u32, n as u32));
    let mut f = Float::with_val(bits, &c) * Float::with_val(bits, Constant::Pi);
    f >>= 2 * n as u32 + 1;
    W::from_float(&f, p)
}

/// Sums the power series Σ c_j with c_0 = 1 and c_{j+1} = c_j·x·ratio(j), where the caller's
/// `ratio(j) = num(j)/den(j)` (integers), with `|x|·bound(j)` bounding every later ratio.
fn hyper_sum<W: Real>(
    x: &W,
    num: impl Fn(i64) -> i64,
    den: impl Fn(i64) -> i64,
    later_ratio: impl Fn(i64) -> W,
) -> Result<(W, usize)> {
    let p = x.prec();
    let one = W::one(p);
    let mut term = one.clone();
    let gen = |j: usize| {
        if j > 0 {
            let jj = j as i64 - 1;
            term = (term.clone() * x).mul_i64(num(jj)).div_i64(den(jj));
        }
        term.clone()
    };
    let tail = |j: usize, t: &W, s: &W| {
        let rho = later_ratio(j as i64);
        if rho < one {
            t.clone().abs() * &rho / (one.clone() - &rho)
        } else {
            s.clone().abs() + &t.clone().abs()
        }
    };
    let tol = W::epsilon(p).div_i64(8);
    let s = sum_series_with_tail(gen, tail, p, &tol, MAX_TOP_TERMS).map_err(|e| match e {
        Error::TermCap { cap, reached, .. } => Error::TermCap {
            what: "top-value series of L_n, M_n",
            cap,
            needed: None,
            reached,
        },
        other => other,
    })?;
    Ok((s.sum, s.terms))
}

/// Fails at once with [`Error::TermCap`] when a top-value series of `bits` bits at term ratio
/// `rho` (asymptotically) would need more than [`MAX_TOP_TERMS`] terms.
fn check_top_terms(rho: f64, bits: u32) -> Result<()> {
    let need = (bits as f64 + 8.0) / -rho.log2();
    if need.is_finite() && need <= MAX_TOP_TERMS as f64 {
        return Ok(());
    }
    Err(Error::TermCap {
        what: "top-value series of L_n, M_n",
        cap: MAX_TOP_TERMS,
        needed: (need.is_finite() && need < 1e18).then(|| need.ceil() as u64),
        reached: "not started".into(),
    })
}

/// (M_n, L_n, terms) by the series of `method` at the working precision.
fn top_values<W: Real>(e2: &W, mc: &W, n: usize, method: MomentMethod) -> Result<(W, W, usize)> {
    let p = e2.prec();
    let one = W::one(p);
    let bits = W::bits(p);
    let wn = wallis::<W>(n, p);
    let ni = n as i64;
    match method {
        MomentMethod::BackwardGauss => {
            let a = e2.clone().abs();
            if a >= one {
                return Err(Error::domain(
                    "e^2 (hypergeometric series in e^2)",
                    short(e2),
                    "|e^2| < 1",
                ));
            }
            if gauss_terms(e2.to_f64(), n, bits) as usize >= MAX_TOP_TERMS {
                check_top_terms(a.to_f64(), bits)?;
            }
            // Term ratios e²(2j+1)²/(4(j+1)(n+1+j)) and e²(2j+3)(2j+1)/(4(j+1)(n+1+j)),
            // both at most |e²|.
            let (den, bound) = (|j: i64| 4 * (j + 1) * (ni + 1 + j), |_: i64| a.clone());
            let (sm, jm) = hyper_sum(e2, |j| (2 * j + 1) * (2 * j + 1), den, bound)?;
            let (sl, jl) = hyper_sum(e2, |j| (2 * j + 3) * (2 * j + 1), den, bound)?;
            Ok((wn.clone() * sm, wn * sl, jm.max(jl)))
        }
        MomentMethod::BackwardPfaff => {
            if e2.clone().mul_i64(2) >= one {
                return Err(Error::domain(
                    "e^2 (cos^2 expansion of L_n, M_n)",
                    short(e2),
                    "e^2 < 1/2",
                ));
            }
            let t = -(e2.clone() / mc);
            let a = t.clone().abs();
            // |t| = |e²|/k² < 1 here; 1 − |t| = 1/k² for e² < 0, computed without cancellation.
            let rho = if e2.is_negative() {
                -(-(mc.clone().recip().to_f64())).ln_1p() / std::f64::consts::LN_2
            } else {
                -a.to_f64().log2()
            };
            check_top_terms(2f64.powf(-rho), bits)?;
            // Ratios t(2j+1)(2n+2j+1)/(4(j+1)(n+j+1)) ≤ |t| and
            // t(2j+3)(2n+2j+1)/(4(j+1)(n+j+1)) ≤ |t|(2j+3)/(2j+2) (decreasing in j).
            let (den, bound) = (|j: i64| 4 * (j + 1) * (ni + j + 1), |_: i64| a.clone());
            let (sm, jm) = hyper_sum(&t, |j| (2 * j + 1) * (2 * ni + 2 * j + 1), den, bound)?;
            let later = |j: i64| (a.clone().mul_i64(2 * j + 3)).div_i64(2 * j + 2);
            let (sl, jl) = hyper_sum(&t, |j| (2 * j + 3) * (2 * ni + 2 * j + 1), den, later)?;
            let k = mc.clone().sqrt();
            let m = wn.clone() * sm / &k;
            let l = wn * sl / (k * mc);
            Ok((m, l, jm.max(jl)))
        }
        MomentMethod::Forward => Err(Error::domain(
            "moment method (top values)",
            "forward".into(),
            "a backward method",
        )),
    }
}

/// The exact form of (40): L_n = α_n K + β_n E and M_n = γ_n K + δ_n E, the coefficient pairs
/// generated by the recursion (40) itself (one forward step, written once and applied to the K and the E parts
/// separately) from (42). Over `rug::Rational` with a rational k² the coefficients are exact
/// (their size grows about linearly in n); over [`crate::symbolic::RatFunc`] with k² = 1 − e² they
/// are exact rational functions of e²; over a floating type they are the dominant solutions of
/// (40) and accurate to a few ε·n relative.
#[derive(Clone, Debug)]
pub struct KeForm<F: FieldOps> {
    e2: F,
    step: ForwardStep<F>,
    /// (α, β) of L_{n−2}, L_{n−1} and (γ, δ) of M_{n−2}, M_{n−1}.
    l: [(F, F); 2],
    m: [(F, F); 2],
    n: usize,
}

/// The coefficients of one index: L_n = l.0·K + l.1·E, M_n = m.0·K + m.1·E.
#[derive(Clone, Debug, PartialEq)]
pub struct KeTerm<F> {
    /// n.
    pub n: usize,
    /// (α_n, β_n).
    pub l: (F, F),
    /// (γ_n, δ_n).
    pub m: (F, F),
}

impl<F: FieldOps> KeForm<F> {
    /// The generator for k² = `mc`; [`Error::Domain`] when e² = 1 − k² = 0 (the recursion divides
    /// by e²).
    /// The coefficients of L_n, M_n in K, E by (40) from (42) (A.8).
    pub fn new(mc: F) -> Result<Self> {
        let p = mc.prec();
        let e2 = F::one(p) - &mc;
        if e2.is_zero() {
            return Err(Error::domain(
                "e^2 (exact form of (40))",
                "0".into(),
                "e^2 != 0",
            ));
        }
        let inv_e2 = e2.clone().recip();
        let (z, o) = (F::zero(p), F::one(p));
        // L0 = E/k², L1 = (K − E)/e², M0 = K, M1 = (E − k²K)/e²  (42)
        let l = [
            (z.clone(), mc.clone().recip()),
            (inv_e2.clone(), -inv_e2.clone()),
        ];
        let m = [(o, z), (-(mc.clone() * &inv_e2), inv_e2)];
        Ok(KeForm {
            step: ForwardStep::new(mc),
            e2,
            l,
            m,
            n: 0,
        })
    }

    /// e² = 1 − k² of (41): exact over an exact field, one rounding otherwise.
    pub fn e2(&self) -> &F {
        &self.e2
    }

    /// The coefficients of index n = 0, 1, 2, … by (40) from (42); exact over an exact field.
    pub fn next_term(&mut self) -> KeTerm<F> {
        let n = self.n;
        self.n += 1;
        if n < 2 {
            return KeTerm {
                n,
                l: self.l[n].clone(),
                m: self.m[n].clone(),
            };
        }
        let [(m2a, m2b), (m1a, m1b)] = &self.m;
        let [(l2a, l2b), (l1a, l1b)] = &self.l;
        let (ma, la) = self.step.apply(n, [m1a, m2a], [l1a, l2a]);
        let (mb, lb) = self.step.apply(n, [m1b, m2b], [l1b, l2b]);
        self.m = [self.m[1].clone(), (ma.clone(), mb.clone())];
        self.l = [self.l[1].clone(), (la.clone(), lb.clone())];
        KeTerm {
            n,
            l: (la, lb),
            m: (ma, mb),
        }
    }
}

/// Bits lost by any evaluation of L_n, M_n in the K, E basis: log₂ of the condition numbers
/// (|α_n|K + |β_n|E)/L_n and (|γ_n|K + |δ_n|E)/M_n, for n = 0 … n_max, at k² = `mc` ≠ 1.
/// Computed at the working precision of `mc` (a 64-bit MPFR is plenty: the coefficients are
/// dominant solutions, computed forward with small relative error; the moments come from
/// [`moments`]).
///
/// Errors: as [`moments`] and [`KeForm::new`].
/// The conditioning of (40)–(42) in the K, E basis; to a few percent (an f64 log₂).
pub fn ke_condition_bits<T: Real>(mc: &T, n_max: usize) -> Result<Vec<(f64, f64)>> {
    let mom = moments(mc, n_max)?;
    let (k, e) = ellipke_mc(mc)?;
    let mut form = KeForm::new(mc.clone())?;
    let mut out = Vec::with_capacity(n_max + 1);
    for n in 0..=n_max {
        let t = form.next_term();
        let kl = (t.l.0.abs() * &k + t.l.1.abs() * &e) / &mom.l()[n];
        let km = (t.m.0.abs() * &k + t.m.1.abs() * &e) / &mom.m()[n];
        out.push((log2_of(&kl), log2_of(&km)));
    }
    Ok(out)
}

/// log₂ x for a positive value of any range (via MPFR when `x` leaves the `f64` range).
fn log2_of<T: Real>(x: &T) -> f64 {
    let f = x.to_f64();
    if f.is_finite() && f > 1e-300 {
        f.log2()
    } else {
        x.to_float(64).log2().to_f64()
    }
}

#[cfg(test)]
#[path = "../../tests/unit/moments.rs"]
mod tests;
