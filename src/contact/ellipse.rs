//! The shape of the contact ellipse, (33): given ν, M_R and the curvature ratio
//! A1/B1 = R2/R1 (R1 the punch's radius of curvature along the motion, R2 across it), the axis
//! ratio k = b/a (a along the motion, b across) solves
//!
//! ```text
//! I2(k)/I1(k) = A1/B1.
//! ```
//!
//! Newton's method on F(λ) = ln(I2/(I1·A1/B1)), λ = ln k, with F'(λ) = k (I2′/I2 − I1′/I1)
//! from the integrals' k-derivatives (differentiated under the integral sign), safeguarded by a
//! bracket: F increases with k (checked over ν, M_R and 10^-6 ≤ A1/B1 ≤ 10^6 in
//! `tests/contact.rs`), so a step leaving the bracket is replaced by bisection in λ.
//!
//! The start is the static ellipse: Hamrock & Brewe's k ≈ (A1/B1)^(2/π) below A1/B1 = 30, the
//! k ≫ 1 form of static Hertz, A1/B1 = k²/(ln 4k − 1), from 30 on.
//!
//! **Stopping and chord steps.** Once converging, a Newton step δ leaves an error ~δ²: the
//! iteration stops when 64δ² ≤ ε. The evaluation expected to be the last (64δ³ ≤ ε) skips the
//! k-derivatives and steps with the previous F′ (a chord step, error ~δ·|λ − λ_F′|). An
//! unseeded solve also stops one evaluation earlier where the Hermite cubic through F, F′ at
//! its last two iterates (distance D) pins the remaining step h to O(D²h²) ≤ ε/8
//! (`hermite_root`; I1, I2 carried by their own cubics in k, relative error ≤ 16D²h² ≤ ε). From
//! A1/B1 = 30 on, long steps at kε ≥ 5 solve the asymptotic form of (33) for k ≫ 1
//! (`log_model_step`). The thresholds and the evidence they were chosen on:
//! `docs/calibration.md`.
//!
//! **Precision ladder** (`ShapeSolver::ladder`): a solve at high precision is started from
//! the `f64` root and its F′ (good to ~2^-40). At double-double one evaluation with
//! k-derivatives and a Halley step whose F″ (and the integrals' second derivatives, for carrying
//! I1, I2 to the new k) come by secants from the `f64` stage's iterates (`halley_from_f64`):
//! the Newton error (F″/2F′)δ² ~ 10⁻³² of an `f64` root off by δ ~ 10⁻¹⁶ shrinks by F″'s
//! relative accuracy (~10⁻⁵). Where its error bounds do not reach ε, or the inputs' rounding to
//! `f64` moved the root by more than 10⁻¹⁵ (M_R ≳ 0.999), two chord steps with the `f64` F′
//! instead (each contracts the error by F′'s accuracy, 2^-48 to 2^-88 to below 2^-106): two
//! evaluations without k-derivatives. Above 106 bits a double-double stage comes first (one
//! chord step with the `f64` F′, then one Newton step, so that it hands on its own F′, good to
//! ~2^-90), then chord steps from its root (~2^-100 to ~2^-190 to below 2^-256): 2 evaluations without
//! k-derivatives at 256 bits, 3 at 512, 4 at 1024 — a few high-precision
//! evaluations of the integrals, no search. Above 1024 bits (MPFR) the stage below p bits is the
//! same solve at m = p/2 + 32 bits, itself a ladder (`ShapeSolver::via_mid`: 4096 bits climbs
//! 568, 1072 and 2080): its root and F′, each good to ~2^-m, leave one chord step at p bits —
//! one evaluation without k-derivatives, where Newton's steps from the double-double root took
//! log₂(p/100) evaluations with them (six at 4096 bits). Each stage costs about a fifth of the
//! one above it (`docs/precision.md`). Tests: `tests/contact.rs` (the ladder's k within 10ε
//! of a 320-bit adaptive-quadrature solve at f64, double-double and 256 bits),
//! `tests/high_precision.rs` (2048 to 8192 bits, against the solve 256 bits higher).

use crate::error::{Error, Result};
use crate::estimate::{Estimated, RelError};
use crate::physics::Speed;
use crate::routes::evaluate::{Evaluator, IntegralOptions};
use crate::routes::{fast, AxisRatio, Evaluation, Integrals, Method};
use crate::scalar::{check_finite, check_positive, short, Dd, Real};
use std::cell::OnceCell;

/// Which axis of the contact ellipse is the longer one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MajorAxis {
    /// The semi-axis a, along the motion (k ≤ 1).
    Along,
    /// The semi-axis b, across the motion (k > 1).
    Across,
}

impl MajorAxis {
    /// `along` or `across`.
    /// Names the axis of (33)'s major-axis convention; exact.
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
    /// [`Error::Domain`] before any work). Without one (the default) the solve starts from the
    /// static ellipse; with one, from the seed (rounded to `f64`), falling back to the static
    /// ellipse when Newton's method does not converge from it within a few evaluations (or when
    /// the seed rounds to 0 or ∞ in `f64`). Either way,
    /// above `f64` the solve climbs the precision ladder (`f64`, then double-double, above 1024
    /// bits stages at about half the precision of the next, then the working precision: a few
    /// high-precision evaluations, no search).
    pub seed: Option<T>,
    /// The relative accuracy wanted for k; `None` (the default) asks for the working
    /// precision's floor (a few ε). A tolerance below 4ε is refused before any work
    /// ([`Error::Unreachable`]); one above 2⁻²⁰ ≈ 10⁻⁶ is met as 2⁻²⁰ (the loosest the
    /// stopping rules' error model covers). Either way every bound returned holds: k's, and
    /// I1's and I2's, which include their carry from the last evaluation to the root.
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
pub struct Ellipse<T: Real> {
    /// k = b/a (b across the motion, a along it), with a bound on its relative error for the
    /// inputs as represented at the working precision (see [`solve_ellipse`] for the speed's
    /// rounding).
    pub k: Estimated<T>,
    /// The eccentricity √(1 − (minor/major)²) ∈ [0, 1). Its bound is on the *absolute* error
    /// |ẽ − e| (e vanishes for a circular contact, where δe ≈ δk/e: a relative bound would be
    /// unbounded there); since e < 1 it also bounds e's error relative to 1.
    pub e: Estimated<T>,
    /// Which axis is the major one.
    pub major: MajorAxis,
    /// I1, I2 at the solution (normalisation of (37)) with their k-derivatives (when known to
    /// at least one digit) and the route of the last evaluation.
    pub integrals: Integrals<T>,
    /// Evaluations of the integrals at the working precision (above `f64` the precision
    /// ladder's lower stages come on top: an evaluation at `f64` or double-double costs a small
    /// fraction of one at the working precision, one at the half-precision stage above 1024
    /// bits about a fifth).
    pub iterations: usize,
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
        let de = if e.is_positive() {
            (de2 / e.clone().mul_i64(2)).min_of(root)
        } else {
            root
        };
        let e_err = de + &(T::epsilon(p).mul_i64(4) * &e);
        if !(self.k.is_finite() && self.error_estimate.is_finite() && e_err.is_finite()) {
            return Err(Error::NoConvergence {
                what: "the axis ratio k",
                iterations: self.iterations,
                reached: format!(
                    "k = {}, estimate {}",
                    short(&self.k),
                    short(&self.error_estimate)
                ),
            });
        }
        Ok(Ellipse {
            k: Estimated::new(self.k, RelError::of(&self.error_estimate)),
            e: Estimated::absolute(e, RelError::of(&e_err)),
            major,
            integrals: self.integrals.without_poor_extras().publish()?,
            iterations: self.iterations,
        })
    }
}

/// Checks a curvature ratio A1/B1 = R2/R1: positive, finite and within the supported range
/// [10⁻¹⁰⁰, 10¹⁰⁰] ([`RATIO_RANGE`]), before any work.
/// The domain of the shape equation (33) as solved here; exact comparisons on the value as given.
pub fn check_ratio<T: Real>(ratio: &T) -> Result<()> {
    check_finite("curvature ratio A1/B1", ratio)?;
    if !ratio.is_positive() {
        return Err(Error::Domain {
            name: "curvature ratio A1/B1 = R2/R1",
            value: short(ratio),
            bound: "(0, inf)",
        });
    }
    // Compared in f64, so that the decimal ends typed at any precision are inside.
    let (lo, hi) = RATIO_RANGE;
    let r = ratio.to_f64();
    if !(lo..=hi).contains(&r) {
        return Err(Error::Domain {
            name: "curvature ratio A1/B1 = R2/R1",
            value: short(ratio),
            bound: "[1e-100, 1e100], the supported range (beyond it the axis ratio k passes 1e-50 or 1e50, where the quadrature overflows f64 and takes a minute at 256 bits)",
        });
    }
    Ok(())
}

