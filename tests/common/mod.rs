//! Helpers shared by the integration tests: reference-data parsing and error measurement.
#![allow(dead_code)]

use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};
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

/// |got − want| / |scale| in units of the working epsilon of `T` at precision `p`.
pub fn err_eps<T: Real>(got: &T, want: &Float, scale: &Float) -> f64 {
    let g = got.to_float(REF_BITS);
    let d = Float::with_val(REF_BITS, &g - want);
    let rel = Float::with_val(REF_BITS, d / scale).abs();
    let eps = T::epsilon(got.prec()).to_float(64);
    Float::with_val(64, rel / eps).to_f64()
}

/// Relative error in units of ε.
pub fn rel_eps<T: Real>(got: &T, want: &Float) -> f64 {
    err_eps(got, want, want)
}

/// The MPFR precision token for `bits` bits.
pub fn mp(bits: u64) -> MpPrec {
    MpPrec::new(bits).expect("valid precision")
}

/// Runs a generic check at f64, double-double and MPFR at the given bit counts.
#[macro_export]
macro_rules! at_all_precisions {
    ($f:ident, [$($bits:expr),*]) => {{
        $f::<f64>((), "f64");
        $f::<moving_hertz::scalar::Dd>((), "dd");
        $( $f::<moving_hertz::scalar::Mp>(common::mp($bits), concat!("mpfr", stringify!($bits))); )*
    }};
}

/// Keeps the imports used by some test binaries only.
pub fn _types(_: Dd, _: Mp) {}
