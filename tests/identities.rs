//! Identities among I1, I2 of (34), their k-derivatives and J0 of (32), valid at any precision
//! and for any g, checked on every route that returns the quantities, at `f64`, double-double
//! and 128, 256 and 1024 bits:
//!
//! * k² I1′ + I2′ = −3k I1: with D = k² cos²φ + sin²φ, I1′ = −3k ∫ g cos⁴φ/D^{5/2} and
//!   I2′ = −3k ∫ g sin²φ cos²φ/D^{5/2}, and k² cos⁴φ + sin²φ cos²φ = cos²φ·D;
//! * J0 = k² I1 + I2 (the integrands weighted by k² and 1 add up to J0's) against the J0 the
//!   adaptive route integrates on its own nodes with the derivatives;
//! * d0 = A1 a² + B1 b² for the contact solution (with (30) and (32): A1 a² + B1 b² =
//!   p0 k a (I2 + k² I1)/(4μ) = p0 b J0/(4μ)), under a given load and a given approach.
//!
//! Each residual must lie within the bounds each route returns (|error| of each term from its
//! relative bound, plus a few ε of the terms' magnitudes for the residual's own rounding).

mod common;

use moving_hertz::prelude::*;
use moving_hertz::{integrals, ContactSolution, Integrals, Method};

/// The residual of k² I1′ + I2′ + 3k I1 and what the returned bounds allow it, both relative to
/// the magnitude k²|I1′| + |I2′| + 3k|I1| (in units of ε); the same for J0 − (k² I1 + I2) when
/// the route returned J0.
fn residuals<T: Real>(k: &T, r: &Integrals<T>) -> [(f64, f64); 2] {
    let p = k.prec();
    let eps = T::epsilon(p);
    let (i1, i2) = (&r.i1, &r.i2);
    let (d1, d2) = (r.di1_dk.as_ref().unwrap(), r.di2_dk.as_ref().unwrap());
    let k2 = k.clone() * k;
    let three_k = k.clone().mul_i64(3);
    let terms = [
        (k2.clone() * &d1.value, d1.error),
        (d2.value.clone(), d2.error),
        (three_k * &i1.value, i1.error),
    ];
    let scale = terms
        .iter()
        .fold(T::zero(p), |s, (t, _)| s + &t.clone().abs());
    let allowed = terms
        .iter()
        .fold(eps.clone().mul_i64(8) * &scale, |s, (t, e)| {
            s + &(t.clone().abs() * &e.to_real::<T>(p))
        });
    let sum = terms.iter().fold(T::zero(p), |s, (t, _)| s + t);
    let unit = eps.clone() * &scale;
    let derivative = ((sum.abs() / &unit).to_f64(), (allowed / &unit).to_f64());
    let j0 = match &r.j0 {
        None => (0.0, 1.0),
        Some(j) => {
            let a = k2.clone() * &i1.value;
            let formed = a.clone() + &i2.value;
            let unit = eps.clone() * &formed;
            let allowed = a * &i1.error.to_real::<T>(p)
                + &(i2.value.clone() * &i2.error.to_real::<T>(p))
                + &(j.value.clone() * &j.error.to_real::<T>(p))
                + &(eps.mul_i64(4) * &formed);
            let diff = (j.value.clone() - &formed).abs();
            ((diff / &unit).to_f64(), (allowed / &unit).to_f64())
        }
    };
    [derivative, j0]
}

/// The adaptive route's I1, I2 and k-derivatives against the fixed rule's, within the sum of
/// their bounds and 8ε: the adaptive route forms its five integrands from one value of G a node,
/// so the identities above hold on it whatever G is; the fixed rule (its own variables, nodes
/// and set-up) is what can tell a wrong G or a wrong weight shared by the five.
fn agree<T: Real>(adaptive: &Integrals<T>, fixed: &Integrals<T>, at: &str) {
    let (a, f) = (adaptive, fixed);
    let pairs = [
        ("I1", &a.i1, &f.i1),
        ("I2", &a.i2, &f.i2),
        (
            "dI1/dk",
            a.di1_dk.as_ref().unwrap(),
            f.di1_dk.as_ref().unwrap(),
        ),
        (
            "dI2/dk",
            a.di2_dk.as_ref().unwrap(),
            f.di2_dk.as_ref().unwrap(),
        ),
    ];
    for (name, x, y) in pairs {
        let p = x.value.prec();
        let d = ((x.value.clone() - &y.value) / &y.value).abs().to_f64();
        let allowed = x.error.to_f64() + y.error.to_f64() + 8.0 * T::epsilon(p).to_f64();
        assert!(
            d <= allowed,
            "{at}: {name} adaptive {:?} vs fixed {:?}: {d:e} > {allowed:e}",
            x.value,
            y.value
        );
    }
}

