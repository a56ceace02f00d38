//! The scalar layer: the traits every formula of the crate is generic over, and their backends
//! (`docs/design.md`, "The scalar layer" and "The backends", says why they are shaped so).
//!
//! * [`FieldOps`] — field arithmetic and integers and integer ratios *at a precision*, without
//!   ordering: what the exact recurrences (36) and (40) need.
//! * [`Field`] — [`FieldOps`] plus comparison, sign and the nearest `f64`: `f64`, [`Dd`], [`Mp`]
//!   and `rug::Rational` (exact).
//! * [`Real`] — a rounded real type: precision queries, constants and decimal text at the
//!   working precision, elementary functions. `f64` (IEEE, libm within about 1 ulp), [`Dd`]
//!   (about 2⁻¹⁰⁴) and [`Mp`] (MPFR, correctly rounded).
//! * [`Complex`] — a complex number over any [`Real`], with principal square and cube roots.
//!
//! Values are not `Copy` and each knows its precision: [`FieldOps::prec`] returns a `Copy` token
//! that generic code passes to every constructor (`T::from_ratio(1, 3, p)`, `T::pi(p)`). An
//! [`Mp`] operation on mixed precisions runs at the larger one and is counted
//! ([`mixed_precision_events`]; the tests assert zero). No item of this module implements a
//! formula of the paper: the traits and backends are what every formula is written over, each
//! backend to the accuracy stated above.

mod complex;
mod dd;
mod f64_impl;
mod interop;
mod mp;
mod parse;
mod rational;

pub use complex::Complex;
pub use dd::Dd;
pub(crate) use f64_impl::write_exponent;
pub use mp::{mixed_precision_events, Mp, MpPrec};
pub use parse::decimal_to_rational;

use crate::error::{Error, Result};
use std::fmt::Debug;
use std::hash::Hash;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// Field arithmetic without ordering: what an exact recurrence needs.
///
/// Implementors: `f64`, [`Dd`], [`Mp`], `rug::Rational` (through [`Field`]) and the rational
/// functions of [`crate::symbolic`], which have no order, no sign and no nearest `f64`. Every
/// formula whose coefficients are exact rationals — the recurrence (36) of the paper
/// ([`crate::routes::GreenSeries`]) and the L_n/M_n recursion (40)
/// ([`crate::routes::moments::KeForm`]) — is written once over this trait, so that the same code
/// runs rounded, exactly, and symbolically in ν or e².
pub trait FieldOps:
    Clone
    + Debug
    + PartialEq
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + for<'a> Div<&'a Self, Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
    + for<'a> AddAssign<&'a Self>
    + for<'a> SubAssign<&'a Self>
    + for<'a> MulAssign<&'a Self>
    + for<'a> DivAssign<&'a Self>
{
    /// The precision token: `()` for fixed-precision and exact types, [`MpPrec`] for MPFR.
    type Prec: Copy + Debug + PartialEq + Eq + Hash + Send + Sync + 'static;

    /// Precision of this value.
    fn prec(&self) -> Self::Prec;
    /// The integer `n` at precision `p` (exact when `|n|` fits the significand).
    fn from_i64(n: i64, p: Self::Prec) -> Self;
    /// The ratio `num/den` rounded once at precision `p` (exact for `Rational`). `den != 0`.
    fn from_ratio(num: i64, den: i64, p: Self::Prec) -> Self;
    /// Zero at precision `p`.
    fn zero(p: Self::Prec) -> Self {
        Self::from_i64(0, p)
    }
    /// One at precision `p`.
    fn one(p: Self::Prec) -> Self {
        Self::from_i64(1, p)
    }
    /// True when the value is exactly zero.
    fn is_zero(&self) -> bool;
    /// `self * n` for a small integer (a fast path on every backend).
    fn mul_i64(self, n: i64) -> Self;
    /// `self / n` for a small nonzero integer, rounded once.
    fn div_i64(self, n: i64) -> Self;
    /// `self * self`.
    fn square(&self) -> Self {
        self.clone() * self
    }
    /// `1 / self`.
    fn recip(self) -> Self {
        Self::one(self.prec()) / self
    }
    /// `self^n` for an integer `n` by binary powering (`n < 0` inverts).
    fn powi(&self, n: i64) -> Self {
        let p = self.prec();
        let mut base = self.clone();
        let mut e = n.unsigned_abs();
        let mut acc = Self::one(p);
        while e > 0 {
            if e & 1 == 1 {
                acc *= &base;
            }
            e >>= 1;
            if e > 0 {
                base = base.square();
            }
        }
        if n < 0 {
            acc.recip()
        } else {
            acc
        }
    }
}

