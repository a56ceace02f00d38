//! Helpers shared by the integration tests: reference-data parsing, error measurement, and a
//! macro running a generic check at every precision.
#![allow(dead_code)]

use moving_hertz::scalar::{mixed_precision_events, MpPrec, Real};
use rug::Float;

/// Bits used to hold reference values.
pub const REF_BITS: u32 = 1200;

/// Reads a committed CSV under tests/data, skipping `#` comments; returns the fields per line.
pub fn read_csv(name: &str) -> Vec<Vec<String>> {
    let path = format!("{}/tests/data/{}", env!("CARGO_MANIFEST_DIR"), name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| l.split(',').map(|s| s.trim().to_string()).collect())
        .collect()
}

/// A reference decimal at REF_BITS.
pub fn reference(s: &str) -> Float {
    Float::with_val(
        REF_BITS,
        Float::parse(s).unwrap_or_else(|_| panic!("bad reference {s}")),
    )
}

/// |got − want| / |scale| in units of the working epsilon of `got`'s precision.
pub fn err_eps<T: Real>(got: &T, want: &Float, scale: &Float) -> f64 {
    let g = got.to_float(REF_BITS);
    let d = Float::with_val(REF_BITS, &g - want);
    let rel = Float::with_val(REF_BITS, d / scale).abs();
    let eps = T::epsilon(got.prec()).to_float(64);
    Float::with_val(64, rel / eps).to_f64()
}

/// Relative error against a high-precision reference, in units of ε.
pub fn rel_eps<T: Real>(got: &T, want: &Float) -> f64 {
    err_eps(got, want, want)
}

/// `|got − want| / |want|` in units of the working ε when both are at the working precision
/// (absolute error in ε if want = 0).
pub fn rel_err_eps<T: Real>(got: &T, want: &T) -> f64 {
    let p = want.prec();
    let d = (got.clone() - want).abs();
    let r = if want.is_zero() {
        d
    } else {
        d / &want.clone().abs()
    };
    (r / &T::epsilon(p)).to_f64()
}

/// SplitMix64: a small deterministic generator for test arguments.
pub struct SplitMix(pub u64);

impl SplitMix {
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E3779B97F4A7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58476D1CE4E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D049BB133111EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The MPFR precision token for `bits` bits.
pub fn mp(bits: u64) -> MpPrec {
    MpPrec::new(bits).expect("valid precision")
}

/// Asserts that no MPFR operation in this test process mixed precisions.
pub fn assert_no_mixing() {
    assert_eq!(
        mixed_precision_events(),
        0,
        "an MPFR operation mixed precisions"
    );
}

/// Runs a generic check `f::<T>(p, label)` at f64, double-double and MPFR at the given bit
/// counts (default 128, 256, 1024), then checks the mixed-precision counter.
#[macro_export]
macro_rules! at_all_precisions {
    ($f:ident) => {
        at_all_precisions!($f, [128, 256, 1024])
    };
    ($f:ident, [$($bits:expr),*]) => {{
        $f::<f64>((), "f64");
        $f::<moving_hertz::scalar::Dd>((), "dd");
        $( $f::<moving_hertz::scalar::Mp>(common::mp($bits), concat!("mpfr", stringify!($bits))); )*
        common::assert_no_mixing();
    }};
}