/// The supported curvature ratios A1/B1: a solve inside costs at most about 100 solves at
/// A1/B1 ~ 1 at 256 bits and a few at `f64` (evidence: `docs/calibration.md`).
pub const RATIO_RANGE: (f64, f64) = (1e-100, 1e100);

/// A start for Newton: the static Hertz ellipse, by Hamrock & Brewe's approximation
/// k ≈ (A1/B1)^(2/π) below A1/B1 = 30 (within a few per cent of the static k down to 10⁻⁶) and by
/// the k ≫ 1 form of static Hertz from 30 on ([`static_seed_wide`]); the speed lowers k further,
/// which the safeguarded Newton iteration follows.
fn static_seed(ratio: f64) -> f64 {
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

/// From this ratio on the static seed is the k ≫ 1 form of static Hertz instead of Hamrock &
/// Brewe's, which overestimates the static root there (evidence: `docs/calibration.md`).
const ASYMPTOTIC_SEED_RATIO: f64 = 30.0;

/// The static root for A1/B1 = `ratio` ≥ 30 from the k ≫ 1 form of (33) at rest,
/// A1/B1 = k²/(ln 4k − 1) (I2 ≈ 2g/k, I1 ≈ (2g/k³)(ln 4k − 1)), by four fixed-point steps
/// k ← √(ratio·(ln 4k − 1)) (a contraction: each step divides the error by ~2(ln 4k − 1)); within
/// 1.5 % of the static root at A1/B1 = 30 and 0.01 % at 10⁶.
fn static_seed_wide(ratio: f64) -> f64 {
    let mut k = ratio.sqrt();
    for _ in 0..4 {
        k = (ratio * ((4.0 * k).ln() - 1.0)).sqrt();
    }
    k
}

/// Solves (33), I2(k)/I1(k) = A1/B1, for the axis ratio k = b/a at the working precision of
/// `ratio` = A1/B1 = R2/R1, for the material and speed of `speed`.
///
/// Without a seed (the default) the solve climbs the precision ladder above `f64`
/// (the precision ladder of the module docs): a few evaluations of the integrals at the
/// working precision, no search.
///
/// Accuracy: k to a few ε (measured ≤ 2.4ε against a 320-bit quadrature solve,
/// `tests/contact.rs`; within 4ε where |ln k| is large, up to 2878 at 256 bits,
/// `tests/edges.rs`), I1, I2 at k to a few ε, with error bounds that include their carry
/// from the last evaluation to the root (`every_bound_holds_at_any_tolerance`). The bound on k
/// is for the inputs as represented at the working precision: near the Rayleigh speed k is
/// ill-conditioned in M_R (condition number ~M_R/(4(1 − M_R))) but well conditioned in the gap
/// 1 − M_R, which a speed made by [`crate::physics::Material::parse_speed`] or
/// [`crate::physics::Material::speed_from_gap`] carries to within ε.
///
/// Errors: [`Error::Domain`] for a ratio that is not positive and finite, for the series or the
/// adaptive subtracted method (no k-derivatives); [`Error::Precision`] above 32,768 bits (the
/// rules' limit), before any work; [`Error::Unreachable`] for a tolerance below 4ε;
/// [`Error::NoConvergence`] if Newton's method fails (not observed).
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

/// The checks of [`solve_ellipse`] that the options and the precision decide, before any work:
/// a precision the quadrature rules are built for (at most
/// [`crate::numerics::quadrature::MAX_RULE_BITS`]), a method that gives k-derivatives, a
/// tolerance not below 4ε, a seed that is a positive finite number. Returns the tolerance at
/// the working precision `p` (`None`: its floor).
pub(crate) fn checked_options<T: Real>(opts: &Options<T>, p: T::Prec) -> Result<Option<T>> {
    crate::numerics::quadrature::check_rule_bits(T::bits(p))?;
    if let Some(seed) = &opts.seed {
        check_positive("seed for the axis ratio k", seed)?;
    }
    if matches!(opts.method, Method::Series | Method::AdaptiveSubtracted) {
        return Err(Error::Domain {
            name: "method for the ellipse solve",
            value: opts.method.label().into(),
            bound: "auto, adaptive or fixed (the series and adaptive-subtracted routes give no k-derivatives)",
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
    Ok(opts.tolerance.map(|t| {
        t.min(RelError::pow2(LOOSEST_TOLERANCE_LOG2))
            .to_real::<T>(p)
    }))
}

/// The loosest tolerance on k the solve works to, 2⁻²⁰ ≈ 10⁻⁶: a looser one is met as this
/// one. The stopping rules' error model (an error ~δ² after a Newton step δ) and the
/// integrals' carry from the last iterate to the root ([`carry_error`], Hermite's
/// [`hermite_root`]) hold for the steps they allow here; at `f64` a solve to 2⁻²⁰ costs about
/// two evaluations fewer than one to the working precision's floor.
const LOOSEST_TOLERANCE_LOG2: i64 = -20;

/// The ellipse solve for one speed and method: the evaluators of the precision ladder's
/// stages, each built on first use and kept, so that the fixed rules' set-ups serve every
/// solve at this speed (a sweep's points).
pub(crate) struct ShapeSolver<T: Real + 'static> {
    top: Evaluator<T>,
    stage64: OnceCell<Option<Evaluator<f64>>>,
    stage_dd: OnceCell<Option<Evaluator<Dd>>>,
    /// Above [`MID_ABOVE_BITS`], the solver at about half the working precision
    /// ([`ShapeSolver::via_mid`]).
    stage_mid: OnceCell<Option<Box<ShapeSolver<T>>>>,
}

impl<T: Real> ShapeSolver<T> {
    /// The solver for `speed` by `method` (checked by the caller).
    pub(crate) fn new(speed: &Speed<T>, method: Method) -> Result<Self> {
        Ok(ShapeSolver {
            top: Evaluator::new(speed, newton_options(method))?,
            stage64: OnceCell::new(),
            stage_dd: OnceCell::new(),
            stage_mid: OnceCell::new(),
        })
    }

    /// Solves (33) at `ratio` to the tolerance `tol` (`None`: the working precision's floor)
    /// by the precision ladder ([`ShapeSolver::ladder`]), whose lowest stage starts from the
    /// `seed` (the caller's) or else the `guess` (a neighbouring point's root), rounded to
    /// `f64`, when it converges from there within [`GUESS_EVALUATIONS`], and from the static
    /// ellipse otherwise: a far seed costs a few `f64` evaluations, never a search at the
    /// working precision.
    pub(crate) fn solve(
        &self,
        ratio: &T,
        tol: Option<T>,
        seed: Option<&T>,
        guess: Option<f64>,
    ) -> Result<Shape<T>> {
        let guess = seed.map(|s| s.to_f64()).or(guess);
        let shape = self.ladder(ratio, tol.clone(), guess)?;
        self.meet_tolerance(ratio, shape, tol)
    }

    /// A shape whose bound misses the tolerance (or, without one, exceeds 1/64) — a stop from a
    /// far seed at |ln k| ≫ 1, where the stopping rules' step relative to ln k is large in k —
    /// is refined from its own root at the working precision's floor; a bound still missing it
    /// is [`Error::Unreachable`].
    fn meet_tolerance(&self, ratio: &T, shape: Shape<T>, tol: Option<T>) -> Result<Shape<T>> {
        let p = ratio.prec();
        let wanted = tol.clone().unwrap_or_else(|| T::from_ratio(1, 64, p));
        if shape.error_estimate <= wanted {
            return Ok(shape);
        }
        let stage = Stage {
            seed: Some(&shape.k),
            ..Stage::final_stage()
        };
        let refined = solve_core(&self.top, ratio, stage)?.0;
        if refined.error_estimate <= wanted {
            return Ok(refined);
        }
        Err(Error::Unreachable {
            what: "the axis ratio k",
            tolerance: RelError::of(&wanted).to_string(),
            reason: format!(
                "the solve's bound is {}",
                RelError::of(&refined.error_estimate)
            ),
        })
    }

    /// The speed this solver serves.
    pub(crate) fn speed(&self) -> &Speed<T> {
        self.top.speed()
    }

    /// The evaluator of the ladder's `f64` or double-double stage (`None` where the speed does
    /// not convert).
    fn lower<'s, S: Real<Prec = ()>>(
        &'s self,
        cell: &'s OnceCell<Option<Evaluator<S>>>,
    ) -> Option<&'s Evaluator<S>> {
        cell.get_or_init(|| {
            let speed = self.top.speed().at::<S>(()).ok()?;
            Evaluator::new(&speed, newton_options(self.top.method())).ok()
        })
        .as_ref()
    }
}

/// The integral options of a Newton iterate: the method, with k-derivatives.
fn newton_options(method: Method) -> IntegralOptions {
    IntegralOptions {
        method,
        derivatives: true,
        ..Default::default()
    }
}

/// The evaluations a stage started from a neighbour's root may spend before the solve starts
/// again from the static ellipse (a converging start needs 2–4).
const GUESS_EVALUATIONS: usize = 8;

/// Runs the lowest stage of the ladder (chord steps at its end as `allow_chord` says) from
/// `guess` when there is one and it converges within [`GUESS_EVALUATIONS`], from the static
/// ellipse otherwise.
fn lowest_stage<S: Real>(
    ev: &Evaluator<S>,
    ratio: &S,
    allow_chord: bool,
    tol: Option<S>,
    guess: Option<f64>,
) -> Result<(Shape<S>, Option<Chord<S>>)> {
    let seed = guess
        .filter(|g| g.is_finite() && *g > 0.0)
        .map(|g| S::from_f64(g, ratio.prec()));
    let stage = |seed, budget| Stage {
        seed,
        allow_chord,
        budget,
        tol: tol.clone(),
        ..Stage::final_stage()
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
    solve_core(ev, ratio, stage(None, MAX_EVALUATIONS))
}

/// The distance in λ = ln k of [`secant_partner`]'s evaluation: about √r for derivatives with
/// relative error r ~ 2⁻⁴⁰, where the secant's rounding and truncation errors balance.
const PARTNER_STEP: f64 = 9.5367431640625e-7; // 2^-20

/// A stage started from a neighbour's root may converge in one evaluation, leaving its
/// derivatives without the earlier iterate that the next stage's Halley step takes F″ from
/// ([`f_second`]): one more evaluation with derivatives at [`PARTNER_STEP`] from its root
/// supplies it (at the stage's own, lower, precision). Unchanged if that evaluation fails.
fn secant_partner<S: Real>(ev: &Evaluator<S>, ratio: &S, mut c: Chord<S>) -> Chord<S> {
    let p = ratio.prec();
    let lam = c.lam.clone() + S::from_f64(PARTNER_STEP, p);
    if let Some(b) = slope_at(ev, ratio, lam) {
        c.before = Some([b.lam, b.df, b.di1, b.di2]);
    }
    c
}

/// A stage's result: the shape and the derivatives it hands on to the stage above.
type Handed<T> = Result<(Shape<T>, Option<Chord<T>>)>;

/// F′ and the integrals' k-derivatives at λ = ln k (one evaluation with derivatives): a
/// secant's partner, or the hand-off of a stage whose last step was a chord step; `None` if
/// that evaluation fails.
fn slope_at<S: Real>(ev: &Evaluator<S>, ratio: &S, lam: S) -> Option<Chord<S>> {
    let newton = Newton::new(ev, ratio, None, false, None, 1);
    let (_, df, ci) = newton.eval(&lam, None, false).ok()?;
    Some(Chord {
        di1: ci.di1_dk(),
        di2: ci.di2_dk(),
        df,
        rel_err: S::zero(lam.prec()),
        before: None,
        lam,
    })
}

/// How one stage of the solve runs: its seed and the derivatives handed on by the stage below,
/// whether its last evaluation may skip the k-derivatives (`allow_chord`; false for a stage that
/// hands its derivatives on), whether a Halley step from the `f64` stage is tried, and the
/// tolerance on k (`None`: the working precision's floor).
struct Stage<'s, T: Real> {
    seed: Option<&'s T>,
    seed_slope: Option<(Chord<T>, T)>,
    allow_chord: bool,
    halley: bool,
    tol: Option<T>,
    /// The evaluations the stage may spend.
    budget: usize,
}

impl<T: Real> Stage<'_, T> {
    /// The last (or only) stage: no seed, chord steps allowed.
    fn final_stage() -> Self {
        Stage {
            seed: None,
            seed_slope: None,
            allow_chord: true,
            halley: false,
            tol: None,
            budget: MAX_EVALUATIONS,
        }
    }
}

