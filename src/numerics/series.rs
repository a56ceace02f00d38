//! The series driver: every series of the crate is a term generator summed by one function that
//! decides when to stop and reports how many terms it took.
//!
//! [`sum_series`] stops on the size of the terms (two consecutive terms below `rel_tol·|sum|`,
//! which protects against a single vanishing term), on stalled progress (the sum no longer
//! changes), or at the term cap ([`Error::TermCap`]). [`sum_series_with_tail`] stops on a tail
//! bound supplied by the caller. Sums are compensated (Knuth's TwoSum), so a long or
//! alternating series loses no more than a couple of roundings beyond the cancellation
//! inherent in it.

use super::sum::CompSum;
use crate::error::{Error, Result};
use crate::scalar::{short, Real};

/// The result of the series driver.
#[derive(Clone, Debug, PartialEq)]
pub struct SeriesSum<T> {
    /// The sum.
    pub sum: T,
    /// Number of terms added (terms `0 .. terms − 1`).
    pub terms: usize,
    /// Relative size of the last term, `|t_last| / |sum|` ([`sum_series`]), or the relative tail
    /// bound ([`sum_series_with_tail`]); `|t_last|` itself when the sum is zero.
    pub last_rel: T,
}

/// `|x| / |s|`, or `|x|` when `s = 0`.
fn rel<T: Real>(x: &T, s: &T) -> T {
    if s.is_zero() {
        x.clone().abs()
    } else {
        x.clone().abs() / &s.clone().abs()
    }
}

fn check_tol<T: Real>(rel_tol: &T) -> Result<()> {
    crate::scalar::check_finite("series tolerance", rel_tol)?;
    if rel_tol.is_negative() {
        return Err(Error::Domain {
            name: "series tolerance",
            value: crate::scalar::short(rel_tol),
            bound: "rel_tol >= 0",
        });
    }
    Ok(())
}

fn term_check<T: Real>(t: &T) -> Result<()> {
    crate::scalar::check_finite("series term", t)
}

/// Sums `gen(0) + gen(1) + …` at precision `p`.
///
/// Stops after term `k` when
/// * `|t_k| ≤ rel_tol·|sum|` and the same held for `t_{k−1}` (tolerance reached; two terms, so
///   that one vanishing term — an odd term of an even function, say — does not end the sum), or
/// * the compensated sum was unchanged by two consecutive nonzero terms (progress stalled: a
///   `rel_tol` below the precision is met as well as the precision allows), or
/// * `max_terms` terms were added without either: [`Error::TermCap`] with the relative size of
///   the last term and, when the last term ratios look geometric (ratio < 0.99 and steady), an
///   estimate of the number of terms needed.
///
/// Accuracy: the truncation error is about the first omitted term (for series whose terms
/// decrease at least geometrically; alternating series with decreasing terms are bounded by it);
/// rounding adds a couple of `ε·|sum|` plus `ε²·Σ|t_k|`. Work: at most `max_terms` calls of `gen`
/// and about ten operations per term.
///
/// Errors: [`Error::NotFinite`] for a non-finite term or tolerance, [`Error::Domain`] for a
/// negative tolerance, [`Error::TermCap`] at the cap.
pub fn sum_series<T: Real, G: FnMut(usize) -> T>(
    mut gen: G,
    p: T::Prec,
    rel_tol: &T,
    max_terms: usize,
) -> Result<SeriesSum<T>> {
    check_tol(rel_tol)?;
    let mut acc = CompSum::new(p);
    let mut total = T::zero(p);
    let (mut small_run, mut still_run) = (0, 0);
    let mut last_rel = T::one(p);
    // |t_{k−2}|, |t_{k−1}| and |t_k| in f64, for the estimate in the TermCap error.
    let mut mags = [f64::NAN; 3];
    for k in 0..max_terms {
        let t = gen(k);
        term_check(&t)?;
        let at = t.clone().abs();
        acc.add(t);
        let new_total = acc.total();
        let stalled = !at.is_zero() && new_total == total;
        total = new_total;
        last_rel = rel(&at, &total);
        small_run = if at <= rel_tol.clone() * &total.clone().abs() {
            small_run + 1
        } else {
            0
        };
        still_run = if stalled { still_run + 1 } else { 0 };
        if small_run >= 2 || still_run >= 2 {
            return Ok(SeriesSum {
                sum: total,
                terms: k + 1,
                last_rel,
            });
        }
        mags = [mags[1], mags[2], at.to_f64()];
    }
    Err(Error::TermCap {
        what: "series",
        cap: max_terms,
        needed: geometric_need(&mags, last_rel.to_f64(), rel_tol.to_f64(), max_terms),
        reached: short(&last_rel),
    })
}

