//! I2 ~ C (1 − M_R)^(−1/2) + D as M_R → 1: C = π² G(1)/√2 (independent of k) and D against I2
//! computed by the subtracted route at M_R = 1 − 10^-4 … 1 − 10^-12.

mod common;

use moving_hertz::physics::Material;
use moving_hertz::prelude::*;
use moving_hertz::routes::asymptotic::{leading_coefficient, I2Asymptotics};
use moving_hertz::routes::{direct, AxisRatio};

fn check<T: Real>(p: T::Prec, label: &str) {
    for (nu, k) in [
        ("0.25", "0.5"),
        ("0.0", "0.05"),
        ("0.5", "0.001"),
        ("-0.5", "1"),
    ] {
        let mat = Material::new(T::parse(nu, p).unwrap()).unwrap();
        let ax = AxisRatio::new(T::parse(k, p).unwrap()).unwrap();
        let asy = I2Asymptotics::new(&mat, &ax).unwrap();
        assert_eq!(asy.c, leading_coefficient(&mat));
        let mut prev_ratio = f64::INFINITY;
        for j in [4, 6, 8, 10, 12] {
            let mr = T::one(p) - T::one(p) / T::from_i64(10i64.pow(j as u32), p);
            // 1 − M_R of the rounded M_R (exact by Sterbenz's lemma).
            let delta = T::one(p) - &mr;
            let sp = mat.speed(mr).unwrap();
            let i2 = direct::subtracted(&sp, &ax, &T::zero(p)).unwrap().i2;
            // One term: relative error ~ (D/C)·δ^(1/2); two terms: ~ δ.
            let e1 = ((asy.leading(&delta) - &i2) / &i2).abs().to_f64();
            let e2 = ((asy.two_term(&delta) - &i2) / &i2).abs().to_f64();
            let d = delta.to_f64();
            let dc = (asy.d.clone() / &asy.c).abs().to_f64();
            assert!(
                e1 <= 1.5 * dc * d.sqrt() + 1e-13,
                "{label} nu={nu} k={k} 1-M_R={d:e}: one-term error {e1:e}"
            );
            assert!(
                e2 <= 10.0 * (1.0 + dc) * d + 1e-13,
                "{label} nu={nu} k={k} 1-M_R={d:e}: two-term error {e2:e}"
            );
            // The one-term error, divided by δ^(1/2), tends to |D/C|.
            let ratio = e1 / d.sqrt();
            if j >= 8 {
                assert!(
                    (ratio - dc).abs() <= 0.05 * dc + 1e-6 / d.sqrt(),
                    "{label}: ratio {ratio} vs D/C {dc}"
                );
            }
            prev_ratio = prev_ratio.min(ratio);
        }
        println!(
            "{label} nu={nu} k={k}: C = {:.12e}, D = {:.12e}",
            asy.c.to_f64(),
            asy.d.to_f64()
        );
    }
}

#[test]
fn two_term_asymptotics_of_i2() {
    check::<f64>((), "f64");
    check::<Dd>((), "dd");
}

#[test]
fn leading_coefficient_is_independent_of_k() {
    let mat = Material::new(0.2).unwrap();
    let c = leading_coefficient(&mat);
    // C = π² G(1)/√2; as a function of ν only it equals the limit of I2·(1 − M_R)^(1/2) for
    // different k (the k-dependence enters through D).
    for k in [0.01, 0.3, 1.0] {
        let ax = AxisRatio::new(k).unwrap();
        let sp = mat.speed(1.0 - 1e-12).unwrap();
        let i2 = direct::subtracted(&sp, &ax, &0.0).unwrap().i2;
        let est = i2 * 1e-6;
        assert!((est - c).abs() / c < 1e-4, "k = {k}: {est} vs {c}");
    }
}
