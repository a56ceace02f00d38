//! Tanh–sinh (double-exponential) quadrature at the working precision: an independent method
//! for the references of the tests (endpoint singularities, complete elliptic integrals, the
//! moments' defining integrals), next to the crate's adaptive Gauss–Legendre.

use moving_hertz::numerics::quadrature::{check_rule_bits, Quadrature};
use moving_hertz::scalar::{short, Real};
use moving_hertz::{Error, Result};
use std::any::{Any, TypeId};
use std::cmp::Ordering;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// A running sum `s + c` where `c` collects the rounding errors of the additions (TwoSum).
struct CompSum<T: Real> {
    s: T,
    c: T,
}

impl<T: Real> CompSum<T> {
    fn new(p: T::Prec) -> Self {
        CompSum {
            s: T::zero(p),
            c: T::zero(p),
        }
    }

    fn add(&mut self, x: T) {
        let t = self.s.clone() + &x;
        let bb = t.clone() - &self.s;
        let s = std::mem::replace(&mut self.s, t);
        let e = (s - &(self.s.clone() - &bb)) + &(x - bb);
        self.c += e;
    }

    fn total(&self) -> T {
        self.s.clone() + &self.c
    }
}

/// Work bounds of [`tanh_sinh`].
#[derive(Clone, Copy, Debug)]
pub struct DeLimits {
    /// Cap on evaluations of the integrand over all sub-intervals.
    pub max_evals: usize,
    /// Cap on levels (step `h = 2^-level`), at most 20.
    pub max_levels: u32,
}

impl Default for DeLimits {
    /// 500 000 evaluations, 12 levels.
    fn default() -> Self {
        DeLimits {
            max_evals: 500_000,
            max_levels: 12,
        }
    }
}

type Cache = Mutex<HashMap<(TypeId, u32, u32), Arc<dyn Any + Send + Sync>>>;

/// The level's table at precision `p`, built once per (type, level, bits).
fn cached<T: Real>(level: u32, p: T::Prec) -> Arc<DeLevel<T>> {
    static CACHE: OnceLock<Cache> = OnceLock::new();
    let key = (TypeId::of::<T>(), level, T::bits(p));
    let cache = CACHE.get_or_init(Default::default);
    if let Some(t) = cache.lock().unwrap().get(&key) {
        return t.clone().downcast::<DeLevel<T>>().unwrap();
    }
    let table = Arc::new(DeLevel::<T>::compute(level, p));
    cache.lock().unwrap().insert(key, table.clone());
    table
}

/// The increasing sub-intervals of `points`, and whether the points decrease (the integral then
/// changes sign); [`Error::Domain`] unless the points are finite, strictly monotone and at least
/// two, and `tol` finite and nonnegative.
fn setup<T: Real>(points: &[T], tol: &T) -> Result<(Vec<(T, T)>, bool)> {
    let n = points.len();
    let reversed = n >= 2 && points[0] > points[n - 1];
    let monotone = points
        .windows(2)
        .all(|w| w[0] != w[1] && (w[0] < w[1]) != reversed);
    let finite = points.iter().all(|x| x.is_finite()) && tol.is_finite();
    if n < 2 || !monotone || !finite || tol.is_negative() {
        return Err(Error::Domain {
            name: "tanh-sinh breakpoints and tolerance",
            value: format!("{n} point(s), tol {}", short(tol)),
            bound: "at least two finite, strictly monotone points; 0 <= tol < inf",
        });
    }
    let mut ends = points.to_vec();
    if reversed {
        ends.reverse();
    }
    let iv = ends.windows(2).map(|w| (w[0].clone(), w[1].clone()));
    Ok((iv.collect(), reversed))
}

fn not_finite<T: Real>(v: &T) -> Error {
    Error::NotFinite {
        name: "integrand",
        value: short(v),
    }
}

/// `err / |value|` for reports (or `err` itself when the value is zero).
fn relative<T: Real>(err: &T, value: &T) -> String {
    if value.is_zero() {
        short(err)
    } else {
        short(&(err.clone() / &value.clone().abs()))
    }
}