/// One stage of the solve ([`Stage`]): Newton's method on F(λ) = ln(I2/(I1·A1/B1)), λ = ln k,
/// with its named steps — the k = 1 probe ([`Newton::probe_k_one`]), the Halley step from a
/// lower precision ([`Newton::halley_step`]), the safeguarded Newton or asymptotic step inside
/// the bracket ([`Newton::next_iterate`]), the Hermite stop ([`Newton::hermite_stop`]), the
/// stopping rules ([`Newton::converged`]) and the chord steps at the end ([`Newton::plan_chord`]).
/// Returns the shape and the derivatives of the last evaluation that computed them (the hand-off
/// to the next stage).
fn solve_core<T: Real>(
    evaluator: &Evaluator<T>,
    ratio: &T,
    stage: Stage<'_, T>,
) -> Result<(Shape<T>, Option<Chord<T>>)> {
    check_ratio(ratio)?;
    let method = evaluator.method();
    let Stage {
        seed,
        seed_slope,
        allow_chord,
        halley,
        tol,
        budget,
    } = stage;
    let mut newton = Newton::new(evaluator, ratio, seed, allow_chord, tol, budget);
    let halley_slope = seed_slope.and_then(|(c, err)| newton.adopt_slope(c, &err, halley));
    if seed.is_none() && method != Method::Adaptive {
        newton.probe_k_one()?;
    }
    if let Some(c) = halley_slope {
        if let Some(shape) = newton.halley_step(&c)? {
            return Ok((shape, None));
        }
    }
    newton.iterate()
}

/// The bound on the evaluations of one stage (from the static ellipse).
const MAX_EVALUATIONS: usize = 200;

/// The state of one stage's iteration.
struct Newton<'a, T: Real + 'static> {
    ratio: &'a T,
    evaluator: &'a Evaluator<T>,
    /// The stopping rules' unit: ε, or the tolerance asked for.
    eps: T,
    /// ε_R = √(1 − M_R²), the width of G's Rayleigh pole: the asymptotic step needs k·ε_R ≫ 1.
    pole_width: f64,
    seeded: bool,
    /// Whether the evaluation expected to be the last may skip the k-derivatives.
    allow_chord: bool,
    /// The current iterate λ = ln k.
    lam: T,
    /// Bracket [lo, hi] in λ with F(lo) < 0 < F(hi), grown as evaluations reveal signs.
    lo: Option<T>,
    hi: Option<T>,
    last_step: Option<T>,
    /// Derivatives for a chord step at the next evaluation (none: a Newton step).
    chord: Option<Chord<T>>,
    /// The derivatives of the last evaluation that computed them, handed to the next stage.
    fresh_slope: Option<Chord<T>>,
    /// The last iterate with derivatives, for the Hermite stop.
    prev: Option<Point<T>>,
    /// Evaluations spent.
    spent: usize,
    /// The evaluations it may spend.
    budget: usize,
    /// The longest unbracketed step in λ: 2 (a factor e² in k), doubled after each step cut
    /// to it ([`Newton::next_iterate`]).
    reach: T,
    /// The λ range a step longer than 2 may reach: the fixed rules' k ≤ 2^180, and k⁴ ≥ 2⁸
    /// times the smallest normal number (the range [`AxisRatio`] admits, with a margin).
    lam_range: (f64, f64),
}

impl<'a, T: Real> Newton<'a, T> {
    fn new(
        evaluator: &'a Evaluator<T>,
        ratio: &'a T,
        seed: Option<&T>,
        allow_chord: bool,
        tol: Option<T>,
        budget: usize,
    ) -> Self {
        let p = ratio.prec();
        let k0 = match seed {
            Some(s) if s.is_positive() && s.is_finite() => s.clone(),
            _ => T::from_f64(static_seed(ratio.to_f64()), p),
        };
        Newton {
            ratio,
            evaluator,
            eps: tol.map_or_else(|| T::epsilon(p), |t| t.max_of(T::epsilon(p))),
            pole_width: evaluator.speed().one_minus_mr2().to_f64().sqrt(),
            seeded: seed.is_some(),
            allow_chord,
            lam: k0.ln(),
            lo: None,
            hi: None,
            last_step: None,
            chord: None,
            fresh_slope: None,
            prev: None,
            spent: 0,
            budget,
            reach: T::from_i64(2, p),
            lam_range: (
                (RelError::of(&T::min_positive(p)).log2() + 8.0) / 4.0 * std::f64::consts::LN_2,
                crate::routes::graded::K_MAX_LOG2 as f64 * std::f64::consts::LN_2,
            ),
        }
    }

    fn prec(&self) -> T::Prec {
        self.ratio.prec()
    }

    /// F and F′ = k(I2′/I2 − I1′/I1) at λ, with the integrals. With `chord` (the derivatives
    /// kept from an earlier iterate) the derivatives are not evaluated again: a chord step
    /// instead of a Newton step. `probe`: see [`Evaluator::for_newton`].
    #[inline(always)]
    fn eval(
        &self,
        lam: &T,
        chord: Option<&Chord<T>>,
        probe: bool,
    ) -> Result<(T, T, Evaluation<T>)> {
        let p = self.prec();
        let ax = AxisRatio::new(lam.clone().exp())?;
        let mut ci = self.evaluator.for_newton(&ax, chord.is_none(), probe)?;
        let f = shape_residual(&ci, self.ratio);
        let df = match chord {
            Some(c) => {
                // Derivatives kept from an earlier iterate: their relative error grows by
                // ≲ 8|Δλ| (see [`finish`]).
                ci.dk = Some([c.di1.clone(), c.di2.clone()]);
                let age = (lam.clone() - &c.lam).abs().mul_i64(8) + &c.rel_err;
                ci.extra_error = age + &T::epsilon(p).mul_i64(fast::DK_BOUND_EPS);
                c.df.clone()
            }
            None => shape_slope(&ax.k, &ci),
        };
        Ok((f, df, ci))
    }

