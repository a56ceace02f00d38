//! Failures of the native entries and their Python exceptions.
//!
//! Every entry computes a `Result<_, Fail>` without the GIL and turns a failure into an
//! exception of `moving_hertz._errors` once it holds the GIL again: the crate's [`Error`]
//! variants map onto `DomainError` (inputs, and a method that cannot give what was asked for),
//! `ConvergenceError` (an iteration or series cap), `ToleranceError` (an accuracy no precision
//! on offer reaches); an internal error (a bug) and a Rust panic, caught by [`guard`] before it
//! can unwind into the interpreter, onto `MovingHertzError`.

use moving_hertz::Error;
use pyo3::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Why an entry failed.
#[derive(Debug)]
pub enum Fail {
    /// A library error, with the Python argument it is about (when one input decides it).
    Lib {
        error: Error,
        argument: Option<&'static str>,
    },
    /// A message about an argument (a value the binding refuses before the library sees it).
    Arg {
        argument: &'static str,
        message: String,
    },
    /// A panic inside the library: a bug, reported as `MovingHertzError`.
    Panic(String),
}

impl Fail {
    /// A library error about `argument`.
    pub fn about(argument: &'static str) -> impl Fn(Error) -> Fail {
        move |error| Fail::Lib {
            error,
            argument: Some(argument),
        }
    }

    /// The message a Python user reads.
    pub fn message(&self) -> String {
        match self {
            Fail::Lib { error, .. } => error.to_string(),
            Fail::Arg { message, .. } => message.clone(),
            Fail::Panic(m) => {
                format!("internal error (a panic in moving-hertz, please report it): {m}")
            }
        }
    }

    /// The name of the Python exception class in `moving_hertz._errors`.
    fn class(&self) -> &'static str {
        match self {
            Fail::Lib { error, .. } => class_of(error),
            Fail::Arg { .. } => "DomainError",
            Fail::Panic(_) => "MovingHertzError",
        }
    }

    fn argument(&self) -> Option<&'static str> {
        match self {
            Fail::Lib { argument, .. } => *argument,
            Fail::Arg { argument, .. } => Some(argument),
            Fail::Panic(_) => None,
        }
    }

    /// The Python exception: `CLASS(message)` with the attribute `argument` (or `None`).
    pub fn into_py(self, py: Python<'_>) -> PyErr {
        let make = || -> PyResult<PyErr> {
            let module = py.import("moving_hertz._errors")?;
            let exc = module
                .getattr(self.class())?
                .call1((self.message(), self.argument()))?;
            Ok(PyErr::from_value(exc))
        };
        make().unwrap_or_else(|e| e)
    }
}

impl From<Error> for Fail {
    fn from(error: Error) -> Fail {
        let argument = match &error {
            // A precision the quadrature rules are not built for is refused by the solve.
            Error::Precision { .. } => Some("precision"),
            Error::Domain { name, .. } | Error::NotFinite { name, .. } => argument_of(name),
            // A method that cannot give what was asked for.
            Error::Unsupported { .. } => Some("method"),
            // Only a tolerance asked for can be unreachable.
            Error::Unreachable { .. } => Some("tol"),
            _ => None,
        };
        Fail::Lib { error, argument }
    }
}

/// The Python keyword of an input the library names in an error (`None`: a result or an
/// intermediate quantity, not an input).
fn argument_of(name: &str) -> Option<&'static str> {
    const KEYWORDS: [(&str, &str); 9] = [
        ("method", "method"),
        ("curvature ratio", "ratio"),
        ("radius along", "radius_along"),
        ("radius across", "radius_across"),
        ("shear modulus", "shear_modulus"),
        ("load P", "load"),
        ("approach d0", "approach"),
        ("relative tolerance", "tol"),
        ("axis ratio", "k"),
    ];
    KEYWORDS
        .iter()
        .find(|(start, _)| name.starts_with(start))
        .map(|(_, keyword)| *keyword)
}

/// The exception class of a library error.
pub fn class_of(e: &Error) -> &'static str {
    match e {
        Error::Domain { .. } | Error::NotFinite { .. } | Error::Precision { .. } => "DomainError",
        Error::Parse { .. } | Error::Unsupported { .. } => "DomainError",
        Error::NoConvergence { .. } | Error::TermCap { .. } => "ConvergenceError",
        Error::Unreachable { .. } => "ToleranceError",
        // A bug: the base class, as for a panic.
        Error::Internal { .. } => "MovingHertzError",
        // A variant this package does not know yet: the base class of them all.
        _ => "MovingHertzError",
    }
}

/// Runs `f`, turning a panic into [`Fail::Panic`] (never an unwind across the boundary).
pub fn guard<R>(f: impl FnOnce() -> Result<R, Fail>) -> Result<R, Fail> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(payload) => Err(Fail::Panic(panic_text(payload.as_ref()))),
    }
}

/// The message of a panic payload.
pub fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "a panic without a message".into()
    }
}

/// `r` with its failure as a Python exception.
pub fn to_py<R>(py: Python<'_>, r: Result<R, Fail>) -> PyResult<R> {
    r.map_err(|f| f.into_py(py))
}
