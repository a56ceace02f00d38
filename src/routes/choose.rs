//! I1, I2 to a requested accuracy at the lowest sufficient precision, from inputs held exactly.
//!
//! [`integrals_to_tolerance`] takes the inputs as exact rationals ([`ExactInputs`]: a decimal
//! "0.2" is 1/5, the speed's gap 1 − M_R formed exactly), a relative tolerance of any size
//! ([`RelError`]: 10⁻¹⁰⁰⁰⁰ is fine) and a method, and
//!
//! 1. picks the precision from the tolerance's binary exponent (never through an `f64`): the
//!    inputs are rounded once to it, which perturbs I1, I2 by at most [`INPUT_KAPPA`]·ε (k by
//!    ≤ 3ε as I1 ~ k⁻³, the gap by ≤ ε/2 as I2 ~ (1 − M_R²)^{−1/2}, M_R and ν by O(ε)), and the
//!    route gets two thirds of the tolerance and adds at most its bound (16ε for the fixed
//!    rule): the lowest of `f64`, double-double and MPFR in steps of 8 bits whose
//!    (3/2·16 + κ)·ε meets the tolerance, so that the estimate lies within 2⁹ of it;
//! 2. runs [`crate::routes::evaluate::integrals`] there and accepts the result when its
//!    estimate plus κε is within the tolerance; otherwise it moves up by a quarter of the
//!    precision, at most three times, before returning [`Error::Unreachable`].
//!
//! The returned error estimate bounds the error relative to the exact integrals of the exact
//! inputs (tested against computations at higher precision in `tests/choose.rs`).

use super::evaluate::{IntegralOptions, FLOOR_EPS};
use super::{fast, AxisRatio, Integrals, Method, BEYOND_EXPONENT_RANGE};
use crate::error::{Error, Result};
use crate::estimate::{Estimated, RelError};
use crate::numerics::quadrature::check_rule_bits;
use crate::physics::material::round_rational;
use crate::physics::{Material, Speed};
use crate::scalar::{decimal_to_rational, Mp, MpPrec, Precision, Real};
use rug::Rational;

/// The inputs of I1, I2 held exactly, with the text they were given as (for messages).
#[derive(Clone, Debug, PartialEq)]
pub struct ExactInputs {
    nu: Rational,
    mr: Rational,
    k: Rational,
    text: [String; 3],
}

/// The amplification of the inputs' rounding in I1, I2, in units of ε (module docs).
pub const INPUT_KAPPA: u32 = 8;

impl ExactInputs {
    /// The inputs of (34) from decimal (or p/q) text, exactly: ν, the speed M_R, the axis ratio k.
    pub fn parse(nu: &str, mr: &str, k: &str) -> Result<ExactInputs> {
        ExactInputs::new(
            decimal_to_rational(nu)?,
            decimal_to_rational(mr)?,
            decimal_to_rational(k)?,
            [nu, mr, k],
        )
    }

    /// [`ExactInputs::parse`] with the speed given by its gap 1 − M_R; the inputs of (34), exact.
    pub fn parse_gap(nu: &str, gap: &str, k: &str) -> Result<ExactInputs> {
        let g = decimal_to_rational(gap)?;
        let text = format!("1 - {}", gap.trim());
        ExactInputs::new(
            decimal_to_rational(nu)?,
            Rational::from(1) - g,
            decimal_to_rational(k)?,
            [nu, &text, k],
        )
    }

