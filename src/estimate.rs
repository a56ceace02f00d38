//! Relative error bounds that neither underflow nor overflow at any precision, and values that
//! carry one.
//!
//! Every result of the crate comes with an estimate of its relative error: a bound on
//! |x̃ − x|/|x|, x the exact value for the inputs as given (or as represented at the working
//! precision, where a page says so) and x̃ the value returned. The one exception is the
//! eccentricity e, whose bound is on |x̃ − x| ([`BoundKind::Absolute`]): e vanishes for a
//! circular contact. At 4096 bits such a bound is about 2⁻⁴⁰⁹⁰ ≈ 10⁻¹²³², far below the
//! smallest `f64`; [`RelError`] holds it as an `f64` mantissa and an `i64` binary exponent, so
//! that it survives at every MPFR precision and prints as a decimal string (`3.1e-1232`). It
//! also carries a requested tolerance, as small as 10⁻¹⁰⁰⁰⁰ or 10⁻¹⁰⁰⁰⁰⁰⁰.
//!
//! Arithmetic on bounds ([`RelError::add`], [`RelError::mul`], …) rounds upwards (each result is
//! enlarged by 2⁻⁵⁰ relative), so a sum of bounds stays a bound.
//!
//! No item of this module implements a formula of the paper: they are the error-bound
//! arithmetic behind every result, and their accuracy is the upward rounding above (a bound is
//! never made smaller than the exact operation on its inputs would give).

use crate::error::{Error, Result};
use crate::scalar::{decimal_to_rational, Real};
use std::cmp::Ordering;
use std::fmt;

/// A non-negative relative error bound m·2^e (m ∈ [1/2, 1), or 0, or +∞ for "unbounded").
///
/// `Copy`, ordered, and exact in its exponent: 2⁻¹⁰⁰⁰⁰⁰⁰ is as representable as 2⁻⁵². Built from a
/// value of any precision ([`RelError::of`]), from ε ([`RelError::eps`]), from decimal text
/// ([`RelError::parse`], e.g. a tolerance `1e-10000`) or from an `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RelError {
    /// Mantissa in [1/2, 1), or 0, or +∞.
    m: f64,
    /// Binary exponent (0 when m is 0 or +∞).
    e: i64,
}

/// Enlarges a bound by 2⁻⁵⁰ relative: every operation on bounds rounds upwards.
const UP: f64 = 1.0 + 1.0 / (1u64 << 50) as f64;

impl RelError {
    /// No error (an exact result).
    pub const ZERO: RelError = RelError { m: 0.0, e: 0 };
    /// An unbounded error: never part of a successful result (the boundary of every public
    /// function turns it into an [`Error`]).
    pub const INFINITE: RelError = RelError {
        m: f64::INFINITY,
        e: 0,
    };

    /// m·2^e normalised (m ≥ 0).
    #[inline]
    fn normal(m: f64, e: i64) -> RelError {
        if (0.5..1.0).contains(&m) {
            return RelError { m, e };
        }
        if m == 0.0 {
            return RelError::ZERO;
        }
        if !m.is_finite() {
            return RelError::INFINITE;
        }
        let (f, x) = frexp(m);
        RelError { m: f, e: e + x }
    }

    /// The bound |x| for an `f64` (NaN and ±∞ give [`RelError::INFINITE`]).
    #[inline]
    pub fn from_f64(x: f64) -> RelError {
        if x.is_nan() {
            return RelError::INFINITE;
        }
        RelError::normal(x.abs(), 0)
    }

    /// The bound |x| for a value of any precision, without underflow (NaN and ±∞ give
    /// [`RelError::INFINITE`]).
    #[inline]
    pub fn of<T: Real>(x: &T) -> RelError {
        let f = x.to_f64().abs();
        if f.is_normal() {
            let (m, e) = frexp(f);
            return RelError { m, e };
        }
        RelError::of_extreme(x)
    }

    /// [`RelError::of`] for zero, non-finite values and values beyond the `f64` exponent range.
    #[cold]
    fn of_extreme<T: Real>(x: &T) -> RelError {
        if x.is_zero() {
            return RelError::ZERO;
        }
        if !x.is_finite() {
            return RelError::INFINITE;
        }
        // Beyond the f64 exponent range (MPFR): read mantissa and exponent from the value.
        let (m, e) = x.to_float(64).to_f64_exp();
        RelError::normal(m.abs(), e as i64)
    }

