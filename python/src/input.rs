//! The inputs as the Python layer hands them over, and their conversion to the library's
//! inputs at the working precision.
//!
//! The pure-Python layer (`moving_hertz/_numbers.py`) turns every accepted number into either a
//! Python `float` (taken as the binary value it is) or exact text: decimal text, or `p/q` for a
//! `Fraction` or an `mpmath.mpf`. Text goes to the library's parsers — [`Material::parse`],
//! [`Material::parse_speed`], [`Material::parse_gap`] (ν and the speed checked exactly, the gap
//! 1 − M_R formed exactly) and `T::parse` — as the command-line tool's does, so that the same
//! text gives the same bits here and there.

use crate::fail::Fail;
use moving_hertz::scalar::{decimal_to_rational, Precision, Real};
use moving_hertz::{Material, Speed};
use pyo3::prelude::*;
use pyo3::types::{PyFloat, PyString};

/// A number as handed over: a binary `f64` or exact text.
#[derive(Clone, Debug)]
pub enum Num {
    /// A Python float.
    F(f64),
    /// Exact text: a decimal (`0.25`, `1e-12`) or a fraction `p/q`.
    T(String),
}

impl Num {
    /// A float or a str; anything else is refused naming `argument` (the Python layer converts
    /// every other accepted type first).
    pub fn from_py(x: &Bound<'_, PyAny>, argument: &'static str) -> Result<Num, Fail> {
        if let Ok(f) = x.cast::<PyFloat>() {
            return Ok(Num::F(f.value()));
        }
        if x.is_instance_of::<PyString>() {
            if let Ok(s) = x.extract::<String>() {
                return Ok(Num::T(s));
            }
        }
        Err(Fail::Arg {
            argument,
            message: format!("{argument} must be a float or decimal text here"),
        })
    }

    /// The text an error message quotes.
    pub fn shown(&self) -> String {
        match self {
            Num::F(f) => format!("{f:?}"),
            Num::T(s) => s.trim().to_string(),
        }
    }

    /// The value at precision `p` without a check (a float exactly, text by `T::parse`, a
    /// fraction rounded once).
    fn value<T: Real>(&self, p: T::Prec) -> Result<T, moving_hertz::Error> {
        match self {
            Num::F(f) => Ok(T::from_f64(*f, p)),
            Num::T(s) if s.contains('/') => {
                let exact = decimal_to_rational(s)?;
                let bits = T::bits(p) + 64;
                Ok(T::from_float(&rug::Float::with_val(bits, &exact), p))
            }
            Num::T(s) => T::parse(s, p),
        }
    }
}

/// `f64`, `dd` or a number of bits, as [`Precision::parse`] reads it (the Python layer passes
/// an int as its decimal text).
pub fn precision(text: &str) -> Result<Precision, Fail> {
    Precision::parse(text).map_err(Fail::about("precision"))
}

/// How the speed is given.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpeedKind {
    /// M_R = V/c_R.
    Mr,
    /// The gap 1 − M_R.
    Gap,
}

impl SpeedKind {
    /// `speed` or `gap` (the Python keyword).
    pub fn parse(s: &str) -> SpeedKind {
        if s == "gap" {
            SpeedKind::Gap
        } else {
            SpeedKind::Mr
        }
    }

    /// The Python keyword.
    pub fn argument(self) -> &'static str {
        match self {
            SpeedKind::Mr => "speed",
            SpeedKind::Gap => "gap",
        }
    }
}

/// The material of Poisson's ratio `nu` at precision `p` ([`Material::parse`] for text, checked
/// exactly; [`Material::new`] for a float).
pub fn material<T: Real>(nu: &Num, p: T::Prec) -> Result<Material<T>, Fail> {
    let about = Fail::about("nu");
    match nu {
        Num::F(f) => Material::new(T::from_f64(*f, p)).map_err(about),
        Num::T(s) => Material::parse(s, p).map_err(about),
    }
}

