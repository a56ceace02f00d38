//! The coefficients of g = −πΓ = Σ f_n sin^{2n}φ: the corrected recurrence (36) against exact
//! Taylor coefficients computed independently from (5)–(6) as printed (tools/gen_series.py), in
//! exact rationals and at every precision; the erratum in f2; stability for n up to 10^5.

mod common;

use common::{read_csv, rel_eps};
use moving_hertz::physics::Material;
use moving_hertz::routes::GreenSeries;
use moving_hertz::scalar::{decimal_to_rational, mixed_precision_events, Real};
use rug::{Float, Rational};

fn exact_table() -> Vec<(Rational, Vec<Rational>)> {
    let mut out: Vec<(Rational, Vec<Rational>)> = Vec::new();
    for row in read_csv("series_coefficients.csv") {
        let nu = decimal_to_rational(&row[0]).expect("nu");
        let c = decimal_to_rational(&row[2]).expect("F_n");
        match out.last_mut() {
            Some((n, v)) if *n == nu => v.push(c),
            _ => out.push((nu, vec![c])),
        }
    }
    out
}

#[test]
fn exact_recurrence_equals_taylor_coefficients_of_printed_gamma() {
    let table = exact_table();
    assert_eq!(table.len(), 6);
    for (nu, want) in &table {
        let got = GreenSeries::new(nu, Rational::from(1)).take(want.len());
        assert_eq!(&got, want, "nu = {nu}");
    }
}

#[test]
fn printed_f2_is_a_misprint_and_f1_is_right() {
    for (nu, want) in exact_table() {
        let one = Rational::from(1);
        // Printed: f1 = (16ν² − 24ν + 14)/16, f2 = (27 − 220ν + 312ν² − 224ν³ + 64ν⁴)/(64(1 − ν)).
        let n2 = nu.clone() * &nu;
        let n3 = n2.clone() * &nu;
        let n4 = n3.clone() * &nu;
        let f1 = (n2.clone() * 16u32 - nu.clone() * 24u32 + 14u32) / 16u32;
        assert_eq!(f1, want[1]);
        let poly = |c0: u32| {
            Rational::from(c0) - nu.clone() * 220u32 + n2.clone() * 312u32 - n3.clone() * 224u32
                + n4.clone() * 64u32
        };
        let den = (one.clone() - &nu) * 64u32;
        let printed = poly(27) / den.clone();
        let corrected = poly(67) / den;
        assert_eq!(corrected, want[2], "nu = {nu}");
        assert_eq!(
            printed - &want[2],
            Rational::from(-5) / ((one - &nu) * 8u32)
        );
    }
}

/// The floating recurrence at x0 = 1 against the exact coefficients. The recurrence is stable (the
/// wanted solution is dominant), so each step's rounding persists without growing: the relative
/// error accumulates at most linearly, ≤ (n + 4) ε here.
fn float_vs_exact<T: Real>(p: T::Prec, label: &str) {
    let mut worst: f64 = 0.0;
    for (nu, want) in exact_table() {
        let nu_t = T::from_float(&Float::with_val(T::bits(p) + 64, &nu), p);
        // ν is rounded to T; compare against the exact coefficients of that rounded ν.
        let nu_exact = nu_t
            .to_float(T::bits(p) + 64)
            .to_rational()
            .expect("finite");
        let exact = GreenSeries::new(&nu_exact, Rational::from(1)).take(want.len());
        let got = GreenSeries::new(&nu_t, T::one(p)).take(want.len());
        for (n, (g, w)) in got.iter().zip(&exact).enumerate() {
            let e = rel_eps(g, &Float::with_val(common::REF_BITS, w));
            worst = worst.max(e);
            assert!(
                e <= (n + 4) as f64,
                "{label}: nu = {nu}, n = {n}: error {e} eps"
            );
        }
    }
    println!("{label}: worst relative error of F_n, n ≤ 60: {worst:.2} eps");
}

#[test]
fn floating_recurrence_matches_exact() {
    at_all_precisions!(float_vs_exact, [64, 256, 1024]);
    assert_eq!(mixed_precision_events(), 0);
}

/// The scaled coefficients h_n = f_n/M_R^{2n} (x0 = m1) stay finite and O(1) up to n = 10^5 at
/// f64 — where F_n itself overflows past n ≈ 2700 — and agree with a 256-bit run.
#[test]
fn scaled_coefficients_to_ten_to_the_five() {
    let n = 100_000;
    for nu in ["-0.5", "0.2", "0.5"] {
        let mat = Material::new(nu.parse::<f64>().unwrap()).expect("material");
        let h = GreenSeries::new(mat.nu(), *mat.m1()).take(n);
        let p = common::mp(256);
        let mat_mp = Material::new(moving_hertz::scalar::Mp::parse(nu, p).unwrap()).expect("mp");
        let mut gen = GreenSeries::new(mat_mp.nu(), mat_mp.m1().clone());
        let mut worst: f64 = 0.0;
        for (k, hk) in h.iter().enumerate() {
            let r = gen.next_coefficient();
            assert!(hk.is_finite() && hk.abs() < 1e3, "h_{k} = {hk}");
            if k % 97 == 0 || k + 1 == n {
                // The f64 run also carries the rounding of ν and m1; allow for its conditioning.
                let e = rel_eps(hk, &r.to_float(300));
                worst = worst.max(e);
            }
        }
        println!("nu = {nu}: h_n up to n = 10^5, worst relative error vs 256 bits {worst:.1} eps");
        assert!(worst < 1e3, "nu = {nu}: {worst} eps");
    }
}
