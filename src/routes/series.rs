//! The series route of section 5: I1 = 2 Σ f_n D_n and I2 = 2 Σ f_n L_{n+1} by (37), with f_n
//! the coefficients of g = −πΓ (35)–(36) ([`SpeedCoefficients`]) and the moments of
//! [`super::moments`]. `docs/series.md` derives the tail bound that stops the sums (every term
//! positive; default tolerance ε/4 of the working precision times the partial sums) and
//! measures the terms needed; beyond the cap ([`SeriesOptions::max_terms`], default 10⁵) the
//! route returns [`Error::TermCap`] with the estimate instead of working for minutes.
//! Everything runs at the working precision plus the guard bits of the moment [`plan`], then
//! rounds once: within about ε plus the tail bound (`tests/series_route.rs`: ≤ 2 ε measured).

use super::coefficients::SpeedCoefficients;
use super::guard::{run_guarded, GuardedJob};
use super::moments::{plan, table_at, MAX_INDEX};
use super::{AxisRatio, Evaluation, Route};
use crate::error::{Error, Result};
use crate::estimate::RelError;
use crate::numerics::series::sum_series_with_tail;
use crate::physics::Speed;
use crate::scalar::{short, Real};

/// Default cap on the number of series terms.
pub const DEFAULT_MAX_TERMS: usize = 100_000;

/// Options of the series route.
#[derive(Clone, Debug)]
pub struct SeriesOptions<T> {
    /// Relative tolerance on the truncation of each sum; `None`: ε/4 of the working precision.
    /// Values below ε/8 are raised to ε/8 (rounding dominates there).
    pub rel_tol: Option<T>,
    /// Cap on the number of terms (≤ 10⁶).
    pub max_terms: usize,
}

impl<T> Default for SeriesOptions<T> {
    fn default() -> Self {
        SeriesOptions {
            rel_tol: None,
            max_terms: DEFAULT_MAX_TERMS,
        }
    }
}

/// Terms the series needs for relative tolerance `tol` at M_R² = `q` (an over-estimate: it
/// assumes D_n, L_{n+1} do not decrease and h_n = h_0). 1 at q = 0.
/// Terms of (37); an over-estimate, not a bound on accuracy.
pub fn terms_estimate(q: f64, tol: f64) -> u64 {
    terms_for_ln_tol(q, tol.ln())
}

/// [`terms_estimate`] from ln(tol), so that a tolerance below the `f64` range (a working
/// precision above about 1000 bits) gives its true count instead of overflowing.
fn terms_for_ln_tol(q: f64, ln_tol: f64) -> u64 {
    if q <= 0.0 {
        return 1;
    }
    let n = (ln_tol + (2.0 * (1.0 - q) / q).ln()) / q.ln();
    if n.is_finite() && n > 0.0 {
        (n.ceil() as u64).saturating_add(2)
    } else if n.is_finite() {
        2
    } else {
        u64::MAX
    }
}

/// I1 and I2 by the series (37) for the material `mat`, speed `speed` and axis ratio `axis`,
/// with truncation and precision control as in the module docs.
///
/// Accuracy: relative error ≤ the returned `error_estimate` = tail bound + ε (measured ≤ 2 ε at
/// f64, double-double, 128 and 256 bits for M_R ≤ 0.9 and k from 0.01 to 100).
/// Work: `work` = the number of terms n + 1, each about 60 operations at the guarded precision;
/// one cel and one Rayleigh root.
///
/// Errors: [`Error::TermCap`] (with the estimated number of terms needed) when the terms needed
/// exceed `opts.max_terms`; [`Error::Domain`] for a cap above 10⁶ or a negative tolerance;
/// errors of the moments and the Rayleigh roots.
pub fn integrals<T: Real>(
    speed: &Speed<T>,
    axis: &AxisRatio<T>,
    opts: &SeriesOptions<T>,
) -> Result<Evaluation<T>> {
    let p = axis.k.prec();
    let eps = T::epsilon(p);
    let tol = match &opts.rel_tol {
        Some(t) => {
            crate::scalar::check_finite("series tolerance", t)?;
            if t.is_negative() {
                return Err(Error::domain("series tolerance", short(t), "rel_tol >= 0"));
            }
            t.clone().max_of(eps.clone().div_i64(8))
        }
        None => eps.clone().div_i64(4),
    };
    if opts.max_terms > MAX_INDEX || opts.max_terms == 0 {
        return Err(Error::domain(
            "max_terms (series route)",
            opts.max_terms.to_string(),
            "1 <= max_terms <= 1000000",
        ));
    }
    let q = speed.mr2().to_f64();
    let est = terms_for_ln_tol(q, RelError::of(&tol).log2() * std::f64::consts::LN_2);
    let cap = opts.max_terms;
    if est > (cap as u64).saturating_mul(3) / 2 {
        return Err(Error::TermCap {
            what: "series (37) for I1, I2",
            cap,
            needed: Some(est),
            reached: format!("{:.1e}", q.powf(cap as f64) / (1.0 - q)),
        });
    }
    let mut n_max = (est as usize).clamp(2, cap);
    loop {
        let pl = plan(axis.k2.to_f64(), n_max, T::bits(p));
        let out = run_guarded(
            p,
            pl.guard_bits,
            SeriesJob {
                speed,
                axis,
                tol: &tol,
                n_max,
                method: pl.method,
            },
        )?;
        match out {
            Some(r) => return Ok(r),
            None if n_max >= cap => {
                return Err(Error::TermCap {
                    what: "series (37) for I1, I2",
                    cap,
                    needed: Some(est.max(cap as u64 + 1)),
                    reached: "tail bound above tolerance".into(),
                })
            }
            None => n_max = (2 * n_max).min(cap),
        }
    }
}