/// An ordered field at a given precision (exact for `rug::Rational`): [`FieldOps`] plus
/// comparison, sign and the nearest `f64`.
///
/// Implementors: `f64`, [`Dd`], [`Mp`], `rug::Rational`.
pub trait Field: FieldOps + PartialOrd {
    /// True when the value is strictly negative.
    fn is_negative(&self) -> bool;
    /// True when the value is strictly positive.
    fn is_positive(&self) -> bool {
        !self.is_zero() && !self.is_negative()
    }
    /// Absolute value.
    fn abs(self) -> Self {
        if self.is_negative() {
            -self
        } else {
            self
        }
    }
    /// Nearest `f64` (for seeds, reports and charts only; never fed back at higher precision).
    fn to_f64(&self) -> f64;
    /// The larger of two values.
    fn max_of(self, other: Self) -> Self {
        if other > self {
            other
        } else {
            self
        }
    }
    /// The smaller of two values.
    fn min_of(self, other: Self) -> Self {
        if other < self {
            other
        } else {
            self
        }
    }
}

/// A rounded real number type at a fixed or run-time precision.
///
/// Implementors: `f64` (53 bits), [`Dd`] (double-double, 106 bits, relative accuracy ≈ 2^-104 for
/// every operation and function listed here), [`Mp`] (MPFR, 24 bits to [`MpPrec::MAX_BITS`],
/// correctly rounded).
///
/// What a new backend must implement is listed in `docs/design.md`: the [`Field`] operations, the
/// precision queries, `from_f64`/`parse`/`to_decimal`, conversion to and from `rug::Float`, and the
/// elementary functions without default bodies below.
pub trait Real: Field {
    /// A type with at least twice this precision, for computations that need guard digits
    /// (a double root, a residual that cancels): `Dd` for `f64`, `Mp` for `Dd` and `Mp`.
    type Wide: Real;
    /// The precision of [`Real::Wide`] used to guard precision `p`: ≥ 2·bits(p) + 32 for MPFR.
    fn wide_prec(p: Self::Prec) -> <Self::Wide as FieldOps>::Prec;
    /// This value at the wide precision `pw` (exact).
    fn to_wide(&self, pw: <Self::Wide as FieldOps>::Prec) -> Self::Wide;
    /// A wide value rounded back to precision `p`.
    fn from_wide(w: &Self::Wide, p: Self::Prec) -> Self;
    /// Significand bits of the precision `p` (53 for `f64`, 106 for [`Dd`], the MPFR precision).
    fn bits(p: Self::Prec) -> u32;
    /// A precision of this type with `bits` bits, for a stage below `p` (the ellipse solve's
    /// precision ladder): `None` for the fixed-precision types and where `bits` is not below
    /// `p`'s.
    fn lower_prec(p: Self::Prec, bits: u32) -> Option<Self::Prec> {
        let _ = (p, bits);
        None
    }
    /// The worst relative error of one operation (`+ − × ÷`, `sqrt`, `cbrt`, a rounding from
    /// [`Real::Wide`]) in units of [`Real::epsilon`], which every error bound that counts
    /// operations multiplies (`RelError::rounding`): 1/2 for `f64` and MPFR, 1.625 for
    /// double-double (`docs/design.md`, "Rounding unit"). `f64`'s libm `cbrt` is not counted:
    /// the closed forms take their cube roots from [`Real::Wide`].
    const ROUNDING: f64;
    /// Machine epsilon `2^(1 - bits)` at precision `p`: the unit every tolerance is built from.
    fn epsilon(p: Self::Prec) -> Self {
        Self::one(p).mul_pow2(1 - Self::bits(p) as i32)
    }
    /// `2^(-bits/n)`, rounded down in the exponent: ε^(1/n) up to a factor of 2 (√ε for n = 2).
    fn epsilon_root(p: Self::Prec, n: u32) -> Self {
        Self::one(p).mul_pow2(-((Self::bits(p) - 1) as i32 / n as i32))
    }
    /// Smallest positive normal number (guards divisions by tiny quantities).
    fn min_positive(p: Self::Prec) -> Self;
    /// π at precision `p`.
    fn pi(p: Self::Prec) -> Self;
    /// ln 2 at precision `p`.
    fn ln2(p: Self::Prec) -> Self;
    /// The `f64` value `x` exactly (for seeds and exactly representable test inputs).
    fn from_f64(x: f64, p: Self::Prec) -> Self;
    /// The decimal text `s` rounded at precision `p` (not via `f64`).
    fn parse(s: &str, p: Self::Prec) -> Result<Self>;
    /// Every significant digit of the working precision, in scientific notation.
    fn to_decimal(&self) -> String;
    /// [`Real::to_decimal`]'s text (ASCII) appended to `out` (`f64` writes its digits there
    /// without a string of their own: the `sweep` command's rows).
    fn push_decimal(&self, out: &mut Vec<u8>) {
        out.extend_from_slice(self.to_decimal().as_bytes());
    }
    /// The value as an MPFR number with at least `bits` bits (exact if `bits` suffices).
    fn to_float(&self, bits: u32) -> rug::Float;
    /// The MPFR number `x` rounded to precision `p`.
    fn from_float(x: &rug::Float, p: Self::Prec) -> Self;
    /// `self · 2^k`, exact barring overflow or underflow.
    fn mul_pow2(self, k: i32) -> Self;
    /// Neither NaN nor infinite.
    fn is_finite(&self) -> bool;
    /// NaN.
    fn is_nan(&self) -> bool;
    /// Largest integer not above `self`.
    fn floor(self) -> Self;
    /// Nearest integer, ties away from zero.
    fn round(self) -> Self;
    /// Square root (NaN for negative input).
    fn sqrt(self) -> Self;
    /// 1/√x (NaN for negative input, +∞ at 0): `sqrt` then `recip` by default (≤ 1 ulp at
    /// `f64`); MPFR's is correctly rounded, double-double's as `docs/design.md` measures it.
    fn recip_sqrt(self) -> Self {
        self.sqrt().recip()
    }
    /// √self / b, the form of G's factors in (45): one square root and one division by default,
    /// no division at double-double (`docs/design.md`, "Kernel powers without a division").
    fn sqrt_div(self, b: &Self) -> Self {
        self.sqrt() / b
    }
    /// x^{−3/2}, the kernel power of (34) (u^{−3/2}, Δ⁻³): 1/(x·√x) by default, y³ from
    /// y = [`Real::recip_sqrt`] at double-double (accuracy in `docs/design.md`).
    fn pow_m3_2(self) -> Self {
        (self.clone() * self.sqrt()).recip()
    }
    /// (x^{−3/2}, x^{−5/2}), the kernel powers of (34) and of its k-derivative: v = 1/(x²·√x)
    /// and (v·x, v) by default, (y³, y⁵) at double-double (accuracy in `docs/design.md`).
    fn pow_m3_2_m5_2(self) -> (Self, Self) {
        let v = (self.clone() * &self * self.clone().sqrt()).recip();
        (v.clone() * self, v)
    }
    /// Real cube root.
    fn cbrt(self) -> Self;
    /// e^x.
    fn exp(self) -> Self;
    /// e^x − 1, accurate for small x.
    fn exp_m1(self) -> Self;
    /// Natural logarithm.
    fn ln(self) -> Self;
    /// ln(1 + x), accurate for small x.
    fn ln_1p(self) -> Self;
    /// Sine.
    fn sin(self) -> Self;
    /// Cosine.
    fn cos(self) -> Self;
    /// Sine and cosine together.
    fn sin_cos(self) -> (Self, Self) {
        (self.clone().sin(), self.cos())
    }
    /// Four-quadrant arctangent of `self / x`, in (−π, π].
    fn atan2(self, x: &Self) -> Self;
    /// Arctangent.
    fn atan(self) -> Self {
        let one = Self::one(self.prec());
        self.atan2(&one)
    }
    /// Arcsine on [−1, 1].
    fn asin(self) -> Self {
        let p = self.prec();
        let c = ((Self::one(p) - &self) * (Self::one(p) + &self)).sqrt();
        self.atan2(&c)
    }
    /// Arccosine on [−1, 1].
    fn acos(self) -> Self {
        let p = self.prec();
        let s = ((Self::one(p) - &self) * (Self::one(p) + &self)).sqrt();
        s.atan2(&self)
    }
    /// √(x² + y²) without undue overflow.
    fn hypot(self, y: &Self) -> Self {
        let a = self.abs();
        let b = y.clone().abs();
        let (big, small) = if a >= b { (a, b) } else { (b, a) };
        if big.is_zero() {
            return big;
        }
        let r = small / &big;
        let p = r.prec();
        big * (Self::one(p) + r.square()).sqrt()
    }
    /// The same value at another precision (rounded when narrowing).
    fn with_prec(&self, p: Self::Prec) -> Self {
        let bits = Self::bits(self.prec()).max(Self::bits(p)) + 64;
        Self::from_float(&self.to_float(bits), p)
    }
}

