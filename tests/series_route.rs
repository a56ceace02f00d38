//! The series route (37) for I1, I2: the static limit (43), an independent quadrature of (46)–(47)
//! at a higher precision, the factor π against (34) as printed, the tail bound's premise (h_n
//! decreasing to H) and the term cap.

mod common;

use common::rel_eps;
use moving_hertz::numerics::elliptic::ellipke_mc;
use moving_hertz::numerics::quadrature::{integrate, Limits};
use moving_hertz::physics::{GreenFunction, Material};
use moving_hertz::routes::series::{integrals, terms_estimate, SeriesOptions};
use moving_hertz::routes::{AxisRatio, GreenSeries, Route};
use moving_hertz::scalar::{Field, FieldOps, Mp, MpPrec, Real};
use moving_hertz::Error;
use rug::Float;

fn series<T: Real>(nu: &T, mr: &T, k: &T) -> moving_hertz::routes::Evaluation<T> {
    let mat = Material::new(nu.clone()).expect("material");
    let speed = mat.speed(mr.clone()).expect("speed");
    let axis = AxisRatio::new(k.clone()).expect("axis");
    integrals(&speed, &axis, &SeriesOptions::default()).expect("series")
}

/// M_R = 0: the series reduces to f0 = 1 − ν and (43): I1 = 2(1 − ν)(E/k² − K)/e²,
/// I2 = 2(1 − ν)(K − E)/e², here evaluated as printed at 1024 bits.
fn static_limit<T: Real>(p: T::Prec, label: &str) {
    let r = common::mp(1024);
    let mut worst: f64 = 0.0;
    for nu_s in ["0.25", "-0.5", "0.5"] {
        for k_s in ["0.01", "0.5", "0.875", "2", "100"] {
            let (nu, k) = (T::parse(nu_s, p).unwrap(), T::parse(k_s, p).unwrap());
            let got = series(&nu, &T::zero(p), &k);
            assert_eq!(got.route, Route::Series);
            assert_eq!(got.work, 1, "one term at M_R = 0");
            let nu_r = Mp::from_float(&nu.to_float(T::bits(p)), r);
            let k_r = Mp::from_float(&k.to_float(T::bits(p)), r);
            let mc = k_r.square();
            let e2 = Mp::one(r) - &mc;
            let (kk, ee) = ellipke_mc(&mc).unwrap();
            let f0 = (Mp::one(r) - &nu_r).mul_i64(2);
            let i1 = f0.clone() * (ee.clone() / &mc - &kk) / &e2;
            let i2 = f0 * (kk - ee) / &e2;
            let (e1, e2r) = (
                rel_eps(&got.i1, &i1.to_float(1024)),
                rel_eps(&got.i2, &i2.to_float(1024)),
            );
            worst = worst.max(e1).max(e2r);
            assert!(
                e1 <= 2.0 && e2r <= 2.0,
                "{label}: nu = {nu_s}, k = {k_s}: {e1} {e2r} eps"
            );
        }
    }
    println!("{label}: static limit (43), worst {worst:.2} eps");
}

#[test]
fn static_limit_is_43() {
    at_all_precisions!(static_limit, [128, 256]);
}

/// Breakpoints for (46)–(47): the peak at α = 0 of width √(1 − M_R²), the peak of Δ⁻³ near π/2
/// of width k (small k) or near 0 of width 1/k (large k), on geometric ladders.
fn breakpoints(mr: f64, k: f64) -> Vec<f64> {
    let half_pi = std::f64::consts::FRAC_PI_2;
    let mut v = vec![0.0, half_pi];
    let mut ladder = |w: f64, from_top: bool| {
        let mut x = w;
        while x < 1.2 {
            v.push(if from_top { half_pi - x } else { x });
            x *= 2.0;
        }
    };
    ladder((1.0 - mr * mr).sqrt(), false);
    if k < 1.0 {
        ladder(k, true);
    } else {
        ladder(1.0 / k, false);
    }
    v.retain(|x| *x >= 0.0 && *x <= half_pi);
    v.sort_by(|a, b| a.total_cmp(b));
    v.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    v
}

