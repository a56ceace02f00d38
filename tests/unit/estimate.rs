//! Unit tests of `RelError` and `Estimated` (`src/estimate.rs`).

use super::*;
use crate::scalar::{FieldOps, Mp, MpPrec};

/// The bound's text, written from integers, is what `std` writes for the same mantissa
/// rounded upwards and at least 1 (`{:.N}` of the float `mant / 10^N`), for 0 to 12 decimals and bounds
/// from 1e-300 to 1e300, powers of ten and values just above them included.
#[test]
fn display_writes_the_digits_std_writes() {
    let std_text = |r: &RelError, digits: i32| {
        let l10 = r.log2() * std::f64::consts::LOG10_2;
        let mut exp10 = l10.floor();
        let scale = 10f64.powi(digits);
        let mut mant = ((10f64.powf(l10 - exp10) * scale * (1.0 - 1e-9)).ceil() / scale).max(1.0);
        if mant >= 10.0 {
            mant /= 10.0;
            exp10 += 1.0;
        }
        format!("{mant:.prec$}e{}", exp10 as i64, prec = digits as usize)
    };
    let mut x = 1e-300f64;
    while x < 1e300 {
        for v in [x, x * 1.0000001, x * 9.999999, x * 3.125] {
            let r = RelError::from_f64(v);
            for digits in 0..=12 {
                assert_eq!(
                    format!("{r:.digits$}", digits = digits as usize),
                    std_text(&r, digits),
                    "{v:e}"
                );
            }
        }
        x *= 10.0 * 1.37;
    }
}

/// The text's digits by one exact power of ten (the bounds of `f64` results) are those of
/// the logarithm and power, on random bounds over the whole span of the fast path (and
/// beyond, where it declines), powers of ten and their neighbours, at 0 to 2 decimals (it
/// declines more).
#[test]
fn decimal_by_a_power_of_ten_agrees_with_the_logarithm() {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    let mut fast = 0;
    let mut check = |r: RelError| {
        for digits in [0, 1, 2, 5, 12] {
            if let Some(d) = r.decimal_in_f64(digits) {
                fast += 1;
                assert_eq!(d, r.decimal(digits), "{r} at {digits} decimals");
            }
        }
    };
    for _ in 0..200_000 {
        let x = f64::from_bits(((1023 - 90 + next() % 120) << 52) | (next() >> 12));
        check(RelError::from_f64(x));
    }
    for e in -40..=30 {
        let p = 10f64.powi(e);
        for x in [
            p,
            p.next_up(),
            p.next_down(),
            p * (1.0 + 1e-6),
            p * (1.0 - 1e-6),
        ] {
            check(RelError::from_f64(x));
        }
    }
    assert!(fast > 300_000, "{fast} bounds took the fast path");
}

#[test]
fn round_trips_and_order() {
    for x in [1.0, 0.75, 3e-300, 5e-324, 1.7e308, 2f64.powi(-52)] {
        let r = RelError::from_f64(x);
        assert_eq!(r.to_f64(), x, "{x}");
    }
    let a = RelError::from_f64(1e-20);
    let b = RelError::parse("1e-10000").unwrap();
    assert!(b < a && a < RelError::INFINITE && RelError::ZERO < b);
    assert!((b.log2() - (-10000.0 / std::f64::consts::LOG10_2)).abs() < 1e-6);
    assert_eq!(format!("{b}"), "1.00e-10000");
    assert_eq!(format!("{}", RelError::from_f64(2.345e-7)), "2.35e-7");
    assert_eq!(format!("{}", RelError::from_f64(9.9999e-7)), "1.00e-6");
}

#[test]
fn below_the_f64_range() {
    let p = MpPrec::new(8192).unwrap();
    let eps = <Mp as Real>::epsilon(p);
    let r = RelError::of(&eps);
    assert_eq!(r, RelError::eps::<Mp>(1, p));
    assert!((r.log2() + 8191.0).abs() < 1e-12);
    assert!(r.to_f64() == 0.0 && r.is_finite() && !r.is_zero());
    let back: Mp = r.to_real(p);
    assert!(back >= eps && back <= eps.clone().mul_i64(2));
    // Sums round upwards and keep the larger exponent.
    let s = r.add(r);
    assert!(s > r && (s.log2() + 8190.0).abs() < 1e-9);
    assert_eq!(format!("{r}"), format!("{}", r));
}
