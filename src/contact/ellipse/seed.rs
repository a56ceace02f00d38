//! Stage 2: the start of the ladder's lowest stage — the caller's seed or a neighbour's root,
//! else the grid seed (an `f64` solve by a fixed-rule method), else the static Hertz ellipse in
//! closed form, with the k = 1 probe that tells on which side of k = 1 the root lies.

use super::newton::{newton_options, residual, Chord, Handed, Newton, MAX_EVALUATIONS};
use super::{shape_residual, shape_slope};
use crate::error::Result;
use crate::routes::evaluate::Evaluator;
use crate::routes::{AxisRatio, Method};
use crate::scalar::Real;
use std::sync::OnceLock;

/// The evaluations a stage started from the caller's seed or a neighbour's root may spend
/// before it starts again from the grid seed or the static ellipse (a converging start needs
/// 1–3).
const GUESS_EVALUATIONS: usize = 8;

/// The ladder's lowest stage: from `guess` when it converges within [`GUESS_EVALUATIONS`],
/// else, at `f64` by a fixed rule with `allow_chord`, from the grid seed ([`grid_seed`], whose
/// nodes count in the shape's iterations), else from the static ellipse. `allow_chord`:
/// whether its last evaluation may skip the k-derivatives (not when it hands them on). A
/// seeded stage that hands on derivatives from one evaluation gets a [`secant_partner`].
#[inline]
pub(super) fn lowest_stage<S: Real>(
    ev: &Evaluator<S>,
    ratio: &S,
    allow_chord: bool,
    tol: Option<S>,
    guess: Option<f64>,
) -> Handed<S> {
    let run = |seed: f64, budget| {
        let seed = S::from_f64(seed, ratio.prec());
        let mut newton = Newton::new(ev, ratio, Some(&seed), tol.clone(), allow_chord);
        newton.budget = budget;
        let (shape, slope) = newton.run(None)?;
        let slope = match slope {
            Some(c) if !allow_chord && c.before.is_none() => Some(secant_partner(ev, ratio, c)),
            other => other,
        };
        Ok((shape, slope))
    };
    if let Some(g) = guess.filter(|g| g.is_finite() && *g > 0.0) {
        if let Ok(done) = run(g, GUESS_EVALUATIONS) {
            return Ok(done);
        }
    }
    if let Some((k, nodes)) = allow_chord.then(|| grid_seed(ev, ratio)).flatten() {
        let (mut shape, slope) = run(k, MAX_EVALUATIONS)?;
        shape.iterations += nodes;
        return Ok((shape, slope));
    }
    Newton::new(ev, ratio, None, tol.clone(), allow_chord).run(None)
}

/// A seeded stage that hands on derivatives from one evaluation leaves no earlier iterate for
/// the Halley step's secant above: one more evaluation with derivatives at [`PARTNER_STEP`]
/// from its root supplies it (unchanged if that evaluation fails).
#[inline(never)]
fn secant_partner<S: Real>(ev: &Evaluator<S>, ratio: &S, mut c: Chord<S>) -> Chord<S> {
    let lam = c.lam.clone() + S::from_f64(PARTNER_STEP, ratio.prec());
    if let Ok((_, df, ci, _)) = residual(ev, ratio, &lam, None) {
        c.before = Some([lam, df, ci.di1_dk(), ci.di2_dk()]);
    }
    c
}

/// The secant partner's distance in λ: √r for derivatives of relative error r ~ 2⁻⁴⁰, where
/// the secant's rounding and truncation errors balance.
const PARTNER_STEP: f64 = 9.5367431640625e-7; // 2^-20

/// The static Hertz ellipse: Hamrock & Brewe's k ≈ (A1/B1)^(2/π) below A1/B1 = 30, the k ≫ 1
/// form ([`static_seed_wide`]) from 30 on (`docs/calibration.md`).
#[inline]
pub(super) fn static_seed(ratio: f64) -> f64 {
    let k = match ratio.is_finite() && ratio >= ASYMPTOTIC_SEED_RATIO {
        true => static_seed_wide(ratio),
        false => ratio.powf(std::f64::consts::FRAC_2_PI),
    };
    Some(k).filter(|k| k.is_finite() && *k > 0.0).unwrap_or(1.0)
}

