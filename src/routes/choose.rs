//! Choosing the cheapest method and the lowest precision that reach a requested accuracy.
//!
//! [`integrals`] takes the inputs exactly (as rationals: a decimal "0.2" is 1/5), a relative
//! tolerance and a method request, and
//!
//! 1. picks the precision from the tolerance and the conditioning of the problem: the inputs are
//!    rounded once to the working precision, which perturbs I2 by about κ·ε with
//!    κ ≈ 4 + M_R²/(1 − M_R²) (I2 ~ (1 − M_R²)^(−1/2)); the methods' own error is a few ε. The
//!    precision is the smallest of f64 (53 bits), double-double (106) or MPFR (a multiple of 32
//!    bits) with 64·κ·ε ≤ tol — so a 1e-6 request runs in f64 and a 1e-60 request at about 220
//!    bits;
//! 2. picks the method: for k ≤ 1 the direct quadrature with the singular parts subtracted, run
//!    by the fixed-rule fast route ([`crate::routes::fast`], [`direct::fast`]) when its a-priori
//!    bound (16ε) is within the tolerance, else by the adaptive (48) with S by (53); for k > 1 the
//!    plain quadrature, by the graded fixed panels ([`crate::routes::graded`]) when their bound
//!    (32ε) is within the tolerance, else adaptive;
//! 3. runs it, and accepts the result when its error estimate plus the input-rounding term κ·ε is
//!    within the tolerance; otherwise it moves up one precision and tries again (at most three
//!    times) before returning [`Error::Unreachable`].
//!
//! The returned error estimate bounds the error relative to the exact integrals of the exact
//! inputs (tested against computations at higher precision in `tests/choose.rs`).

use super::fast::FastRule;
use super::{direct, graded, AxisRatio, Integrals, Method};
use crate::error::{Error, Result};
use crate::physics::Material;
use crate::scalar::{decimal_to_rational, Field, MpPrec, Precision, Real};
use rug::{Float, Rational};

/// The inputs of I1, I2, held exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct Inputs {
    /// Poisson's ratio ν ∈ (−1, 1/2].
    pub nu: Rational,
    /// M_R = V/c_R ∈ [0, 1).
    pub mr: Rational,
    /// Axis ratio k = b/a > 0.
    pub k: Rational,
}

impl Inputs {
    /// Parses decimal (or p/q) text exactly and validates the ranges.
    pub fn parse(nu: &str, mr: &str, k: &str) -> Result<Inputs> {
        Inputs::new(
            decimal_to_rational(nu)?,
            decimal_to_rational(mr)?,
            decimal_to_rational(k)?,
        )
    }

    /// The exact values of three `f64` (NaN and ∞ are typed errors).
    pub fn from_f64(nu: f64, mr: f64, k: f64) -> Result<Inputs> {
        let conv = |name: &'static str, x: f64| {
            Rational::from_f64(x).ok_or_else(|| Error::NotFinite {
                name,
                value: format!("{x}"),
            })
        };
        Inputs::new(
            conv("nu", nu)?,
            conv("speed M_R", mr)?,
            conv("axis ratio k", k)?,
        )
    }

    /// Validates the ranges: −1 < ν ≤ 1/2, 0 ≤ M_R < 1, k > 0.
    pub fn new(nu: Rational, mr: Rational, k: Rational) -> Result<Inputs> {
        let dom = |name, v: &Rational, bound| Error::Domain {
            name,
            value: format!("{}", v.to_f64()),
            bound,
        };
        if nu <= -1 || nu > Rational::from((1, 2)) {
            return Err(dom("nu (Poisson's ratio)", &nu, "(-1, 1/2]"));
        }
        if !(0..1).contains(&mr) {
            return Err(dom("speed M_R = V/c_R", &mr, "[0, 1) (sub-Rayleigh)"));
        }
        if k <= 0 {
            return Err(dom("axis ratio k = b/a", &k, "(0, inf)"));
        }
        Ok(Inputs { nu, mr, k })
    }

    /// The inputs rounded to precision `p`.
    pub fn at<T: Real>(
        &self,
        p: T::Prec,
    ) -> Result<(Material<T>, crate::physics::Speed<T>, AxisRatio<T>)> {
        let bits = T::bits(p) + 64;
        let conv = |r: &Rational| T::from_float(&Float::with_val(bits, r), p);
        let mat = Material::new(conv(&self.nu))?;
        let speed = mat.speed(conv(&self.mr))?;
        let axes = AxisRatio::new(conv(&self.k))?;
        Ok((mat, speed, axes))
    }

    /// κ ≈ 4 + M_R²/(1 − M_R²): the amplification of a relative perturbation of the inputs in
    /// I1, I2 (their sensitivity to M_R dominates near M_R = 1; to k and ν it is O(1)).
    pub fn condition(&self) -> f64 {
        let m2 = self.mr.to_f64().powi(2);
        let one_minus = (Rational::from(1) - self.mr.clone() * &self.mr).to_f64();
        4.0 + m2 / one_minus
    }
}