/// The new abscissae of one tanh–sinh level on the reference interval [−1, 1], for `t ≥ 0`:
/// level 0 holds `t = 0, 1, 2, …`, level `k ≥ 1` holds `t = (2j−1)/2^k`.
///
/// With `u = (π/2) sinh t` and `q = e^(−2u) = exp(−π sinh t)`, the point is `x = tanh u`, its
/// distance to the endpoint is `1 − tanh u = 2q/(1+q)` (stored as `gap`, accurate to a few ulps
/// however small), and the weight is `dx/dt = (π/2) cosh t / cosh² u = 2π cosh t · q/(1+q)²`.
/// The table stops when the gap drops below `max(ε^12, min_positive/ε)`.
#[derive(Debug)]
struct DeLevel<T: Real> {
    gap: Vec<T>,
    weight: Vec<T>,
}

/// Largest tanh–sinh level accepted.
const MAX_DE_LEVEL: u32 = 20;

impl<T: Real> DeLevel<T> {
    /// Estimated table length, for checking the evaluation cap before building.
    fn estimated_len(level: u32, p: T::Prec) -> usize {
        let tmax = (12.0 * T::bits(p) as f64 * std::f64::consts::LN_2 / std::f64::consts::PI)
            .asinh()
            + 1.0;
        (tmax * 2f64.powi(level.max(1) as i32 - 1)) as usize + 2
    }

    fn get(level: u32, p: T::Prec) -> Result<Arc<Self>> {
        check_rule_bits(T::bits(p))?;
        Ok(cached::<T>(level, p))
    }

    fn compute(level: u32, p: T::Prec) -> Self {
        let eps = T::epsilon(p);
        let floor = eps.powi(12).max_of(T::min_positive(p) / &eps);
        let one = T::one(p);
        let pi = T::pi(p);
        let (mut gap, mut weight) = (Vec::new(), Vec::new());
        // The gap falls below any floor long before t = 40 (exp(−π sinh 40) ≈ 2^(−5·10^17));
        // the bound only makes the loop's end explicit.
        for j in 0..(40i64 << level) {
            let t = if level == 0 {
                T::from_i64(j, p)
            } else {
                T::from_ratio(2 * j + 1, 1i64 << level, p)
            };
            // e^t = 1 + m; sinh t = (m + m/e^t)/2 and cosh t = (e^t + 1/e^t)/2, both without
            // cancellation for t ≥ 0.
            let m = t.exp_m1();
            let et = m.clone() + &one;
            let sinh = (m.clone() + &(m / &et)).mul_pow2(-1);
            let cosh = (et.clone() + &(one.clone() / &et)).mul_pow2(-1);
            let q = (-(pi.clone() * &sinh)).exp();
            let opq = one.clone() + &q;
            let g = q.clone().mul_pow2(1) / &opq;
            // Below the floor, or NaN: the table ends.
            if !matches!(
                g.partial_cmp(&floor),
                Some(Ordering::Greater | Ordering::Equal)
            ) {
                break;
            }
            let w = (pi.clone() * &cosh * &q).mul_pow2(1) / &opq.square();
            gap.push(g);
            weight.push(w);
        }
        DeLevel { gap, weight }
    }
}

