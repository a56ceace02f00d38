//! Unit tests of the Gauss–Legendre rule construction (`src/numerics/gauss_legendre.rs`) against the reference construction at guard precision.

use super::*;
use crate::numerics::quadrature::GaussLegendre;
use crate::scalar::{Mp, MpPrec};

/// The n-point rule by [`reference_build`] at `bits` + [`GUARD`] bits, as MPFR numbers: the
/// construction the fast one is tested against (`O(n²)` products at the guard precision, about
/// log₂(bits/53) passes a node).
fn reference_rule(n: usize, bits: u32) -> Result<(Vec<Float>, Vec<Float>)> {
    let q = MpPrec::new(bits as u64 + GUARD as u64)?;
    let (x, w) = reference_build::<Mp>(n, q, bits)?;
    Ok((
        x.into_iter().map(|v| v.0).collect(),
        w.into_iter().map(|v| v.0).collect(),
    ))
}

/// The short-point construction (fixed-point recurrence at a 112-bit point, then the Taylor
/// expansion there) against Newton on the three-term recurrence at the guard precision (the
/// construction it replaced, kept here as `reference_rule`): both rounded to the working precision,
/// every node and weight equal or one ulp apart, at 256 and 1024 bits (and for small rules at 4096
/// and 8192 bits).
#[test]
fn gauss_legendre_short_point_construction_matches_newton_on_the_recurrence() {
    let cases: [(u32, &[usize]); 4] = [
        (256, &[1, 2, 3, 4, 7, 20, 63, 64, 109, 200]),
        (1024, &[5, 63, 120, 247, 441]),
        // A Taylor expansion of some 50 and 100 terms at the short point.
        (4096, &[64]),
        (8192, &[24]),
    ];
    for (bits, ns) in cases {
        let p = MpPrec::new(bits as u64).expect("precision");
        let ulp = |v: &rug::Float| {
            let e = v.get_exp().unwrap_or(0) - bits as i32;
            rug::Float::with_val(64, 1) << e
        };
        for &n in ns {
            let rule = GaussLegendre::<Mp>::get(n, p).expect("rule");
            let (x, w) = reference_rule(n, bits).expect("reference");
            let (mut dx, mut dw, mut equal) = (0f64, 0f64, 0usize);
            for i in 0..x.len() {
                for (got, want, worst) in [
                    (&rule.nodes()[i].0, &x[i], &mut dx),
                    (&rule.weights()[i].0, &w[i], &mut dw),
                ] {
                    let want = rug::Float::with_val(bits, want);
                    let d = rug::Float::with_val(bits + 8, got - &want).abs();
                    equal += usize::from(d.is_zero());
                    if !want.is_zero() {
                        *worst = worst.max((d / ulp(&want)).to_f64());
                    }
                }
            }
            println!(
                "{bits:5} bits n = {n:3}: nodes {dx:.0} ulp, weights {dw:.0} ulp, {equal} of {} equal",
                2 * x.len()
            );
            assert!(dx <= 1.0 && dw <= 1.0, "{bits} bits n = {n}: {dx} {dw}");
            assert_eq!(rule.nodes().len(), x.len());
        }
    }
    // A rule built at 512 bits serves 200 bits rounded down: the same values as a rule
    // computed for 200 bits.
    let hi = GaussLegendre::<Mp>::get(90, MpPrec::new(512).expect("precision")).expect("rule");
    let lo = GaussLegendre::<Mp>::get(90, MpPrec::new(200).expect("precision")).expect("rule");
    let (x, w) = reference_rule(90, 200).expect("reference");
    for i in 0..x.len() {
        assert_eq!(
            lo.nodes()[i].0,
            rug::Float::with_val(200, &x[i]),
            "node {i}"
        );
        assert_eq!(
            lo.weights()[i].0,
            rug::Float::with_val(200, &w[i]),
            "weight {i}"
        );
        assert_eq!(lo.nodes()[i].0, rug::Float::with_val(200, &hi.nodes()[i].0));
    }
}
