//! Double-double arithmetic: [`Dd`], a wrapper over [`twofloat::TwoFloat`] that is accurate to
//! about 2^-104 relative for `+ − × ÷`, `sqrt` and every elementary function of [`Real`].
//! Storage, addition and subtraction are `twofloat`'s; multiplication (the error-free product
//! [`two_prod`] on the hardware FMA where there is one, Dekker's splitting elsewhere: the same
//! bits), division, the elementary functions and decimal text (exactly, through MPFR) are ours,
//! for the reasons and with the measured accuracy in `docs/design.md` ("Double-double";
//! `tests/dd_accuracy.rs`). `Dd::EPSILON` is `2^-105`. No item of this module implements a
//! formula of the paper: they are the double-double arithmetic every formula runs on.

mod eft;
mod elementary;

use super::{Field, FieldOps, Real};
use crate::error::{Error, Result};
use eft::{fast_two_sum, two_prod, two_sum};
use elementary::consts;
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use twofloat::TwoFloat;

/// A double-double number: an unevaluated sum `hi + lo` of two `f64` with `|lo| ≤ ulp(hi)/2`,
/// about 106 significant bits.
#[derive(Clone, Copy, Debug, Default)]
pub struct Dd(TwoFloat);

impl Dd {
    /// `2^-105`: the spacing of double-double numbers relative to 1 (106-bit significand).
    pub const EPSILON: f64 = 2.465190328815662e-32;

    /// The double-double `hi + lo`, renormalised exactly.
    #[inline(always)]
    pub fn from_parts(hi: f64, lo: f64) -> Dd {
        Dd(TwoFloat::new_add(hi, lo))
    }
    /// The `f64` value `x` exactly.
    #[inline(always)]
    pub const fn from_f64_exact(x: f64) -> Dd {
        Dd(TwoFloat::from_f64(x))
    }
    /// Leading component.
    #[inline(always)]
    pub fn hi(&self) -> f64 {
        self.0.hi()
    }
    /// Trailing component.
    #[inline(always)]
    pub fn lo(&self) -> f64 {
        self.0.lo()
    }
    /// Product with an `f64`, error ≤ 2·2^-106 relative.
    #[inline(always)]
    pub fn mul_f64(self, b: f64) -> Dd {
        let (p, e) = two_prod(self.hi(), b);
        Dd::from_parts(p, e + self.lo() * b)
    }

    /// Quotient by an `f64`, error ≈ 2^-105 relative.
    #[inline]
    pub fn div_f64(self, d: f64) -> Dd {
        let q1 = self.hi() / d;
        let (p, pe) = two_prod(q1, d);
        let (s, e) = two_sum(self.hi(), -p);
        let e = e - pe + self.lo();
        let q2 = (s + e) / d;
        let (h, l) = fast_two_sum(q1, q2);
        Dd::from_parts(h, l)
    }

    #[inline(always)]
    fn mul_dd(self, b: Dd) -> Dd {
        // Joldes et al. Algorithm 11 (the renormalisation is twofloat's exact TwoSum).
        let (p, e) = two_prod(self.hi(), b.hi());
        Dd::from_parts(p, e + (self.hi() * b.lo() + self.lo() * b.hi()))
    }

    #[inline]
    fn div_dd(self, b: Dd) -> Dd {
        // Long division with two correction quotients, q1 + q2 + q3 (as in the QD library):
        // measured worst error 2.7·2^-106 (tests/dd_accuracy.rs). The one-correction variant
        // (Joldes et al. Algorithm 17) is twice as fast but measured 6.7·2^-106.
        // The three partial quotients use one f64 division, 1/b.hi, and multiply by it: each
        // quotient is then off by 2 ulp instead of ½, which the next correction absorbs (same
        // measured error, two fewer dependent divisions).
        let q1 = self.hi() / b.hi();
        if !q1.is_finite() || b.hi() == 0.0 {
            return Dd::from_f64_exact(q1);
        }
        let inv = 1.0 / b.hi();
        if !inv.is_finite() || inv.abs() < f64::MIN_POSITIVE {
            // |b| near the ends of the exponent range: the divisions themselves.
            let r = self - b.mul_f64(q1);
            let q2 = r.hi() / b.hi();
            let r = r - b.mul_f64(q2);
            let q3 = r.hi() / b.hi();
            let (h, l) = fast_two_sum(q1, q2);
            return Dd::from_parts(h, l + q3);
        }
        let r = self - b.mul_f64(q1);
        let q2 = r.hi() * inv;
        let r = r - b.mul_f64(q2);
        let q3 = r.hi() * inv;
        let (h, l) = fast_two_sum(q1, q2);
        Dd::from_parts(h, l + q3)
    }
}

// ---------------------------------------------------------------------------------------------
// Operators.

impl Neg for Dd {
    type Output = Dd;
    #[inline(always)]
    fn neg(self) -> Dd {
        Dd(-self.0)
    }
}