/// I1, I2 by adaptive Gauss–Legendre quadrature of (46)–(47) at `r`:
/// 2∫ g(V cos α){sin²α, cos²α}/Δ³ dα with g = πG(t)/(1 − t), t = M_R² cos²α,
/// 1 − t = (1 − M_R²) + M_R² sin²α.
fn quadrature_46_47(nu: &Mp, mr: &Mp, k: &Mp) -> (Mp, Mp) {
    let r = nu.prec();
    let mat = Material::new(nu.clone()).unwrap();
    let green = GreenFunction::new(&mat);
    let mr2 = mr.square();
    let omr2 = (Mp::one(r) - mr) * (Mp::one(r) + mr);
    let k2 = k.square();
    let pts: Vec<Mp> = breakpoints(mr.to_f64(), k.to_f64())
        .into_iter()
        .map(|x| Mp::from_f64(x, r))
        .collect();
    let mut pts = pts;
    if let Some(last) = pts.last_mut() {
        *last = Mp::pi(r).mul_pow2(-1);
    }
    let tol = Mp::epsilon(r);
    let run = |sin2: bool| {
        let f = |a: &Mp| {
            let (s, c) = a.clone().sin_cos();
            let (s2, c2) = (s.square(), c.square());
            let t = mr2.clone() * &c2;
            let omt = omr2.clone() + mr2.clone() * &s2;
            let g = green.g_normalised(&t, &omt);
            // Δ² = cos²α + k² sin²α (no cancellation for small k, unlike 1 − e² sin²α).
            let d2 = c2.clone() + k2.clone() * &s2;
            let d3 = d2.clone() * d2.sqrt();
            g * if sin2 { s2 } else { c2 } / d3
        };
        integrate(f, &pts, &tol, Limits::default())
            .unwrap_or_else(|e| {
                panic!(
                    "quadrature at M_R = {}, k = {}: {e}",
                    mr.to_f64(),
                    k.to_f64()
                )
            })
            .value
            .mul_i64(2)
    };
    (run(true), run(false))
}

fn against_quadrature<T: Real>(p: T::Prec, label: &str) {
    let r = common::mp(T::bits(p) as u64 + 64);
    let mut worst: f64 = 0.0;
    let mut most_terms = 0;
    let ks: &[&str] = if T::bits(p) > 120 {
        &["0.05", "1", "20"]
    } else {
        &["0.05", "0.5", "1", "2", "20"]
    };
    for nu_s in ["0.25", "-0.5", "0.5"] {
        for mr_s in ["0.3", "0.7", "0.9"] {
            for k_s in ks {
                let (nu, mr, k) = (
                    T::parse(nu_s, p).unwrap(),
                    T::parse(mr_s, p).unwrap(),
                    T::parse(k_s, p).unwrap(),
                );
                let got = series(&nu, &mr, &k);
                let up = |x: &T| Mp::from_float(&x.to_float(T::bits(p)), r);
                let (q1, q2) = quadrature_46_47(&up(&nu), &up(&mr), &up(&k));
                let e1 = rel_eps(&got.i1, &q1.to_float(r.bits()));
                let e2 = rel_eps(&got.i2, &q2.to_float(r.bits()));
                let est = (got.error_estimate.clone() / T::epsilon(p)).to_f64();
                worst = worst.max(e1).max(e2);
                most_terms = most_terms.max(got.work);
                assert!(
                    e1 <= 4.0 && e2 <= 4.0 && e1.max(e2) <= est,
                    "{label}: nu = {nu_s}, M_R = {mr_s}, k = {k_s}: I1 {e1} eps, I2 {e2} eps, estimate {est}"
                );
            }
        }
    }
    println!("{label}: series vs quadrature of (46)-(47): worst {worst:.2} eps, up to {most_terms} terms");
}

#[test]
fn series_matches_quadrature_of_46_47() {
    at_all_precisions!(against_quadrature, [128, 256]);
}

/// (37) is π times (34) as printed (with Γ by (5)–(6) as printed): errata #3.
#[test]
fn series_equals_pi_times_quadrature_of_34() {
    let p = common::mp(256);
    let r = common::mp(320);
    let nu = Mp::parse("0.25", p).unwrap();
    let mr = Mp::parse("0.5", p).unwrap();
    let k = Mp::parse("0.5", p).unwrap();
    let got = series(&nu, &mr, &k);
    println!(
        "nu = 1/4, M_R = 1/2, k = 1/2: I1 = {}, I2 = {}",
        got.i1.to_decimal(),
        got.i2.to_decimal()
    );
    let mat = Material::new(Mp::parse("0.25", r).unwrap()).unwrap();
    let (mr_r, k2) = (Mp::parse("0.5", r).unwrap(), Mp::parse("0.25", r).unwrap());
    let pi = Mp::pi(r);
    let pts = [Mp::zero(r), pi.clone().mul_pow2(-1), pi.clone()];
    let tol = Mp::from_f64(1e-70, r);
    let run = |cos2: bool| {
        let f = |phi: &Mp| {
            let (s, c) = phi.clone().sin_cos();
            let v = mat.speed(mr_r.clone() * &s).unwrap();
            let gamma = common::printed::gamma(&mat, &v);
            let den = k2.clone() * c.square() + s.square();
            let w = if cos2 { c.square() } else { s.square() };
            -(gamma * w / (den.clone() * den.sqrt()))
        };
        integrate(f, &pts, &tol, Limits::default()).unwrap().value
    };
    let (q1, q2) = (run(true), run(false));
    let rel = |a: &Mp, b: &Mp| {
        let d = Float::with_val(320, &a.0 - &b.0);
        Float::with_val(64, d / &b.0).abs().to_f64()
    };
    let (r1, r2) = (
        got.i1.with_prec(r) / &q1 / &pi - Mp::one(r),
        got.i2.with_prec(r) / &q2 / &pi - Mp::one(r),
    );
    println!("I(37)/(pi I(34)) - 1: {} {}", r1.to_f64(), r2.to_f64());
    assert!(rel(&(got.i1.with_prec(r)), &(q1 * &pi)) < 1e-60);
    assert!(rel(&(got.i2.with_prec(r)), &(q2 * &pi)) < 1e-60);
}