    /// n·ε of the precision `p` (ε = 2^(1 − bits)).
    #[inline]
    pub fn eps<T: Real>(n: u32, p: T::Prec) -> RelError {
        RelError::normal(n as f64, 1 - T::bits(p) as i64)
    }

    /// The rounding of `n` operations of `T` at the precision `p`: γ = n·r/(1 − n·r) with
    /// r = [`Real::ROUNDING`]·ε the worst relative error of one (ε/2 at `f64` and MPFR, 1.625ε at
    /// double-double), so that (1 + δ1)⋯(1 + δn) − 1 ≤ γ for |δi| ≤ r; `n` may be fractional
    /// (a rounding raised to the power 1/3 in a cube root counts 1/3). [`RelError::INFINITE`]
    /// where n·r ≥ 1/2.
    #[inline]
    pub fn rounding<T: Real>(n: f64, p: T::Prec) -> RelError {
        let nr = RelError::normal(n * T::ROUNDING, 1 - T::bits(p) as i64);
        let small = nr.to_f64();
        if small >= 0.5 {
            return RelError::INFINITE;
        }
        nr.scale(1.0 / (1.0 - small))
    }

    /// 2^e.
    pub fn pow2(e: i64) -> RelError {
        RelError { m: 0.5, e: e + 1 }
    }

    /// Parses a positive decimal bound such as `1e-10000` or `0.001` exactly (rounded upwards
    /// to the representation); [`Error::Parse`] for text that is not a number, [`Error::Domain`]
    /// for a value ≤ 0.
    pub fn parse(text: &str) -> Result<RelError> {
        let r = decimal_to_rational(text)?;
        if r <= 0 {
            return Err(Error::domain(
                "relative tolerance",
                text.trim().to_string(),
                "(0, inf)",
            ));
        }
        let f = rug::Float::with_val_round(64, &r, rug::float::Round::Up).0;
        let (m, e) = f.to_f64_exp();
        Ok(RelError::normal(m * UP, e as i64))
    }

    /// True unless unbounded.
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.m.is_finite()
    }

    /// True for the zero bound.
    #[inline]
    pub fn is_zero(&self) -> bool {
        self.m == 0.0
    }

    /// The bound of a sum of two errors.
    #[allow(clippy::should_implement_trait)]
    #[inline]
    pub fn add(self, o: RelError) -> RelError {
        if self.is_zero() {
            return o;
        }
        if o.is_zero() {
            return self;
        }
        if !self.is_finite() || !o.is_finite() {
            return RelError::INFINITE;
        }
        let (big, small) = if self >= o { (self, o) } else { (o, self) };
        let shift = big.e - small.e;
        if shift > 60 {
            return RelError::normal(big.m * UP * UP, big.e);
        }
        // small.m·2^-shift: 2^-shift built from its exponent bits (0 ≤ shift ≤ 60).
        let scale = f64::from_bits(((1023 - shift) as u64) << 52);
        RelError::normal((big.m + small.m * scale) * UP, big.e)
    }

    /// The bound of a product of two relative factors (1 + a)(1 + b) − 1 ≤ a + b + ab: use
    /// [`RelError::add`] for compounding; this is the plain product a·b (a bound scaled by a
    /// condition number, say).
    #[allow(clippy::should_implement_trait)]
    #[inline]
    pub fn mul(self, o: RelError) -> RelError {
        if self.is_zero() || o.is_zero() {
            return RelError::ZERO;
        }
        if !self.is_finite() || !o.is_finite() {
            return RelError::INFINITE;
        }
        RelError::normal(self.m * o.m * UP, self.e + o.e)
    }

    /// The bound times a non-negative factor (NaN or ∞ give [`RelError::INFINITE`]).
    #[inline]
    pub fn scale(self, f: f64) -> RelError {
        self.mul(RelError::from_f64(f))
    }

    /// The larger of two bounds.
    #[inline]
    pub fn max(self, o: RelError) -> RelError {
        if o > self {
            o
        } else {
            self
        }
    }

    /// The smaller of two bounds.
    #[inline]
    pub fn min(self, o: RelError) -> RelError {
        if o < self {
            o
        } else {
            self
        }
    }

    /// The square root of the bound (rounded upwards).
    pub fn sqrt(self) -> RelError {
        if self.is_zero() || !self.is_finite() {
            return self;
        }
        // m·2^e with e even: √m·2^(e/2).
        let (m, e) = if self.e % 2 == 0 {
            (self.m, self.e)
        } else {
            (self.m * 2.0, self.e - 1)
        };
        RelError::normal(m.sqrt() * UP, e / 2)
    }

    /// log₂ of the bound (−∞ for zero, +∞ when unbounded).
    pub fn log2(&self) -> f64 {
        if self.is_zero() {
            f64::NEG_INFINITY
        } else if !self.is_finite() {
            f64::INFINITY
        } else {
            self.e as f64 + self.m.log2()
        }
    }

    /// The bound as an `f64`: 0 below the `f64` range, ∞ above it (for charts and quick
    /// comparisons; [`fmt::Display`] prints every bound faithfully).
    pub fn to_f64(&self) -> f64 {
        if !self.is_finite() {
            return f64::INFINITY;
        }
        let e = self.e.clamp(-2000, 2000) as i32;
        // Two steps so that neither factor overflows or underflows prematurely.
        self.m * 2f64.powi(e / 2) * 2f64.powi(e - e / 2)
    }

    /// The bound at the precision `p` (rounded upwards in the last place; 0 if it underflows
    /// the type, as it may at `f64`).
    pub fn to_real<T: Real>(&self, p: T::Prec) -> T {
        if !self.is_finite() {
            return T::from_f64(f64::INFINITY, p);
        }
        let e = self.e.clamp(i32::MIN as i64 / 2, i32::MAX as i64 / 2) as i32;
        T::from_f64(self.m * UP, p).mul_pow2(e)
    }
}