/// What the caller asks for: a method, or the automatic choice.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MethodRequest {
    /// The cheapest method that reaches the tolerance.
    Auto,
    /// A given method.
    Fixed(Method),
}

impl MethodRequest {
    /// Parses `auto`, `series`, `quadrature` or `subtracted`.
    pub fn parse(s: &str) -> Result<MethodRequest> {
        match s {
            "auto" => Ok(MethodRequest::Auto),
            "series" => Ok(MethodRequest::Fixed(Method::Series)),
            "quadrature" => Ok(MethodRequest::Fixed(Method::Quadrature)),
            "subtracted" => Ok(MethodRequest::Fixed(Method::Subtracted)),
            _ => Err(Error::Parse {
                text: s.to_string(),
                reason: "expected auto, series, quadrature or subtracted",
            }),
        }
    }
}

/// I1 and I2 from [`integrals`], held as MPFR numbers that carry the value computed at the
/// working precision exactly.
#[derive(Clone, Debug)]
pub struct Answer {
    /// I1 (normalisation of (37)).
    pub i1: Float,
    /// I2.
    pub i2: Float,
    /// Bound on the relative error of I1 and I2 with respect to the exact inputs.
    pub error_estimate: f64,
    /// The method used.
    pub method: Method,
    /// The precision used.
    pub precision: Precision,
    /// Series terms or integrand evaluations spent in the accepted run.
    pub work: usize,
}

/// The method the automatic choice takes for these inputs and tolerance:
/// [`Method::Subtracted`] for k ≤ 1 (run by the fast route, ~0.25 µs at f64), and
/// [`Method::Quadrature`] for k > 1 (run by the graded fixed panels of [`crate::routes::graded`],
/// 0.3–1 µs at f64, when their bound meets the tolerance; the series, 6–12 µs at f64 even where it
/// needs few terms, is never cheaper).
pub fn choose_method(inputs: &Inputs, _tol: f64) -> Method {
    if inputs.k <= 1 {
        Method::Subtracted
    } else {
        Method::Quadrature
    }
}

/// The lowest precision whose 64·κ·ε is within `tol`.
pub fn choose_precision(inputs: &Inputs, tol: f64) -> Result<Precision> {
    let need = (64.0 * inputs.condition() / tol).log2().ceil().max(1.0) as u64;
    Ok(if need <= 53 {
        Precision::F64
    } else if need <= 106 {
        Precision::DoubleDouble
    } else {
        Precision::Mpfr(MpPrec::new(need.div_ceil(32) * 32)?)
    })
}

/// The next precision up the ladder: f64 → double-double → MPFR, growing by half.
fn next_precision(p: Precision) -> Result<Precision> {
    Ok(match p {
        Precision::F64 => Precision::DoubleDouble,
        Precision::DoubleDouble => Precision::Mpfr(MpPrec::new(160)?),
        Precision::Mpfr(q) => {
            Precision::Mpfr(MpPrec::new((q.bits() as u64 * 3 / 2).div_ceil(32) * 32)?)
        }
    })
}