/// Terms needed if the last three term magnitudes `m` decrease geometrically with a steady ratio
/// `ρ < 0.99`: `cap + ln(tol/last_rel)/ln ρ`. `None` otherwise (algebraic decay, for instance,
/// would be grossly underestimated by a geometric model).
fn geometric_need(m: &[f64; 3], last_rel: f64, tol: f64, cap: usize) -> Option<u64> {
    let (r1, r2) = (m[1] / m[0], m[2] / m[1]);
    let steady = r2.is_finite() && r1.is_finite() && (r2 - r1).abs() <= (1.0 - r2) / 10.0;
    if !(steady && r2 > 0.0 && r2 < 0.99 && last_rel > tol && tol > 0.0) {
        return None;
    }
    let more = (tol / last_rel).ln() / r2.ln();
    (more.is_finite() && more < 1e18).then(|| cap as u64 + more.ceil() as u64)
}

/// Sums `gen(0) + gen(1) + …` at precision `p`, stopping as soon as the caller's tail bound
/// `tail(k, &t_k, &sum_k)` — an upper bound on `|Σ_{j>k} t_j|`, e.g. `|t_k|·ρ/(1−ρ)` for terms
/// known to shrink at least geometrically by `ρ` — is at most `rel_tol·|sum_k|`.
///
/// Also stops when the sum is unchanged by two consecutive nonzero terms (the precision is
/// exhausted) and fails with [`Error::TermCap`] after `max_terms` terms. `last_rel` in the result
/// is the final relative tail bound.
///
/// Accuracy: truncation error at most the tail bound (if the bound is valid) plus a couple of
/// `ε·|sum|`. Work: at most `max_terms` calls of `gen` and of `tail`.
///
/// Errors: as [`sum_series`]; also [`Error::NotFinite`] for a non-finite tail bound.
pub fn sum_series_with_tail<T, G, B>(
    mut gen: G,
    mut tail: B,
    p: T::Prec,
    rel_tol: &T,
    max_terms: usize,
) -> Result<SeriesSum<T>>
where
    T: Real,
    G: FnMut(usize) -> T,
    B: FnMut(usize, &T, &T) -> T,
{
    check_tol(rel_tol)?;
    let mut acc = CompSum::new(p);
    let mut total = T::zero(p);
    let mut still_run = 0;
    let mut last_rel = T::one(p);
    for k in 0..max_terms {
        let t = gen(k);
        term_check(&t)?;
        let nonzero = !t.is_zero();
        acc.add(t.clone());
        let new_total = acc.total();
        still_run = if nonzero && new_total == total {
            still_run + 1
        } else {
            0
        };
        total = new_total;
        let bound = tail(k, &t, &total);
        crate::scalar::check_finite("series tail bound", &bound)?;
        last_rel = rel(&bound, &total);
        if bound.abs() <= rel_tol.clone() * &total.clone().abs() || still_run >= 2 {
            return Ok(SeriesSum {
                sum: total,
                terms: k + 1,
                last_rel,
            });
        }
    }
    Err(Error::TermCap {
        what: "series (tail bound)",
        cap: max_terms,
        needed: None,
        reached: short(&last_rel),
    })
}