/// Every method that returns k-derivatives (the fixed rules, the adaptive route with J0 too,
/// and `Auto`) on ν ∈ {−0.9, 0, 0.25, 0.5}, 1 − M_R from 1 to 10⁻¹⁰ and k from 10⁻⁶ to 10⁶.
fn identities_hold<T: Real>(p: T::Prec, label: &str) {
    let x = |s: &str| T::parse(s, p).unwrap();
    let bits = T::bits(p);
    let mut worst = [0.0f64; 2];
    for nu in ["-0.9", "0", "0.25", "0.5"] {
        let mat = Material::new(x(nu)).unwrap();
        for gap in ["1", "0.5", "0.01", "1e-6", "1e-10"] {
            let speed = mat.parse_gap(gap).unwrap();
            for ks in ["1e-6", "0.01", "0.3", "1", "3", "100", "1e6"] {
                let k = x(ks);
                let mut fixed: Option<Integrals<T>> = None;
                for (method, j0) in [
                    (Method::Fixed, false),
                    (Method::Auto, false),
                    (Method::Adaptive, true),
                ] {
                    // The adaptive route at 1024 bits costs seconds a call: two cases suffice.
                    if method == Method::Adaptive && bits > 300 && !(nu == "0.25" && gap == "0.01")
                    {
                        continue;
                    }
                    let opts = IntegralOptions {
                        method,
                        derivatives: true,
                        j0,
                        ..Default::default()
                    };
                    let at = format!("{label} nu={nu} gap={gap} k={ks} {method:?}");
                    let r = integrals(&speed, &k, &opts).unwrap_or_else(|e| panic!("{at}: {e}"));
                    for (i, (got, allowed)) in residuals(&k, &r).into_iter().enumerate() {
                        let what = ["k² I1′ + I2′ + 3k I1", "J0 − (k² I1 + I2)"][i];
                        assert!(
                            got <= allowed,
                            "{at}: {what} = {got:.2} eps of its terms, bounds allow {allowed:.2}"
                        );
                        worst[i] = worst[i].max(got);
                    }
                    match (method, &fixed) {
                        (Method::Fixed, _) => fixed = Some(r),
                        (Method::Adaptive, Some(f)) => agree(&r, f, &at),
                        _ => {}
                    }
                }
            }
        }
    }
    println!(
        "{label}: worst residual k² I1′ + I2′ + 3k I1 {:.2} eps, J0 − (k² I1 + I2) {:.2} eps",
        worst[0], worst[1]
    );
}

#[test]
fn derivative_and_j0_identities_hold_within_the_bounds() {
    at_all_precisions!(identities_hold);
}

/// |d0 − (A1 a² + B1 b²)| and what the solution's bounds allow it (the terms' bounds, twice a's
/// and b's for their squares, plus 8ε of the terms for the roundings of A1, B1 and the sum), both
/// in units of ε·d0.
fn approach_residual<T: Real>(sol: &ContactSolution<T>, r1: &T, r2: &T) -> (f64, f64) {
    let p = r1.prec();
    let eps = T::epsilon(p);
    let (a, b, d0) = (sol.a(), sol.b(), sol.d0());
    let along = a.value.clone() * &a.value / &r1.clone().mul_pow2(1);
    let across = b.value.clone() * &b.value / &r2.clone().mul_pow2(1);
    let rel = |e: RelError| e.to_real::<T>(p);
    let allowed = d0.value.clone() * &rel(d0.error)
        + &(along.clone() * &rel(a.error).mul_pow2(1))
        + &(across.clone() * &rel(b.error).mul_pow2(1))
        + &(eps.clone().mul_i64(8) * &(along.clone() + &across + &d0.value));
    let diff = (d0.value.clone() - &along - &across).abs();
    let unit = eps * &d0.value;
    ((diff / &unit).to_f64(), (allowed / &unit).to_f64())
}

/// d0 = A1 a² + B1 b² on ν ∈ {−0.5, 0.25, 0.5}, 1 − M_R from 1 to 10⁻¹⁰ (and 10⁻¹⁰⁰⁰ at MPFR,
/// k ≈ 10⁻²⁵⁰) and R2/R1 from 10⁻⁶ to 10⁶, under a load and under an approach: within the
/// bounds, and within 16ε of d0 (the residual carries k's error through the root's ratio).
fn approach_identity_holds<T: Real>(p: T::Prec, label: &str) {
    let x = |s: &str| T::parse(s, p).unwrap();
    let mut gaps = vec!["1", "0.01", "1e-10"];
    if T::bits(p) > 106 {
        gaps.push("1e-1000");
    }
    let mut worst = 0.0f64;
    for nu in ["-0.5", "0.25", "0.5"] {
        let mat = Material::new(x(nu)).unwrap();
        for &gap in &gaps {
            for r2 in ["1e-6", "0.2", "1", "7", "1e6"] {
                for loading in [Loading::Load(x("1000")), Loading::Approach(x("1e-5"))] {
                    let at = format!("{label} nu={nu} gap={gap} R2/R1={r2} {loading:?}");
                    let (r1, r2) = (x("1"), x(r2));
                    let sol = ContactProblem {
                        speed: mat.parse_gap(gap).unwrap(),
                        radius_along: r1.clone(),
                        radius_across: r2.clone(),
                        loading,
                        shear_modulus: x("80e9"),
                    }
                    .solve(&Options::default())
                    .unwrap_or_else(|e| panic!("{at}: {e}"));
                    let (got, allowed) = approach_residual(&sol, &r1, &r2);
                    assert!(
                        got <= allowed && got <= 16.0,
                        "{at}: d0 − (A1 a² + B1 b²) = {got:.2} eps of d0, bounds allow {allowed:.2}"
                    );
                    worst = worst.max(got);
                }
            }
        }
    }
    println!("{label}: worst residual d0 − (A1 a² + B1 b²) {worst:.2} eps of d0");
}

#[test]
fn the_approach_is_a1_a2_plus_b1_b2_within_the_bounds() {
    at_all_precisions!(approach_identity_holds, [128, 256]);
}
