//! The crate's one error type.
//!
//! Every public function that can meet bad input or a computation that does not converge returns
//! [`Result<T, Error>`](Result). Each variant names the offending value and the bound it broke, so
//! that a message such as `poisson ratio nu = 0.7 is outside (-1, 1/2]` can be shown to a user as
//! is. Nothing in the library panics on user input and nothing returns NaN silently.

use std::fmt;

/// Result alias used throughout the crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Everything that can go wrong in `moving-hertz`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum Error {
    /// An argument lies outside its mathematical or physical domain, or outside the domain of
    /// the method or precision that serves it (an axis ratio k above 1 for the adaptive
    /// subtracted route; a k whose integrals leave the working type's exponent range). Returned
    /// before any work where the inputs decide it.
    Domain {
        /// Name of the argument, as in the API (`"nu"`, `"m"`, `"speed M_R"`, ...).
        name: &'static str,
        /// The value received, printed at the working precision.
        value: String,
        /// The allowed range, e.g. `"(-1, 1/2]"` or `"m < 1"`.
        bound: &'static str,
    },
    /// An argument is NaN or infinite.
    NotFinite {
        /// Name of the argument.
        name: &'static str,
        /// The value received (`NaN`, `inf`, `-inf`).
        value: String,
    },
    /// A requested precision outside the supported range.
    Precision {
        /// The number of bits requested.
        bits: u64,
        /// The smallest supported precision in bits.
        min: u32,
        /// The largest supported precision in bits.
        max: u32,
    },
    /// An iteration did not reach its tolerance within its work bound (after it ran: a refusal
    /// before any work is [`Error::Domain`], [`Error::Unsupported`] or [`Error::Unreachable`]).
    NoConvergence {
        /// What was being computed.
        what: &'static str,
        /// Iterations (or function evaluations) spent; 0 where the count is not known (then
        /// not printed).
        iterations: usize,
        /// The best error estimate reached, relative, printed in short form (empty: none, not
        /// printed).
        reached: String,
    },
    /// A series would need more terms than its cap.
    TermCap {
        /// What was being summed.
        what: &'static str,
        /// The cap on the number of terms.
        cap: usize,
        /// An estimate of the number of terms that would be needed, when one is available.
        needed: Option<u64>,
        /// The relative size of the last term reached (how far the summation got).
        reached: String,
    },
    /// Text that does not parse as a number (CLI arguments, test data).
    Parse {
        /// The text received.
        text: String,
        /// Why it was rejected.
        reason: &'static str,
    },
    /// A method asked for something it cannot give (k-derivatives of I1, I2 from the series or
    /// the adaptive subtracted route, which the ellipse solve needs): returned before any work.
    Unsupported {
        /// What was asked for.
        what: &'static str,
        /// The method, by its label ([`crate::Method::label`]).
        method: &'static str,
        /// Which methods give it.
        reason: &'static str,
    },
    /// A state the crate's logic rules out was reached (a result slot left unwritten, a
    /// Gauss–Legendre node at a zero of P_n′): a bug, to be reported with the inputs. No input
    /// is known to lead here.
    Internal {
        /// What went wrong.
        what: &'static str,
    },
    /// The requested accuracy cannot be reached by any method and precision on offer, or a
    /// result's error bound is not finite (no correct digit can be promised).
    Unreachable {
        /// What was requested.
        what: &'static str,
        /// The requested relative tolerance.
        tolerance: String,
        /// Why it cannot be met.
        reason: String,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Domain { name, value, bound } => {
                write!(f, "{name} = {value} is outside its domain {bound}")
            }
            Error::NotFinite { name, value } => write!(f, "{name} = {value} is not finite"),
            Error::Precision { bits, min, max } => write!(
                f,
                "precision of {bits} bits is outside the supported range [{min}, {max}] bits"
            ),
            Error::NoConvergence {
                what,
                iterations,
                reached,
            } => {
                // A check that refuses before iterating has no count, and a placeholder no
                // estimate: neither is printed then.
                write!(f, "{what} did not converge")?;
                if *iterations > 0 {
                    write!(f, " after {iterations} iterations")?;
                }
                if !reached.is_empty() {
                    write!(f, " (error estimate {reached})")?;
                }
                Ok(())
            }
            Error::TermCap {
                what,
                cap,
                needed,
                reached,
            } => match needed {
                // An estimate that saturated its count: said in words, not as 2^64 - 1.
                Some(u64::MAX) => write!(
                    f,
                    "{what} would need more terms than a 64-bit count holds, more than the cap of {cap} (last term relative size {reached})"
                ),
                Some(n) => write!(
                    f,
                    "{what} would need about {n} terms, more than the cap of {cap} (last term relative size {reached})"
                ),
                None => write!(
                    f,
                    "{what} did not converge within the cap of {cap} terms (last term relative size {reached})"
                ),
            },
            Error::Parse { text, reason } => write!(f, "cannot parse {text:?}: {reason}"),
            Error::Unsupported {
                what,
                method,
                reason,
            } => write!(f, "method {method} cannot give {what}: {reason}"),
            Error::Internal { what } => {
                write!(f, "internal error (a bug in moving-hertz, please report it): {what}")
            }
            Error::Unreachable {
                what,
                tolerance,
                reason,
            } => write!(f, "{what} cannot reach relative tolerance {tolerance}: {reason}"),
        }
    }
}