    /// The hand-off from a lower precision: its derivatives `c` (relative error r) and a bound
    /// `seed_err` on its root's error. Chord steps multiply the error by ~r each: they are
    /// planned when two of them bring the seed's error to ε/64. Returns the slope for the
    /// Halley step instead when `halley` asks for it and the lower stage's secant F″ exists.
    fn adopt_slope(&mut self, c: Chord<T>, seed_err: &T, halley: bool) -> Option<Chord<T>> {
        if !(self.seeded && c.df.is_positive() && c.df.is_finite()) {
            return None;
        }
        if halley && f_second(&c, &self.lam).is_some() {
            return Some(c);
        }
        let r = c.rel_err.clone() + &(self.lam.clone() - &c.lam).abs();
        if r.square() * &seed_err.clone().mul_i64(64) <= self.eps {
            self.chord = Some(c);
        }
        None
    }

    /// The k = 1 probe: an unseeded start above k = 1 with A1/B1 below [`PROBE_BELOW_RATIO`]
    /// (or with the static seed's k0·ε_R below [`PROBE_BELOW_SEED_K_EPS`], near the Rayleigh
    /// speed): the root may lie below k = 1, where the fast route applies, while iterates above
    /// it pay graded layouts. One evaluation at k = 1 (the one-shot fast route) tells the side
    /// and starts Newton from there with the bracket's end at λ = 0: from above 1, not above the
    /// static seed (speed lowers k) nor, away from the Rayleigh speed, more than a factor e²
    /// below it; from below, at most a factor e² below 1.
    fn probe_k_one(&mut self) -> Result<()> {
        let near_rayleigh = self.lam.to_f64().exp() * self.pole_width < PROBE_BELOW_SEED_K_EPS;
        if !(self.lam.is_positive() && (self.ratio.to_f64() < PROBE_BELOW_RATIO || near_rayleigh)) {
            return Ok(());
        }
        let p = self.prec();
        let (zero, two) = (T::zero(p), T::from_i64(2, p));
        let (f, df, _) = self.eval(&zero, None, true)?;
        self.spent += 1;
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

    /// The double-double stage's Halley step from the `f64` root ([`halley_from_f64`]): one
    /// evaluation with derivatives. `None` (and a Newton step taken instead) when its bounds do
    /// not reach ε — near the Rayleigh speed, where the `f64` stage solved inputs rounded to
    /// `f64`.
    fn halley_step(&mut self, c: &Chord<T>) -> Result<Option<Shape<T>>> {
        let lam = self.lam.clone();
        let (f, df, ci) = self.eval(&lam, None, false)?;
        self.spent += 1;
        let scale = lam.clone().abs().max_of(T::one(self.prec()));
        if let Some((root, err, ints)) = halley_from_f64(&lam, &f, &df, &ci, c, &self.eps, &scale) {
            return Ok(Some(finish(
                root.clone(),
                &root,
                ints,
                self.ratio,
                err,
                self.spent,
            )));
        }
        if df.is_positive() && df.is_finite() {
            self.lam = lam - f / &df;
        }
        Ok(None)
    }

    /// The Newton iteration proper: evaluate, step, stop.
    fn iterate(mut self) -> Result<(Shape<T>, Option<Chord<T>>)> {
        let p = self.prec();
        while self.spent < self.budget {
            let lam = self.lam.clone();
            let (f, df, ci) = self.eval(&lam, self.chord.as_ref(), false)?;
            self.spent += 1;
            if f.is_zero() {
                let shape = finish(lam.clone(), &lam, ci, self.ratio, T::zero(p), self.spent);
                return Ok((shape, self.fresh_slope));
            }
            if f.is_negative() {
                self.lo = Some(lam.clone());
            } else {
                self.hi = Some(lam.clone());
            }
            let (next, was_newton, cut) = self.next_iterate(&f, &df);
            if cut {
                self.reach = self.reach.clone().mul_pow2(1);
            }
            let step = (next.clone() - &lam).abs();
            let scale = lam.clone().abs().max_of(T::one(p));
            // How far the derivative used for this step lies behind (0 for a Newton step).
            let age = self
                .chord
                .as_ref()
                .map_or_else(|| T::zero(p), |c| (lam.clone() - &c.lam).abs() + &c.rel_err);
            let fresh = self.chord.is_none();
            let here = fresh.then(|| Point {
                lam: lam.clone(),
                f,
                df,
                ints: ci.clone(),
            });
            if let Some(done) = self.hermite_stop(here.as_ref(), was_newton, &scale) {
                return Ok(done);
            }
            if let Some(h) = here {
                self.hand_on(&h);
                self.prev = Some(h);
            }
            self.lam = next;
            if let Some(shape) = self.converged(&lam, ci, &step, &age, &scale, was_newton) {
                return Ok((shape, self.fresh_slope));
            }
            self.plan_chord(&step, &scale, was_newton, fresh);
            self.last_step = Some(step);
        }
        Err(Error::NoConvergence {
            what: "Newton iteration for the axis ratio k",
            iterations: self.spent,
            reached: self.last_step.map(|s| short(&s)).unwrap_or_default(),
        })
    }

    /// The next iterate from F, F′ at λ: the Newton (or chord) step — or the asymptotic step for
    /// k ≫ 1 ([`log_model_step`], where it lands at k·ε_R ≥ [`MODEL_MIN_K_EPS`]) — when it stays
    /// inside the bracket; bisection when it does not; unbracketed, the step cut to the reach
    /// and never past a known end. The reach starts at 2 (a factor e² in k) and doubles after
    /// each cut step, as long as the longer step stays inside `lam_range` (else 2): far from the
    /// root F grows like 2|λ| (I1 ~ k^{−2} as k → 0, I2 ~ 1/k as k → ∞), so that a root at
    /// |λ| = L takes about log₂ L cut steps instead of L/2 — near the Rayleigh speed the root
    /// falls to k ~ (1 − M_R)^{1/4}, λ ≈ −576 at 1 − M_R = 10⁻¹⁰⁰⁰. Returns the iterate, whether
    /// it is a full Newton step (which the stopping rules assume) and whether it was cut.
    #[inline]
    fn next_iterate(&self, f: &T, df: &T) -> (T, bool, bool) {
        let p = self.prec();
        let lam = &self.lam;
        let newton = (df.is_positive() && df.is_finite()).then(|| {
            let model = log_model_step(lam.to_f64(), f.to_f64(), df.to_f64())
                .filter(|d| (lam.to_f64() + d).exp() * self.pole_width >= MODEL_MIN_K_EPS);
            match model {
                Some(d) => lam.clone() + T::from_f64(d, p),
                None => lam.clone() - f.clone() / df,
            }
        });
        let half_way = |end: &T| (lam.clone() + end).mul_pow2(-1);
        match (&self.lo, &self.hi, newton) {
            // Inside the closed bracket (a converged step may land on its end).
            (Some(l), Some(h), Some(n)) if n >= *l && n <= *h => (n, true, false),
            (Some(l), Some(h), _) => ((l.clone() + h).mul_pow2(-1), false, false),
            (lo, hi, Some(n)) => {
                let cut =
                    |r: &T| lam.clone() + (n.clone() - lam).min_of(r.clone()).max_of(-r.clone());
                let mut next = cut(&self.reach);
                let x = next.to_f64();
                if !(x >= self.lam_range.0 && x <= self.lam_range.1) {
                    next = cut(&T::from_i64(2, p));
                }
                match (lo, hi) {
                    (Some(l), _) if next <= *l => (half_way(l), false, false),
                    (_, Some(h)) if next >= *h => (half_way(h), false, false),
                    _ => {
                        let full = next == n;
                        (next, full, !full)
                    }
                }
            }
            (Some(_), None, None) => (lam.clone() + T::one(p), false, false),
            (None, _, None) => (lam.clone() - T::one(p), false, false),
        }
    }

    /// The Hermite stop ([`hermite_root`]): with F, F′ at this and the previous iterate, the
    /// cubic through them gives the root's remaining step h to O(D²h²), and I1, I2 are carried
    /// by their own cubics — one evaluation fewer than Newton's stop where the step is ≲ 10⁻⁶
    /// but not yet ≲ 10⁻⁹. Only for unseeded solves that may end on any evaluation.
    #[inline]
    fn hermite_stop(
        &self,
        here: Option<&Point<T>>,
        was_newton: bool,
        scale: &T,
    ) -> Option<(Shape<T>, Option<Chord<T>>)> {
        if !(self.allow_chord && !self.seeded && was_newton) {
            return None;
        }
        let (a, b) = (self.prev.as_ref()?, here?);
        let (root, err, ints) = hermite_root(a, b, &self.eps, scale)?;
        let slope = Chord {
            lam: b.lam.clone(),
            di1: b.ints.di1_dk(),
            di2: b.ints.di2_dk(),
            df: b.df.clone(),
            rel_err: T::zero(self.prec()),
            before: None,
        };
        Some((
            finish(root.clone(), &root, ints, self.ratio, err, self.spent),
            Some(slope),
        ))
    }

    /// Keeps this iterate's derivatives for the next stage. For its secants (F″, I″, the
    /// Halley step) a ladder stage (no chord steps) also keeps, of the last iterate with
    /// derivatives and the one kept before it, the one whose distance D from this iterate
    /// minimises the secant's error bound r/D + D (r = 2¹²ε, the derivatives' error bound).
    #[inline]
    fn hand_on(&mut self, h: &Point<T>) {
        let r = self.eps.to_f64() * 4096.0;
        let bound = |x: &T| {
            let d = (h.lam.clone() - x).to_f64().abs();
            if d > 0.0 {
                r / d + d
            } else {
                f64::INFINITY
            }
        };
        let before = self
            .fresh_slope
            .as_ref()
            .filter(|_| !self.allow_chord)
            .map(|c| match &c.before {
                Some(b) if bound(&b[0]) < bound(&c.lam) => b.clone(),
                _ => [c.lam.clone(), c.df.clone(), c.di1.clone(), c.di2.clone()],
            });
        self.fresh_slope = Some(Chord {
            lam: h.lam.clone(),
            di1: h.ints.di1_dk(),
            di2: h.ints.di2_dk(),
            df: h.df.clone(),
            rel_err: T::zero(self.prec()),
            before,
        });
    }

    /// The stopping rules after a step of length `step` from `lam_old` (the integrals `ci`
    /// are those at `lam_old`, carried to the new iterate by [`finish`]): the step is at
    /// rounding level, or stopped shrinking near it; or, once Newton is converging (from a
    /// seed, or after two steps), a step δ leaves an error ~δ² — δ·age for a chord step whose
    /// derivative is `age` behind — and 64 δ·max(δ, age) ≤ ε·scale², counted in the estimate,
    /// while the integrals' carry over δ ([`carry_error`]) stays below ε.
    #[inline]
    fn converged(
        &self,
        lam_old: &T,
        ci: Evaluation<T>,
        step: &T,
        age: &T,
        scale: &T,
        was_newton: bool,
    ) -> Option<Shape<T>> {
        let eps = &self.eps;
        let small = *step <= scale.clone() * &eps.clone().mul_i64(4);
        let stalled = self
            .last_step
            .as_ref()
            .is_some_and(|s| step >= s && *step <= scale.clone() * &eps.clone().mul_i64(64));
        if small || stalled {
            return Some(finish(
                self.lam.clone(),
                lam_old,
                ci,
                self.ratio,
                step.clone(),
                self.spent,
            ));
        }
        let projected = step.clone() * &step.clone().max_of(age.clone()).mul_i64(64);
        let quadratic = self.seeded || self.spent >= 3;
        // The integrals' carry over the step (|dk/k| ≈ step; the derivatives' relative error
        // ≲ 8·age) is also held to ε.
        let carry = carry_error(step, &age.clone().mul_i64(8));
        if was_newton && quadratic && projected <= eps.clone() * &scale.square() && carry <= *eps {
            let err = projected / scale;
            return Some(finish(
                self.lam.clone(),
                lam_old,
                ci,
                self.ratio,
                err,
                self.spent,
            ));
        }
        None
    }

    /// Chord steps at the end: when the next evaluation is expected to be the last (its step
    /// ~δ², so that δ³ ≤ ε/64), it skips the k-derivatives and steps with this iterate's F′,
    /// which costs no convergence at that distance (a wrong guess costs no accuracy — the stop
    /// counts the derivative's age — and at most one more evaluation without derivatives).
    /// A chord slope used for this step (not `fresh`) is kept for the next while the steps stay
    /// full ones (the ladder's successive chord steps with a lower precision's F′); an
    /// intermediate ladder stage (no chord steps allowed) takes one chord step with the lower
    /// precision's derivative and then evaluates the derivatives, so that it hands on its own F′
    /// (a precision's worth of chord contraction) to the next stage.
    #[inline]
    fn plan_chord(&mut self, step: &T, scale: &T, was_newton: bool, fresh: bool) {
        let past_first = self.seeded || self.spent >= 2;
        if self.allow_chord && was_newton && past_first && fresh {
            let cube = step.square() * step;
            if cube.mul_i64(64) <= self.eps.clone() * &scale.square() * scale {
                self.chord = self.fresh_slope.clone();
            }
        } else if !was_newton || !self.allow_chord {
            self.chord = None;
        }
    }
}

/// Below this curvature ratio an unseeded solve whose static seed lies above k = 1 first
/// evaluates at k = 1 ([`Newton::probe_k_one`]; evidence: `docs/calibration.md`).
const PROBE_BELOW_RATIO: f64 = 30.0;

/// ... and at any ratio when the static seed k0 has k0·ε below this (ε = √(1 − M_R²)): near the
/// Rayleigh speed the root falls far below the static seed (evidence: `docs/calibration.md`).
const PROBE_BELOW_SEED_K_EPS: f64 = 0.5;

/// The asymptotic step of [`log_model_step`] is taken only when it lands at kε ≥ this
/// (ε = √(1 − M_R²)): its form assumes the Rayleigh pole's width ε ≫ 1/k (evidence:
/// `docs/calibration.md`).
const MODEL_MIN_K_EPS: f64 = 5.0;

/// A long first step above k = 1 from the asymptotic form of (33) for k ≫ 1: I2 ≈ 2g(V)/k and
/// I1 ≈ (2/k³)(g(V)(ln 4k − 1) + J(ν, M_R)), so F(λ) ≈ 2λ − ln(λ + c) + d. The two constants
/// are fitted to F and F′ at the iterate (λ + c = 1/(2 − F′)) and the model solved for the step
/// Δ in `f64`: g(Δ) = F + 2Δ − ln(1 + Δ/(λ + c)) = 0 on the model's increasing branch
/// λ + c + Δ > 1/2. g is convex there and g ≥ 0 at Newton's step, so Newton's method on g from
/// that step falls monotonically to the root when one exists. `None` (a plain Newton step
/// instead) below k = 1, where the Newton step is short (|F/F′| ≤ 10⁻²: the last steps stay
/// Newton's, whose error the stopping rule assumes), where the fit does not apply (F′ ∉ (0, 2)),
/// where the model has no root on its branch (far from the asymptotic regime, e.g. kε ≲ 1 near
/// the Rayleigh speed), or where its step is not within a factor 4 of Newton's. The caller also
/// drops it where it lands at kε < [`MODEL_MIN_K_EPS`].
fn log_model_step(lam: f64, f: f64, df: f64) -> Option<f64> {
    let newton = -f / df;
    if !(lam > 0.0 && newton.abs() > 1e-2 && df > 0.0 && df < 2.0) {
        return None;
    }
    let q0 = 1.0 / (2.0 - df);
    let g = |d: f64| f + 2.0 * d - (d / q0).ln_1p();
    let mut d = newton;
    // Converged when a step falls below 1e-10 (1 + |d|): then |g| ≤ 2·10⁻¹⁰(1 + |d|), as
    // 0 < g′ ≤ 2 on the branch.
    let mut converged = false;
    for _ in 0..30 {
        let step = g(d) / (2.0 - 1.0 / (q0 + d));
        d -= step;
        if (q0 + d).is_nan() || q0 + d <= 0.5 {
            return None;
        }
        if step.abs() <= 1e-10 * (1.0 + d.abs()) {
            converged = true;
            break;
        }
    }
    let ratio = d / newton;
    (converged && (0.25..=4.0).contains(&ratio)).then_some(d)
}

/// An iterate with its F, F′ and integrals with their k-derivatives (the Hermite stop).
struct Point<T: Real> {
    lam: T,
    f: T,
    df: T,
    ints: Evaluation<T>,
}

/// The cubic through (x_b, y_b, y′_b) and (x_a, y_a, y′_a), as coefficients c2, c3 of
/// y(x_b + h) = y_b + y′_b h + c2 h² + c3 h³.
fn hermite_coefficients<T: Real>(d: &T, ya: &T, yb: &T, dya: &T, dyb: &T) -> (T, T) {
    let c3 = ((dya.clone() + dyb) * d - (ya.clone() - yb).mul_i64(2)) / (d.square() * d);
    let c2 = (dya.clone() - dyb) / d.clone().mul_i64(2) - (c3.clone() * d).mul_i64(3).mul_pow2(-1);
    (c2, c3)
}

/// y(x + h) and y′(x + h) for y(x + h) = y + y′h + c2h² + c3h³: the integrals carried from an
/// evaluated iterate to the root (the Hermite stop and the double-double Halley step).
fn carry_cubic<T: Real>(y: &T, dy: &T, c2: &T, c3: &T, h: &T) -> (T, T) {
    let val = y.clone() + (dy.clone() + (c2.clone() + c3.clone() * h) * h) * h;
    let der = dy.clone() + (c2.clone().mul_i64(2) + c3.clone().mul_i64(3) * h) * h;
    (val, der)
}

/// The Hermite stop of [`solve_core`]: from iterates `a` (earlier) and `b` (this one, both with
/// derivatives), the root λ_b + h of the cubic through F, F′ at both, and I1, I2 (with their
/// k-derivatives) carried to it by the cubics through their values and k-derivatives. Taken when
/// |h| ≤ |D|/8 (D = λ_a − λ_b) and 8(1 + |c3|)D²h²/F′ ≤ ε·scale, the interpolation error
/// (F⁗/24)D²h²/F′ with |F⁗| ≤ 24(1 + |c3|) assumed, c3 the cubic's F‴/6 (measured F″, F‴ of
/// order 0.01–1 in λ). The integrals are interpolated in k: at the root x, the remainder
/// I⁗(ξ)/24·(x − k_a)²(x − k_b)² relative to I(x) is at most
/// 16·((x − k_a)/x)²((x − k_b)/x)²·(x/k_min)⁷ for I ∝ k^-s ln k with s ≤ 3 (k⁴|I⁗|/24I ≤ 16:
/// 15 for I1 ∝ ln k/k³ at k ≫ 1, 5 for I1 ∝ k⁻² at k ≪ 1; ξ ≥ k_min, the least of the three
/// k); also required ≤ ε and added to the integrals' error estimate.
/// Returns λ, the error bound in λ, and the carried integrals.
fn hermite_root<T: Real>(
    a: &Point<T>,
    b: &Point<T>,
    eps: &T,
    scale: &T,
) -> Option<(T, T, Evaluation<T>)> {
    let d = a.lam.clone() - &b.lam;
    if d.is_zero() || !b.df.is_positive() {
        return None;
    }
    let (c2, c3) = hermite_coefficients(&d, &a.f, &b.f, &a.df, &b.df);
    // h: Newton's step corrected twice by the cubic's terms (|c2 h| ≪ F′ here).
    let newton = -(b.f.clone() / &b.df);
    let mut h = newton.clone();
    for _ in 0..2 {
        h = newton.clone() - (c2.clone() + c3.clone() * &h) * &h.square() / &b.df;
    }
    let (hf, df_, c3f) = (h.to_f64().abs(), d.to_f64().abs(), c3.to_f64().abs());
    let err = 8.0 * (1.0 + c3f) * df_ * df_ * hf * hf / b.df.to_f64();
    // The integrals, in k: Hermite cubics from the two iterates' values and k-derivatives.
    let (ka, kb) = (a.lam.clone().exp(), b.lam.clone().exp());
    let x = (b.lam.clone() + &h).exp();
    let least = ka.clone().min_of(kb.clone()).min_of(x.clone());
    let dk = ka.clone() - &kb;
    let hk = x.clone() - &kb;
    let rel = |y: T| (y / &x).to_f64();
    let carry_err = 16.0 * (rel(x.clone() - &ka) * rel(hk.clone())).powi(2) * rel(least).powi(-7);
    let epsf = eps.to_f64();
    let fine = err <= epsf * scale.to_f64() && carry_err <= epsf;
    if !(hf * 8.0 <= df_ && fine && err.is_finite() && carry_err.is_finite()) {
        return None;
    }
    let carry = |ya: &T, yb: &T, dya: &T, dyb: &T| {
        let (c2, c3) = hermite_coefficients(&dk, ya, yb, dya, dyb);
        carry_cubic(yb, dyb, &c2, &c3, &hk)
    };
    let (ia, ib) = (&a.ints, &b.ints);
    let (i1, di1) = carry(&ia.i1, &ib.i1, &ia.di1_dk(), &ib.di1_dk());
    let (i2, di2) = carry(&ia.i2, &ib.i2, &ia.di2_dk(), &ib.di2_dk());
    let carried = T::from_f64(carry_err, eps.prec());
    let ints = Evaluation {
        i1,
        i2,
        dk: Some([di1, di2]),
        error_estimate: ib.error_estimate.clone() + &carried,
        extra_error: ib.extra_error.clone() + &carried.sqrt(),
        ..ib.clone()
    };
    Some((b.lam.clone() + h, T::from_f64(err, eps.prec()), ints))
}

/// F″ at λ0 and its error bound, the first part of [`curvature`] (which needs no evaluation at
/// λ0, so that the ladder decides before evaluating whether the Halley step can work).
fn f_second<T: Real>(c: &Chord<T>, lam0: &T) -> Option<(f64, f64)> {
    let b = c.before.as_ref()?;
    let (la, lb) = (b[0].to_f64(), c.lam.to_f64());
    let d = (lb - la).abs();
    if d == 0.0 {
        return None;
    }
    let f2 = (c.df.to_f64() - b[1].to_f64()) / (lb - la);
    let off = (lam0.to_f64() - lb).abs();
    let f2_err = 2.0 * c.rel_err.to_f64() * c.df.to_f64().abs() / d + (1.0 + f2.abs()) * (d + off);
    (f2_err.is_finite() && f2_err <= 0.1).then_some((f2, f2_err))
}

/// F″ and d²I1/dk², d²I2/dk² at λ0 by secants between the lower-precision stage's last two
/// iterates with derivatives (`c` and `c.before`, F′ and I′ with relative error r = `c.rel_err`),
/// with bounds on their errors: 2r|F′|/D + (1 + |F″|)(D + |λ0 − λ_c|) for F″ (rounding over the
/// distance D between the iterates, the secant's truncation with |F‴| ≤ 1 + |F″| assumed), and
/// 2r|I′|/Δk + 100(I/k³)(Δk + |k0 − k_c|) for I″ (|k³I‴| ≤ 100 I assumed: 60 for
/// I1 ∝ ln k/k³; `ints` gives I at λ0). `None` when the F″ bound exceeds 0.1 (D too small for the
/// rounding or too large for the truncation).
fn curvature<T: Real>(
    c: &Chord<T>,
    lam0: &T,
    ints: &Evaluation<T>,
) -> Option<([f64; 3], [f64; 3])> {
    let (f2, f2_err) = f_second(c, lam0)?;
    let b = c.before.as_ref()?;
    let r = c.rel_err.to_f64();
    let (la, lb) = (b[0].to_f64(), c.lam.to_f64());
    let (ka, kb, k0) = (la.exp(), lb.exp(), lam0.to_f64().exp());
    let dk = kb - ka;
    let reach = dk.abs() + (k0 - kb).abs();
    let second = |dia: &T, dib: &T| (dib.to_f64() - dia.to_f64()) / dk;
    let i_err = |di: &T, i: &T| {
        2.0 * r * di.to_f64().abs() / dk.abs() + 100.0 * i.to_f64() * reach / k0.powi(3)
    };
    Some((
        [f2, second(&b[2], &c.di1), second(&b[3], &c.di2)],
        [f2_err, i_err(&c.di1, &ints.i1), i_err(&c.di2, &ints.i2)],
    ))
}

/// The double-double step of the ladder straight from the `f64` stage: with F, F′ and the
/// integrals' k-derivatives at the `f64` root λ0 (this precision) and F″, I″ from the `f64`
/// stage ([`curvature`]), a Halley step h = δ − F″δ²/(2F′) (δ = −F/F′, error ≤
/// (|ΔF″|/2F′)δ² + |δ|³) and I1, I2 carried to second order (relative error ≤ ½|ΔI″|dk²/I).
/// Taken when the first bound is ≤ ε·scale/4 and the second ≤ ε: one evaluation with
/// derivatives instead of two chord evaluations without.
fn halley_from_f64<T: Real>(
    lam: &T,
    f: &T,
    df: &T,
    ints: &Evaluation<T>,
    c: &Chord<T>,
    eps: &T,
    scale: &T,
) -> Option<(T, T, Evaluation<T>)> {
    let ([f2, i1pp, i2pp], [f2_err, i1_err, i2_err]) = curvature(c, lam, ints)?;
    if !(df.is_positive() && df.is_finite()) {
        return None;
    }
    let p = eps.prec();
    let newton = -(f.clone() / df);
    let (nf, dff) = (newton.to_f64().abs(), df.to_f64());
    let err = f2_err / (2.0 * dff) * nf * nf + nf * nf * nf;
    let epsf = eps.to_f64();
    if !(err.is_finite() && err <= epsf * scale.to_f64() / 4.0) {
        return None;
    }
    let h = newton.clone() - T::from_f64(f2, p) * newton.square() / df.clone().mul_i64(2);
    let k0 = lam.clone().exp();
    let dk = (lam.clone() + &h).exp() - &k0;
    let dkf = dk.to_f64();
    let zero = T::zero(p);
    let carry = |i: &T, di: &T, ipp: f64, ipp_err: f64| -> (T, T, f64) {
        let (val, der) = carry_cubic(i, di, &T::from_f64(ipp / 2.0, p), &zero, &dk);
        (val, der, 0.5 * ipp_err * dkf * dkf / i.to_f64())
    };
    let (i1, di1, e1) = carry(&ints.i1, &ints.di1_dk(), i1pp, i1_err);
    let (i2, di2, e2) = carry(&ints.i2, &ints.di2_dk(), i2pp, i2_err);
    if !(e1.is_finite() && e2.is_finite() && e1.max(e2) <= epsf) {
        return None;
    }
    let carried = T::from_f64(e1.max(e2), p);
    let ints = Evaluation {
        i1,
        i2,
        dk: Some([di1, di2]),
        error_estimate: ints.error_estimate.clone() + &carried,
        extra_error: ints.extra_error.clone() + &carried.sqrt(),
        ..ints.clone()
    };
    Some((lam.clone() + h, T::from_f64(err, p), ints))
}

/// The relative error of carrying I1, I2 a relative distance `moved` = |dk/k| to first order
/// with k-derivatives of relative error `r`: the Taylor remainder ½|k²I″/I|·moved² with
/// ½|k²I″/I| ≤ 8 (6 for I1 ∝ ln k/k³ at k ≫ 1, with room for I″ between the two k), plus the
/// derivatives' error through |kI′/I| ≤ 4: 16·moved² + 4r·moved (valid for moved ≤ 1/8, which
/// the stopping rules keep: [`Newton::converged`]).
fn carry_error<T: Real>(moved: &T, r: &T) -> T {
    (moved.clone().mul_i64(16) + &r.clone().mul_i64(4)) * moved
}

/// The derivatives kept for chord steps: at λ = `lam`, dI1/dk, dI2/dk and F′, with F′'s
/// relative error when it comes from a lower precision (0 otherwise).
#[derive(Clone)]
struct Chord<T> {
    lam: T,
    di1: T,
    di2: T,
    df: T,
    rel_err: T,
    /// The previous iterate with derivatives: λ, F′, dI1/dk, dI2/dk (for second derivatives by
    /// secants, [`halley_from_f64`]).
    before: Option<[T; 4]>,
}

/// F(λ) = ln(I2/(I1·A1/B1)) of the shape equation (33), whose root in λ = ln k the solve finds
/// (the quotient formed first, so that F near its root carries a few ε absolute).
fn shape_residual<T: Real>(ci: &Evaluation<T>, ratio: &T) -> T {
    (ci.i2.clone() / &ci.i1 / ratio).ln()
}

/// F′ = dF/dλ = k (I2′/I2 − I1′/I1) at k from the k-derivatives of `ci`.
fn shape_slope<T: Real>(k: &T, ci: &Evaluation<T>) -> T {
    k.clone() * (ci.di2_dk() / &ci.i2 - ci.di1_dk() / &ci.i1)
}

/// Carries I1, I2 of `ci` from `k_old` to `k` to first order, I(k) ≈ I(k_old) + I′(k_old)(k − k_old):
/// their error estimate grows by the carry's error ([`carry_error`]) and the derivatives',
/// which stay those at `k_old`, by ≲ |k I″/I′|·|dk/k| with |k I″/I′| ≤ 8 (5 for I1 ∝ ln k/k³).
fn carry<T: Real>(ci: &mut Evaluation<T>, k_old: &T, k: &T) {
    let dk = k.clone() - k_old;
    ci.i1 += &(ci.di1_dk() * &dk);
    ci.i2 += &(ci.di2_dk() * &dk);
    let moved = (dk / k).abs();
    ci.error_estimate += &carry_error(&moved, &ci.extra_error);
    ci.extra_error += &moved.mul_i64(8);
}

/// Above this |λ| = |ln k| the solve ends with a Newton step in k itself ([`finish`]): below it
/// e^λ's rounding, at most |λ|ε/2 = 4ε relative, stays in k (and in its bound), where the step
/// would cost about 5–10% of an `f64` solve (an exponential and a logarithm;
/// docs/calibration.md).
const STEP_IN_K_ABOVE: f64 = 8.0;

/// The shape at λ = ln k from the integrals `ci` evaluated at the previous iterate `lam_old`,
/// `last_step` a bound on |λ − λ*| (the step that stopped the iteration, or the Halley and
/// Hermite stops' own estimate). I1, I2 are carried to k = e^λ ([`carry`]).
///
/// That k inherits λ's rounding, half an ulp of λ, as a relative error up to |λ|ε/2. Up to
/// |λ| = [`STEP_IN_K_ABOVE`] the bound carries it: (δI2/I2 + δI1/I1)/F′ (F′ ≥ ~1 here; 1/4 is
/// the floor) plus twice the last step plus (|λ| + 4)ε. Above (λ ≈ −576 at 1 − M_R = 10⁻¹⁰⁰⁰),
/// one Newton step is taken in k itself on the carried integrals: F = ln(I2/(I1·A1/B1)) there,
/// and k ← k·e^{−F/F′} with I1, I2 carried again. Its result's relative error is bounded by
///
/// * the integrals' error through F: (δI2/I2 + δI1/I1 + 4ε)/F′;
/// * the step's own error from F′'s, |F/F′|·8(r + δI/I)/F′ with r the derivatives' relative
///   error (|k I′/I| ≤ 4 each);
/// * the second-order remainder of both steps, 16·(|λ − λ*| + |F/F′|)²;
/// * the rounding of e^{−F/F′} and of the product, 4ε.
///
/// Where F′ is not positive and finite no step is taken, and the first bound applies.
fn finish<T: Real>(
    lam: T,
    lam_old: &T,
    mut ci: Evaluation<T>,
    ratio: &T,
    last_step: T,
    iterations: usize,
) -> Shape<T> {
    let p = lam.prec();
    let eps = T::epsilon(p);
    let lam_abs = lam.clone().abs();
    let stepped = lam.exp();
    let own = ci.error_estimate.clone();
    carry(&mut ci, &lam_old.clone().exp(), &stepped);
    let df = shape_slope(&stepped, &ci);
    let floor = df.clone().abs().max_of(T::from_ratio(1, 4, p));
    if lam_abs.to_f64() <= STEP_IN_K_ABOVE || !(df.is_positive() && df.is_finite()) {
        let prop = own.mul_i64(2) / &floor;
        return Shape {
            error_estimate: prop + &last_step.mul_i64(2) + &(eps * &(lam_abs + &T::from_i64(4, p))),
            k: stepped,
            integrals: ci,
            iterations,
        };
    }
    let delta = shape_residual(&ci, ratio) / &df;
    let k = stepped.clone() * &(-delta.clone()).exp();
    carry(&mut ci, &stepped, &k);
    let through_f = (ci.error_estimate.clone().mul_i64(2) + &eps.clone().mul_i64(4)) / &floor;
    let df_error = (ci.extra_error.clone() + &ci.error_estimate).mul_i64(8) / &floor;
    let second = (last_step.abs() + &delta.clone().abs())
        .square()
        .mul_i64(16);
    Shape {
        error_estimate: through_f + &(delta.abs() * &df_error) + &second + &eps.mul_i64(4),
        k,
        integrals: ci,
        iterations,
    }
}

impl<T: Real> ShapeSolver<T> {
    /// The precision ladder (module docs): solves at `f64` first (inputs rounded to `f64`, the speed by its gap),
    /// above 106 bits then at double-double, above 1024 bits at half the precision
    /// ([`ShapeSolver::via_mid`]), and refines the root at the working precision of `T`
    /// from the last stage's root and derivative — one Halley step or two chord steps at
    /// double-double, two chord steps at 256 bits, three at 512 — a few high-precision
    /// evaluations of the integrals instead of a search. At `f64` it is the plain solve. If a lower
    /// stage fails (inputs beyond its range), the working precision solves on its own from the
    /// static seed. The `f64` stage starts from `guess` when given. `tol`: the tolerance on k at
    /// the working precision (`None`: its floor).
    fn ladder(&self, ratio: &T, tol: Option<T>, guess: Option<f64>) -> Result<Shape<T>> {
        self.climb(ratio, tol, guess, true).map(|(s, _)| s)
    }

