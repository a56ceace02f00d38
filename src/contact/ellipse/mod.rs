//! The shape of the contact ellipse, (33): given ν, M_R and the curvature ratio
//! A1/B1 = R2/R1 (R1 the punch's radius of curvature along the motion, R2 across it), the axis
//! ratio k = b/a (a along the motion, b across) solves I2(k)/I1(k) = A1/B1.
//!
//! The stages, in the order they run (a file each): check the inputs (this file); seed
//! (`seed.rs`: the caller's or a neighbour's root, the grid seed, or the static ellipse and the
//! k = 1 probe); safeguarded Newton in λ = ln k at the ladder's lowest stage (`newton.rs`);
//! lift through the precision ladder (`ladder.rs`: `f64`, double-double above 106 bits,
//! p/2 + 32 bits above 1024, the lower stages' speeds kept in `contact/solve_cache.rs`); the
//! final step and error bound (`finish.rs`). Thresholds, and what each tactic beside Newton's
//! method saves: `docs/calibration.md`, "The ellipse solve". Tests: `tests/contact.rs` (k
//! within 10ε of a 320-bit quadrature solve), `tests/high_precision.rs`, `tests/edges.rs`.

mod finish;
mod ladder;
mod newton;
mod seed;

pub(crate) use ladder::ShapeSolver;

use crate::error::{Error, Result};
use crate::estimate::{Estimated, RelError};
use crate::physics::Speed;
use crate::routes::{Evaluation, Integrals, Method};
use crate::scalar::{check_finite, check_positive, short, Real};

/// Which axis of the contact ellipse is the longer one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum MajorAxis {
    /// The semi-axis a, along the motion (k ≤ 1).
    Along,
    /// The semi-axis b, across the motion (k > 1).
    Across,
}

impl MajorAxis {
    /// `along` or `across`; exact.
    pub fn label(&self) -> &'static str {
        match self {
            MajorAxis::Along => "along",
            MajorAxis::Across => "across",
        }
    }
}

/// Options of [`solve_ellipse`] (and of [`crate::contact::ContactProblem::solve`]): every
/// field has a default, so a call names only what it changes,
/// `Options { method: Method::Adaptive, ..Default::default() }`.
#[derive(Clone, Debug)]
pub struct Options<T> {
    /// How the integrals are evaluated at each Newton iterate: [`Method::Auto`] (default: the
    /// fixed rules where they apply, the adaptive quadrature elsewhere), [`Method::Fixed`] (the
    /// fixed rules only; an iterate above k = 2¹⁸⁰ is an error) or [`Method::Adaptive`].
    /// The series and the adaptive subtracted routes give no k-derivatives and are refused.
    pub method: Method,
    /// A starting value for k, positive and finite (else [`Error::NotFinite`] or
    /// [`Error::Domain`] before any work), rounded to `f64`, where the solve falls back to its
    /// own start (the default: the grid seed or the static ellipse) when Newton's method does
    /// not converge from it within a few evaluations.
    pub seed: Option<T>,
    /// The relative accuracy wanted for k; `None` (the default) asks for the working
    /// precision's floor (a few ε). A tolerance below 4ε is refused before any work
    /// ([`Error::Unreachable`]); one above 2⁻²⁰ ≈ 10⁻⁶ is met as 2⁻²⁰ (the loosest the
    /// stopping rules' error model covers). Every bound returned holds either way.
    pub tolerance: Option<RelError>,
}

impl<T> Default for Options<T> {
    fn default() -> Self {
        Options {
            method: Method::Auto,
            seed: None,
            tolerance: None,
        }
    }
}

/// The solved shape of the contact ellipse (33), each quantity with a bound on its error.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Ellipse<T: Real> {
    pub(crate) k: Estimated<T>,
    pub(crate) e: Estimated<T>,
    pub(crate) major: MajorAxis,
    pub(crate) integrals: Integrals<T>,
    pub(crate) iterations: usize,
}

impl<T: Real> Ellipse<T> {
    /// k = b/a (b across the motion, a along it), the root of (33), with a bound on its relative
    /// error for the inputs as represented at the working precision (see [`solve_ellipse`] for
    /// the speed's rounding).
    pub fn k(&self) -> &Estimated<T> {
        &self.k
    }

