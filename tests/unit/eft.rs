//! Unit tests of the error-free transformations (`src/scalar/dd/eft.rs`) in exact arithmetic.

/// Both error-free products — Dekker's and the hardware FMA's, whichever this processor
/// runs by default — give the exact error of the rounded product, checked in exact
/// arithmetic over random and extreme arguments.
#[cfg(not(target_feature = "fma"))]
#[test]
fn both_error_free_products_are_exact() {
    let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    };
    let mut args = vec![
        (1.0 + 2f64.powi(-52), 1.0 - 2f64.powi(-53)),
        (1e300, 3e-301),
    ];
    args.push((6.7e299, 1.3e-5));
    for _ in 0..20000 {
        let m = |r: u64| (r >> 11) as f64 / (1u64 << 53) as f64 + 0.5;
        let (r1, r2) = (next(), next());
        let e1 = (r1 % 600) as i32 - 300;
        let e2 = (r2 % 600) as i32 - 300;
        let s = if r1 & 1 == 1 { -1.0 } else { 1.0 };
        args.push((s * m(next()) * 2f64.powi(e1), m(next()) * 2f64.powi(e2)));
    }
    for (a, b) in args {
        let p = a * b;
        let exact = rug::Float::with_val(256, a) * b - p;
        let want = exact.to_f64();
        assert_eq!(super::dekker_error(a, b, p), want, "Dekker at {a:e}·{b:e}");
        assert_eq!(super::two_prod(a, b).1, want, "two_prod at {a:e}·{b:e}");
        #[cfg(target_arch = "x86_64")]
        if super::hw::has_fma() {
            assert_eq!(super::hw::fms(a, b, p), want, "FMA at {a:e}·{b:e}");
        }
    }
}

/// The one-leaf FMA test answers as std's detection does on this processor.
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
#[test]
fn fma_detection_agrees_with_std() {
    assert_eq!(
        super::hw::has_fma(),
        std::arch::is_x86_feature_detected!("fma")
    );
}