impl PartialOrd for RelError {
    #[inline]
    fn partial_cmp(&self, o: &RelError) -> Option<Ordering> {
        let rank = |x: &RelError| match (x.is_zero(), x.is_finite()) {
            (true, _) => 0,
            (_, false) => 2,
            _ => 1,
        };
        match rank(self).cmp(&rank(o)) {
            Ordering::Equal if rank(self) == 1 => {
                Some(self.e.cmp(&o.e).then(self.m.total_cmp(&o.m)))
            }
            ord => Some(ord),
        }
    }
}

impl fmt::Display for RelError {
    /// Three significant digits, rounded upwards, with an exponent of any size: `2.3e-1232`
    /// (`0` for an exact result, `inf` when unbounded). `{:.N}` asks for N + 1 digits.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let digits = f.precision().unwrap_or(2).min(12) as i32;
        let (text, end) = self.text(digits);
        // ASCII digits, a point, "e" and "-" only.
        f.write_str(std::str::from_utf8(&text[..end]).unwrap_or("?"))
    }
}

impl RelError {
    /// Appends the bound's text (ASCII) as [`fmt::Display`] writes it (three significant
    /// digits), without a string of its own (the `sweep` commands' rows): a bound whose three
    /// digits fit an `f64`'s decimal range (every bound of an `f64` result) as `d.dde±x`
    /// straight from those digits, any other through the general decimal text.
    pub fn push_text(&self, out: &mut Vec<u8>) {
        if let Some((mant, exp10)) = self.decimal_in_f64(2) {
            // "d.dde-xxx": three digits, a point, "e", a sign and at most 3 digits (|exp10|
            // ≤ 310 in that range), copied whole (a fixed-size copy) and cut to length.
            let mut text = [0u8; 10];
            let mant = mant as u32; // in [100, 1000)
            text[0] = b'0' + (mant / 100) as u8;
            text[1] = b'.';
            text[2] = b'0' + (mant / 10 % 10) as u8;
            text[3] = b'0' + (mant % 10) as u8;
            text[4] = b'e';
            let end = crate::scalar::write_exponent(&mut text, 5, exp10 as i32);
            let start = out.len();
            out.extend_from_slice(&text);
            out.truncate(start + end);
            return;
        }
        let (text, end) = self.text(2);
        out.extend_from_slice(&text[..end]);
    }