/// The tail bound's premise: h_n = f_n/M_R^{2n} decreases monotonically to H = πG(1) > 0, for ν
/// on a grid of (−1, 1/2] and n ≤ 3000 (at 128 bits, allowing (4n + 64) ε of accumulated rounding in h_n).
#[test]
fn scaled_coefficients_decrease_to_their_limit() {
    let p = common::mp(128);
    for i in 0..60 {
        // ν from −0.99 to 0.5
        let nu = Mp::from_ratio(-99 + i * 149 / 59, 100, p);
        let mat = Material::new(nu.clone()).unwrap();
        let green = GreenFunction::new(&mat);
        let h_lim = green.g_regular(&Mp::one(p)) * Mp::pi(p);
        assert!(h_lim.is_positive());
        let mut gen = GreenSeries::new(&nu, mat.m1().clone());
        let mut prev = gen.next_coefficient();
        for n in 1..3000 {
            let noise = Mp::epsilon(p).mul_i64(4 * n + 64) * &prev;
            let h = gen.next_coefficient();
            assert!(
                h <= prev.clone() + &noise && h.clone() + &noise >= h_lim,
                "nu = {}: h_{n} - h_{} = {:e}, h_{n} - H = {:e}",
                nu.to_f64(),
                n - 1,
                (h.clone() - &prev).to_f64(),
                (h.clone() - &h_lim).to_f64()
            );
            prev = h;
        }
        let close = (prev - &h_lim).abs() / &h_lim;
        assert!(close.to_f64() < 1e-30, "h_3000 vs H: {}", close.to_f64());
    }
}

/// Beyond the cap the route fails fast with an estimate of the terms needed; the estimate is an
/// over-estimate by at most a third.
#[test]
fn term_cap() {
    let mat = Material::new(0.25f64).unwrap();
    let axis = AxisRatio::new(0.5f64).unwrap();
    let t0 = std::time::Instant::now();
    let speed = mat.speed(0.9999).unwrap();
    match integrals(&speed, &axis, &SeriesOptions::default()) {
        Err(Error::TermCap {
            needed: Some(n),
            cap,
            ..
        }) => {
            assert_eq!(cap, 100_000);
            assert!(n > 150_000 && n < 300_000, "needed {n}");
        }
        other => panic!("expected TermCap, got {other:?}"),
    }
    let p = MpPrec::new(256).unwrap();
    let mat_mp = Material::new(Mp::parse("0.25", p).unwrap()).unwrap();
    let speed_mp = mat_mp.speed(Mp::parse("0.9999", p).unwrap()).unwrap();
    let axis_mp = AxisRatio::new(Mp::parse("0.5", p).unwrap()).unwrap();
    assert!(matches!(
        integrals(&speed_mp, &axis_mp, &SeriesOptions::default()),
        Err(Error::TermCap { .. })
    ));
    // Above about 1000 bits ε is below the f64 range: the count grows on linearly in the bits
    // (n(p) − n(512) = (p − 512)·ln 2 / (−ln M_R²)) instead of saturating at u64::MAX.
    let needed = |bits: u64| {
        let p = MpPrec::new(bits).unwrap();
        let x = |s: &str| Mp::parse(s, p).unwrap();
        let speed = Material::new(x("0.25")).unwrap().speed(x("0.999")).unwrap();
        let axis = AxisRatio::new(x("0.5")).unwrap();
        match integrals(&speed, &axis, &SeriesOptions::default()) {
            Err(Error::TermCap {
                needed: Some(n), ..
            }) => n as f64,
            other => panic!("{bits} bits: expected TermCap, got {other:?}"),
        }
    };
    let per_bit = std::f64::consts::LN_2 / -(0.999f64 * 0.999).ln();
    for bits in [2048, 4096, 16384] {
        let grown = needed(bits) - needed(512);
        let want = (bits - 512) as f64 * per_bit;
        assert!(
            (grown - want).abs() <= 4.0,
            "{bits} bits: {grown} vs {want}"
        );
    }
    assert!(t0.elapsed().as_secs_f64() < 1.0, "the refusal must be fast");

    let speed = mat.speed(0.9).unwrap();
    let full = integrals(&speed, &axis, &SeriesOptions::default()).unwrap();
    let small = SeriesOptions {
        rel_tol: None,
        max_terms: 50,
    };
    match integrals(&speed, &axis, &small) {
        Err(Error::TermCap {
            needed: Some(n), ..
        }) => {
            let actual = full.work as u64;
            println!("M_R = 0.9, f64: {actual} terms used, {n} estimated");
            assert!(n >= actual && n <= actual * 4 / 3, "{n} vs {actual}");
        }
        other => panic!("expected TermCap, got {other:?}"),
    }
    assert!(terms_estimate(0.0, 1e-16) == 1);
    // A looser tolerance needs fewer terms and says so in its error estimate.
    let loose = SeriesOptions {
        rel_tol: Some(1e-8),
        max_terms: 1000,
    };
    let r = integrals(&speed, &axis, &loose).unwrap();
    assert!(r.work < full.work && r.error_estimate <= 1.1e-8);
    assert!(((r.i2 - full.i2) / full.i2).abs() <= r.error_estimate);
}

