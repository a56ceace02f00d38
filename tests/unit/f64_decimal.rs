//! Unit tests of the f64 decimal writer (`push_17_digits`, `src/scalar/f64_impl.rs`) against `std`'s `{:.16e}`.

use super::push_17_digits;

fn check(x: f64) {
    let mut s = Vec::new();
    if push_17_digits(x, &mut s) {
        let s = String::from_utf8(s).expect("ASCII");
        assert_eq!(s, format!("{x:.16e}"), "{:e} (bits {:#x})", x, x.to_bits());
    } else {
        assert!(s.is_empty());
        let a = x.abs();
        assert!(a <= 1e-6 || a >= 9_007_199_254_740_992.0, "{x:e} refused");
    }
}

/// Against std's exact formatter: random bit patterns over the whole range of the fast
/// path (and beyond, where it must decline), ties, the ends of the range, the powers of
/// ten and their neighbours, values that round up to the next power of ten.
#[test]
fn seventeen_digits_agree_with_std() {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    for _ in 0..300_000 {
        // Exponents from 2^-24 to 2^55: across both ends of the range.
        let exp = 1023 - 24 + next() % 80;
        let x = f64::from_bits((exp << 52) | (next() & ((1 << 52) - 1)));
        check(x);
        check(-x);
    }
    // Ties: two fractional bits at 2^50..2^51 put a 5 in the 18th digit.
    for i in 0..20_000u64 {
        let x = (1u64 << 50) as f64 + (i * 7_919) as f64 + 0.25 * (i % 4) as f64;
        check(x);
    }
    for e in -7..=16 {
        let p = 10f64.powi(e);
        for x in [p, p.next_up(), p.next_down(), 9.999_999_999_999_999_5 * p] {
            check(x);
            check(x.next_up());
            check(x.next_down());
        }
    }
    for x in [
        1e-6,
        9_007_199_254_740_991.0,
        9_007_199_254_740_992.0,
        0.5,
        1.0,
        0.1,
    ] {
        check(x);
        check(x.next_down());
        check(x.next_up());
    }
}