const ASYMPTOTIC_SEED_RATIO: f64 = 30.0;

/// The static root for A1/B1 ≥ 30 from (33)'s k ≫ 1 form at rest, A1/B1 = k²/(ln 4k − 1)
/// (I2 ≈ 2g/k, I1 ≈ (2g/k³)(ln 4k − 1)), by four contracting fixed-point steps
/// k ← √(A1/B1·(ln 4k − 1)): within 1.5 % of the static root at 30, 0.01 % at 10⁶.
fn static_seed_wide(ratio: f64) -> f64 {
    let mut k = ratio.sqrt();
    for _ in 0..4 {
        k = (ratio * ((4.0 * k).ln() - 1.0)).sqrt();
    }
    k
}

impl<T: Real> Newton<'_, T> {
    /// The k = 1 probe, for an unseeded start above k = 1 with A1/B1 below
    /// [`PROBE_BELOW_RATIO`] or the seed's k0·√(1 − M_R²) below [`PROBE_BELOW_SEED_K_EPS`]
    /// (`docs/calibration.md`): one evaluation at k = 1 (kept with the speed) tells the root's
    /// side and starts Newton from there with the bracket's end at λ = 0: from above, not above
    /// the seed nor (away from the Rayleigh speed) more than e² below it; from below, at most
    /// e² below 1. Out of line: it never runs on a seeded start, the common one.
    #[inline(never)]
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
            if let Some(n) = newton.map(|n| n.min_of(self.lam.clone())) {
                let far = (!near_rayleigh).then(|| self.lam.clone() - &two);
                self.lam = far.map_or_else(|| n.clone(), |floor| n.clone().max_of(floor));
            }
            self.lo = Some(zero);
        } else {
            self.lam = newton.map_or_else(|| -two.clone(), |n| n.max_of(-two.clone()));
            self.hi = Some(zero);
        }
        Ok(())
    }
}

/// The probe's thresholds: an unseeded start above k = 1 with A1/B1 below the first, or at
/// any A1/B1 with the static seed's k0·√(1 − M_R²) below the second (near the Rayleigh speed
/// the root falls far below the static seed).
const PROBE_BELOW_RATIO: f64 = 30.0;
const PROBE_BELOW_SEED_K_EPS: f64 = 0.5;

/// The seed grid's spacing in λ = ln k, its nodes' range |λ| ≤ `GRID_HALF`·`GRID_STEP`, and
/// the nodes a seed may read before it gives up (a root off the grid, a failed evaluation).
const GRID_STEP: f64 = 0.25;
const GRID_HALF: i64 = 63;
const GRID_READS: usize = 8;