    /// The eccentricity √(1 − (minor/major)²) ∈ [0, 1). Its bound is on the *absolute* error
    /// |ẽ − e| (e vanishes for a circular contact, where δe ≈ δk/e: a relative bound would be
    /// unbounded there); since e < 1 it also bounds e's error relative to 1.
    pub fn e(&self) -> &Estimated<T> {
        &self.e
    }

    /// Which axis is the major one: along the motion for k ≤ 1, across it for k > 1; exact.
    pub fn major(&self) -> MajorAxis {
        self.major
    }

    /// I1, I2 of (34) at the solution (normalisation of (37)) with their k-derivatives (when
    /// known to at least one digit) and the route of the last evaluation, with the solve's
    /// bounds (which include the carry from the last evaluation to the root).
    pub fn integrals(&self) -> &Integrals<T> {
        &self.integrals
    }

    /// Evaluations of the integrals at the working precision: Newton's iterates (and the k = 1
    /// probe's) and, at `f64`, the distinct nodes the grid seed read (kept with the speed, and
    /// counted whether kept or not, so that the count does not depend on the solves before).
    /// The precision ladder's lower stages are not counted (an evaluation at `f64` or
    /// double-double costs a small fraction of one at the working precision, one at the
    /// half-precision stage above 1024 bits about a fifth).
    pub fn iterations(&self) -> usize {
        self.iterations
    }
}

/// The solve's internal result: k, the integrals at k, the error estimate of k, the work.
#[derive(Clone, Debug)]
pub(crate) struct Shape<T: Real> {
    k: T,
    integrals: Evaluation<T>,
    error_estimate: T,
    iterations: usize,
}

impl<T: Real> Shape<T> {
    /// The public result: e and its absolute bound from k's, everything checked finite.
    pub(crate) fn publish(self) -> Result<Ellipse<T>> {
        let p = self.k.prec();
        let one = T::one(p);
        let (q, major) = if self.k <= one {
            (self.k.clone(), MajorAxis::Along)
        } else {
            (self.k.clone().recip(), MajorAxis::Across)
        };
        let e = ((one.clone() - &q) * (one + &q)).sqrt();
        // δ(e²) = 2q²·δk/k; |δe| ≤ min(δ(e²)/(2e), √δ(e²)), plus e's own rounding (4ε·e),
        // formed at the working precision (which holds any bound without underflow).
        let de2 = q.square().mul_i64(2) * &self.error_estimate;
        let root = de2.clone().sqrt();
        let de = match e.is_positive() {
            true => (de2 / e.clone().mul_i64(2)).min_of(root),
            false => root,
        };
        let e_err = de + &(T::epsilon(p).mul_i64(4) * &e);
        if !(self.k.is_finite() && self.error_estimate.is_finite() && e_err.is_finite()) {
            let (k, estimate) = (short(&self.k), short(&self.error_estimate));
            let reached = format!("k = {k}, estimate {estimate}");
            let (what, iterations) = ("the axis ratio k", self.iterations);
            return Err(Error::NoConvergence {
                what,
                iterations,
                reached,
            });
        }
        let integrals = self.integrals.without_poor_extras().publish(&self.k)?;
        Ok(Ellipse {
            k: Estimated::new(self.k, RelError::of(&self.error_estimate)),
            e: Estimated::absolute(e, RelError::of(&e_err)),
            major,
            integrals,
            iterations: self.iterations,
        })
    }
}

/// Checks a curvature ratio A1/B1 = R2/R1, the domain of (33) as solved here: positive, finite
/// and within [`RATIO_RANGE`], by exact comparisons on the value as given.
pub fn check_ratio<T: Real>(ratio: &T) -> Result<()> {
    check_finite("curvature ratio A1/B1", ratio)?;
    // Compared in f64, so that the decimal ends typed at any precision are inside.
    let (lo, hi) = RATIO_RANGE;
    let bound = if !ratio.is_positive() {
        "(0, inf)"
    } else if !(lo..=hi).contains(&ratio.to_f64()) {
        "[1e-100, 1e100], the supported range (beyond it the axis ratio k passes 1e-50 or 1e50, where the quadrature overflows f64 and takes a minute at 256 bits)"
    } else {
        return Ok(());
    };
    Err(Error::domain(
        "curvature ratio A1/B1 = R2/R1",
        short(ratio),
        bound,
    ))
}