/// A run-time choice of backend and precision, as the CLI and studies take it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Precision {
    /// IEEE double.
    F64,
    /// Double-double ([`Dd`]).
    DoubleDouble,
    /// MPFR with the given number of bits ([`Mp`]).
    Mpfr(MpPrec),
}

impl Precision {
    /// The precision of the backend `T` at the token `p`.
    pub fn of<T: Real>(p: T::Prec) -> Precision {
        use std::any::TypeId;
        let id = TypeId::of::<T>();
        if id == TypeId::of::<f64>() {
            Precision::F64
        } else if id == TypeId::of::<Dd>() {
            Precision::DoubleDouble
        } else {
            Precision::Mpfr(MpPrec::clamped(T::bits(p)))
        }
    }

    /// Parses the names [`Precision::label`] prints: `f64`, `dd`, or a number of MPFR bits as
    /// `256` or `mpfr256` (any case; `53` is MPFR at 53 bits, not `f64`). `double` is refused as
    /// ambiguous (f64 or double-double); a bit count outside [[`MpPrec::MIN_BITS`],
    /// [`MpPrec::MAX_BITS`]] is [`Error::Precision`], one too long for a `u64` a parse error.
    pub fn parse(s: &str) -> Result<Self> {
        let bad = |reason: &'static str| Error::Parse {
            text: s.to_string(),
            reason,
        };
        let t = s.trim().to_ascii_lowercase();
        match t.as_str() {
            "f64" => return Ok(Precision::F64),
            "dd" => return Ok(Precision::DoubleDouble),
            "double" => {
                return Err(bad(
                    "ambiguous: f64 (53 bits) or dd (double-double, 106 bits)",
                ))
            }
            _ => {}
        }
        let digits = t.strip_prefix("mpfr").unwrap_or(&t);
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return Err(bad("expected f64, dd or a number of bits (256 or mpfr256)"));
        }
        let bits: u64 = digits
            .parse()
            .map_err(|_| bad("a number of bits far outside the supported range"))?;
        Ok(Precision::Mpfr(MpPrec::new(bits)?))
    }
    /// Significand bits of this precision.
    pub fn bits(&self) -> u32 {
        match self {
            Precision::F64 => 53,
            Precision::DoubleDouble => 106,
            Precision::Mpfr(p) => p.bits(),
        }
    }
    /// A short label: `f64`, `dd`, `mpfr256`.
    pub fn label(&self) -> String {
        match self {
            Precision::F64 => "f64".into(),
            Precision::DoubleDouble => "dd".into(),
            Precision::Mpfr(p) => format!("mpfr{}", p.bits()),
        }
    }
}

