//! The shape of the contact ellipse, (33): given ν, M_R and the curvature ratio
//! A1/B1 = R2/R1 (R1 the punch's radius of curvature along the motion, R2 across it), the axis
//! ratio k = b/a (a along the motion, b across) solves
//!
//! ```text
//! I2(k)/I1(k) = A1/B1.
//! ```
//!
//! Newton's method on F(λ) = ln I2 − ln I1 − ln(A1/B1), λ = ln k, with F'(λ) = k (I2′/I2 − I1′/I1)
//! from the integrals' k-derivatives (differentiated under the integral sign), safeguarded by a
//! bracket: F increases with k (checked over ν, M_R and 10^-6 ≤ A1/B1 ≤ 10^6 in
//! `tests/ellipse.rs`), so a step leaving the bracket is replaced by bisection in λ.
//!
//! The start is the static solution (M_R = 0), whose ratio is k² D(e²)/(E(e²) − k² D(e²))
//! (D = (K − E)/e²), refined by the same Newton iteration on cheap elliptic integrals.
//!
//! **Precision ladder** ([`solve_ellipse`] with a seed): a solve at high precision is started from
//! the `f64` root, so Newton's quadratic convergence reaches 256 bits in 2–3 steps — a few
//! high-precision evaluations of the integrals, no search.

use crate::error::{Error, Result};
use crate::numerics::elliptic::{ellipd_mc, ellipke_mc};
use crate::physics::{Material, Speed};
use crate::routes::direct::{contact_integrals, ContactIntegrals};
use crate::routes::AxisRatio;
use crate::scalar::{check_finite, short, Real};

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
    pub fn label(&self) -> &'static str {
        match self {
            MajorAxis::Along => "along",
            MajorAxis::Across => "across",
        }
    }
}

/// The solved shape of the contact ellipse.
#[derive(Clone, Debug)]
pub struct EllipseShape<T: Real> {
    /// k = b/a, b across the motion, a along it.
    pub k: T,
    /// Eccentricity √(1 − (minor/major)²).
    pub e: T,
    /// Which axis is the major one.
    pub major: MajorAxis,
    /// The integrals at the solution (normalisation of (37)), with J0 and the k-derivatives.
    pub integrals: ContactIntegrals<T>,
    /// Estimated relative error of k (from the integrals' error and the last Newton step).
    pub error_estimate: T,
    /// Newton iterations (integral evaluations) spent.
    pub iterations: usize,
}

/// Checks a curvature ratio A1/B1 = R2/R1: positive and finite.
pub fn check_ratio<T: Real>(ratio: &T) -> Result<()> {
    check_finite("curvature ratio A1/B1", ratio)?;
    if !ratio.is_positive() {
        return Err(Error::Domain {
            name: "curvature ratio A1/B1 = R2/R1",
            value: short(ratio),
            bound: "(0, inf)",
        });
    }
    Ok(())
}

/// The static ratio I2/I1 at axis ratio k: k² D/(E − k² D), D = (K − E)/e², and its logarithmic
/// derivative d ln(ratio)/d ln k by a centred difference of the closed form.
fn static_log_ratio<T: Real>(k: &T) -> Result<T> {
    let k2 = k.square();
    let d = ellipd_mc(&k2)?;
    let (_, e) = ellipke_mc(&k2)?;
    let kd = k2 * d;
    Ok((kd.clone() / (e - kd)).ln())
}

/// The static solution k0 of k² D/(E − k² D) = ratio, in `f64` (a start for Newton).
fn static_seed(ratio: f64) -> f64 {
    // Bisection in ln k on the monotone static ratio, 60 steps over [1e-12, 1e12].
    let target = ratio.ln();
    let (mut lo, mut hi) = (-27.6f64, 27.6f64);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        match static_log_ratio(&mid.exp()) {
            Ok(v) if v < target => lo = mid,
            Ok(_) => hi = mid,
            Err(_) => break,
        }
    }
    (0.5 * (lo + hi)).exp()
}

