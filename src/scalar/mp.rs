//! MPFR through `rug`: [`Mp`], a wrapper over `rug::Float` whose precision is chosen at run time
//! ([`MpPrec`], 24 bits to [`MpPrec::MAX_BITS`]). Every operation and elementary function is
//! MPFR's, correctly rounded to the working precision.
//!
//! A value carries its precision. An operation on two values of different precisions is carried
//! out at the larger precision (never silently at the smaller) and counted in
//! [`mixed_precision_events`], which the test suite asserts stays at zero.
//!
//! No item of this module implements a formula of the paper: they are the MPFR arithmetic every
//! formula runs on, correctly rounded to the working precision.

use super::{Field, FieldOps, Real};
use crate::error::{Error, Result};
use rug::float::Constant;
use rug::Float;
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::sync::atomic::{AtomicU64, Ordering as AtOrd};

/// An MPFR number at a run-time precision.
#[derive(Clone, Debug)]
pub struct Mp(pub Float);

/// A validated MPFR precision in bits, between [`MpPrec::MIN_BITS`] and [`MpPrec::MAX_BITS`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct MpPrec(u32);

/// The methods of [`Real`] for `Mp` that are `rug`'s of the same name: unary ones, ones of a
/// second `&Mp` (brought to the wider precision first), and predicates.
macro_rules! rug_methods {
    ($($unary:ident)*; $($binary:ident)*; $($pred:ident)*) => {
        $(fn $unary(self) -> Mp {
            Mp(self.0.$unary())
        })*
        $(fn $binary(mut self, y: &Mp) -> Mp {
            harmonise(&mut self.0, &y.0);
            Mp(self.0.$binary(&y.0))
        })*
        $(fn $pred(&self) -> bool {
            self.0.$pred()
        })*
    };
}

impl MpPrec {
    /// Smallest supported precision (IEEE single's significand).
    pub const MIN_BITS: u32 = 24;
    /// Largest supported precision (2^20 bits, about 315 000 decimal digits).
    pub const MAX_BITS: u32 = 1 << 20;

    /// A precision of `bits` bits, or [`Error::Precision`] outside the supported range.
    pub fn new(bits: u64) -> Result<MpPrec> {
        if bits < Self::MIN_BITS as u64 || bits > Self::MAX_BITS as u64 {
            Err(Error::Precision {
                bits,
                min: Self::MIN_BITS,
                max: Self::MAX_BITS,
            })
        } else {
            Ok(MpPrec(bits as u32))
        }
    }
    /// A precision of `bits` bits clamped into the supported range (for internal constants).
    pub fn clamped(bits: u32) -> MpPrec {
        MpPrec(bits.clamp(Self::MIN_BITS, Self::MAX_BITS))
    }
    /// The number of bits.
    pub fn bits(self) -> u32 {
        self.0
    }
    /// The wide precision guarding double-double: 2·106 + 32 bits.
    pub(super) const DD_WIDE: MpPrec = MpPrec(2 * 106 + 32);
}

static MIXED: AtomicU64 = AtomicU64::new(0);

/// Number of MPFR operations so far, in this process, whose operands had different precisions.
///
/// Such an operation is carried out at the larger precision; a nonzero count points at generic
/// code that built a constant at the wrong precision.
pub fn mixed_precision_events() -> u64 {
    MIXED.load(AtOrd::Relaxed)
}

#[inline]
fn harmonise(a: &mut Float, b: &Float) {
    if a.prec() != b.prec() {
        MIXED.fetch_add(1, AtOrd::Relaxed);
        if b.prec() > a.prec() {
            a.set_prec(b.prec());
        }
    }
}

impl Mp {
    /// Wraps an MPFR number (its precision must be at least [`MpPrec::MIN_BITS`]).
    pub fn new(x: Float) -> Mp {
        Mp(x)
    }
    /// The wrapped MPFR number.
    pub fn as_float(&self) -> &Float {
        &self.0
    }
    /// The precision token of a raw MPFR number, clamped into the supported range.
    fn prec_of(x: &Float) -> MpPrec {
        MpPrec(x.prec().clamp(MpPrec::MIN_BITS, MpPrec::MAX_BITS))
    }
}

impl PartialEq for Mp {
    fn eq(&self, other: &Mp) -> bool {
        self.0 == other.0
    }
}

impl PartialOrd for Mp {
    fn partial_cmp(&self, other: &Mp) -> Option<Ordering> {
        self.0.partial_cmp(&other.0)
    }
}

impl Neg for Mp {
    type Output = Mp;
    fn neg(self) -> Mp {
        Mp(-self.0)
    }
}

