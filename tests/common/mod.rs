//! Helpers shared by the numerics test binaries.
#![allow(dead_code)]

use moving_hertz::scalar::{mixed_precision_events, Real};

/// `|got − want| / |want|` in units of the working ε, as f64 (absolute error in ε if want = 0).
pub fn err_eps<T: Real>(got: &T, want: &T) -> f64 {
    let p = want.prec();
    let d = (got.clone() - want).abs();
    let r = if want.is_zero() {
        d
    } else {
        d / &want.clone().abs()
    };
    (r / &T::epsilon(p)).to_f64()
}

/// Asserts that no MPFR operation in this test process mixed precisions.
pub fn assert_no_mixing() {
    assert_eq!(
        mixed_precision_events(),
        0,
        "an MPFR operation mixed precisions"
    );
}

/// Runs a generic test body at f64, double-double and MPFR 128, 256 and 1024 bits, then checks
/// the mixed-precision counter.
#[macro_export]
macro_rules! at_all_precisions {
    ($f:ident) => {{
        use moving_hertz::scalar::{Dd, Mp, MpPrec};
        $f::<f64>((), "f64");
        $f::<Dd>((), "dd");
        for bits in [128u64, 256, 1024] {
            let p = MpPrec::new(bits).expect("valid precision");
            $f::<Mp>(p, &format!("mp{bits}"));
        }
        $crate::common::assert_no_mixing();
    }};
}