/// Tanh–sinh on one interval `[a, b]` (`a < b`). Returns (value, error estimate).
fn de_interval<T: Real, F: FnMut(&T, &T, &T) -> T>(
    f: &mut F,
    a: &T,
    b: &T,
    tol: &T,
    limits: DeLimits,
    evals: &mut usize,
    uses_gaps: bool,
) -> Result<(T, T)> {
    let p = a.prec();
    let eps = T::epsilon(p);
    let mut sweep = DeSweep::new(a, b, uses_gaps);
    let max_level = limits.max_levels.min(MAX_DE_LEVEL);
    // The last non-negligible term where the table or the representable range ran out, per
    // level (a bound on what was cut off); kept as h_k·|w f|.
    let mut tail = T::zero(p);
    // Like `tail`, for sides stopped where the abscissa rounds onto the endpoint: the sliver
    // within an ulp of it, part of the rounding floor (no level can recover it).
    let mut edge = T::zero(p);
    let mut last_est: Option<T> = None;
    let mut prev: Option<T> = None; // S_{k−1}
    let mut d_prev: Option<T> = None; // |S_{k−1} − S_{k−2}|
    let mut l1_prev = T::zero(p);
    for k in 0..=max_level {
        let need = 2 * DeLevel::<T>::estimated_len(k, p);
        if *evals + need > limits.max_evals {
            let s = prev.clone().unwrap_or_else(|| T::zero(p));
            return Err(Error::NoConvergence {
                what: "tanh-sinh quadrature (evaluation cap)",
                iterations: *evals,
                reached: relative(&last_est.unwrap_or_else(|| s.clone().abs()), &s),
            });
        }
        let table = DeLevel::<T>::get(k, p)?;
        // A term is negligible once h_k |w f| ≤ ε·L1/64 (L1 of the previous level, ≥ |S|);
        // beyond two such terms the rest decay double-exponentially (by a factor of at least
        // e^(−π h cosh t / 2) per step, ≈ 0.2 at h = 2^-10, t = 7), so each level leaves out
        // well under ε·L1/64.
        let negl = (l1_prev.clone() * &eps).mul_pow2(-6);
        let (level_tail, level_edge) = sweep.level(f, &table, k, &negl, evals)?;
        // Whatever was still non-negligible when the table or the range ran out.
        tail = tail.max_of(level_tail.mul_pow2(-(k as i32)));
        edge = edge.max_of(level_edge.mul_pow2(-(k as i32)));
        let s = sweep.raw.total().mul_pow2(-(k as i32));
        let l1 = sweep.raw_abs.clone().mul_pow2(-(k as i32));
        let floor = l1.clone().mul_i64(2) * &eps + &edge;
        if let Some(sp) = prev.replace(s.clone()) {
            let d = (s.clone() - &sp).abs();
            let trunc = de_truncation(&d, d_prev.as_ref(), k);
            let est = trunc.clone().max_of(floor.clone()) + &tail;
            if k >= 3 {
                // Converged: the estimate meets the tolerance, or nothing is left to gain
                // above the rounding floor.
                let converged =
                    est <= tol.clone() * &s.clone().abs() || trunc.clone() + &tail <= floor;
                // Stalled: the differences stopped shrinking at a level that can only be the
                // integrand's own noise (below √ε·L1); larger ones are pre-asymptotic (a peak
                // not yet resolved) and the next level is taken.
                let noise = l1.clone() * &T::epsilon_root(p, 2);
                let stalled = d_prev.as_ref().is_some_and(|dp| d >= *dp) && d <= noise;
                if converged || stalled {
                    return Ok((s, est));
                }
            }
            d_prev = Some(d);
            last_est = Some(est);
        }
        l1_prev = l1;
    }
    let s = prev.unwrap_or_else(|| T::zero(p));
    Err(Error::NoConvergence {
        what: "tanh-sinh quadrature (level cap)",
        iterations: *evals,
        reached: relative(&last_est.unwrap_or_else(|| s.clone().abs()), &s),
    })
}

/// Truncation estimate for S_k from d_k = |S_k − S_{k−1}| (≈ the error of S_{k−1}) and the
/// ratio ρ = d_k/d_{k−1}: in the double-exponential regime (ρ ≤ 1/4) the error of S_k is
/// ≈ d_k²/d_{k−1}; d_k·√ρ is well above that. Slower, geometric convergence leaves
/// d_k·ρ/(1−ρ); no convergence (ρ ≥ 1) leaves d_k.
fn de_truncation<T: Real>(d: &T, d_prev: Option<&T>, k: u32) -> T {
    match d_prev {
        Some(dp) if k >= 2 && d < dp && dp.is_positive() => {
            let p = d.prec();
            let rho = d.clone() / dp;
            if rho <= T::from_ratio(1, 4, p) {
                d.clone() * &rho.sqrt()
            } else {
                let geo = rho.clone() / &(T::one(p) - &rho);
                d.clone() * &geo.max_of(T::one(p))
            }
        }
        _ => d.clone(),
    }
}

/// The running raw sums of [`de_interval`] over every abscissa so far, level by level:
/// S_k = h_k · Σ w f (`raw`) and L1_k = h_k · Σ |w f| (`raw_abs`), both before the factor h_k.
struct DeSweep<'a, T: Real> {
    a: &'a T,
    b: &'a T,
    /// Half the interval's width.
    r: T,
    width: T,
    uses_gaps: bool,
    raw: CompSum<T>,
    raw_abs: T,
}