/// How the integrals inside the ellipse solve are evaluated.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EllipseMethod {
    /// The cheapest available for the inputs.
    Auto,
    /// Adaptive vector quadrature of (46)–(47) and their k-derivatives
    /// ([`crate::routes::direct::contact_integrals`]).
    Quadrature,
}

impl EllipseMethod {
    /// `auto` or `quadrature`.
    pub fn label(&self) -> &'static str {
        match self {
            EllipseMethod::Auto => "auto",
            EllipseMethod::Quadrature => "quadrature",
        }
    }
    /// Parses a label.
    pub fn parse(s: &str) -> Result<EllipseMethod> {
        match s {
            "auto" => Ok(EllipseMethod::Auto),
            "quadrature" => Ok(EllipseMethod::Quadrature),
            _ => Err(Error::Parse {
                text: s.to_string(),
                reason: "expected auto or quadrature",
            }),
        }
    }
    /// The concrete method `Auto` stands for.
    pub fn resolve(self) -> EllipseMethod {
        match self {
            EllipseMethod::Auto => EllipseMethod::Quadrature,
            m => m,
        }
    }
}

/// The integrals and k-derivatives at one axis ratio by `method`.
fn evaluate<T: Real>(
    method: EllipseMethod,
    mat: &Material<T>,
    speed: &Speed<T>,
    axes: &AxisRatio<T>,
) -> Result<ContactIntegrals<T>> {
    match method.resolve() {
        _ => contact_integrals(mat, speed, axes, &T::zero(axes.k.prec())),
    }
}

/// Solves (33) for the axis ratio at the working precision of `ratio`, optionally from a seed
/// (the precision ladder: an `f64` root converted to `T`), with the integrals by
/// [`EllipseMethod::Auto`]. Accuracy: k to a few ε times the conditioning
/// |d ln k/d ln(A1/B1)| (≈ 1/2 for small k), with an error estimate.
pub fn solve_ellipse<T: Real>(
    mat: &Material<T>,
    speed: &Speed<T>,
    ratio: &T,
    seed: Option<&T>,
) -> Result<EllipseShape<T>> {
    solve_ellipse_seeded(mat, speed, ratio, seed, EllipseMethod::Auto)
}

/// [`solve_ellipse`] with a chosen method for the integrals.
pub fn solve_ellipse_seeded<T: Real>(
    mat: &Material<T>,
    speed: &Speed<T>,
    ratio: &T,
    seed: Option<&T>,
    method: EllipseMethod,
) -> Result<EllipseShape<T>> {
    check_ratio(ratio)?;
    let p = ratio.prec();
    let target = ratio.clone().ln();
    let k0 = match seed {
        Some(s) if s.is_positive() && s.is_finite() => s.clone(),
        _ => T::from_f64(static_seed(ratio.to_f64()), p),
    };
    let eval = |lnk: &T| -> Result<(T, T, ContactIntegrals<T>)> {
        let ax = AxisRatio::new(lnk.clone().exp())?;
        let ci = evaluate(method, mat, speed, &ax)?;
        let f = ci.i2.clone().ln() - ci.i1.clone().ln() - &target;
        let df = ax.k.clone() * (ci.di2_dk.clone() / &ci.i2 - ci.di1_dk.clone() / &ci.i1);
        Ok((f, df, ci))
    };
    let eps = T::epsilon(p);
    let mut lam = k0.ln();
    // Bracket [lo, hi] in λ with F(lo) < 0 < F(hi), grown as evaluations reveal signs.
    let mut lo: Option<T> = None;
    let mut hi: Option<T> = None;
    let mut last_step: Option<T> = None;
    for it in 0..200 {
        let (f, df, ci) = eval(&lam)?;
        if f.is_zero() {
            return Ok(finish(lam, ci, T::zero(p), it + 1));
        }
        if f.is_negative() {
            lo = Some(lam.clone());
        } else {
            hi = Some(lam.clone());
        }
        // Newton step, or bisection / bracket growth when Newton misbehaves.
        let newton = if df.is_positive() && df.is_finite() {
            Some(lam.clone() - f.clone() / &df)
        } else {
            None
        };
        let next = match (&lo, &hi, newton) {
            // Inside the closed bracket (a converged step may land on its end).
            (Some(l), Some(h), Some(n)) if n >= *l && n <= *h => n,
            (Some(l), Some(h), _) => (l.clone() + h).mul_pow2(-1),
            (_, _, Some(n)) => {
                // Unbracketed: limit the step to a factor e² in k.
                let two = T::from_i64(2, p);
                let step = n - &lam;
                lam.clone() + step.clone().min_of(two.clone()).max_of(-two)
            }
            (Some(_), None, None) => lam.clone() + T::one(p),
            (None, _, None) => lam.clone() - T::one(p),
        };
        let step = (next.clone() - &lam).abs();
        let scale = lam.clone().abs().max_of(T::one(p));
        lam = next;
        // Converged: the step is at rounding level, or stopped shrinking near it.
        let small = step <= scale.clone() * &eps.clone().mul_i64(4);
        let stalled = last_step
            .as_ref()
            .is_some_and(|s| step >= *s && step <= scale.clone() * &eps.clone().mul_i64(64));
        if small || stalled {
            // The integrals are those of the previous iterate, one rounding-level step away;
            // the step is part of the error estimate.
            return Ok(finish(lam, ci, step, it + 1));
        }
        last_step = Some(step);
    }
    Err(Error::NoConvergence {
        what: "Newton iteration for the axis ratio k",
        iterations: 200,
        reached: last_step.map(|s| short(&s)).unwrap_or_default(),
    })
}

