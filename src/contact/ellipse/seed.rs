//! Stage 2: the start — the static Hertz ellipse in closed form, or a neighbour's root (a
//! sweep's extrapolated guess, or the caller's seed) — and the k = 1 probe that tells on which
//! side of k = 1 an unseeded root lies.

use super::ladder::secant_partner;
use super::newton::{solve_core, Handed, Newton, Stage};
use super::{shape_residual, shape_slope};
use crate::error::Result;
use crate::routes::evaluate::Evaluator;
use crate::routes::AxisRatio;
use crate::scalar::Real;
use std::sync::OnceLock;

/// The static Hertz ellipse: Hamrock & Brewe's k ≈ (A1/B1)^(2/π) below A1/B1 = 30 (within a
/// few per cent of the static root down to 10⁻⁶), the k ≫ 1 form ([`static_seed_wide`]) from
/// 30 on; the speed lowers k further, which Newton follows.
#[inline]
pub(super) fn static_seed(ratio: f64) -> f64 {
    if !(ratio.is_finite() && ratio > 0.0) {
        return 1.0;
    }
    if ratio >= ASYMPTOTIC_SEED_RATIO {
        return static_seed_wide(ratio);
    }
    let k = ratio.powf(std::f64::consts::FRAC_2_PI);
    if k.is_finite() && k > 0.0 {
        k
    } else {
        1.0
    }
}

/// From this ratio on the static seed is the k ≫ 1 form (`docs/calibration.md`).
pub(super) const ASYMPTOTIC_SEED_RATIO: f64 = 30.0;

/// The static root for A1/B1 ≥ 30 from (33)'s k ≫ 1 form at rest, A1/B1 = k²/(ln 4k − 1)
/// (I2 ≈ 2g/k, I1 ≈ (2g/k³)(ln 4k − 1)), by four contracting fixed-point steps
/// k ← √(A1/B1·(ln 4k − 1)): within 1.5 % of the static root at 30, 0.01 % at 10⁶.
pub(super) fn static_seed_wide(ratio: f64) -> f64 {
    let mut k = ratio.sqrt();
    for _ in 0..4 {
        k = (ratio * ((4.0 * k).ln() - 1.0)).sqrt();
    }
    k
}

/// The evaluations a stage started from a neighbour's root may spend before it starts again
/// from the static ellipse (a converging start needs 1–3).
pub(super) const GUESS_EVALUATIONS: usize = 8;

/// The ladder's lowest stage (chord steps at its end as `allow_chord` says) from `guess` when
/// it converges within [`GUESS_EVALUATIONS`], else from the static ellipse. A guessed stage
/// that hands on derivatives without an earlier iterate gets a secant partner.
#[inline]
pub(super) fn lowest_stage<S: Real>(
    ev: &Evaluator<S>,
    ratio: &S,
    allow_chord: bool,
    tol: Option<S>,
    guess: Option<f64>,
) -> Handed<S> {
    let seed = guess
        .filter(|g| g.is_finite() && *g > 0.0)
        .map(|g| S::from_f64(g, ratio.prec()));
    let stage = |seed, budget| Stage {
        allow_chord,
        budget,
        ..Stage::from(seed, tol.clone())
    };
    if let Some(seed) = &seed {
        if let Ok((shape, slope)) = solve_core(ev, ratio, stage(Some(seed), GUESS_EVALUATIONS)) {
            let slope = match slope {
                Some(c) if !allow_chord && c.before.is_none() => Some(secant_partner(ev, ratio, c)),
                other => other,
            };
            return Ok((shape, slope));
        }
    }
    solve_core(ev, ratio, stage(None, super::newton::MAX_EVALUATIONS))
}

impl<T: Real> Newton<'_, T> {
    /// The k = 1 probe, for an unseeded start above k = 1 with A1/B1 below
    /// [`PROBE_BELOW_RATIO`] or the seed's k0·√(1 − M_R²) below [`PROBE_BELOW_SEED_K_EPS`]:
    /// the root may lie below 1, where the fixed rule applies, while iterates above pay graded
    /// layouts. One evaluation at k = 1 tells the side and starts Newton from there with the
    /// bracket's end at λ = 0: from above, not above the seed nor (away from the Rayleigh
    /// speed) more than e² below it; from below, at most e² below 1.
    #[inline]
    pub(super) fn probe_k_one(&mut self) -> Result<()> {
        // In the working type: √(1 − M_R²) may lie below the f64 range at MPFR.
        let p = self.prec();
        let pole_width = self.evaluator.speed().one_minus_mr2().clone().sqrt();
        let near_rayleigh =
            self.lam.clone().exp() * &pole_width < T::from_f64(PROBE_BELOW_SEED_K_EPS, p);
        if !(self.lam.is_positive() && (self.ratio.to_f64() < PROBE_BELOW_RATIO || near_rayleigh)) {
            return Ok(());
        }
        let (zero, two, one) = (T::zero(p), T::from_i64(2, p), T::one(p));
        let ev = self.evaluator;
        let kept = ev.speed().solve_cache().probe(ev.method());
        let ci = match kept.and_then(OnceLock::get) {
            Some(ci) => ci.clone(),
            None => {
                let ci = ev.for_newton(&AxisRatio::new(one.clone())?, true)?;
                if let Some(slot) = kept {
                    let _ = slot.set(ci.clone());
                }
                ci
            }
        };
        self.spent += 1;
        let (f, df) = (shape_residual(&ci, self.ratio), shape_slope(&one, &ci));
        let newton = (df.is_positive() && df.is_finite()).then(|| -(f.clone() / &df));
        if f.is_negative() {
            if let Some(n) = newton {
                let below_seed = n.min_of(self.lam.clone());
                self.lam = if near_rayleigh {
                    below_seed
                } else {
                    below_seed.max_of(self.lam.clone() - &two)
                };
            }
            self.lo = Some(zero);
        } else {
            self.lam = newton.map_or_else(|| -two.clone(), |n| n.max_of(-two.clone()));
            self.hi = Some(zero);
        }
        Ok(())
    }
}

/// Below this A1/B1 an unseeded start above k = 1 first evaluates at k = 1
/// (`docs/calibration.md`).
pub(super) const PROBE_BELOW_RATIO: f64 = 30.0;

/// ... and at any A1/B1 when the static seed's k0·√(1 − M_R²) is below this: near the
/// Rayleigh speed the root falls far below the static seed (`docs/calibration.md`).
pub(super) const PROBE_BELOW_SEED_K_EPS: f64 = 0.5;
