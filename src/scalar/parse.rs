//! Exact decimal parsing: decimal text to `rug::Rational`, for the exact mode and for inputs that
//! must be known exactly (a Poisson's ratio given as `0.2` is exactly 1/5 here).
//!
//! No item of this module implements a formula of the paper: decimal text becomes an exact
//! rational, with no rounding.

use crate::error::{Error, Result};
use rug::{Integer, Rational};

/// Parses `[+-]digits[.digits][(e|E)[+-]digits]` or `p/q` into the exact rational it denotes.
pub fn decimal_to_rational(text: &str) -> Result<Rational> {
    let bad = |reason: &'static str| Error::Parse {
        text: text.to_string(),
        reason,
    };
    let s = text.trim();
    if s.contains('/') {
        let r: Rational = s.parse().map_err(|_| bad("not a fraction p/q"))?;
        return Ok(r);
    }
    // An exponent too large for an i64 is refused below as out of range, unless the mantissa
    // is zero: `0e-99999999999999999999` is exactly 0.
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => {
            let t = &s[i + 1..];
            let digits = t.strip_prefix(['+', '-']).unwrap_or(t);
            if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
                return Err(bad("bad exponent"));
            }
            (&s[..i], t.parse::<i64>().unwrap_or(i64::MAX))
        }
        None => (s, 0),
    };
    let (neg, body) = match mantissa.strip_prefix('-') {
        Some(b) => (true, b),
        None => (false, mantissa.strip_prefix('+').unwrap_or(mantissa)),
    };
    let (int_part, frac_part) = match body.find('.') {
        Some(i) => (&body[..i], &body[i + 1..]),
        None => (body, ""),
    };
    if int_part.is_empty() && frac_part.is_empty() {
        return Err(bad("no digits"));
    }
    if !int_part.bytes().all(|b| b.is_ascii_digit())
        || !frac_part.bytes().all(|b| b.is_ascii_digit())
    {
        return Err(bad("not a decimal number"));
    }
    let digits = format!("{int_part}{frac_part}");
    if digits.bytes().all(|b| b == b'0') {
        return Ok(Rational::new());
    }
    if exponent.abs() > 100_000 {
        return Err(bad("exponent out of range"));
    }
    let m: Integer = if digits.is_empty() {
        Integer::new()
    } else {
        digits.parse().map_err(|_| bad("not a decimal number"))?
    };
    let scale = exponent - frac_part.len() as i64;
    let p10 = |n: i64| Integer::from(Integer::u_pow_u(10, n as u32));
    let r = if scale >= 0 {
        Rational::from(m * p10(scale))
    } else {
        Rational::from((m, p10(-scale)))
    };
    Ok(if neg { -r } else { r })
}