    /// The exact values of three `f64` (NaN and ∞ are typed errors). The inputs of (34); exact.
    pub fn from_f64(nu: f64, mr: f64, k: f64) -> Result<ExactInputs> {
        let conv = |name: &'static str, x: f64| {
            Rational::from_f64(x).ok_or_else(|| Error::NotFinite {
                name,
                value: format!("{x}"),
            })
        };
        let text = [nu, mr, k].map(|x| format!("{x:e}"));
        ExactInputs::new(
            conv("nu", nu)?,
            conv("speed M_R", mr)?,
            conv("axis ratio k", k)?,
            [&text[0], &text[1], &text[2]],
        )
    }

    /// Validates the ranges exactly: −1 < ν ≤ 1/2, 0 ≤ M_R < 1, k > 0.
    fn new(nu: Rational, mr: Rational, k: Rational, text: [&str; 3]) -> Result<ExactInputs> {
        let dom = |name, i: usize, bound| Error::Domain {
            name,
            value: text[i].trim().to_string(),
            bound,
        };
        if nu <= -1 || nu > Rational::from((1, 2)) {
            return Err(dom("nu (Poisson's ratio)", 0, "(-1, 1/2]"));
        }
        if !(0..1).contains(&mr) {
            return Err(dom("speed M_R = V/c_R", 1, "[0, 1) (sub-Rayleigh)"));
        }
        if k <= 0 {
            return Err(dom("axis ratio k = b/a", 2, "(0, inf)"));
        }
        Ok(ExactInputs {
            nu,
            mr,
            k,
            text: text.map(|t| t.trim().to_string()),
        })
    }

    /// Poisson's ratio ν. An input of (34); exact.
    pub fn nu(&self) -> &Rational {
        &self.nu
    }
    /// The speed M_R. An input of (34); exact.
    pub fn mr(&self) -> &Rational {
        &self.mr
    }
    /// The axis ratio k. An input of (34); exact.
    pub fn k(&self) -> &Rational {
        &self.k
    }

    /// The inputs as rounded to precision `p`, held exactly: ν and k rounded, the gap 1 − M_R
    /// rounded and M_R its exact complement (for studies that measure a route's own error
    /// against a reference for the very inputs it saw).
    /// The inputs of (34); the roundings of `p`, held exactly.
    pub fn rounded<T: Real>(&self, p: T::Prec) -> Result<ExactInputs> {
        let bits = T::bits(p) + 64;
        let r = |q: &Rational| -> Rational {
            let t: T = round_rational(q, p);
            t.to_float(bits).to_rational().unwrap_or_default()
        };
        let gap = r(&(Rational::from(1) - &self.mr));
        let text = [&self.nu, &self.mr, &self.k].map(|q| r(q).to_string());
        ExactInputs::new(
            r(&self.nu),
            Rational::from(1) - gap,
            r(&self.k),
            [&text[0], &text[1], &text[2]],
        )
    }

    /// The inputs rounded once to precision `p`: the speed (with its material) and k.
    /// The inputs of (34), each rounded once (the gap 1 − M_R rounded, M_R its complement).
    pub fn at<T: Real>(&self, p: T::Prec) -> Result<(Speed<T>, T)> {
        let mat = Material::<T>::from_exact(&self.nu, &self.text[0], p)?;
        let speed = mat.speed_from_exact(&self.mr, &self.text[1])?;
        let k: T = round_rational(&self.k, p);
        AxisRatio::new(k.clone())?;
        Ok((speed, k))
    }
}

/// The lowest precision whose (route bound + κ)·ε meets `tol` (module docs): bits from the
/// tolerance's binary exponent, MPFR in steps of 8 bits.
/// Chooses the precision for I1, I2 of (34); implements no equation.
pub fn choose_precision(tol: RelError) -> Result<Precision> {
    // The route gets 2/3 of the tolerance, the inputs' rounding the rest:
    // (3/2·16 + κ)·2^(1 − bits) ≤ tol  ⇔  bits ≥ 1 + log2(3/2·16 + κ) − log2(tol).
    let bound = (fast::BOUND_EPS as u32).max(FLOOR_EPS) * 3 / 2 + INPUT_KAPPA;
    let need = 1.0 + (bound as f64).log2() - tol.log2();
    if !need.is_finite() {
        return Err(Error::Domain {
            name: "relative tolerance",
            value: tol.to_string(),
            bound: "(0, 1)",
        });
    }
    let need = need.ceil().max(1.0) as u64;
    Ok(if need <= 53 {
        Precision::F64
    } else if need <= 106 {
        Precision::DoubleDouble
    } else {
        Precision::Mpfr(MpPrec::new(need.div_ceil(8) * 8)?)
    })
}

/// The next precision up: f64 → double-double → MPFR, growing by a quarter.
fn next_precision(p: Precision) -> Result<Precision> {
    Ok(match p {
        Precision::F64 => Precision::DoubleDouble,
        Precision::DoubleDouble => Precision::Mpfr(MpPrec::new(136)?),
        Precision::Mpfr(q) => {
            Precision::Mpfr(MpPrec::new((q.bits() as u64 * 5 / 4).div_ceil(8) * 8)?)
        }
    })
}