struct SeriesJob<'a, T: Real> {
    speed: &'a Speed<T>,
    axis: &'a AxisRatio<T>,
    tol: &'a T,
    n_max: usize,
    method: super::moments::MomentMethod,
}

impl<T: Real> GuardedJob<T> for SeriesJob<'_, T> {
    /// `None` when the table to `n_max` was too short for the tolerance.
    type Output = Option<Evaluation<T>>;

    fn run<W: Real>(
        self,
        pw: W::Prec,
        up: &dyn Fn(&T) -> W,
        down: &dyn Fn(&W) -> T,
    ) -> Result<Option<Evaluation<T>>> {
        let n = self.n_max;
        let one = W::one(pw);
        // The material at the guarded precision: its Rayleigh root m1 and H = πG(1), the limit
        // of h_n.
        let mat = self.speed.material().at::<W>(pw)?;
        let nu = mat.nu().clone();
        // M_R as the complement of the speed's gap, the input's own representation near the
        // Rayleigh speed (the M_R the fast and graded routes see through 1 − M_R²).
        let gap = up(self.speed.gap());
        let mr = one.clone() - &gap;
        let k = up(&self.axis.k);
        let mc = k.square();
        let m1 = mat.m1().clone();
        let mr2 = mr.square();
        let one_minus_mr2 = gap * (one.clone() + &mr);
        let h_lim = mat.pi_g_rayleigh().clone();
        let tab = table_at(&mc, n + 1, self.method)?;
        // Binomial terms below ε·2⁻³⁰ (of the guarded precision) cannot change h_n ≥ H ≈ 0.2.
        let tiny = W::epsilon(pw).mul_pow2(-30);
        let mut coef = SpeedCoefficients::new(&nu, m1, mr2.clone()).flush_below(tiny);
        let mut f = Vec::with_capacity(n + 1);
        let mut ratio = Vec::with_capacity(n + 1);
        // Tail factor after term j: (max(h_j, H)/h_j)·M_R²/(1 − M_R²).
        let geo = mr2 / &one_minus_mr2;
        for _ in 0..=n {
            let (h, fj) = coef.next_pair();
            // h_n ≥ H > 0 (h decreases to H): the factor is 1; otherwise H/|h_n|.
            ratio.push(if h >= h_lim {
                geo.clone()
            } else if h.is_zero() {
                h_lim.clone().abs() * &geo
            } else {
                h_lim.clone().abs() / h.abs() * &geo
            });
            f.push(fj);
        }
        let d: Vec<W> = (0..=n).map(|j| tab.d(j, &mc)).collect();
        let tol = up(self.tol);
        let sum = |terms: Vec<W>| {
            sum_series_with_tail(
                |j| terms[j].clone(),
                |j, t, _| t.clone().abs() * &ratio[j],
                pw,
                &tol,
                n + 1,
            )
        };
        let s1 = sum((0..=n).map(|j| f[j].clone() * &d[j]).collect());
        let s2 = sum((0..=n).map(|j| f[j].clone() * &tab.l[j + 1]).collect());
        let (s1, s2) = match (s1, s2) {
            (Ok(a), Ok(b)) => (a, b),
            (Err(Error::TermCap { .. }), _) | (_, Err(Error::TermCap { .. })) => return Ok(None),
            (Err(e), _) | (_, Err(e)) => return Err(e),
        };
        if s1.last_rel > tol || s2.last_rel > tol {
            return Ok(None);
        }
        let eps = T::epsilon(self.axis.k.prec());
        let tail = s1.last_rel.max_of(s2.last_rel);
        Ok(Some(Evaluation::pair(
            down(&s1.sum.mul_i64(2)),
            down(&s2.sum.mul_i64(2)),
            down(&tail) + eps,
            Route::Series,
            s1.terms.max(s2.terms),
        )))
    }
}
