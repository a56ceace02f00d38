//! Unit tests of the Gauss–Legendre rule construction (`src/numerics/gauss_legendre.rs`) against
//! the reference construction, Newton's method on the three-term recurrence at guard precision.

use super::*;
use crate::numerics::quadrature::GaussLegendre;
use crate::scalar::{Mp, MpPrec};

/// The reference construction: nonnegative nodes (decreasing) and weights of the n-point rule,
/// computed in `U` (precision `q`) accurately enough to be rounded to a target of `target_bits`
/// bits, by Newton's method on the three-term recurrence at the precision of `U` from the `f64`
/// nodes. `O(n²)` operations in `U` (the library's construction needs `O(n²)` word operations).
///
/// Each pass doubles the correct bits. The weight `w(x) = 2/((1 − x²) P_n'(x)²)` comes from the
/// same pass: at the last iterate `x` with step `dx` (root `x − dx`),
/// `w(x − dx) = w(x)·(1 + 2x·dx/(1 − x²)) + O(n⁴dx²)`, since `d ln w/dx = −2x/(1 − x²)` at a root
/// (Legendre's equation). The pass is the last once `4(n+1)⁴dx² ≤ 2^-6 ε_target`, which also
/// makes Newton's own remaining error `≈ n² dx²/6` negligible.
fn reference_build<U: Real>(n: usize, q: U::Prec, target_bits: u32) -> Result<(Vec<U>, Vec<U>)> {
    let m = n.div_ceil(2);
    let cap = 10 + 2 * U::bits(q).max(2).ilog2() as usize;
    let enough = U::one(q).mul_pow2(-(target_bits as i32) - 5);
    let n1 = U::from_i64(n as i64 + 1, q).powi(4).mul_i64(4);
    let mut nodes = Vec::with_capacity(m);
    let mut weights = Vec::with_capacity(m);
    for k in 1..=m {
        let mut x = if 2 * k - 1 == n {
            // The middle node of an odd rule is 0 by symmetry (then P_n(0) = 0 exactly).
            U::zero(q)
        } else {
            U::from_f64(node_f64(n, k)?, q)
        };
        let mut prev: Option<U> = None;
        let mut done = false;
        for it in 0..cap {
            let (pn, d, omx2) = legendre_scaled(n, &x);
            let dx = pn * &omx2 / &d;
            let w = omx2.clone().mul_i64(2) / d.square();
            let adx = dx.clone().abs();
            let diverging = prev.as_ref().is_some_and(|pv| adx >= *pv && !adx.is_zero());
            if !adx.is_finite() || !w.is_finite() || diverging {
                return Err(Error::NoConvergence {
                    what: "Gauss-Legendre node (Newton at guard precision)",
                    iterations: it,
                    reached: short(&adx),
                });
            }
            if n1.clone() * &adx.square() <= enough {
                let corr = (x.clone() * &dx).mul_pow2(1) / &omx2;
                weights.push(w.clone() + &(w * &corr));
                x -= dx;
                done = true;
                break;
            }
            x -= dx;
            prev = Some(adx);
        }
        if !done {
            return Err(Error::NoConvergence {
                what: "Gauss-Legendre node (Newton at guard precision)",
                iterations: cap,
                reached: prev.as_ref().map(short).unwrap_or_default(),
            });
        }
        nodes.push(x);
    }
    Ok((nodes, weights))
}

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

/// The `f64` rules, built by the short-point construction at 85 bits and rounded once, are the
/// rules of Newton's method on the recurrence in double-double (how `f64` rules were built before
/// one construction served every precision), bit for bit, for every n = 1 … 160 (checked once for
/// n ≤ 1100: every one of the 606,100 values equal).
#[test]
fn f64_rules_are_those_of_newton_in_double_double() {
    for n in 1..=160usize {
        let rule = GaussLegendre::<f64>::get(n, ()).expect("rule");
        let (x, w) = reference_build::<Dd>(n, (), 53).expect("reference");
        let round = |v: &Dd| f64::from_float(&v.to_float(106), ());
        for i in 0..x.len() {
            assert_eq!(rule.nodes()[i], round(&x[i]), "n = {n}, node {i}");
            assert_eq!(rule.weights()[i], round(&w[i]), "n = {n}, weight {i}");
        }
        assert_eq!(rule.nodes().len(), x.len());
    }
}
