//! Unit tests of the moment tables (`src/routes/moments.rs`) against their hypergeometric series.

use super::*;
use crate::scalar::{Field, Mp, MpPrec};

/// M_50, L_50 by their hypergeometric series alone (Gauss for |e²| ≤ 3/4, Pfaff for
/// e² < −3/4) agree with the table of [`moments`] (top values above n, then the recursion).
#[test]
fn single_index_series_agree_with_the_table() {
    let p = MpPrec::new(128).expect("precision");
    for mc_s in ["0.75", "3", "0.3"] {
        let mc = Mp::parse(mc_s, p).expect("mc");
        let tab = moments(&mc, 50).expect("table");
        let e2 = Mp::one(p) - &mc;
        let method = if e2.clone().abs().mul_i64(4) <= Mp::from_i64(3, p) {
            MomentMethod::BackwardGauss
        } else {
            MomentMethod::BackwardPfaff
        };
        let (m, l, _) = top_values(&e2, &mc, 50, method).expect("series");
        let rel = |a: &Mp, b: &Mp| ((a.clone() - b).abs() / &b.clone().abs()).to_f64();
        let e = rel(&m, &tab.m()[50]).max(rel(&l, &tab.l()[50])) / Mp::epsilon(p).to_f64();
        assert!(e <= 16.0, "k2 = {mc_s}: {e}");
    }
}