/// The start of an `f64` stage by a fixed rule (`docs/calibration.md`, "The grid seed"): λ at
/// ln(A1/B1) of the Hermite interpolant of λ(ln(I2/I1)) with slopes 1/F′ through the four
/// nodes of a grid in λ around the root (the two that bracket it and one on either side). The
/// bracket is found from the static seed's nearest node (k = 1 for a static seed above it with
/// A1/B1 below 30) by Newton's step from each node read to the nearest node inside the bracket
/// so far. Each node is evaluated on an evaluator of its
/// own, once per speed, so that the seed does not depend on the solves before. Returns the seed
/// and the distinct nodes read; `None` above `f64`, for the adaptive method, and where the root
/// lies off the grid.
pub(super) fn grid_seed<S: Real>(ev: &Evaluator<S>, ratio: &S) -> Option<(f64, usize)> {
    if S::bits(ratio.prec()) > 53 || !matches!(ev.method(), Method::Auto | Method::Fixed) {
        return None;
    }
    let target = ratio.to_f64().ln();
    let slots = ev.speed().solve_cache().grid(2 * GRID_HALF as usize + 1);
    // The nodes read (bit j + GRID_HALF), for the count.
    let mut read = 0u128;
    let mut node = |j: i64| -> Option<(f64, f64, f64)> {
        let slot = slots.get(usize::try_from(j + GRID_HALF).ok()?)?;
        read |= 1 << (j + GRID_HALF);
        let kept = slot.get();
        let (g, d) = kept.or_else(|| slot.fill(grid_node(ev, j as f64 * GRID_STEP)))?;
        Some((j as f64 * GRID_STEP, g - target, d))
    };
    // Nodes strictly between `lo` and `hi` (index and value) lie inside the bracket.
    let (mut lo, mut hi) = (None, None);
    let ratio64 = ratio.to_f64();
    // Below A1/B1 = 30 a start above k = 1 reads k = 1 first (as the probe does): at speed the
    // root often lies below it, and a node above k = 1 costs a fresh speed a graded layout.
    let mut lam = match ratio64 < ASYMPTOTIC_SEED_RATIO {
        true => (std::f64::consts::FRAC_2_PI * target).min(0.0),
        false => static_seed_wide(ratio64).ln(),
    };
    for _ in 0..GRID_READS {
        let first = lo.map_or(1 - GRID_HALF, |(l, _)| l + 1);
        let last = hi.map_or(GRID_HALF - 1, |(h, _)| h - 1);
        if first > last {
            // The interpolant also reads a node beyond each end of the bracket.
            let ((l, at_l), (h, at_h)) = (lo?, hi?);
            let nodes = [at_l, at_h, node(l - 1)?, node(h + 1)?];
            let root = inverse_hermite(nodes.map(|(x, y, d)| (x, y, d.recip())));
            return Some((
                root.max(at_l.0).min(at_h.0).exp(),
                read.count_ones() as usize,
            ));
        }
        // The nearest node (`as` truncates: shifted by GRID_HALF, a floor), kept inside.
        let i =
            ((lam / GRID_STEP + (GRID_HALF as f64 + 0.5)) as i64 - GRID_HALF).clamp(first, last);
        let at = node(i)?;
        *(if at.1 <= 0.0 { &mut lo } else { &mut hi }) = Some((i, at));
        // Newton's step from it.
        lam = at.0 - at.1 / at.2;
    }
    None
}

/// ln(I2/I1) and its λ-derivative F′ at λ, by the fixed rules on an evaluator of its own. Out
/// of line: it runs once per node and speed.
#[inline(never)]
fn grid_node<S: Real>(ev: &Evaluator<S>, lam: f64) -> Option<(f64, f64)> {
    let own = Evaluator::new(ev.speed(), newton_options(Method::Auto)).ok()?;
    let one = S::one(ev.speed().mr().prec());
    let ax = AxisRatio::new(S::from_f64(lam.exp(), one.prec())).ok()?;
    let ci = own.for_newton(&ax, true).ok()?;
    let g = shape_residual(&ci, &one).to_f64();
    let d = shape_slope(&ax.k, &ci).to_f64();
    (g.is_finite() && d.is_finite() && d > 0.0).then_some((g, d))
}

/// The value at 0 of the Hermite interpolant x(y) through the points (xᵢ, yᵢ) with slopes
/// dx/dy = sᵢ (`nodes`: (xᵢ, yᵢ, sᵢ), the yᵢ distinct), by Newton's divided differences on
/// the doubled nodes.
fn inverse_hermite(nodes: [(f64, f64, f64); 4]) -> f64 {
    let y: [f64; 8] = std::array::from_fn(|i| nodes[i / 2].1);
    let mut c: [f64; 8] = std::array::from_fn(|i| nodes[i / 2].0);
    for order in 1..8 {
        for i in (order..8).rev() {
            c[i] = match order == 1 && i % 2 == 1 {
                true => nodes[i / 2].2,
                false => (c[i] - c[i - 1]) / (y[i] - y[i - order]),
            };
        }
    }
    (0..7).rev().fold(c[7], |x, i| c[i] - x * y[i])
}
