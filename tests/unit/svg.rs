//! Unit tests of the SVG writer (`src/studies/svg.rs`).

use super::push_px;

fn px(v: f64) -> String {
    let mut s = String::new();
    push_px(&mut s, v);
    s
}

/// `push_px` writes what `{:.2}` writes, except within the product's rounding of a tie of x·100,
/// where it may differ by one in the last digit; the sign of a value that rounds to zero is dropped.
#[test]
fn px_writes_two_decimals_as_format_does() {
    let mut x = 0.000_123_f64;
    let mut differ = 0;
    for j in 0..20_000 {
        for v in [x, -x, x * 1e3, 1e12 + x] {
            let (got, want) = (px(v), format!("{v:.2}"));
            if got != want {
                let (g, w): (f64, f64) = (got.parse().unwrap(), want.parse().unwrap());
                // Within the rounding of the product x·100 of a tie.
                let tie = ((v * 100.0).fract().abs() - 0.5).abs() <= (v * 100.0).abs() * 4e-16;
                assert!(
                    (tie && (g - w).abs() < 0.015) || (g == 0.0 && w == 0.0),
                    "{v}: {got} against {want} (case {j})"
                );
                differ += 1;
            }
        }
        x = x * 1.003 + 0.0037;
    }
    assert!(differ < 800, "{differ} of 80000 differ"); // rare: under 1 %
    assert_eq!(px(1e300), format!("{:.2}", 1e300));
    assert_eq!(px(-0.004), "0.00");
    assert_eq!(px(1.005), "1.00"); // 1.005 is 1.00499999999999989… in binary
    assert_eq!(px(-12.345678), "-12.35");
}
