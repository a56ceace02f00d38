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

impl Error {
    /// [`Error::Domain`]: the argument `name`, received as `value`, outside `bound`.
    pub(crate) fn domain(name: &'static str, value: String, bound: &'static str) -> Error {
        Error::Domain { name, value, bound }
    }
}

#[cfg(test)]
#[path = "../tests/unit/error.rs"]
mod tests;
