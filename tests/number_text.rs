//! The number writers of the `sweep` commands' rows against exact rational references: an error
//! bound's three-digit text ([`RelError::push_text`], the text `Display` prints) over random
//! `f64` bounds from the subnormals to the largest, powers of ten and their neighbours, and
//! bounds that round up across a decade (9.995e-16 → 1.00e-15); an `f64`'s 17 digits
//! ([`Real::push_decimal`]) over random doubles, against the exact value rounded to nearest
//! (ties to even) and against std's `{:.16e}`.

use moving_hertz::scalar::Real;
use moving_hertz::RelError;
use rug::ops::Pow;
use rug::{Integer, Rational};

/// A xorshift generator (the same sequence on every run).
fn xorshift(mut state: u64) -> impl FnMut() -> u64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    }
}

/// 10^n exactly.
fn pow10(n: i64) -> Rational {
    let p = Rational::from(Integer::from(10).pow(n.unsigned_abs() as u32));
    if n >= 0 {
        p
    } else {
        p.recip()
    }
}

/// ⌊log₁₀ x⌋ of a positive rational, exactly.
fn decade(x: &Rational) -> i64 {
    let mut e = x.to_f64().log10().floor() as i64;
    if x.to_f64() == 0.0 {
        e = -324;
    }
    while pow10(e) > *x {
        e -= 1;
    }
    while pow10(e + 1) <= *x {
        e += 1;
    }
    e
}

/// The bound text's reference: the bound x written d.dd·10^E with the mantissa rounded
/// upwards after forgiving 10⁻⁹ of it (`RelError`'s `Display`: a bound parsed from `1e-10`
/// prints as `1.00e-10`), E = ⌊log₁₀ x⌋, carried into the next decade at 1000; `None` where
/// the forgiven mantissa lies within 10⁻⁹ of an integer (where the writer's `f64` arithmetic
/// may round either way).
fn bound_reference(x: f64) -> Option<String> {
    let q = Rational::from_f64(x).expect("finite");
    let e = decade(&q);
    let scaled = q * pow10(2 - e) * (Rational::from(1) - pow10(-9));
    let ceil = scaled.clone().ceil();
    let below = Rational::from(&ceil - &scaled);
    if below < pow10(-9) || below > Rational::from(1) - pow10(-9) {
        return None;
    }
    let mut mant = ceil
        .numer()
        .to_u32()
        .expect("a mantissa below 1000")
        .max(100);
    let mut e = e;
    if mant == 1000 {
        (mant, e) = (100, e + 1);
    }
    Some(format!("{}.{:02}e{e}", mant / 100, mant % 100))
}

fn bound_text(x: f64) -> String {
    let mut out = Vec::new();
    RelError::from_f64(x).push_text(&mut out);
    String::from_utf8(out).expect("ASCII")
}

/// Checks one bound against the reference and `Display`; returns whether the reference
/// applied.
fn check_bound(x: f64) -> bool {
    let text = bound_text(x);
    assert_eq!(
        text,
        RelError::from_f64(x).to_string(),
        "{x:e}: push_text and Display"
    );
    match bound_reference(x) {
        Some(reference) => {
            assert_eq!(text, reference, "{x:e} (bits {:#x})", x.to_bits());
            true
        }
        None => false,
    }
}

