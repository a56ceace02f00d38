//! `f64` as a [`Field`] and [`Real`]: every method is a thin `#[inline]` wrapper over `std`, so
//! generic code instantiated at `f64` compiles to the same machine code as hand-written `f64`
//! code (checked by the `generic_cost` bench).

use super::{Field, FieldOps, Real};
use crate::error::{Error, Result};

/// The `f64` methods of [`Real`] that are `std`'s of the same name: unary ones, ones of a
/// second `&f64`, and predicates.
macro_rules! std_methods {
    ($($unary:ident)*; $($binary:ident)*; $($pred:ident)*) => {
        $(#[inline(always)]
        fn $unary(self) -> f64 {
            f64::$unary(self)
        })*
        $(#[inline(always)]
        fn $binary(self, y: &f64) -> f64 {
            f64::$binary(self, *y)
        })*
        $(#[inline(always)]
        fn $pred(&self) -> bool {
            f64::$pred(*self)
        })*
    };
}

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
    std_methods!(abs;;);
    #[inline(always)]
    fn is_negative(&self) -> bool {
        *self < 0.0
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
    /// IEEE round to nearest: ε/2.
    const ROUNDING: f64 = 0.5;
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
        let mut s = Vec::with_capacity(24);
        self.push_decimal(&mut s);
        String::from_utf8(s).unwrap_or_default()
    }
    fn push_decimal(&self, out: &mut Vec<u8>) {
        if !push_17_digits(*self, out) {
            // Writing to a vector never fails.
            let _ = std::io::Write::write_fmt(out, format_args!("{:.16e}", self));
        }
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
    std_methods!(
        floor round sqrt cbrt exp exp_m1 ln ln_1p sin cos atan asin acos;
        atan2 hypot;
        is_finite is_nan
    );
    #[inline(always)]
    fn recip_sqrt(self) -> f64 {
        1.0 / f64::sqrt(self)
    }
    #[inline(always)]
    fn sin_cos(self) -> (f64, f64) {
        f64::sin_cos(self)
    }
    #[inline(always)]
    fn with_prec(&self, _: ()) -> f64 {
        *self
    }
}

/// Appends `x` to 17 significant digits, correctly rounded (ties to even), exactly as
/// `format!("{:.16e}", x)` writes it, and returns `true`, for 10⁻⁶ ≤ |x| < 2⁵³ (from the
/// double above 10⁻⁶). There x·10^(16−E) = m·10^(16−E)/2^j (x = m·2^−j, m < 2⁵³, E the
/// decimal exponent) fits in 128 bits, so one product, one shift and its remainder give the
/// digits, without std's general algorithm (the sweeps write two decimals a point): E from a
/// comparison with the powers of ten in `f64`, checked on the exact digits (a second product
/// where x lies within a rounding of a power of ten), the digits two at a time from a table.
/// Returns `false`, having written nothing, elsewhere; std's formatter then writes them.
fn push_17_digits(x: f64, out: &mut Vec<u8>) -> bool {
    const LOW: f64 = 1e-6;
    const HIGH: f64 = 9_007_199_254_740_992.0; // 2^53
    let a = x.abs();
    if !(LOW..HIGH).contains(&a) {
        return false;
    }
    let bits = a.to_bits();
    let m = (bits & ((1 << 52) - 1)) | (1 << 52);
    // a = m / 2^j with 0 ≤ j ≤ 72 (a is normal, below 2^53 and at least 10^-6 > 2^-20).
    let j = 1075 - (bits >> 52) as u32;
    // a ∈ [2^b, 2^(b+1)), b = 52 − j: E is ⌊b·log₁₀2⌋ (78913/2¹⁸ ≈ log₁₀2) or one more, as a
    // reaches the next power of ten (the double nearest it below 1, so that E may be one off
    // next to those: the digits say).
    let e0 = ((52 - j as i32) * 78_913) >> 18;
    let mut e10 = e0
        + usize::try_from(e0 + 7)
            .ok()
            .and_then(|i| F64_DECADES.get(i))
            .map_or(0, |&p| i32::from(a >= p));
    // At most two passes: a wrong decade moves E toward the right one and never back.
    for _ in 0..2 {
        // 0 ≤ 16 − E ≤ 22: m·10^(16−E) < 2^53·10^22 < 2^127 (the double nearest 10^-6 lies
        // below it, E = −7: there the product may not fit, and std writes the digits).
        let Some(&p) = usize::try_from(16 - e10).ok().and_then(|s| POW10.get(s)) else {
            return false;
        };
        let scaled = p * u128::from(m);
        let q = (scaled >> j) as u64;
        // The decade from the exact floor: 10^16 ≤ ⌊x·10^(16−E)⌋ < 10^17 exactly when
        // 10^E ≤ x < 10^(E+1).
        if q < 10_000_000_000_000_000 {
            e10 -= 1;
            continue;
        }
        if q >= 100_000_000_000_000_000 {
            e10 += 1;
            continue;
        }
        // Ties to even, as std: the remainder against half of 2^j.
        let up = j > 0 && {
            let (r, half) = (scaled & ((1u128 << j) - 1), 1u128 << (j - 1));
            r > half || (r == half && q % 2 == 1)
        };
        let digits = match q + u64::from(up) {
            // Rounded up to the next power of ten: one digit, one decade up.
            100_000_000_000_000_000 => {
                e10 += 1;
                10_000_000_000_000_000
            }
            q => q,
        };
        write_17_digits(out, x < 0.0, digits, e10);
        return true;
    }
    false
}