macro_rules! mp_binop {
    ($Tr:ident, $m:ident, $TrA:ident, $ma:ident) => {
        impl<'r> $TrA<&'r Mp> for Mp {
            #[inline]
            fn $ma(&mut self, rhs: &'r Mp) {
                harmonise(&mut self.0, &rhs.0);
                self.0.$ma(&rhs.0);
            }
        }
        impl $TrA<Mp> for Mp {
            #[inline]
            fn $ma(&mut self, rhs: Mp) {
                self.$ma(&rhs);
            }
        }
        impl<'r> $Tr<&'r Mp> for Mp {
            type Output = Mp;
            #[inline]
            fn $m(mut self, rhs: &'r Mp) -> Mp {
                self.$ma(rhs);
                self
            }
        }
        impl $Tr<Mp> for Mp {
            type Output = Mp;
            #[inline]
            fn $m(mut self, rhs: Mp) -> Mp {
                self.$ma(&rhs);
                self
            }
        }
    };
}

mp_binop!(Add, add, AddAssign, add_assign);
mp_binop!(Sub, sub, SubAssign, sub_assign);
mp_binop!(Mul, mul, MulAssign, mul_assign);
mp_binop!(Div, div, DivAssign, div_assign);

impl FieldOps for Mp {
    type Prec = MpPrec;
    #[inline]
    fn prec(&self) -> MpPrec {
        Mp::prec_of(&self.0)
    }
    fn from_i64(n: i64, p: MpPrec) -> Mp {
        Mp(Float::with_val(p.0, n))
    }
    fn from_ratio(num: i64, den: i64, p: MpPrec) -> Mp {
        // One correct rounding of the exact ratio.
        Mp(Float::with_val(p.0, rug::Rational::from((num, den))))
    }
    rug_methods!(recip;; is_zero);
    fn mul_i64(mut self, n: i64) -> Mp {
        self.0 *= n;
        self
    }
    fn div_i64(mut self, n: i64) -> Mp {
        self.0 /= n;
        self
    }
    fn square(&self) -> Mp {
        Mp(self.0.clone().square())
    }
}

impl Field for Mp {
    rug_methods!(abs;;);
    fn is_negative(&self) -> bool {
        self.0.cmp0() == Some(Ordering::Less)
    }
    fn to_f64(&self) -> f64 {
        self.0.to_f64()
    }
}

impl Real for Mp {
    type Wide = Mp;
    /// MPFR rounds every operation correctly to nearest: ε/2.
    const ROUNDING: f64 = 0.5;
    fn wide_prec(p: MpPrec) -> MpPrec {
        MpPrec((2 * p.0 + 32).min(MpPrec::MAX_BITS))
    }
    fn to_wide(&self, pw: MpPrec) -> Mp {
        Mp(Float::with_val(pw.0.max(self.0.prec()), &self.0))
    }
    fn from_wide(w: &Mp, p: MpPrec) -> Mp {
        Mp(Float::with_val(p.0, &w.0))
    }
    fn bits(p: MpPrec) -> u32 {
        p.0
    }
    fn lower_prec(p: MpPrec, bits: u32) -> Option<MpPrec> {
        (bits < p.0).then(|| MpPrec::clamped(bits))
    }
    fn min_positive(p: MpPrec) -> Mp {
        let mut one = Float::with_val(p.0, 1);
        one >>= 1_000_000u32;
        Mp(one)
    }
    fn pi(p: MpPrec) -> Mp {
        Mp(Float::with_val(p.0, Constant::Pi))
    }
    fn ln2(p: MpPrec) -> Mp {
        Mp(Float::with_val(p.0, Constant::Log2))
    }
    fn from_f64(x: f64, p: MpPrec) -> Mp {
        Mp(Float::with_val(p.0, x))
    }
    fn parse(s: &str, p: MpPrec) -> Result<Mp> {
        let parsed = Float::parse(s.trim()).map_err(|_| Error::Parse {
            text: s.to_string(),
            reason: "not a decimal number",
        })?;
        Ok(Mp(Float::with_val(p.0, parsed)))
    }
    fn to_decimal(&self) -> String {
        // Enough digits to identify the value: ceil(bits · log10 2) + 1.
        let digits = (self.0.prec() as f64 * std::f64::consts::LOG10_2).ceil() as usize + 1;
        self.0.to_string_radix(10, Some(digits))
    }
    fn to_float(&self, bits: u32) -> Float {
        Float::with_val(bits.max(self.0.prec()), &self.0)
    }
    fn from_float(x: &Float, p: MpPrec) -> Mp {
        Mp(Float::with_val(p.0, x))
    }
    fn mul_pow2(mut self, k: i32) -> Mp {
        self.0 <<= k;
        self
    }
    rug_methods!(
        floor round sqrt recip_sqrt cbrt exp exp_m1 ln ln_1p sin cos atan asin acos;
        atan2 hypot;
        is_finite is_nan
    );
    fn sin_cos(self) -> (Mp, Mp) {
        let c = Float::new(self.0.prec());
        let (s, c) = self.0.sin_cos(c);
        (Mp(s), Mp(c))
    }
    fn with_prec(&self, p: MpPrec) -> Mp {
        Mp(Float::with_val(p.0, &self.0))
    }
}
