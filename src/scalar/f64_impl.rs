//! `f64` as a [`Field`] and [`Real`]: every method is a thin `#[inline]` wrapper over `std`, so
//! generic code instantiated at `f64` compiles to the same machine code as hand-written `f64`
//! code (checked by the `generic_cost` bench).

use super::{Field, FieldOps, Real};
use crate::error::{Error, Result};

impl FieldOps for f64 {
    type Prec = ();
    #[inline(always)]
    fn prec(&self) {}
    #[inline(always)]
    fn from_i64(n: i64, _: ()) -> f64 {
        n as f64
    }
    #[inline(always)]
    fn from_ratio(num: i64, den: i64, _: ()) -> f64 {
        // Both integers are exact in f64 for |n| < 2^53; one rounding.
        num as f64 / den as f64
    }
    #[inline(always)]
    fn zero(_: ()) -> f64 {
        0.0
    }
    #[inline(always)]
    fn one(_: ()) -> f64 {
        1.0
    }
    #[inline(always)]
    fn is_zero(&self) -> bool {
        *self == 0.0
    }
    #[inline(always)]
    fn mul_i64(self, n: i64) -> f64 {
        self * n as f64
    }
    #[inline(always)]
    fn div_i64(self, n: i64) -> f64 {
        self / n as f64
    }
    #[inline(always)]
    fn square(&self) -> f64 {
        self * self
    }
    #[inline(always)]
    fn recip(self) -> f64 {
        1.0 / self
    }
    #[inline(always)]
    fn powi(&self, n: i64) -> f64 {
        if n.unsigned_abs() <= i32::MAX as u64 {
            f64::powi(*self, n as i32)
        } else {
            f64::powf(*self, n as f64)
        }
    }
}

impl Field for f64 {
    #[inline(always)]
    fn is_negative(&self) -> bool {
        *self < 0.0
    }
    #[inline(always)]
    fn abs(self) -> f64 {
        f64::abs(self)
    }
    #[inline(always)]
    fn to_f64(&self) -> f64 {
        *self
    }
    #[inline(always)]
    fn max_of(self, other: f64) -> f64 {
        if other > self {
            other
        } else {
            self
        }
    }
    #[inline(always)]
    fn min_of(self, other: f64) -> f64 {
        if other < self {
            other
        } else {
            self
        }
    }
}

impl Real for f64 {
    type Wide = super::Dd;
    #[inline(always)]
    fn wide_prec(_: ()) {}
    #[inline(always)]
    fn to_wide(&self, _: ()) -> super::Dd {
        super::Dd::from_f64_exact(*self)
    }
    #[inline(always)]
    fn from_wide(w: &super::Dd, _: ()) -> f64 {
        w.hi() + w.lo()
    }
    #[inline(always)]
    fn bits(_: ()) -> u32 {
        53
    }
    #[inline(always)]
    fn epsilon(_: ()) -> f64 {
        f64::EPSILON
    }
    #[inline(always)]
    fn min_positive(_: ()) -> f64 {
        f64::MIN_POSITIVE
    }
    #[inline(always)]
    fn pi(_: ()) -> f64 {
        std::f64::consts::PI
    }
    #[inline(always)]
    fn ln2(_: ()) -> f64 {
        std::f64::consts::LN_2
    }
    #[inline(always)]
    fn from_f64(x: f64, _: ()) -> f64 {
        x
    }
    fn parse(s: &str, _: ()) -> Result<f64> {
        // Rust's parser rounds correctly to nearest.
        let t = s.trim();
        t.parse::<f64>().map_err(|_| Error::Parse {
            text: s.to_string(),
            reason: "not a decimal number",
        })
    }
    fn to_decimal(&self) -> String {
        // 17 significant digits identify every f64; 24 characters hold the longest
        // ("-1.2345678901234567e-308"), so the string is allocated once.
        let mut s = String::with_capacity(24);
        let _ = std::fmt::Write::write_fmt(&mut s, format_args!("{:.16e}", self));
        s
    }
    fn to_float(&self, bits: u32) -> rug::Float {
        rug::Float::with_val(bits.max(53), *self)
    }
    fn from_float(x: &rug::Float, _: ()) -> f64 {
        x.to_f64()
    }
    #[inline(always)]
    fn mul_pow2(self, k: i32) -> f64 {
        // Exact scaling by 2^k in at most two multiplications by normal powers of two (no
        // recursion, so it inlines).
        if (-1022..=1023).contains(&k) {
            self * f64::from_bits(((1023 + k) as u64) << 52)
        } else {
            let k = k.clamp(-2044, 2046);
            let h = k / 2;
            self * f64::from_bits(((1023 + h) as u64) << 52)
                * f64::from_bits(((1023 + (k - h)) as u64) << 52)
        }
    }
    #[inline(always)]
    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }
    #[inline(always)]
    fn is_nan(&self) -> bool {
        f64::is_nan(*self)
    }
    #[inline(always)]
    fn floor(self) -> f64 {
        f64::floor(self)
    }
    #[inline(always)]
    fn round(self) -> f64 {
        f64::round(self)
    }
    #[inline(always)]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn recip_sqrt(self) -> f64 {
        1.0 / f64::sqrt(self)
    }
    #[inline(always)]
    fn cbrt(self) -> f64 {
        f64::cbrt(self)
    }
    #[inline(always)]
    fn exp(self) -> f64 {
        f64::exp(self)
    }
    #[inline(always)]
    fn exp_m1(self) -> f64 {
        f64::exp_m1(self)
    }
    #[inline(always)]
    fn ln(self) -> f64 {
        f64::ln(self)
    }
    #[inline(always)]
    fn ln_1p(self) -> f64 {
        f64::ln_1p(self)
    }
    #[inline(always)]
    fn sin(self) -> f64 {
        f64::sin(self)
    }
    #[inline(always)]
    fn cos(self) -> f64 {
        f64::cos(self)
    }
    #[inline(always)]
    fn sin_cos(self) -> (f64, f64) {
        f64::sin_cos(self)
    }
    #[inline(always)]
    fn atan2(self, x: &f64) -> f64 {
        f64::atan2(self, *x)
    }
    #[inline(always)]
    fn atan(self) -> f64 {
        f64::atan(self)
    }
    #[inline(always)]
    fn asin(self) -> f64 {
        f64::asin(self)
    }
    #[inline(always)]
    fn acos(self) -> f64 {
        f64::acos(self)
    }
    #[inline(always)]
    fn tan(self) -> f64 {
        f64::tan(self)
    }
    #[inline(always)]
    fn sinh(self) -> f64 {
        f64::sinh(self)
    }
    #[inline(always)]
    fn cosh(self) -> f64 {
        f64::cosh(self)
    }
    #[inline(always)]
    fn tanh(self) -> f64 {
        f64::tanh(self)
    }
    #[inline(always)]
    fn hypot(self, y: &f64) -> f64 {
        f64::hypot(self, *y)
    }
    #[inline(always)]
    fn powf(self, y: &f64) -> f64 {
        f64::powf(self, *y)
    }
    #[inline(always)]
    fn mul_add(self, a: &f64, b: &f64) -> f64 {
        // A plain multiply-add: f64::mul_add is a libm call unless FMA is compiled in.
        #[cfg(target_feature = "fma")]
        {
            f64::mul_add(self, *a, *b)
        }
        #[cfg(not(target_feature = "fma"))]
        {
            self * a + b
        }
    }
    #[inline(always)]
    fn with_prec(&self, _: ()) -> f64 {
        *self
    }
}