    /// The text of [`fmt::Display`] with `digits` + 1 significant digits (`digits` ≤ 12), in a
    /// buffer, and its length: "d.ddde-xxxx", ≤ 13 digits, a point, "e", a sign and ≤ 19
    /// digits.
    fn text(&self, digits: i32) -> ([u8; 40], usize) {
        let mut text = [0u8; 40];
        let word: &[u8] = match (self.is_zero(), self.is_finite()) {
            (true, _) => b"0",
            (_, false) => b"inf",
            _ => b"",
        };
        if !word.is_empty() {
            text[..word.len()].copy_from_slice(word);
            return (text, word.len());
        }
        let (mant, exp10) = self
            .decimal_in_f64(digits)
            .unwrap_or_else(|| self.decimal(digits));
        let mut end = push_digits(&mut text, 0, mant);
        if end > 1 {
            text.copy_within(1..end, 2);
            text[1] = b'.';
            end += 1;
        }
        text[end] = b'e';
        end += 1;
        if exp10 < 0 {
            text[end] = b'-';
            end += 1;
        }
        end = push_digits(&mut text, end, exp10.unsigned_abs());
        (text, end)
    }

    /// The bound (finite, nonzero) as mant·10^(exp10 − digits), mant an integer in
    /// [10^digits, 10^(digits+1)): the mantissa rounded upwards to `digits` decimals (a bound
    /// stays a bound), after forgiving the ~10⁻¹¹ relative error of log₁₀ at exponents of 10⁶
    /// (so that a parsed `1e-10000` prints as itself).
    fn decimal(&self, digits: i32) -> (u64, i64) {
        let l10 = self.log2() * std::f64::consts::LOG10_2;
        let exp10 = l10.floor();
        let scale = 10f64.powi(digits);
        // The mantissa's digits as one integer in [10^digits, 10^(digits+1)]: written as
        // integers are (a float formatted to a precision costs ten times more).
        // At least 10^digits: the forgiveness must not take a mantissa of 1 below 1
        // (`1e-300` at 12 digits is `1.000000000000e-300`, not `0.999999999999e-300`).
        let mant = ((10f64.powf(l10 - exp10) * scale * (1.0 - 1e-9)).ceil() as u64)
            .max(10u64.pow(digits as u32));
        Self::carry(mant, exp10 as i64, digits)
    }

    /// [`RelError::decimal`] by one exact power of ten, for at most 2 decimals (the default
    /// text) where the bound is a normal `f64` whose mantissa·10^digits is within 10^±22 of it
    /// (every bound of an `f64` result): the scaled value rounded once instead of a logarithm
    /// and a power, the same digits (the forgiveness of 10⁻⁹ of a mantissa below 1000 is far
    /// above both methods' rounding errors, about 10⁻¹³ of it; they may differ only for a
    /// bound within that of the forgiveness's edge, where neither is more right). `None`
    /// elsewhere.
    fn decimal_in_f64(&self, digits: i32) -> Option<(u64, i64)> {
        if digits > 2 || !(-1020..=1020).contains(&self.e) {
            return None;
        }
        let v = self.m * f64::from_bits(((1023 + self.e) as u64) << 52);
        // v ∈ [2^(e−1), 2^e): its decade is ⌊(e − 1)·log₁₀2⌋ (78913/2¹⁸ ≈ log₁₀2 gives that
        // floor exactly for every e of this range) or one more.
        let mut exp10 = ((self.e - 1) * 78_913) >> 18;
        let low = F64_POW10[digits.max(0) as usize];
        for _ in 0..2 {
            let k = i64::from(digits) - exp10;
            let p = *F64_POW10.get(k.unsigned_abs() as usize)?;
            let scaled = if k >= 0 { v * p } else { v / p };
            if scaled >= 10.0 * low {
                exp10 += 1;
                continue;
            }
            // ⌈x⌉ of 0 < x < 2^53 from its truncation (one more unless x is an integer).
            let x = scaled * (1.0 - 1e-9);
            let t = x as u64;
            let mant = (t + u64::from((t as f64) < x)).max(low as u64);
            return Some(Self::carry(mant, exp10, digits));
        }
        None
    }