/// Appends `-d.dddddddddddddddde-dd` (sign if `negative`) for the 17 digits `digits` and the
/// exponent `e10` (|e10| < 100).
fn write_17_digits(out: &mut Vec<u8>, negative: bool, digits: u64, e10: i32) {
    // A sign, 17 digits, a point, "e", a sign and ≤ 2 digits: at most 24 bytes, copied whole
    // (a fixed-size copy) and cut to length.
    let mut text = [0u8; 24];
    let at = usize::from(negative);
    text[0] = b'-';
    let (first, rest) = (
        digits / 10_000_000_000_000_000,
        digits % 10_000_000_000_000_000,
    );
    text[at] = b'0' + first as u8;
    text[at + 1] = b'.';
    write_8_digits(&mut text, at + 2, (rest / 100_000_000) as u32);
    write_8_digits(&mut text, at + 10, (rest % 100_000_000) as u32);
    text[at + 18] = b'e';
    let end = write_exponent(&mut text, at + 19, e10);
    let start = out.len();
    out.extend_from_slice(&text);
    out.truncate(start + end);
}

/// Writes the 8 digits of `n` < 10⁸ (leading zeros included) at `text[at..at + 8]`: its two
/// 4-digit halves in the 32-bit lanes of a `u64` (the first in the low lane, which comes first
/// in little-endian bytes), each split into two 2-digit values in 16-bit lanes, each of those
/// into its two digits in bytes, by divisions by 100 and 10 as multiply-shifts, exact for
/// these ranges (v/100 = ⌊10486·v/2²⁰⌋ for v < 10⁴, v/10 = ⌊103·v/2¹⁰⌋ for v < 100), done in
/// every lane at once.
fn write_8_digits(text: &mut [u8], at: usize, n: u32) {
    let n = u64::from(n);
    let x = (n / 10_000) | ((n % 10_000) << 32);
    let hundreds = ((x * 10_486) >> 20) & 0x0000_007f_0000_007f;
    let y = hundreds | ((x - hundreds * 100) << 16);
    let tens = ((y * 103) >> 10) & 0x000f_000f_000f_000f;
    let z = tens | ((y - tens * 10) << 8);
    text[at..at + 8].copy_from_slice(&(z | 0x3030_3030_3030_3030).to_le_bytes());
}

/// Writes the decimal exponent `e` (|e| < 10⁴) as `-ddd` (no sign when positive, no leading
/// zeros) at `text[at..]`; returns the end. The exponents of the `f64` decimals and of the
/// error bounds' texts.
pub(crate) fn write_exponent(text: &mut [u8], mut at: usize, e: i32) -> usize {
    if e < 0 {
        text[at] = b'-';
        at += 1;
    }
    // A digit at a time from the first (no copy of a length known only here).
    let e = e.unsigned_abs().min(9_999);
    for scale in [1_000, 100, 10] {
        if e >= scale {
            text[at] = b'0' + (e / scale % 10) as u8;
            at += 1;
        }
    }
    text[at] = b'0' + (e % 10) as u8;
    at + 1
}

/// The doubles nearest 10^-6 … 10^16 (exact from 10^0 up).
const F64_DECADES: [f64; 23] = [
    1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10,
    1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
];

/// 10^0 … 10^22, each exact in a `u128`.
const POW10: [u128; 23] = {
    let mut p = [1u128; 23];
    let mut i = 1;
    while i < 23 {
        p[i] = p[i - 1] * 10;
        i += 1;
    }
    p
};

#[cfg(test)]
#[path = "../../tests/unit/f64_decimal.rs"]
mod decimal_tests;