/// Runs one method at one precision (tolerance `tol` relative, as `f64`; 0 asks for the
/// precision's floor).
///
/// [`Method::Subtracted`] runs the fast fixed-rule route ([`direct::fast`]) when k is in its
/// domain (2^−40 ≤ k ≤ 1) and its bound ([`FastRule::bound_eps`], 16ε) is within `tol` (or `tol`
/// is 0), and the adaptive [`direct::subtracted`] otherwise. [`Method::Quadrature`] runs the
/// graded fixed panels ([`graded::integrals`]) when k ≥ 1, `tol` > 0 and their bound
/// ([`graded::BOUND_EPS`]·ε) is within `tol`, and the adaptive [`direct::quadrature`] otherwise
/// (`tol` = 0, the precision's floor, always runs the adaptive route: the studies' reference).
pub fn run_at<T: Real>(
    inputs: &Inputs,
    p: T::Prec,
    method: Method,
    tol: f64,
) -> Result<Integrals<T>> {
    let (mat, speed, axes) = inputs.at::<T>(p)?;
    let t = T::from_f64(tol, p);
    match method {
        Method::Quadrature => {
            // k ≥ 1 with a tolerance the graded panels' bound meets: the fixed rule.
            let bound = T::epsilon(p).mul_i64(graded::BOUND_EPS);
            if tol > 0.0 && bound <= t && axes.k >= T::one(p) {
                if let Ok(r) = graded::integrals(&mat, &speed, &axes) {
                    return Ok(r);
                }
            }
            direct::quadrature(&mat, &speed, &axes, &t)
        }
        Method::Subtracted => {
            let bound = T::epsilon(p).mul_i64(FastRule::<T>::get(p)?.bound_eps() as i64);
            if tol == 0.0 || bound <= t {
                if let Ok(r) = direct::fast(&mat, &speed, &axes) {
                    return Ok(r);
                }
            }
            direct::subtracted(&mat, &speed, &axes, &t)
        }
        Method::Series => {
            let opts = super::series::SeriesOptions {
                rel_tol: (tol > 0.0).then_some(t),
                ..Default::default()
            };
            super::series::integrals(&mat, &speed, &axes, &opts)
        }
    }
}

/// I1, I2 to relative tolerance `tol` (0 < tol < 1) by the cheapest method and lowest precision
/// that reach it (see the module docs).
pub fn integrals(inputs: &Inputs, tol: f64, request: MethodRequest) -> Result<Answer> {
    if !(tol > 0.0 && tol < 1.0) {
        return Err(Error::Domain {
            name: "tolerance",
            value: format!("{tol}"),
            bound: "(0, 1)",
        });
    }
    let method = match request {
        MethodRequest::Auto => choose_method(inputs, tol),
        MethodRequest::Fixed(m) => m,
    };
    let mut prec = choose_precision(inputs, tol)?;
    let kappa = inputs.condition();
    let mut last = String::new();
    for _ in 0..4 {
        let attempt: Result<(Float, Float, f64, usize)> = crate::with_precision!(prec, T, p => {
            run_at::<T>(inputs, p, method, tol / 4.0).map(|r| {
                let bits = T::bits(p) + 64;
                let eps = T::epsilon(p).to_f64();
                let est = r.error_estimate.to_f64() + kappa * eps;
                (r.i1.to_float(bits), r.i2.to_float(bits), est, r.work)
            })
        });
        match attempt {
            Ok((i1, i2, est, work)) if est <= tol => {
                return Ok(Answer {
                    i1,
                    i2,
                    error_estimate: est,
                    method,
                    precision: prec,
                    work,
                });
            }
            Ok((_, _, est, _)) => last = format!("estimate {est:.2e} at {}", prec.label()),
            Err(e @ Error::Unreachable { .. }) => return Err(e),
            Err(e) => last = e.to_string(),
        }
        prec = next_precision(prec)?;
    }
    Err(Error::Unreachable {
        what: "I1, I2",
        tolerance: format!("{tol:e}"),
        reason: last,
    })
}
