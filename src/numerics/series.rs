//! The series driver: every series of the crate is a term generator summed by one function that
//! decides when to stop and reports how many terms it took.
//!
//! [`sum_series_with_tail`] stops on a tail bound supplied by the caller, on stalled progress
//! (the sum no longer changes), or at the term cap ([`Error::TermCap`]). Sums are compensated (Knuth's TwoSum), so a long or
//! alternating series loses no more than a couple of roundings beyond the cancellation
//! inherent in it.

use super::sum::CompSum;
use crate::error::{Error, Result};
use crate::scalar::{check_finite, short, Real};

/// The result of the series driver.
#[derive(Clone, Debug, PartialEq)]
pub struct SeriesSum<T> {
    /// The sum.
    pub sum: T,
    /// Number of terms added (terms `0 .. terms − 1`).
    pub terms: usize,
    /// The relative tail bound, `bound / |sum|`; the bound itself when the sum is zero.
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
/// Errors: [`Error::NotFinite`] for a non-finite term, tail bound or tolerance,
/// [`Error::Domain`] for a negative tolerance, [`Error::TermCap`] at the cap.
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
    check_finite("series tolerance", rel_tol)?;
    if rel_tol.is_negative() {
        let value = short(rel_tol);
        return Err(Error::domain("series tolerance", value, "rel_tol >= 0"));
    }
    let mut acc = CompSum::new(p);
    let mut total = T::zero(p);
    let mut still_run = 0;
    let mut last_rel = T::one(p);
    for k in 0..max_terms {
        let t = gen(k);
        check_finite("series term", &t)?;
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
        check_finite("series tail bound", &bound)?;
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

#[cfg(test)]
#[path = "../../tests/unit/series.rs"]
mod tests;