    /// The ladder of [`ShapeSolver::ladder`], returning the working precision's last
    /// derivatives too; `allow_chord`: whether its last evaluation may skip the k-derivatives
    /// (false for a stage that hands them on, [`ShapeSolver::via_mid`]).
    fn climb(&self, ratio: &T, tol: Option<T>, guess: Option<f64>, allow_chord: bool) -> Handed<T> {
        let p = ratio.prec();
        if T::bits(p) <= 53 {
            return lowest_stage(&self.top, ratio, allow_chord, tol, guess);
        }
        if let Some(done) = self.via_mid(ratio, &tol, guess, allow_chord) {
            return done;
        }
        let alone = |tol: Option<T>| lowest_stage(&self.top, ratio, allow_chord, tol, None);
        // Each stage ends on a Newton step (no chord), so that its last derivatives lie one
        // rounding-level step from its root and serve the next stage's chord steps.
        let ratio64 = ratio.to_f64();
        let stage64 = match self.lower(&self.stage64) {
            Some(ev) => lowest_stage(ev, &ratio64, false, None, guess),
            None => return alone(tol),
        };
        let (k64, slope64) = match stage64 {
            Ok((s, c)) => (s.k, c),
            Err(_) => return alone(tol),
        };
        // Above double-double, a double-double stage in between: its root is off by ~2^-100,
        // so the target precision needs one Newton step fewer (two chord steps up to ~600 bits).
        if T::bits(p) > 106 {
            if let Some(shape) = self.via_dd(ratio, &tol, k64, slope64.as_ref(), allow_chord) {
                return shape;
            }
        }
        let seed = T::from_f64(k64, p);
        // Straight from the f64 stage at double-double: one evaluation with derivatives and a
        // Halley step ([`halley_from_f64`]) — unless the f64 stage's inputs, rounded to f64,
        // moved the root by more than ~1e-15, where one step cannot reach ε and two chord steps
        // are cheaper than the Halley attempt and a Newton step. k's sensitivity to the
        // relative change of the gap 1 − M_R is about 1/4.
        let moved = |x: &T| {
            let x64 = x.to_f64();
            (x.clone() - T::from_f64(x64, p)).abs().to_f64() / x64.abs().max(f64::MIN_POSITIVE)
        };
        let speed = self.top.speed();
        let perturbation = moved(ratio) + moved(speed.material().nu()) + moved(speed.gap());
        let stage = Stage {
            seed: Some(&seed),
            seed_slope: slope64
                .as_ref()
                .map(|c| lift(c, p, T::from_f64(F64_SLOPE, p), T::from_f64(F64_SEED, p))),
            halley: T::bits(p) <= 106 && perturbation <= 1e-15,
            allow_chord,
            tol,
            ..Stage::final_stage()
        };
        solve_core(&self.top, ratio, stage)
    }