    /// A mantissa rounded up to 10^(digits+1) carried into the exponent.
    fn carry(mant: u64, exp10: i64, digits: i32) -> (u64, i64) {
        match mant >= 10u64.pow(digits as u32 + 1) {
            true => (mant / 10, exp10 + 1),
            false => (mant, exp10),
        }
    }
}

/// 10^0 … 10^22, each exact in an `f64`.
const F64_POW10: [f64; 23] = {
    let mut p = [1.0; 23];
    let mut i = 1;
    while i < 23 {
        p[i] = p[i - 1] * 10.0;
        i += 1;
    }
    p
};

/// Writes the decimal digits of `n` into `text` from `at`; returns the end.
fn push_digits(text: &mut [u8; 40], at: usize, mut n: u64) -> usize {
    let mut digits = [0u8; 20];
    let mut len = 0;
    loop {
        digits[len] = b'0' + (n % 10) as u8;
        len += 1;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    for (slot, d) in text[at..at + len]
        .iter_mut()
        .zip(digits[..len].iter().rev())
    {
        *slot = *d;
    }
    at + len
}

/// What the bound of an [`Estimated`] value measures.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum BoundKind {
    /// |value − exact|/|exact|: every quantity except the eccentricity.
    #[default]
    Relative,
    /// |value − exact|: the eccentricity e, which vanishes for a circular contact (where a
    /// relative bound would be unbounded); e < 1, so it also bounds the error relative to 1.
    Absolute,
}

impl BoundKind {
    /// `"relative"` or `"absolute"`, as the command-line tool and the Python package print it.
    pub fn label(&self) -> &'static str {
        match self {
            BoundKind::Relative => "relative",
            BoundKind::Absolute => "absolute",
        }
    }
}

/// A value with a bound on its error: relative, except where [`Estimated::kind`] says absolute
/// (the eccentricity).
#[derive(Clone, Debug, PartialEq)]
pub struct Estimated<T> {
    /// The value at the working precision.
    pub value: T,
    /// A bound on its error, relative or absolute as `kind` says (see the module docs; kept
    /// as a [`RelError`], which holds either without underflow).
    pub error: RelError,
    /// What `error` bounds.
    pub kind: BoundKind,
}

impl<T: Real> Estimated<T> {
    /// A value and a bound on its relative error.
    pub fn new(value: T, error: RelError) -> Self {
        Estimated {
            value,
            error,
            kind: BoundKind::Relative,
        }
    }

    /// A value and a bound on its absolute error (the eccentricity's).
    pub fn absolute(value: T, error: RelError) -> Self {
        Estimated {
            value,
            error,
            kind: BoundKind::Absolute,
        }
    }

    /// The value as a decimal with every digit of the working precision.
    pub fn to_decimal(&self) -> String {
        self.value.to_decimal()
    }

    /// [`Error::NotFinite`] naming `what` unless the value is finite, [`Error::Unreachable`]
    /// unless its bound is: the check every public function makes before returning a result.
    pub fn checked(self, what: &'static str) -> Result<Self> {
        if !self.value.is_finite() {
            return Err(Error::NotFinite {
                name: what,
                value: crate::scalar::short(&self.value),
            });
        }
        if !self.error.is_finite() {
            return Err(Error::Unreachable {
                what,
                tolerance: "1 (one correct digit)".into(),
                reason: "its error bound is not finite".into(),
            });
        }
        Ok(self)
    }
}

impl<T: Real> fmt::Display for Estimated<T> {
    /// `value (relative error <= bound)`, or `absolute error` for an absolute bound.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (value, kind) = (self.value.to_decimal(), self.kind.label());
        write!(f, "{value} ({kind} error <= {})", self.error)
    }
}

/// (m, e) with x = m·2^e, m ∈ [1/2, 1), for a finite positive `f64` (subnormals included).
#[inline]
fn frexp(x: f64) -> (f64, i64) {
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i64;
    if exp == 0 {
        // Subnormal: scale into the normal range first.
        let (m, e) = frexp(x * 2f64.powi(64));
        return (m, e - 64);
    }
    let m = f64::from_bits((bits & !(0x7ffu64 << 52)) | (1022u64 << 52));
    (m, exp - 1022)
}

#[cfg(test)]
#[path = "../tests/unit/estimate.rs"]
mod tests;