macro_rules! dd_binop {
    ($Tr:ident, $m:ident, $TrA:ident, $ma:ident, |$a:ident, $b:ident| $body:expr) => {
        impl $Tr<Dd> for Dd {
            type Output = Dd;
            #[inline(always)]
            fn $m(self, rhs: Dd) -> Dd {
                let ($a, $b) = (self, rhs);
                $body
            }
        }
        impl<'r> $Tr<&'r Dd> for Dd {
            type Output = Dd;
            #[inline(always)]
            fn $m(self, rhs: &'r Dd) -> Dd {
                let ($a, $b) = (self, *rhs);
                $body
            }
        }
        impl $TrA<Dd> for Dd {
            #[inline(always)]
            fn $ma(&mut self, rhs: Dd) {
                let ($a, $b) = (*self, rhs);
                *self = $body;
            }
        }
        impl<'r> $TrA<&'r Dd> for Dd {
            #[inline(always)]
            fn $ma(&mut self, rhs: &'r Dd) {
                let ($a, $b) = (*self, *rhs);
                *self = $body;
            }
        }
    };
}

dd_binop!(Add, add, AddAssign, add_assign, |a, b| Dd(a.0 + b.0));
dd_binop!(Sub, sub, SubAssign, sub_assign, |a, b| Dd(a.0 - b.0));
dd_binop!(Mul, mul, MulAssign, mul_assign, |a, b| a.mul_dd(b));
dd_binop!(Div, div, DivAssign, div_assign, |a, b| a.div_dd(b));

impl PartialEq for Dd {
    #[inline(always)]
    fn eq(&self, other: &Dd) -> bool {
        self.hi() == other.hi() && self.lo() == other.lo()
    }
}

impl PartialOrd for Dd {
    #[inline(always)]
    fn partial_cmp(&self, other: &Dd) -> Option<Ordering> {
        match self.hi().partial_cmp(&other.hi()) {
            Some(Ordering::Equal) => self.lo().partial_cmp(&other.lo()),
            c => c,
        }
    }
}

impl From<f64> for Dd {
    fn from(x: f64) -> Dd {
        Dd::from_f64_exact(x)
    }
}

impl From<TwoFloat> for Dd {
    fn from(x: TwoFloat) -> Dd {
        Dd(x)
    }
}

impl FieldOps for Dd {
    type Prec = ();
    #[inline(always)]
    fn prec(&self) {}
    #[inline(always)]
    fn from_i64(n: i64, _: ()) -> Dd {
        let hi = n as f64;
        let lo = (n - hi as i64) as f64;
        Dd::from_parts(hi, lo)
    }
    #[inline]
    fn from_ratio(num: i64, den: i64, _: ()) -> Dd {
        Dd::from_i64(num, ()).div_dd(Dd::from_i64(den, ()))
    }
    #[inline(always)]
    fn zero(_: ()) -> Dd {
        Dd::from_f64_exact(0.0)
    }
    #[inline(always)]
    fn one(_: ()) -> Dd {
        Dd::from_f64_exact(1.0)
    }
    #[inline(always)]
    fn is_zero(&self) -> bool {
        self.hi() == 0.0
    }
    #[inline(always)]
    fn mul_i64(self, n: i64) -> Dd {
        if n.unsigned_abs() < (1u64 << 53) {
            self.mul_f64(n as f64)
        } else {
            self * Dd::from_i64(n, ())
        }
    }
    #[inline(always)]
    fn div_i64(self, n: i64) -> Dd {
        if n.unsigned_abs() < (1u64 << 53) {
            self.div_f64(n as f64)
        } else {
            self / Dd::from_i64(n, ())
        }
    }
    #[inline(always)]
    fn square(&self) -> Dd {
        self.mul_dd(*self)
    }
}

impl Field for Dd {
    #[inline(always)]
    fn is_negative(&self) -> bool {
        self.hi() < 0.0
    }
    #[inline(always)]
    fn abs(self) -> Dd {
        if self.hi() < 0.0 {
            -self
        } else {
            self
        }
    }
    #[inline(always)]
    fn to_f64(&self) -> f64 {
        self.hi() + self.lo()
    }
}