/// Near the Rayleigh speed the route still converges within the default cap at f64 (M_R = 0.999:
/// about 2·10⁴ terms) and agrees with the double-double run.
#[test]
fn near_rayleigh_speed() {
    let mat = Material::new(0.2f64).unwrap();
    let axis = AxisRatio::new(0.3f64).unwrap();
    let speed = mat.speed(0.999).unwrap();
    let t0 = std::time::Instant::now();
    let r = integrals(&speed, &axis, &SeriesOptions::default()).unwrap();
    let dt = t0.elapsed().as_secs_f64();
    let dd = series(
        &moving_hertz::scalar::Dd::from_f64(0.2, ()),
        &moving_hertz::scalar::Dd::from_f64(0.999, ()),
        &moving_hertz::scalar::Dd::from_f64(0.3, ()),
    );
    let e1 = rel_eps(&r.i1, &dd.i1.to_float(110));
    let e2 = rel_eps(&r.i2, &dd.i2.to_float(110));
    println!(
        "M_R = 0.999: {} terms in {dt:.3} s, vs dd: {e1:.2} {e2:.2} eps",
        r.work
    );
    assert!(e1 <= 4.0 && e2 <= 4.0);
}

/// Near the Rayleigh speed the series sees the speed as its gap 1 − M_R represents it (the
/// decimal input's own rounding there), so its estimate bounds the error against a reference on
/// those very inputs: the adaptive route 64 bits higher.
#[test]
fn estimate_holds_near_the_rayleigh_speed_for_decimal_inputs() {
    use moving_hertz::prelude::*;
    use moving_hertz::ExactInputs;
    fn check<T: Real>(p: T::Prec, speeds: &[&str]) {
        let pw = MpPrec::new(Precision::of::<T>(p).bits() as u64 + 64).unwrap();
        let opts = |method| IntegralOptions {
            method,
            ..Default::default()
        };
        for mr in speeds {
            let inputs = ExactInputs::parse("0.2", mr, "0.3").unwrap();
            let (speed, k) = inputs.at::<T>(p).unwrap();
            let (speed_w, k_w) = inputs.rounded::<T>(p).unwrap().at::<Mp>(pw).unwrap();
            let r = moving_hertz::integrals(&speed_w, &k_w, &opts(Method::Adaptive)).unwrap();
            let s = moving_hertz::integrals(&speed, &k, &opts(Method::Series)).unwrap();
            for (got, want) in [(&s.i1, &r.i1.value), (&s.i2, &r.i2.value)] {
                let g = Mp::from_float(&got.value.to_float(pw.bits()), pw);
                let err = RelError::of(&((g - want) / want).abs());
                assert!(
                    err <= got.error,
                    "M_R = {mr}: error {err} > estimate {}",
                    got.error
                );
            }
        }
    }
    check::<f64>((), &["0.9", "0.99", "0.999"]);
    check::<Mp>(MpPrec::new(256).unwrap(), &["0.99"]);
}