/// The speed of `mat` given as M_R or its gap (text by [`Material::parse_speed`] /
/// [`Material::parse_gap`], the gap formed exactly; a float by [`Material::speed`] /
/// [`Material::speed_from_gap`]).
pub fn speed<T: Real>(mat: &Material<T>, x: &Num, kind: SpeedKind) -> Result<Speed<T>, Fail> {
    let p = mat.nu().prec();
    let about = Fail::about(kind.argument());
    match (x, kind) {
        (Num::F(f), SpeedKind::Mr) => mat.speed(T::from_f64(*f, p)).map_err(about),
        (Num::F(f), SpeedKind::Gap) => mat.speed_from_gap(T::from_f64(*f, p)).map_err(about),
        (Num::T(s), SpeedKind::Mr) => mat.parse_speed(s).map_err(about),
        (Num::T(s), SpeedKind::Gap) => mat.parse_gap(s).map_err(about),
    }
}

/// The last speed made on this thread, with what it was made from: repeated calls at one
/// material and speed (a loop over ratios) skip the Rayleigh roots and the Green's function's
/// set-up, as a Rust caller holding its `Speed` does.
type Cached = (Precision, Num, Num, SpeedKind, Box<dyn std::any::Any>);

thread_local! {
    static LAST_SPEED: std::cell::RefCell<Option<Cached>> = const { std::cell::RefCell::new(None) };
}

/// [`material`] then [`speed`], or a copy of the last speed made on this thread from the same
/// inputs at the same precision (the same bits: the inputs decide them).
pub fn cached_speed<T: Real>(
    nu: &Num,
    x: &Num,
    kind: SpeedKind,
    p: T::Prec,
) -> Result<Speed<T>, Fail> {
    let prec = Precision::of::<T>(p);
    let hit = LAST_SPEED.with(|c| {
        c.borrow().as_ref().and_then(|(q, n, v, k, speed)| {
            let same = *q == prec && same_num(n, nu) && same_num(v, x) && *k == kind;
            same.then(|| speed.downcast_ref::<Speed<T>>().cloned())
                .flatten()
        })
    });
    if let Some(s) = hit {
        return Ok(s);
    }
    let made = speed(&material::<T>(nu, p)?, x, kind)?;
    let entry = (
        prec,
        nu.clone(),
        x.clone(),
        kind,
        Box::new(made.clone()) as Box<dyn std::any::Any>,
    );
    LAST_SPEED.with(|c| *c.borrow_mut() = Some(entry));
    Ok(made)
}

/// Whether two inputs are the same number as given (a float by its bits, text as typed).
pub fn same_num(a: &Num, b: &Num) -> bool {
    match (a, b) {
        (Num::F(x), Num::F(y)) => x.to_bits() == y.to_bits(),
        (Num::T(x), Num::T(y)) => x == y,
        _ => false,
    }
}

/// A positive quantity (a ratio, k, a radius, a load, a modulus) at precision `p`, as the
/// command-line tool takes it: refused naming `argument` unless it is positive (checked
/// exactly for text) and its rounded value a finite normal number of the working precision
/// (a value that would overflow to ∞ or underflow to 0 is refused as such).
pub fn positive<T: Real>(x: &Num, argument: &'static str, p: T::Prec) -> Result<T, Fail> {
    let refuse = |why: String| Fail::Arg {
        argument,
        message: format!("{argument} = {} {why}", x.shown()),
    };
    let positive = match x {
        Num::F(f) => *f > 0.0 || f.is_nan(),
        Num::T(s) => decimal_to_rational(s).map_err(Fail::about(argument))? > 0,
    };
    if !positive {
        return Err(refuse("is outside its domain (0, inf)".into()));
    }
    let v: T = x.value(p).map_err(Fail::about(argument))?;
    let prec = Precision::of::<T>(p);
    if !v.is_finite() {
        return Err(refuse(format!(
            "is not finite at {prec} (rescale, or use a wider precision)"
        )));
    }
    if v < T::min_positive(p) {
        return Err(refuse(format!(
            "is below the smallest normal number of {prec} (rescale, or use a wider precision)"
        )));
    }
    Ok(v)
}