/// I1, I2 (normalisation of (37)) of the exact `inputs` to relative tolerance `tol` (0 < tol
/// < 1) by `method` at the lowest precision that reaches it (module docs). The values are
/// returned as MPFR numbers carrying the working precision's result exactly, with
/// [`Integrals::precision`] the precision that ran; each bound is relative to the exact
/// integrals of the exact inputs.
///
/// Errors: [`Error::Domain`] for a tolerance outside (0, 1); [`Error::Unreachable`], before
/// any work, for a tolerance that needs more than the rules' 32,768 bits
/// ([`crate::numerics::quadrature::MAX_RULE_BITS`]) by any method but the series, and for one
/// the routes do not meet within three steps up in precision.
///
/// ```
/// use moving_hertz::{integrals_to_tolerance, ExactInputs, Method, RelError};
/// let inputs = ExactInputs::parse("0.25", "0.999", "0.5")?;
/// let r = integrals_to_tolerance(&inputs, RelError::parse("1e-40")?, Method::Auto)?;
/// assert!(r.i1.error <= RelError::parse("1e-40")?);
/// # Ok::<(), moving_hertz::Error>(())
/// ```
pub fn integrals_to_tolerance(
    inputs: &ExactInputs,
    tol: RelError,
    method: Method,
) -> Result<Integrals<Mp>> {
    if tol >= RelError::from_f64(1.0) {
        return Err(Error::Domain {
            name: "relative tolerance",
            value: tol.to_string(),
            bound: "(0, 1)",
        });
    }
    let mut prec = choose_precision(tol)?;
    // Every route but the series builds quadrature rules: a precision beyond theirs is refused
    // here, before the inputs are rounded to it (at 2^20 bits that alone takes half a minute).
    if method != Method::Series {
        check_rule_bits(prec.bits()).map_err(|e| unreachable(tol, e.to_string()))?;
    }
    let mut last = String::new();
    for _ in 0..4 {
        let attempt = crate::with_precision!(prec, T, p => run_at::<T>(inputs, p, method, tol));
        match attempt {
            Ok(r) if r.i1.error <= tol && r.i2.error <= tol => return Ok(r),
            Ok(r) => last = format!("estimate {} at {}", r.i1.error.max(r.i2.error), prec),
            // A value beyond the exponent range: the next precision may hold it (MPFR's does).
            Err(e @ Error::Domain { bound, .. }) if bound == BEYOND_EXPONENT_RANGE => {
                last = e.to_string()
            }
            Err(e @ (Error::Domain { .. } | Error::NotFinite { .. })) => return Err(e),
            Err(e @ Error::Precision { .. }) => return Err(unreachable(tol, e.to_string())),
            Err(e) => last = e.to_string(),
        }
        prec = next_precision(prec).map_err(|e| unreachable(tol, e.to_string()))?;
    }
    Err(unreachable(tol, last))
}

/// The refusal of a tolerance the routes cannot reach, with the reason.
fn unreachable(tol: RelError, reason: String) -> Error {
    Error::Unreachable {
        what: "I1, I2",
        tolerance: tol.to_string(),
        reason,
    }
}

/// One attempt at the precision `p`: the route's result, its bounds enlarged by the inputs'
/// rounding κε, carried to MPFR exactly.
fn run_at<T: Real>(
    inputs: &ExactInputs,
    p: T::Prec,
    method: Method,
    tol: RelError,
) -> Result<Integrals<Mp>> {
    let (speed, k) = inputs.at::<T>(p)?;
    let kappa = RelError::eps::<T>(INPUT_KAPPA, p);
    // The route's share of the tolerance (module docs); below its floor, the floor.
    let route_tol = tol.scale(2.0 / 3.0);
    let opts = IntegralOptions {
        method,
        tolerance: Some(route_tol).filter(|t| *t >= RelError::eps::<T>(FLOOR_EPS, p)),
        ..Default::default()
    };
    let r = super::evaluate::integrals(&speed, &k, &opts)?;
    let bits = T::bits(p) + 64;
    Ok(r.map(|e| {
        let value = Mp::from_float(&e.value.to_float(bits), MpPrec::clamped(bits));
        Estimated::new(value, e.error.add(kappa))
    }))
}