    /// Above [`MID_ABOVE_BITS`], the ladder's stage below the working precision p is the same
    /// solve at m = p/2 + [`MID_GUARD_BITS`] bits (itself a ladder): its root, off by ~2^-m,
    /// and its F′, good to ~2^-m, leave one or two chord steps at p (each contracts the error by
    /// F′'s accuracy), evaluations without k-derivatives — instead of Newton's steps with them
    /// from the double-double root (six at 4096 bits). The stage's root error is bounded by its
    /// own estimate and by 2^(11−m), its F′'s by 2^(16−m): the double-double stage's margins
    /// ([`DD_SEED`], [`DD_SLOPE`]). A stage that ended on a chord step is given its
    /// derivatives by one more evaluation at its own precision ([`slope_at`]). `None` (the
    /// ladder goes on from `f64`) at or below [`MID_ABOVE_BITS`], for the fixed-precision
    /// types, and when that stage fails.
    fn via_mid(
        &self,
        ratio: &T,
        tol: &Option<T>,
        guess: Option<f64>,
        allow_chord: bool,
    ) -> Option<Handed<T>> {
        let p = ratio.prec();
        let bits = T::bits(p);
        if bits <= MID_ABOVE_BITS {
            return None;
        }
        let pm = T::lower_prec(p, bits / 2 + MID_GUARD_BITS)?;
        let mid = self
            .stage_mid
            .get_or_init(|| {
                let speed = self.top.speed().at::<T>(pm).ok()?;
                ShapeSolver::new(&speed, self.top.method())
                    .ok()
                    .map(Box::new)
            })
            .as_deref()?;
        let ratio_m = ratio.with_prec(pm);
        let (s, c) = mid.climb(&ratio_m, None, guess, false).ok()?;
        // A stage that ended on a chord step hands on no derivatives: one evaluation with them
        // at its root (at its precision).
        let c = c.or_else(|| slope_at(&mid.top, &ratio_m, s.k.clone().ln()))?;
        let m = T::bits(pm) as i32;
        let one = T::one(p);
        let seed_err = s
            .error_estimate
            .with_prec(p)
            .max_of(one.clone().mul_pow2(11 - m));
        let seed = s.k.with_prec(p);
        let stage = Stage {
            seed: Some(&seed),
            seed_slope: Some(lift(&c, p, one.mul_pow2(16 - m), seed_err)),
            allow_chord,
            tol: tol.clone(),
            ..Stage::final_stage()
        };
        Some(solve_core(&self.top, ratio, stage))
    }