impl<'a, T: Real> DeSweep<'a, T> {
    fn new(a: &'a T, b: &'a T, uses_gaps: bool) -> Self {
        let p = a.prec();
        let width = b.clone() - a;
        DeSweep {
            a,
            b,
            r: width.clone().mul_pow2(-1),
            width,
            uses_gaps,
            raw: CompSum::new(p),
            raw_abs: T::zero(p),
        }
    }

    /// Adds level `k`'s new abscissas (both sides, the midpoint at level 0) until two terms in
    /// a row are below `negl` (scaled to the level) or both sides close. Returns the level's
    /// cut-off term where its table ran out and its end-point sliver (before the factor h_k).
    fn level<F: FnMut(&T, &T, &T) -> T>(
        &mut self,
        f: &mut F,
        table: &DeLevel<T>,
        k: u32,
        negl: &T,
        evals: &mut usize,
    ) -> Result<(T, T)> {
        let p = self.a.prec();
        let mut quiet = 0;
        // Per side (right, left): still inside the representable range, and |f| at the side's
        // last abscissa (if the side closes, the first omitted weight times it estimates what
        // is left out: the sliver within an ulp of the endpoint).
        let mut open = [true, true];
        let mut last = [T::zero(p), T::zero(p)];
        let (mut level_tail, mut level_edge) = (T::zero(p), T::zero(p));
        for (i, (g, wh)) in table.gap.iter().zip(&table.weight).enumerate() {
            let delta = self.r.clone() * g;
            let w = self.r.clone() * wh;
            let (term, size) = if k == 0 && i == 0 {
                // t = 0: the midpoint, counted once.
                let x = self.a.clone() + &self.r;
                let v = checked(f(&x, &self.r, &self.r), evals)?;
                let term = v * &w;
                (term.clone(), term.abs())
            } else {
                let (mut term, mut size) = (T::zero(p), T::zero(p));
                for side in 0..2 {
                    if !open[side] {
                        continue;
                    }
                    match self.side(f, side, &delta, evals)? {
                        Some(v) => {
                            last[side] = v.clone().abs();
                            let wv = v * &w;
                            size += &wv.clone().abs();
                            term += &wv;
                        }
                        None => {
                            open[side] = false;
                            level_edge = level_edge.max_of(w.clone() * &last[side]);
                        }
                    }
                }
                (term, size)
            };
            self.raw.add(term);
            self.raw_abs += &size;
            if size.clone().mul_pow2(-(k as i32)) <= *negl {
                quiet += 1;
                if quiet >= 2 {
                    break;
                }
            } else {
                quiet = 0;
            }
            if i + 1 == table.gap.len() {
                // The table ran out while terms were still not negligible.
                level_tail = level_tail.max_of(size);
            }
            if !open[0] && !open[1] {
                break;
            }
        }
        Ok((level_tail, level_edge))
    }

    /// `f` at the abscissa `delta` inside the right (`side` 0) or left (1) end, or `None`
    /// where the abscissa rounds onto the endpoint and `f` sees only `x` (with the gaps, `f`
    /// still resolves the distance).
    fn side<F: FnMut(&T, &T, &T) -> T>(
        &self,
        f: &mut F,
        side: usize,
        delta: &T,
        evals: &mut usize,
    ) -> Result<Option<T>> {
        let co = self.width.clone() - delta; // distance to the far endpoint
        let x = if side == 0 {
            self.b.clone() - delta
        } else {
            self.a.clone() + delta
        };
        if !self.uses_gaps && (x == *self.a || x == *self.b) {
            return Ok(None);
        }
        let v = if side == 0 {
            f(&x, &co, delta)
        } else {
            f(&x, delta, &co)
        };
        checked(v, evals).map(Some)
    }
}

/// One integrand value, counted, refused when not finite.
fn checked<T: Real>(v: T, evals: &mut usize) -> Result<T> {
    *evals += 1;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(not_finite(&v))
    }
}