fn finish<T: Real>(
    lam: T,
    ci: ContactIntegrals<T>,
    last_step: T,
    iterations: usize,
) -> EllipseShape<T> {
    let p = lam.prec();
    let one = T::one(p);
    let k = lam.exp();
    let (e, major) = if k <= one {
        (((one.clone() - &k) * (one + &k)).sqrt(), MajorAxis::Along)
    } else {
        let r = k.clone().recip();
        (((one.clone() - &r) * (one + &r)).sqrt(), MajorAxis::Across)
    };
    // δk/k ≈ (δI2/I2 + δI1/I1)/F′ + last step; F′ ≥ ~1 here, keep it simple and safe.
    let df = k.clone() * (ci.di2_dk.clone() / &ci.i2 - ci.di1_dk.clone() / &ci.i1);
    let prop = ci.error_estimate.clone().mul_i64(2) / df.abs().max_of(T::from_ratio(1, 4, p));
    EllipseShape {
        error_estimate: prop + last_step.mul_i64(2) + &T::epsilon(p).mul_i64(4),
        k,
        e,
        major,
        integrals: ci,
        iterations,
    }
}

/// The precision ladder: solves at `f64` first (inputs rounded to `f64`) and refines the root at
/// the working precision of `T` by Newton from that seed — a few high-precision evaluations of the
/// integrals instead of a search. For `T = f64` this is [`solve_ellipse`].
pub fn solve_ellipse_ladder<T: Real>(
    mat: &Material<T>,
    speed: &Speed<T>,
    ratio: &T,
) -> Result<EllipseShape<T>> {
    solve_ellipse_with(mat, speed, ratio, EllipseMethod::Auto)
}

/// The precision ladder with a chosen method for the integrals (the `f64` seed uses the same
/// method).
pub fn solve_ellipse_with<T: Real>(
    mat: &Material<T>,
    speed: &Speed<T>,
    ratio: &T,
    method: EllipseMethod,
) -> Result<EllipseShape<T>> {
    check_ratio(ratio)?;
    let p = ratio.prec();
    if T::bits(p) <= 53 {
        return solve_ellipse_seeded(mat, speed, ratio, None, method);
    }
    let mat64 = Material::new(mat.nu().to_f64())?;
    let mr = speed.mr.to_f64().min(1.0 - f64::EPSILON);
    let seed = Material::speed(&mat64, mr)
        .and_then(|sp| solve_ellipse_seeded(&mat64, &sp, &ratio.to_f64(), None, method))
        .map(|s| T::from_f64(s.k, p))
        .ok();
    solve_ellipse_seeded(mat, speed, ratio, seed.as_ref(), method)
}
