//! Unit tests of the sweep internals (`src/sweep.rs`).

use super::*;
use crate::scalar::MpPrec;

/// The polynomial through 1 to 4 points reproduces a polynomial of that degree less one
/// (a cubic through four), refuses repeated abscissae and no points; the trail extrapolates
/// along the curve of its last roots only (a root at another ν starts a new curve).
#[test]
fn the_trail_extrapolates_along_its_curve() {
    let cubic = |x: f64| 0.5 - 1.25 * x + 0.75 * x * x - 0.125 * x * x * x;
    let xs = [0.3, -0.2, 1.1, 0.7];
    for n in 1..=4 {
        let ys: Vec<f64> = xs[..n].iter().map(|&x| cubic(x)).collect();
        let poly = |t: f64| lagrange(&xs[..n], &ys, t).expect("distinct abscissae");
        for &t in &xs[..n] {
            assert!((poly(t) - cubic(t)).abs() < 1e-14, "{n} points at {t}");
        }
        if n == 4 {
            assert!((poly(1.5) - cubic(1.5)).abs() < 1e-13);
        }
    }
    assert_eq!(lagrange(&[0.1, 0.1], &[1.0, 2.0], 0.5), None);
    assert_eq!(lagrange(&[], &[], 0.5), None);
    // ln k = 0.1 + 0.5 ln(A1/B1) along a speed: the trail's guess from the last four
    // roots is exact; at another ν it starts from the last root alone.
    let mut trail = Trail::default();
    let place = |nu: f64, ln_ratio: f64| Place {
        nu,
        ln_gap: -3.0,
        ln_ratio,
    };
    assert_eq!(trail.guess(&place(0.25, 0.0)), None);
    trail.push(place(0.3, -0.5), 0.9);
    for j in 0..5 {
        let x = 0.1 * f64::from(j);
        trail.push(place(0.25, x), (0.1 + 0.5 * x).exp());
    }
    let guess = trail.guess(&place(0.25, 0.55)).expect("a guess");
    assert!((guess.ln() - (0.1 + 0.5 * 0.55)).abs() < 1e-12, "{guess}");
    let other = trail.guess(&place(0.3, 0.55)).expect("a guess");
    assert!((other.ln() - (0.1 + 0.5 * 0.4)).abs() < 1e-12, "{other}");
}

/// A few hundred `f64` points keep one thread busy, a million keep a thousand; a point
/// costs more at double-double and more again at 256 bits, so the same points keep more
/// threads busy.
#[test]
fn threads_worth_grows_with_points_and_precision() {
    let mp = |bits| Precision::Mpfr(MpPrec::new(bits).expect("bits"));
    assert_eq!(threads_worth(0, &Precision::F64), 1);
    assert_eq!(threads_worth(300, &Precision::F64), 1);
    assert_eq!(threads_worth(1_000_000, &Precision::F64), 1000);
    assert_eq!(threads_worth(2_546, &Precision::F64), 2);
    let (f, d, m) = (
        threads_worth(10_000, &Precision::F64),
        threads_worth(10_000, &Precision::DoubleDouble),
        threads_worth(10_000, &mp(256)),
    );
    assert!(f < d && d < m, "{f} {d} {m}");
    assert_eq!(threads_worth(usize::MAX, &mp(32768)), usize::MAX);
}