impl std::error::Error for Error {}

#[cfg(test)]
mod tests {
    use super::Error;

    /// The iteration count and the estimate are printed only when there are some.
    #[test]
    fn no_convergence_prints_what_it_has() {
        let e = |iterations, reached: &str| {
            Error::NoConvergence {
                what: "x",
                iterations,
                reached: reached.into(),
            }
            .to_string()
        };
        assert_eq!(
            e(7, "1e-3"),
            "x did not converge after 7 iterations (error estimate 1e-3)"
        );
        assert_eq!(
            e(0, "unbounded"),
            "x did not converge (error estimate unbounded)"
        );
        assert_eq!(e(0, ""), "x did not converge");
    }

    /// A method that cannot give the k-derivatives is [`Error::Unsupported`] naming it, before
    /// any work: from `integrals` asking for them and from the ellipse solve, which needs them.
    #[test]
    fn a_method_without_derivatives_is_unsupported() {
        use crate::{integrals, solve_ellipse, IntegralOptions, Material, Method, Options};
        let sp = Material::new(0.25).unwrap().speed(0.5).unwrap();
        for method in [Method::Series, Method::AdaptiveSubtracted] {
            let opts = IntegralOptions {
                method,
                derivatives: true,
                ..Default::default()
            };
            let solve = Options {
                method,
                ..Default::default()
            };
            for r in [
                integrals(&sp, &0.5, &opts).map(|_| ()),
                solve_ellipse(&sp, &2.0, &solve).map(|_| ()),
            ] {
                match r {
                    Err(e @ Error::Unsupported { method: m, .. }) => {
                        assert_eq!(m, method.label());
                        assert!(e
                            .to_string()
                            .starts_with(&format!("method {m} cannot give")));
                    }
                    other => panic!("{method}: {other:?}"),
                }
            }
        }
    }

    /// A k at or beyond the ends of the `f64` exponent range, on every route that admits it
    /// and near the Rayleigh speed, is refused as [`Error::Domain`] naming k as given: before
    /// any work where k⁴ or 1/k⁴ is not a normal number, after it where a value of the route
    /// overflows or vanishes; never as an internal non-finite value ("integrand = -inf is not
    /// finite") nor as a non-convergence. (Without the k⁴ check the routes meet such values;
    /// the count of those refusals is printed.)
    #[test]
    fn an_integrand_beyond_the_exponent_range_names_k() {
        use crate::{integrals, IntegralOptions, Material, Method};
        let mut refused = 0;
        for nu in [0.25, -0.9] {
            let mat = Material::new(nu).unwrap();
            for mr in [0.5, 0.999999, 1.0 - 1e-12] {
                let sp = mat.speed(mr).unwrap();
                for k in [
                    1e-100, 1e-80, 1e-77, 1e-76, 1e-70, 1e70, 1e76, 1e77, 1e80, 1e100,
                ] {
                    for (method, derivatives) in [
                        (Method::Adaptive, true),
                        (Method::Adaptive, false),
                        (Method::AdaptiveSubtracted, false),
                        (Method::Auto, true),
                    ] {
                        let opts = IntegralOptions {
                            method,
                            derivatives,
                            j0: true,
                            ..Default::default()
                        };
                        let what = format!("nu {nu} M_R {mr} k {k:e} {method} {derivatives}");
                        match integrals(&sp, &k, &opts) {
                            Ok(_) => {}
                            Err(Error::Domain { name, bound, .. }) => {
                                assert!(name.starts_with("axis ratio k"), "{what}: {name}");
                                refused += usize::from(bound.contains("exponent range"));
                            }
                            Err(e) => panic!("{what}: {e:?}"),
                        }
                    }
                }
            }
        }
        println!("{refused} refusals after the work for the exponent range");
    }
}
