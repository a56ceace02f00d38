//! The ellipse solve's seeds (src/contact/ellipse/seed.rs) against the solve's root: the static
//! seeds' stated accuracy and the grid seed's distance from the root.

use super::seed::{grid_seed, static_seed};
use super::*;
use crate::physics::Material;
use crate::routes::evaluate::Evaluator;
use crate::routes::IntegralOptions;

/// The seeds' stated accuracy against the static root (M_R = 0): the k ≫ 1 form within
/// 1.5 % at A1/B1 = 30 and 0.01 % at 10⁶, Hamrock & Brewe's 2.3× too large at 10⁶.
#[test]
fn static_seeds_against_the_static_root() {
    let mat = crate::physics::Material::new(0.2f64).unwrap();
    let sp = mat.speed(0.0).unwrap();
    let solve = |ratio: f64| {
        solve_ellipse(&sp, &ratio, &Options::default())
            .unwrap()
            .k
            .value
    };
    for (ratio, tol) in [(30.0, 0.015), (1e3, 0.002), (1e6, 1e-4)] {
        let k = solve(ratio);
        let seed = static_seed(ratio);
        assert!(
            (seed / k - 1.0).abs() <= tol,
            "A1/B1 = {ratio}: seed {seed}, root {k}"
        );
    }
    let k = solve(1e6);
    let hb = 1e6f64.powf(std::f64::consts::FRAC_2_PI);
    assert!(
        hb / k > 2.2 && hb / k < 2.4,
        "Hamrock & Brewe {hb} against {k}"
    );
}

/// The grid seed against the solve's root: within 2·10⁻⁹ in λ (so that Newton stops after
/// one evaluation: its step δ meets 64δ² ≤ ε and the carry 16δ² ≤ ε) over ν, M_R up to 0.9999
/// and A1/B1 from 10⁻³ to 10, on both sides of k = 1.
#[test]
fn grid_seeds_lie_near_the_root() {
    let opts = IntegralOptions {
        derivatives: true,
        ..Default::default()
    };
    let mut worst = 0.0f64;
    for nu in [-0.5, 0.25, 0.5] {
        let mat = Material::new(nu).unwrap();
        for mr in [0.0, 0.5, 0.9, 0.99, 0.9999] {
            let sp = mat.speed(mr).unwrap();
            let ev = Evaluator::new(&sp, opts).unwrap();
            for ratio in [1e-3, 0.01, 0.1, 0.5, 2.0, 10.0] {
                let k = solve_ellipse(&sp, &ratio, &Options::default()).unwrap().k;
                let (seed, _) = grid_seed(&ev, &ratio).expect("a seed on the grid");
                let err = (seed / k.value).ln().abs();
                assert!(err <= 2e-9, "nu {nu}, M_R {mr}, A1/B1 {ratio}: {err:.2e}");
                worst = worst.max(err);
            }
        }
    }
    println!("grid seed: worst |ln(seed/k)| {worst:.2e}");
}

/// `Ellipse::iterations` counts the grid seed's nodes: an unseeded `f64` solve reports the
/// evaluations of the same solve started from the grid seed as the caller's seed, plus the
/// distinct nodes the seed read (two at least), at speeds made anew and kept alike.
#[test]
fn iterations_count_the_grid_seeds_nodes() {
    let opts = IntegralOptions {
        derivatives: true,
        ..Default::default()
    };
    for mr in [0.0, 0.5, 0.99, 0.9999] {
        let sp = Material::new(0.25f64).unwrap().speed(mr).unwrap();
        let ev = Evaluator::new(&sp, opts).unwrap();
        for ratio in [0.01, 0.5, 2.0, 10.0] {
            let (seed, nodes) = grid_seed(&ev, &ratio).expect("a seed on the grid");
            let unseeded = solve_ellipse(&sp, &ratio, &Options::default()).unwrap();
            let from_seed = Options {
                seed: Some(seed),
                ..Default::default()
            };
            let seeded = solve_ellipse(&sp, &ratio, &from_seed).unwrap();
            assert_eq!(
                unseeded.k().value,
                seeded.k().value,
                "M_R {mr}, A1/B1 {ratio}"
            );
            assert!(nodes >= 2, "M_R {mr}, A1/B1 {ratio}: {nodes} nodes");
            assert_eq!(
                unseeded.iterations(),
                seeded.iterations() + nodes,
                "M_R {mr}, A1/B1 {ratio}"
            );
        }
    }
}
