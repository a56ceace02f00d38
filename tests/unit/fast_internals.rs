//! Unit tests of the fast route's internals: the Taylor coefficients b_j against the
//! recurrence (36), the sinh-mapped left half against the single rule, the moments N_j, M_0, P_0
//! against adaptive quadrature.

use super::*;
use crate::physics::Material;
use crate::routes::coefficients::GreenSeries;
use crate::scalar::{Dd, Field, Mp, MpPrec};
use rug::Rational;

/// b_j by an independent route at 512 bits: the coefficients c_l of g (recurrence (36),
/// `GreenSeries`, scale x0 = c) composed with y = σ/(1 + σ) and (1 + σ)^{−1/2}:
/// b = 2 Σ_l c_l σ^l (1 + σ)^{−l−1/2}. With each b_j, the sum of the moduli of its terms.
fn composed_b(nu: f64, mr: f64, j_max: usize) -> Vec<(rug::Float, f64)> {
    let p = MpPrec::new(512).unwrap();
    let mat = Material::new(Mp::from_f64(nu, p)).unwrap();
    let sp = mat.speed(Mp::from_f64(mr, p)).unwrap();
    let c = GreenSeries::new(mat.nu(), sp.m2sq().clone()).take(j_max);
    (0..j_max)
        .map(|j| {
            let mut sum = Mp::zero(p);
            let mut scale = 0.0;
            for (l, cl) in c.iter().enumerate().take(j + 1) {
                // 2 (−1)^m (l + 1/2)_m / m!, m = j − l.
                let mut e = Rational::from(2);
                for m in 0..(j - l) {
                    e *= Rational::from((-(2 * (l + m) as i64 + 1), 2 * m as i64 + 2));
                }
                let t = Mp::from_float(&rug::Float::with_val(600, &e), p) * cl;
                scale += t.to_f64().abs();
                sum += t;
            }
            (sum.to_float(512), scale)
        })
        .collect()
}

fn check_taylor<T: Real>(p: T::Prec, tol_eps: f64) {
    let rule = FastRule::<T>::get(p).unwrap();
    let j_max = rule.sizes.taylor;
    for (nu, mr) in [(0.25, 0.625), (-0.9, 0.99), (0.5, 0.0), (0.5, 0.999)] {
        let want = composed_b(nu, mr, j_max);
        let mat = Material::new(T::from_f64(nu, p)).unwrap();
        let sp = mat.speed(T::from_f64(mr, p)).unwrap();
        let sc = SpeedConsts::new(&sp);
        let mut b = vec![T::zero(p); j_max];
        taylor_b(&sc, &rule, &mut b);
        // b_j may cancel (which does not matter: the same polynomial is subtracted at the
        // nodes and integrated exactly); its error is measured against its terms, and may
        // grow like j² (the triple root of the divisor at M_R = 0).
        let eps = T::epsilon(p).to_f64();
        for (j, (got, (w, scale))) in b.iter().zip(&want).enumerate() {
            let d = rug::Float::with_val(600, got.to_float(600) - w);
            let e = d.abs().to_f64() / scale / eps;
            let tol = tol_eps * (1 + j * j) as f64;
            assert!(e <= tol, "nu={nu} M_R={mr} b_{j}: {e:.1} eps");
        }
    }
}