    /// The double-double stage from the `f64` root `k64` and its derivatives, then the working
    /// precision's stage from the double-double root; `None` when the double-double stage
    /// fails (the caller goes on from the `f64` root).
    fn via_dd(
        &self,
        ratio: &T,
        tol: &Option<T>,
        k64: f64,
        slope64: Option<&Chord<f64>>,
        allow_chord: bool,
    ) -> Option<Handed<T>> {
        let p = ratio.prec();
        let seed_dd = Dd::from_f64(k64, ());
        let stage = Stage {
            seed: Some(&seed_dd),
            seed_slope: slope64.map(|c| {
                lift(
                    c,
                    (),
                    Dd::from_f64(F64_SLOPE, ()),
                    Dd::from_f64(F64_SEED, ()),
                )
            }),
            allow_chord: false,
            ..Stage::final_stage()
        };
        let ratio_dd = Dd::from_float(&ratio.to_float(T::bits(p)), ());
        let (s, c) = solve_core(self.lower(&self.stage_dd)?, &ratio_dd, stage).ok()?;
        let seed = T::from_float(&s.k.to_float(106), p);
        let stage = Stage {
            seed: Some(&seed),
            seed_slope: c
                .as_ref()
                .map(|c| lift(c, p, T::from_f64(DD_SLOPE, p), T::from_f64(DD_SEED, p))),
            allow_chord,
            tol: tol.clone(),
            ..Stage::final_stage()
        };
        Some(solve_core(&self.top, ratio, stage))
    }
}

/// Bounds on a stage's derivative F′ (relative, with a margin over the fixed rules' measured
/// derivative errors) and on its root's error in λ (a few ε): `docs/calibration.md`.
const F64_SLOPE: f64 = 9.094947017729282e-13; // 2^-40
const F64_SEED: f64 = 3.552713678800501e-15; // 2^-48
const DD_SLOPE: f64 = 8.077935669463161e-28; // 2^-90
const DD_SEED: f64 = 2.524354896707238e-29; // 2^-95

/// A stage's derivatives carried to the precision `p` of the next, with their error bound and
/// the bound on the stage's root error.
fn lift<S: Real, T: Real>(c: &Chord<S>, p: T::Prec, slope_err: T, seed_err: T) -> (Chord<T>, T) {
    let up = |x: &S| T::from_float(&x.to_float(S::bits(x.prec())), p);
    (
        Chord {
            lam: up(&c.lam),
            di1: up(&c.di1),
            di2: up(&c.di2),
            df: up(&c.df),
            rel_err: slope_err,
            before: c.before.as_ref().map(|b| [0, 1, 2, 3].map(|i| up(&b[i]))),
        },
        seed_err,
    )
}

/// Above this working precision the ladder's stage below it is the same solve at about half
/// the precision ([`ShapeSolver::via_mid`]); at and below, the double-double root's chord
/// steps reach the working precision in at most four evaluations (1024 bits).
const MID_ABOVE_BITS: u32 = 1024;

/// Bits of the half-precision stage beyond half the working precision: its root and F′
/// (~2^-m each) leave a chord step's error ~2^-2m, 64 times that ≤ 2^-p with ~40 bits to spare.
const MID_GUARD_BITS: u32 = 32;

#[cfg(test)]
mod tests {
    use super::*;

    /// The seeds' stated accuracy against the static root (M_R = 0): the k ≫ 1 form within
    /// 1.5 % at A1/B1 = 30 and 0.01 % at 10⁶, Hamrock & Brewe's 2.3× too large at 10⁶.
    #[test]
    fn static_seeds_against_the_static_root() {
        let mat = crate::physics::Material::new(0.2f64).unwrap();
        let sp = mat.speed(0.0).unwrap();
        let solve = |ratio: f64| {
            solve_ellipse(&sp, &ratio, &Options::default())
                .unwrap()
                .k
                .value
        };
        for (ratio, tol) in [(30.0, 0.015), (1e3, 0.002), (1e6, 1e-4)] {
            let k = solve(ratio);
            let seed = static_seed(ratio);
            assert!(
                (seed / k - 1.0).abs() <= tol,
                "A1/B1 = {ratio}: seed {seed}, root {k}"
            );
        }
        let k = solve(1e6);
        let hb = 1e6f64.powf(std::f64::consts::FRAC_2_PI);
        assert!(
            hb / k > 2.2 && hb / k < 2.4,
            "Hamrock & Brewe {hb} against {k}"
        );
    }
}