impl std::fmt::Display for Precision {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.label())
    }
}

/// Runs a generic body at the backend a [`Precision`] selects.
///
/// `with_precision!(prec, T, p => body)` expands `body` three times, with `T` bound to `f64`,
/// [`Dd`] or [`Mp`] and `p` to the matching precision token.
#[macro_export]
macro_rules! with_precision {
    ($prec:expr, $T:ident, $p:ident => $body:expr) => {{
        match $prec {
            $crate::scalar::Precision::F64 => {
                type $T = f64;
                let $p: () = ();
                $body
            }
            $crate::scalar::Precision::DoubleDouble => {
                type $T = $crate::scalar::Dd;
                let $p: () = ();
                $body
            }
            $crate::scalar::Precision::Mpfr(mp_prec) => {
                type $T = $crate::scalar::Mp;
                let $p: $crate::scalar::MpPrec = mp_prec;
                $body
            }
        }
    }};
}

/// Checks that a value is a positive finite number, naming it in the error otherwise
/// ([`Error::NotFinite`], or [`Error::Domain`] with the bound (0, inf)).
pub fn check_positive<T: Real>(name: &'static str, x: &T) -> Result<()> {
    check_finite(name, x)?;
    if x.is_positive() {
        Ok(())
    } else {
        Err(Error::domain(name, short(x), "(0, inf)"))
    }
}