#[test]
fn bound_texts_are_the_bounds_rounded_up_to_three_digits() {
    let mut next = xorshift(0x853c_49e6_748f_ea9b);
    let mut checked = 0;
    let mut total = 0;
    // Random bit patterns over every finite positive double, subnormals included; then
    // mantissas over the span of an f64 result's bounds (1e-17 to 1e-5), where the writer
    // takes its fast path.
    for i in 0..400_000 {
        let x = if i % 2 == 0 {
            f64::from_bits(next() % 0x7ff0_0000_0000_0000)
        } else {
            f64::from_bits(((1023 - 57 + next() % 41) << 52) | (next() >> 12))
        };
        if x == 0.0 {
            continue;
        }
        total += 1;
        checked += usize::from(check_bound(x));
    }
    assert!(
        checked + total / 10_000 >= total,
        "{checked} of {total} checked"
    );
    // Powers of ten (the doubles nearest them) and their neighbours, subnormal ones included.
    for e in -323..=308 {
        let p: f64 = format!("1e{e}").parse().expect("a power of ten");
        for x in [p, p.next_up(), p.next_down()] {
            check_bound(x);
        }
        if p.is_normal() {
            // (A subnormal 10^e may lie far from it: 1e-323 is 9.88e-324.)
            assert_eq!(bound_text(p), format!("1.00e{e}"), "10^{e}");
        }
    }
    // Across a decade: 9.995e-16 → 1.00e-15, and the values next to each such edge.
    for (text, expected) in [
        ("9.995e-16", "1.00e-15"),
        ("9.99e-16", "9.99e-16"),
        ("9.9901e-16", "1.00e-15"),
        ("9.991e-300", "1.00e-299"),
        ("9.999e-320", "1.00e-319"),
        ("1.0000001e-15", "1.01e-15"),
        ("2.345e-7", "2.35e-7"),
        ("1e-10", "1.00e-10"),
    ] {
        let x: f64 = text.parse().expect("a decimal");
        assert_eq!(bound_text(x), expected, "{text}");
        check_bound(x);
    }
    for e in -320..=300 {
        for m in [
            "9.995", "9.9951", "9.9949", "9.99", "1.001", "1.0049", "5.555",
        ] {
            check_bound(format!("{m}e{e}").parse().expect("a decimal"));
        }
    }
}

/// The 17-digit reference: x exactly, rounded to 17 significant digits to nearest, ties to
/// even, written `d.dddddddddddddddde±x` as std's `{:.16e}` writes it.
fn decimal_reference(x: f64) -> String {
    let q = Rational::from_f64(x.abs()).expect("finite");
    let mut e = decade(&q);
    let scaled = q * pow10(16 - e);
    let (floor, frac) = {
        let f = scaled.clone().floor();
        let frac = scaled - &f;
        (f.numer().clone(), frac)
    };
    let half = Rational::from((1, 2));
    let up = frac > half || (frac == half && floor.is_odd());
    let mut digits = floor + u32::from(up);
    if digits == Integer::from(10).pow(17) {
        digits = Integer::from(10).pow(16);
        e += 1;
    }
    let d = digits.to_string();
    let sign = if x < 0.0 { "-" } else { "" };
    format!("{sign}{}.{}e{e}", &d[..1], &d[1..])
}

#[test]
fn f64_decimals_are_the_exact_values_rounded_to_17_digits() {
    let mut next = xorshift(0x2545_f491_4f6c_dd1d);
    let text = |x: f64| {
        let mut out = Vec::new();
        x.push_decimal(&mut out);
        String::from_utf8(out).expect("ASCII")
    };
    let check = |x: f64| {
        let t = text(x);
        assert_eq!(t, decimal_reference(x), "{x:e} (bits {:#x})", x.to_bits());
        assert_eq!(t, format!("{x:.16e}"), "{x:e}: std");
        assert_eq!(t, x.to_decimal(), "{x:e}: to_decimal");
    };
    for i in 0..100_000 {
        // Every finite double (either sign), then the span of a sweep's k and e (2^-30 to
        // 2^60), across both ends of the writer's fast path.
        let x = if i % 2 == 0 {
            f64::from_bits(next() % 0x7ff0_0000_0000_0000)
        } else {
            f64::from_bits(((1023 - 30 + next() % 90) << 52) | (next() >> 12))
        };
        check(if next().is_multiple_of(2) { x } else { -x });
    }
    for e in -20..=22 {
        let p: f64 = format!("1e{e}").parse().expect("a power of ten");
        for x in [p, p.next_up(), p.next_down(), 9.999_999_999_999_999_5 * p] {
            check(x);
            check(x.next_up());
            check(x.next_down());
        }
    }
    // Ties: two fractional bits at 2^50..2^51 put a 5 in the 18th digit.
    for i in 0..2_000u64 {
        check((1u64 << 50) as f64 + (i * 7_919) as f64 + 0.25 * (i % 4) as f64);
    }
}