/// Above double-double the left half lies on sinh-mapped panels (`RuleSizes::left_sinh`): it
/// agrees with the single Gauss–Legendre rule in w of ⌈0.433·bits⌉ − 2 nodes (the layout used
/// up to double-double, extended) to a few ε at 256 and 1024 bits, on the left half's hardest
/// cases (ν = 1/2 and M_R → 1, where G's branch point comes nearest) and across k.
#[test]
fn left_layouts_agree() {
    for bits in [256u32, 1024] {
        let p = MpPrec::new(bits as u64).unwrap();
        let plain = RuleSizes {
            left: (bits as usize * 433).div_ceil(1000) - 2,
            left_sinh: false,
            ..RuleSizes::for_bits(bits)
        };
        let sinh = RuleSizes::for_bits(bits);
        assert!(sinh.left_sinh && sinh.left == left_sinh_nodes(bits) && sinh.left < plain.left);
        let (a, b) = (
            Arc::new(FastRule::build(plain, p).unwrap()),
            Arc::new(FastRule::build(sinh, p).unwrap()),
        );
        let eps = Mp::epsilon(p);
        let rel = |y: &Mp, x: &Mp| ((y.clone() - x) / x).abs().to_f64() / eps.to_f64();
        let mut worst = 0.0f64;
        for nu in [-0.9, 0.25, 0.5] {
            for mr in [0.0, 0.9, 0.9999, 1.0 - 1e-12] {
                for k in [1e-6, 0.3, 1.0] {
                    let mat = Material::new(Mp::from_f64(nu, p)).unwrap();
                    let sp = mat.speed(Mp::from_f64(mr, p)).unwrap();
                    let ax = AxisRatio::new(Mp::from_f64(k, p)).unwrap();
                    let setup = |r: &Arc<FastRule<Mp>>| {
                        FastSetup::with_rule(&sp, r.clone(), false).unwrap()
                    };
                    let x = setup(&a).run(&ax, true).unwrap();
                    let y = setup(&b).run(&ax, true).unwrap();
                    let e = [
                        rel(&y.i1, &x.i1),
                        rel(&y.i2, &x.i2),
                        rel(&y.di1_dk(), &x.di1_dk()),
                        rel(&y.di2_dk(), &x.di2_dk()),
                    ];
                    let e = e.into_iter().fold(0.0, f64::max);
                    assert!(e <= 8.0, "{bits} bits nu={nu} M_R={mr} k={k}: {e:.1} eps");
                    worst = worst.max(e);
                }
            }
        }
        println!("{bits} bits: sinh-mapped left half against the plain rule, worst {worst:.2} eps");
    }
}

#[test]
fn taylor_coefficients_match_the_recurrence_36() {
    check_taylor::<f64>((), 16.0);
    check_taylor::<Dd>((), 16.0);
    check_taylor::<Mp>(MpPrec::new(256).unwrap(), 16.0);
}

#[test]
fn moments_match_quadrature() {
    // N_j against adaptive quadrature of v^{2j}(v² + k²)^{−1/2} at 128 bits.
    let p = MpPrec::new(128).unwrap();
    for k in [(1, 1000), (3, 10), (1, 1)] {
        let kk = Mp::from_ratio(k.0, k.1, p);
        let k2 = kk.square();
        let inv: Vec<Mp> = (1..=12).map(|j| Mp::from_ratio(1, 2 * j, p)).collect();
        let ratio: Vec<Mp> = (1..=12)
            .map(|j| Mp::from_ratio(2 * j - 1, 2 * j, p))
            .collect();
        let (m0, p0, n0, r1) = moment_bases(&kk, &k2);
        let mut n = vec![n0];
        for j in 0..11 {
            n.push(next_moment(&n[j], &k2, &r1, &inv[j], &ratio[j]));
        }
        let pts = [
            Mp::zero(p),
            kk.clone().min_of(Mp::from_ratio(1, 2, p)),
            Mp::one(p),
        ];
        let lim = crate::numerics::quadrature::Limits::default();
        let tol = Mp::epsilon(p);
        let q = |f: &dyn Fn(&Mp) -> Mp| {
            crate::numerics::quadrature::integrate(f, &pts, &tol, lim)
                .unwrap()
                .value
        };
        for (j, nj) in n.iter().enumerate() {
            let want = q(&|v: &Mp| v.powi(2 * j as i64) / (v.square() + &k2).sqrt());
            assert!(
                ((nj.clone() - &want) / &want).abs() < Mp::epsilon(p).mul_i64(64),
                "N_{j} k={k:?}"
            );
        }
        let w = |m: i64| q(&|v: &Mp| (v.square() + &k2).powi(-m) / (v.square() + &k2).sqrt());
        assert!(((m0 - w(1)) / w(1)).abs() < Mp::epsilon(p).mul_i64(16));
        assert!(((p0 - w(2)) / w(2)).abs() < Mp::epsilon(p).mul_i64(16));
    }
}
