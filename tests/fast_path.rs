//! The `f64` fast path against the generic path at `f64`, on every reference case: the fixed
//! rules as the ellipse solve runs them (`Method::Fixed` with k-derivatives: the kept
//! k-independent set-up of `routes::fast` for k ≤ 1, the graded rule above) against the adaptive
//! direct quadrature (`Method::Adaptive`, the generic ground truth) at the same `f64` inputs,
//! and the default solve of (33) against the solve on the adaptive route.
//!
//! The cases: every row of tests/data/references_arb.csv (its ν, M_R = 1 − gap and reference k,
//! rounded to `f64`; the solve at its A1/B1), of fast_reference.csv and graded_reference.csv
//! (the k grids of the two fixed rules) and the I1, I2 rows of integrals_mpmath.csv. Two results
//! agree when their difference lies within the sum of their own bounds (relative, as reported).

mod common;

use common::{integral_cases, integral_inputs, mpmath_cases, read_csv, reference};
use moving_hertz::prelude::*;
use moving_hertz::routes::AxisRatio;
use moving_hertz::{solve_ellipse, Evaluator, IntegralOptions, Integrals, Method, Options};

/// (ν, M_R, k) of every reference case, with A1/B1 where the case is a solve of (33).
fn cases() -> Vec<(f64, f64, f64, Option<f64>)> {
    let mut all = Vec::new();
    for r in read_csv("references_arb.csv") {
        let f = |i: usize| -> f64 { r[i].parse().expect("input") };
        let k = reference(&r[8]).to_f64();
        all.push((f(0), 1.0 - f(1), k, Some(f(2))));
    }
    for name in ["fast_reference.csv", "graded_reference.csv"] {
        for c in integral_cases(name) {
            all.push((c.nu, c.mr, c.k, None));
        }
    }
    for c in mpmath_cases() {
        let (sp, ax) = c.inputs::<f64>(());
        all.push((sp.material().nu().to_f64(), sp.mr().to_f64(), ax.k, None));
    }
    all
}

/// I1, I2, dI1/dk, dI2/dk at (ν, M_R, k) by `method` at `f64`.
fn integrals(nu: f64, mr: f64, k: f64, method: Method) -> Integrals<f64> {
    let (sp, _) = integral_inputs::<f64>(nu, mr, 1.0, ());
    let opts = IntegralOptions {
        method,
        derivatives: true,
        ..Default::default()
    };
    let ev = Evaluator::new(&sp, opts).expect("evaluator");
    ev.at(&k)
        .unwrap_or_else(|e| panic!("{method:?} nu={nu} M_R={mr} k={k}: {e}"))
}

/// |a − b|/|b| over the sum of the two relative bounds (≤ 1: agreement).
fn over_bounds(a: &Estimated<f64>, b: &Estimated<f64>) -> f64 {
    let bound = a.error.to_f64() + b.error.to_f64();
    ((a.value - b.value) / b.value).abs() / bound
}

#[test]
fn fixed_rules_agree_with_the_adaptive_route_at_f64() {
    let all = cases();
    assert_eq!(all.len(), 320 + 224 + 144 + 12, "{} cases", all.len());
    let mut worst = (0.0f64, String::new());
    for (nu, mr, k, _) in all {
        if !(k <= 2f64.powi(180) && AxisRatio::new(k).is_ok()) {
            continue;
        }
        let fast = integrals(nu, mr, k, Method::Fixed);
        let generic = integrals(nu, mr, k, Method::Adaptive);
        let d = |x: &Option<Estimated<f64>>| x.clone().expect("derivative");
        let pairs = [
            (fast.i1.clone(), generic.i1.clone(), "I1"),
            (fast.i2.clone(), generic.i2.clone(), "I2"),
            (d(&fast.di1_dk), d(&generic.di1_dk), "dI1/dk"),
            (d(&fast.di2_dk), d(&generic.di2_dk), "dI2/dk"),
        ];
        for (a, b, what) in pairs {
            let r = over_bounds(&a, &b);
            let at = format!("{what} nu={nu} M_R={mr} k={k:e} ({})", fast.route);
            assert!(
                r <= 1.0,
                "{at}: {} against {}, {r:.2} of the bounds",
                a.value,
                b.value
            );
            if r > worst.0 {
                worst = (r, at);
            }
        }
    }
    println!("worst difference / bounds: {:.3} at {}", worst.0, worst.1);
}

#[test]
fn the_solve_agrees_with_the_solve_on_the_adaptive_route_at_f64() {
    let mut worst = (0.0f64, String::new());
    let mut n = 0;
    for (nu, mr, _, ratio) in cases() {
        let Some(ratio) = ratio else { continue };
        let (sp, _) = integral_inputs::<f64>(nu, mr, 1.0, ());
        let solve = |method| {
            let opts = Options {
                method,
                ..Default::default()
            };
            solve_ellipse(&sp, &ratio, &opts)
                .unwrap_or_else(|e| panic!("{method:?} nu={nu} M_R={mr} A1/B1={ratio}: {e}"))
        };
        let (fast, generic) = (solve(Method::Auto), solve(Method::Adaptive));
        for (a, b, what) in [
            (fast.k(), generic.k(), "k"),
            (&fast.integrals().i1, &generic.integrals().i1, "I1"),
            (&fast.integrals().i2, &generic.integrals().i2, "I2"),
        ] {
            let r = over_bounds(a, b);
            let at = format!("{what} nu={nu} M_R={mr} A1/B1={ratio:e}");
            assert!(
                r <= 1.0,
                "{at}: {} against {}, {r:.2} of the bounds",
                a.value,
                b.value
            );
            if r > worst.0 {
                worst = (r, at);
            }
        }
        n += 1;
    }
    assert_eq!(n, 320);
    println!("worst difference / bounds: {:.3} at {}", worst.0, worst.1);
}