/// The supported curvature ratios A1/B1: a solve inside costs at most about 100 solves at
/// A1/B1 ~ 1 at 256 bits and a few at `f64` (`docs/calibration.md`).
pub const RATIO_RANGE: (f64, f64) = (1e-100, 1e100);

/// Solves (33), I2(k)/I1(k) = A1/B1, for the axis ratio k = b/a at the working precision of
/// `ratio` = A1/B1 = R2/R1, for the material and speed of `speed`: above `f64` by the
/// precision ladder of the module docs, a few evaluations at the working precision.
///
/// Accuracy: k to a few ε (measured ≤ 2.6ε against a 320-bit quadrature solve,
/// `tests/contact.rs`; within 4ε where |ln k| is large, `tests/edges.rs`), I1, I2 at k to a
/// few ε, with bounds that include their carry from the last evaluation to the root. The bound
/// on k is for the inputs as represented: near the Rayleigh speed k is ill-conditioned in M_R
/// (condition number ~M_R/(4(1 − M_R))) but well conditioned in the gap 1 − M_R, which a speed
/// made by [`crate::physics::Material::parse_speed`] or
/// [`crate::physics::Material::speed_from_gap`] carries to within ε.
///
/// Errors, before any work: [`Error::Domain`] for a ratio that is not positive and finite;
/// [`Error::Unsupported`] for the series or the adaptive subtracted method (no
/// k-derivatives); [`Error::Precision`] above 32,768 bits; [`Error::Unreachable`] for a
/// tolerance below 4ε. [`Error::NoConvergence`] if Newton's method fails (not observed).
pub fn solve_ellipse<T: Real>(
    speed: &Speed<T>,
    ratio: &T,
    opts: &Options<T>,
) -> Result<Ellipse<T>> {
    check_ratio(ratio)?;
    let tol = checked_options(opts, ratio.prec())?;
    ShapeSolver::new(speed, opts.method)?
        .solve(ratio, tol, opts.seed.as_ref(), None)?
        .publish()
}

/// The checks of [`solve_ellipse`] that the options and the precision `p` decide, before any
/// work; returns the tolerance at `p` (`None`: its floor).
pub(crate) fn checked_options<T: Real>(opts: &Options<T>, p: T::Prec) -> Result<Option<T>> {
    crate::numerics::quadrature::check_rule_bits(T::bits(p))?;
    if let Some(seed) = &opts.seed {
        check_positive("seed for the axis ratio k", seed)?;
    }
    if matches!(opts.method, Method::Series | Method::AdaptiveSubtracted) {
        return Err(Error::Unsupported {
            what: "the k-derivatives of I1, I2 that the ellipse solve needs",
            method: opts.method.label(),
            reason: "auto, adaptive and fixed give them",
        });
    }
    if let Some(t) = opts.tolerance {
        let floor = RelError::eps::<T>(4, p);
        if t < floor {
            return Err(Error::Unreachable {
                what: "the axis ratio k",
                tolerance: t.to_string(),
                reason: format!("below 4 eps = {floor} of the working precision"),
            });
        }
    }
    let loosest = RelError::pow2(LOOSEST_TOLERANCE_LOG2);
    Ok(opts.tolerance.map(|t| t.min(loosest).to_real::<T>(p)))
}

/// The loosest tolerance on k the solve works to, 2⁻²⁰ ≈ 10⁻⁶ (`docs/calibration.md`): a
/// looser one is met as this one.
const LOOSEST_TOLERANCE_LOG2: i64 = -20;

/// F(λ) = ln(I2/(I1·A1/B1)) of the shape equation (33), whose root in λ = ln k the solve finds
/// (the quotient formed first, so that F near its root carries a few ε absolute).
#[inline]
fn shape_residual<T: Real>(ci: &Evaluation<T>, ratio: &T) -> T {
    (ci.i2.clone() / &ci.i1 / ratio).ln()
}

/// F′ = dF/dλ = k (I2′/I2 − I1′/I1) at k from the k-derivatives of `ci`.
#[inline]
fn shape_slope<T: Real>(k: &T, ci: &Evaluation<T>) -> T {
    k.clone() * (ci.di2_dk() / &ci.i2 - ci.di1_dk() / &ci.i1)
}

#[cfg(test)]
#[path = "../../../tests/unit/ellipse.rs"]
mod tests;
