//! The fixed rules far from k = 1: the fixed rule (`routes::fast`) down to k = 10⁻⁷⁵ and the
//! graded rule (`routes::graded`) up to k = 10⁵⁴, against the adaptive route at a higher
//! precision on the same inputs — I1, I2 within the reported estimate and the route's a-priori
//! bound at `f64`, double-double and 256 bits, and dI/dk against central differences of the
//! reference at `f64` and double-double.

mod common;

use common::{assert_no_mixing, integral_inputs, mp, rel_eps};
use moving_hertz::prelude::*;
use moving_hertz::{integrals, IntegralOptions, Integrals, Route};

const NUS: [f64; 2] = [-0.9, 0.5];
const MRS: [f64; 2] = [0.0, 1.0 - 1e-10];
/// The fixed rules' a-priori bounds in ε ([`Method::Fixed`]): 16ε at k ≤ 1, 32ε above.
const FIXED_BOUND_EPS: f64 = 16.0;
const GRADED_BOUND_EPS: f64 = 32.0;

/// The fixed rule at k ≤ 1, the graded rule above, with derivatives.
fn fixed<T: Real>(nu: f64, mr: f64, k: f64, p: T::Prec) -> Integrals<T> {
    let (sp, ax) = integral_inputs::<T>(nu, mr, k, p);
    let opts = IntegralOptions {
        method: Method::Fixed,
        derivatives: true,
        ..Default::default()
    };
    let r = integrals(&sp, &ax.k, &opts).expect("fixed rule");
    let want = if k <= 1.0 {
        Route::FixedRule
    } else {
        Route::GradedRule
    };
    assert_eq!(r.route, want);
    r
}

/// I1, I2 and (with `dk`) the central differences dI1/dk, dI2/dk (h = k·2⁻⁶⁴) by the adaptive
/// route at `bits`.
fn reference(nu: f64, mr: f64, k: f64, bits: u64, dk: bool) -> Vec<rug::Float> {
    let p = mp(bits);
    let (sp, ax) = integral_inputs::<Mp>(nu, mr, k, p);
    let opts = IntegralOptions {
        method: Method::Adaptive,
        ..Default::default()
    };
    let at = |k: Mp| {
        let r = integrals(&sp, &k, &opts).unwrap();
        (r.i1.value, r.i2.value)
    };
    let r = at(ax.k.clone());
    let mut out = vec![r.0.to_float(bits as u32), r.1.to_float(bits as u32)];
    if dk {
        let h = ax.k.clone().mul_pow2(-64);
        let (up, dn) = (at(ax.k.clone() + &h), at(ax.k.clone() - &h));
        let h2 = h.mul_pow2(1);
        out.push(((up.0 - dn.0) / &h2).to_float(bits as u32));
        out.push(((up.1 - dn.1) / &h2).to_float(bits as u32));
    }
    out
}

/// Worst relative error of I1, I2 (and of dI/dk with `dk`) in ε over the grid at `ks`.
fn check<T: Real>(p: T::Prec, ks: &[f64], dk: bool) -> (f64, f64) {
    let bits = T::bits(p) as u64;
    let (mut worst, mut worst_dk) = (0.0f64, 0.0f64);
    for (&nu, &mr, &k) in NUS.iter().flat_map(|nu| {
        MRS.iter()
            .flat_map(move |mr| ks.iter().map(move |k| (nu, mr, k)))
    }) {
        let got = fixed::<T>(nu, mr, k, p);
        let want = reference(nu, mr, k, (bits + 64).max(256), dk);
        let e = rel_eps(&got.i1.value, &want[0]).max(rel_eps(&got.i2.value, &want[1]));
        let est = got.i1.error.to_f64() / T::epsilon(p).to_f64();
        let bound = if k <= 1.0 {
            FIXED_BOUND_EPS
        } else {
            GRADED_BOUND_EPS
        };
        assert!(
            e <= est && est <= bound,
            "{bits} bits, nu={nu} M_R={mr} k={k:e}: error {e:.2} eps, estimate {est:.1} eps"
        );
        worst = worst.max(e);
        if dk {
            let (d1, d2) = (got.di1_dk.expect("dI1/dk"), got.di2_dk.expect("dI2/dk"));
            let d = rel_eps(&d1.value, &want[2]).max(rel_eps(&d2.value, &want[3]));
            assert!(
                d <= 64.0,
                "{bits} bits, nu={nu} M_R={mr} k={k:e}: dI/dk {d:.1} eps"
            );
            worst_dk = worst_dk.max(d);
        }
    }
    (worst, worst_dk)
}

#[test]
fn the_fixed_rule_holds_its_bound_down_to_tiny_k() {
    let ks = [1e-20, 1e-75];
    println!("f64: {:?}", check::<f64>((), &ks, true));
    println!("dd: {:?}", check::<Dd>((), &[1e-20, 1e-72], true));
    println!("mpfr256: {:?}", check::<Mp>(mp(256), &ks, false));
    assert_no_mixing();
}

#[test]
fn the_graded_rule_holds_its_bound_up_to_huge_k() {
    let ks = [1e20, 1e54];
    println!("f64: {:?}", check::<f64>((), &ks, true));
    println!("dd: {:?}", check::<Dd>((), &ks, true));
    println!("mpfr256: {:?}", check::<Mp>(mp(256), &ks, false));
    assert_no_mixing();
}