/// Tanh–sinh (double-exponential) quadrature of `f` over the breakpoints `points` (strictly
/// monotone), where `f(x, x − a, b − x)` also receives the distances from `x` to the ends of its
/// sub-interval `[a, b]`, accurate to a few ulps even where `x` itself cannot resolve them (use
/// them for singular factors such as `ln(x − a)` or `(b − x)^(−1/2)` when `a ≠ 0` or `b ≠ 0`).
/// The working precision is `tol`'s; `points` must share it.
///
/// Each sub-interval is integrated on its own, level by level (`h = 2^-k`, every level reusing
/// the previous abscissae; abscissae with `h·|w f| ≤ ε·L1/64` end a level's sweep outwards).
/// With `d_k = |S_k − S_{k−1}|` and `ρ = d_k/d_{k−1}`, the truncation estimate of `S_k` is
/// `d_k·√ρ` when `ρ ≤ 1/4` (the double-exponential regime, where the error is ≈ `d_k²/d_{k−1}`,
/// far below it), `d_k·max(1, ρ/(1−ρ))` for slower convergence, `d_k` otherwise. The reported
/// error is `max(truncation, floor) + tail`, with the rounding floor `2ε·L1` (`L1 = h Σ|w f|`)
/// plus the sliver within an ulp of an endpoint that `x` cannot resolve, and `tail` whatever was
/// still non-negligible where the abscissa tables end (gap `ε^12`: singularities stronger than
/// `x^(−11/12)`). A sub-interval stops from level 3 on when the estimate meets `tol·|S|`, when
/// truncation and tail are below the floor, or when the differences stop shrinking below
/// `√ε·L1` (the integrand's own noise, which the estimate then reports).
///
/// Accuracy: for `f` analytic inside the interval with integrable algebraic or logarithmic
/// endpoint behaviour, a few `ε` at every precision (measured ≤ 2.2ε, and the reported error
/// always above the true one, for `ln x`, `√x`, `ln(x−1)/√(2−x)`, complete elliptic integrals and
/// a peak at a breakpoint, `f64` to 1024 bits). The tolerance applies per sub-interval, so the
/// total is accurate relative to `Σ|I_j|`.
/// Work: about `2^(k+1)·t_max` evaluations per sub-interval at the final level `k` (`t_max ≈ 4`
/// at `f64` to `≈ 6` at 1024 bits; k ≈ 3–4 at `f64`, 7–10 at 1024 bits), capped by
/// `limits.max_evals` and `limits.max_levels`; each new (level, precision) builds a cached table
/// at two exponentials per abscissa.
///
/// Errors: as the adaptive Gauss–Legendre `integrate`; [`Error::NoConvergence`] when a level or evaluation cap is hit.
pub fn tanh_sinh_gaps<T: Real, F: FnMut(&T, &T, &T) -> T>(
    f: F,
    points: &[T],
    tol: &T,
    limits: DeLimits,
) -> Result<Quadrature<T>> {
    de_driver(f, points, tol, limits, true)
}

/// Tanh–sinh quadrature of `f(x)` over the breakpoints `points`: [`tanh_sinh_gaps`] for
/// integrands that need only `x` (accuracy, work and errors as there). Abscissae that round onto
/// an endpoint are skipped, so a singularity at an endpoint other than 0 limits the accuracy to
/// about `ε·|endpoint|·|f|` there (the error estimate includes it); use [`tanh_sinh_gaps`] then.
pub fn tanh_sinh<T: Real, F: FnMut(&T) -> T>(
    mut f: F,
    points: &[T],
    tol: &T,
    limits: DeLimits,
) -> Result<Quadrature<T>> {
    de_driver(|x: &T, _: &T, _: &T| f(x), points, tol, limits, false)
}

fn de_driver<T: Real, F: FnMut(&T, &T, &T) -> T>(
    mut f: F,
    points: &[T],
    tol: &T,
    limits: DeLimits,
    uses_gaps: bool,
) -> Result<Quadrature<T>> {
    let (iv, reversed) = setup(points, tol)?;
    let p = tol.prec();
    let mut evals = 0;
    let (mut value, mut error) = (CompSum::new(p), T::zero(p));
    for (a, b) in iv {
        let (v, e) = de_interval(&mut f, &a, &b, tol, limits, &mut evals, uses_gaps)?;
        value.add(v);
        error += &e;
    }
    let value = value.total();
    Ok(Quadrature {
        value: if reversed { -value } else { value },
        error,
        evaluations: evals,
    })
}