/// Checks that a value is finite, naming it in the error otherwise.
pub fn check_finite<T: Real>(name: &'static str, x: &T) -> Result<()> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(Error::NotFinite {
            name,
            value: short(x),
        })
    }
}

/// A value as error messages show it: the shortest decimal that identifies an `f64` (`0.7`
/// prints as `0.7`, `1e-300` as `1e-300`), and for a value of higher precision that is not an
/// `f64`, or lies outside the `f64` range, 20 significant digits (`5.0000000000000000001e-1`,
/// `1e400`): never a page of digits, never a value rounded onto a misleading neighbour.
pub fn short<T: Real>(x: &T) -> String {
    if x.is_nan() {
        return "NaN".into();
    }
    if !x.is_finite() {
        return if x.is_negative() { "-inf" } else { "inf" }.into();
    }
    let f = x.to_f64();
    let is_f64 = f.is_finite() && (f != 0.0 || x.is_zero()) && T::from_f64(f, x.prec()) == *x;
    if is_f64 {
        let a = f.abs();
        return if a != 0.0 && !(1e-5..1e16).contains(&a) {
            format!("{f:e}")
        } else {
            format!("{f}")
        };
    }
    let s = x.to_float(T::bits(x.prec())).to_string_radix(10, Some(20));
    trim_mantissa(&s)
}

/// `5.0000000000000000010e-1` → `5.000000000000000001e-1`: trailing zeros of the mantissa dropped.
fn trim_mantissa(s: &str) -> String {
    let (mant, exp) = match s.find('e') {
        Some(i) => (&s[..i], &s[i..]),
        None => (s, ""),
    };
    let mant = if mant.contains('.') {
        mant.trim_end_matches('0').trim_end_matches('.')
    } else {
        mant
    };
    format!("{mant}{exp}")
}