impl Real for Dd {
    type Wide = super::Mp;
    /// Above the worst measured (mul 3.235·2⁻¹⁰⁶; div, sqrt and cbrt 2.6·2⁻¹⁰⁶, add
    /// 1.9·2⁻¹⁰⁶: `docs/design.md`): 3.25·2⁻¹⁰⁶, which `tests/dd_accuracy.rs` asserts for each
    /// of them.
    const ROUNDING: f64 = 1.625;
    fn wide_prec(_: ()) -> super::MpPrec {
        super::MpPrec::DD_WIDE
    }
    fn to_wide(&self, pw: super::MpPrec) -> super::Mp {
        super::Mp(self.to_float(pw.bits()))
    }
    fn from_wide(w: &super::Mp, _: ()) -> Dd {
        Dd::from_float(&w.0, ())
    }
    #[inline(always)]
    fn bits(_: ()) -> u32 {
        106
    }
    #[inline(always)]
    fn epsilon(_: ()) -> Dd {
        Dd::from_f64_exact(Dd::EPSILON)
    }
    #[inline(always)]
    fn min_positive(_: ()) -> Dd {
        // Below 2^-969 the trailing word is subnormal and accuracy degrades.
        Dd::from_f64_exact(f64::MIN_POSITIVE * 9007199254740992.0)
    }
    #[inline]
    fn pi(_: ()) -> Dd {
        consts().pi
    }
    #[inline]
    fn ln2(_: ()) -> Dd {
        consts().ln2
    }
    #[inline(always)]
    fn from_f64(x: f64, _: ()) -> Dd {
        Dd::from_f64_exact(x)
    }
    fn parse(s: &str, _: ()) -> Result<Dd> {
        let parsed = rug::Float::parse(s.trim()).map_err(|_| Error::Parse {
            text: s.to_string(),
            reason: "not a decimal number",
        })?;
        let f = rug::Float::with_val(320, parsed);
        Ok(Dd::from_float(&f, ()))
    }
    fn to_decimal(&self) -> String {
        if !self.hi().is_finite() {
            return format!("{}", self.hi());
        }
        self.to_float(128).to_string_radix(10, Some(32))
    }
    fn to_float(&self, bits: u32) -> rug::Float {
        let (hi, lo) = (self.hi(), self.lo());
        let need = if lo == 0.0 || !hi.is_finite() {
            53
        } else {
            let eh = hi.abs().log2().floor() as i64;
            let el = lo.abs().log2().floor() as i64;
            ((eh - el) + 54).clamp(53, 2200) as u32
        };
        let mut f = rug::Float::with_val(bits.max(need), hi);
        f += lo;
        f
    }
    fn from_float(x: &rug::Float, _: ()) -> Dd {
        let hi = x.to_f64();
        if !hi.is_finite() {
            return Dd::from_f64_exact(hi);
        }
        let r = rug::Float::with_val(x.prec().max(64), x - hi);
        Dd::from_parts(hi, r.to_f64())
    }
    #[inline(always)]
    fn mul_pow2(self, k: i32) -> Dd {
        Dd::from_parts(self.hi().mul_pow2(k), self.lo().mul_pow2(k))
    }
    #[inline(always)]
    fn is_finite(&self) -> bool {
        self.hi().is_finite()
    }
    #[inline(always)]
    fn is_nan(&self) -> bool {
        self.hi().is_nan()
    }
    fn floor(self) -> Dd {
        let f = self.hi().floor();
        if f == self.hi() {
            Dd::from_parts(f, self.lo().floor())
        } else {
            Dd::from_f64_exact(f)
        }
    }
    fn round(self) -> Dd {
        let half = Dd::from_f64_exact(0.5);
        if self.is_negative() {
            -((-self) + half).floor()
        } else {
            (self + half).floor()
        }
    }
    fn sqrt(self) -> Dd {
        self.sqrt_dd()
    }
    fn recip_sqrt(self) -> Dd {
        self.recip_sqrt_dd()
    }
    fn sqrt_div(self, b: &Dd) -> Dd {
        if !(self.hi() > 0.0 && b.hi() != 0.0 && self.is_finite() && b.is_finite()) {
            return self.sqrt_dd() / *b;
        }
        let q = self * (self * b.square()).recip_sqrt_dd();
        if b.hi() < 0.0 {
            -q
        } else {
            q
        }
    }
    fn pow_m3_2(self) -> Dd {
        let y = self.recip_sqrt_dd();
        y.square() * y
    }
    fn pow_m3_2_m5_2(self) -> (Dd, Dd) {
        let y = self.recip_sqrt_dd();
        let y2 = y.square();
        let y3 = y2 * y;
        (y3, y3 * y2)
    }
    fn cbrt(self) -> Dd {
        self.cbrt_dd()
    }
    fn exp(self) -> Dd {
        self.exp_dd()
    }
    fn exp_m1(self) -> Dd {
        if self.hi().abs() <= 0.5 {
            self.expm1_small()
        } else {
            self.exp_dd() - Dd::from_f64_exact(1.0)
        }
    }
    fn ln(self) -> Dd {
        self.ln_dd()
    }
    fn ln_1p(self) -> Dd {
        self.ln1p_dd()
    }
    fn sin(self) -> Dd {
        self.sin_cos_dd().0
    }
    fn cos(self) -> Dd {
        self.sin_cos_dd().1
    }
    fn sin_cos(self) -> (Dd, Dd) {
        self.sin_cos_dd()
    }
    fn atan2(self, x: &Dd) -> Dd {
        self.atan2_dd(*x)
    }
    fn with_prec(&self, _: ()) -> Dd {
        *self
    }
}
