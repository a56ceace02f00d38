//! The final results held to independent references: k, e, I1, I2 of the ellipse solve (33),
//! J0 of (32), and the contact quantities a, b, p0, d0 under a load and a, b, p0, P under an
//! approach, against `tests/data/references_arb.csv` (320 rows by `tools/gen_references.py`:
//! Arb's rigorous quadrature at two precisions, 45 digits; inputs exact in binary, ν from −0.97
//! to 1/2, 1 − M_R from 1 down to 2⁻⁴⁰ ≈ 9.1e-13, A1/B1 from 1e-6 to 1e6).
//!
//! At `f64`, double-double and 256 bits every result must lie within its returned bound and
//! within a stated number of units u = max(ε, 10⁻⁴⁵) (at 256 bits the reference's 45 digits are
//! the unit); e's bound and error are absolute, the others relative. At `f64` and double-double
//! every bound is also held within 10× of the worst error over the rows (p0 under an approach
//! at double-double within 12×: [`TIGHT_DD`]). The test prints the worst
//! and mean errors in u and the worst error/bound per quantity and precision
//! (`cargo test --release --test references -- --nocapture`).

mod common;

use common::{mp, read_csv, reference, REF_BITS};
use moving_hertz::scalar::Mp;
use moving_hertz::{
    solve_ellipse, ContactProblem, Dd, Estimated, Loading, Material, Options, Real,
};
use rug::Float;

/// The quantities of a row, in the file's order after the inputs.
const NAMES: [&str; 13] = [
    "k", "e", "I1", "I2", "J0", "a|P", "b|P", "p0|P", "d0|P", "a|d0", "b|d0", "p0|d0", "P|d0",
];

/// The largest error allowed, in units u, per quantity (the order of [`NAMES`]), at `f64` and
/// double-double (k's conditioning |d ln k/d ln(A1/B1)| ≤ 1 and I1's |k I1′/I1| ≤ 3 carry the
/// shape's error into the sizes); at 256 bits every quantity within 4 u of the 45-digit
/// reference.
const LIMIT_EPS: [f64; 13] = [
    16.0, 16.0, 32.0, 32.0, 32.0, 24.0, 24.0, 48.0, 64.0, 24.0, 24.0, 48.0, 64.0,
];

/// One reference row: the inputs (exact in `f64`) and the 13 references.
struct Row {
    nu: f64,
    gap: f64,
    ratio: f64,
    r1: f64,
    r2: f64,
    mu: f64,
    load: f64,
    approach: f64,
    want: Vec<Float>,
}

fn rows() -> Vec<Row> {
    read_csv("references_arb.csv")
        .into_iter()
        .map(|r| {
            let f = |i: usize| -> f64 {
                let x: f64 = r[i].parse().expect("input");
                assert_eq!(reference(&r[i]), x, "input {} is not exact in f64", r[i]);
                x
            };
            Row {
                nu: f(0),
                gap: f(1),
                ratio: f(2),
                r1: f(3),
                r2: f(4),
                mu: f(5),
                load: f(6),
                approach: f(7),
                want: r[8..21].iter().map(|s| reference(s)).collect(),
            }
        })
        .collect()
}

/// The crate's 13 results for a row at precision `p`.
fn results<T: Real>(row: &Row, p: T::Prec) -> Vec<Estimated<T>> {
    let x = |v: f64| T::from_f64(v, p);
    let speed = Material::new(x(row.nu))
        .and_then(|m| m.speed(x(1.0 - row.gap)))
        .expect("speed");
    let opts = Options::default();
    let el = solve_ellipse(&speed, &x(row.ratio), &opts).expect("ellipse");
    let solve = |loading| {
        ContactProblem {
            speed: speed.clone(),
            radius_along: x(row.r1),
            radius_across: x(row.r2),
            loading,
            shear_modulus: x(row.mu),
        }
        .solve(&opts)
        .expect("contact")
    };
    let l = solve(Loading::Load(x(row.load)));
    let d = solve(Loading::Approach(x(row.approach)));
    let i = el.integrals();
    vec![
        el.k().clone(),
        el.e().clone(),
        i.i1.clone(),
        i.i2.clone(),
        l.j0().clone(),
        l.a().clone(),
        l.b().clone(),
        l.p0().clone(),
        l.d0().clone(),
        d.a().clone(),
        d.b().clone(),
        d.p0().clone(),
        d.load().clone(),
    ]
}

/// Per quantity: worst and summed error in u, worst error/bound and where.
#[derive(Default, Clone)]
struct Stat {
    worst: f64,
    sum: f64,
    ratio: f64,
    at: usize,
}

/// Checks every row at `T` and prints the table; returns the per-quantity statistics.
fn check<T: Real>(p: T::Prec, label: &str, every: usize) -> Vec<Stat> {
    let rows = rows();
    assert!(rows.len() >= 300, "{} rows", rows.len());
    let eps = T::epsilon(p).to_f64().max(1e-45);
    let mut stats = vec![Stat::default(); NAMES.len()];
    let mut n = 0;
    for (ri, row) in rows.iter().enumerate().step_by(every) {
        n += 1;
        let got = results::<T>(row, p);
        for (qi, (g, want)) in got.iter().zip(&row.want).enumerate() {
            let d = Float::with_val(REF_BITS, g.value.to_float(REF_BITS) - want).abs();
            // e's error and bound are absolute, the others relative.
            let err = if qi == 1 { d } else { d / want.clone().abs() }.to_f64();
            let bound = g.error.to_f64();
            // The reference's own uncertainty (10⁻⁴⁴) is allowed on top of the bound.
            assert!(
                err <= bound + 1e-44,
                "{label} row {ri} {}: error {err:e} above its bound {bound:e}",
                NAMES[qi]
            );
            let u = err / eps;
            assert!(
                u <= LIMIT_EPS[qi],
                "{label} row {ri} {}: error {u:.1} u above {}",
                NAMES[qi],
                LIMIT_EPS[qi]
            );
            let s = &mut stats[qi];
            s.sum += u;
            if u > s.worst {
                (s.worst, s.at) = (u, ri);
            }
            if bound > 0.0 {
                s.ratio = s.ratio.max(err / bound);
            }
        }
    }
    println!("{label}: {n} rows; quantity: worst u (row), mean u, worst error/bound");
    for (name, s) in NAMES.iter().zip(&stats) {
        println!(
            "  {name:6} {:7.2} ({:3}) {:6.2} {:8.2e}",
            s.worst,
            s.at,
            s.sum / n as f64,
            s.ratio
        );
    }
    stats
}

/// The least worst error/bound per quantity (the order of [`NAMES`]) at `f64`: every bound
/// within 10× of the worst error.
const TIGHT_F64: [f64; 13] = [0.1; 13];

/// The same at double-double: 10×, but p0 under an approach within 12×. Where w1 = k²I1/J0 is
/// small its error is −(q1 + q2)/2 to first order in the errors q1, q2 of I1 and I2, so its
/// bound holds half of each of their bounds, 16ε a priori for the fixed rule
/// (`routes::fast::BOUND_EPS`), plus its rounding: 17.6ε, against a worst error of 1.55ε.
const TIGHT_DD: [f64; 13] = [
    0.1,
    0.1,
    0.1,
    0.1,
    0.1,
    0.1,
    0.1,
    0.1,
    0.1,
    0.1,
    0.1,
    1.0 / 12.0,
    0.1,
];

/// The bounds are not loose: for every quantity some row's error is at least `least` of its
/// bound (`f64` and double-double; at 256 bits the reference's 45 digits set the error).
fn assert_tight(stats: &[Stat], least: &[f64; 13], label: &str) {
    for ((name, s), least) in NAMES.iter().zip(stats).zip(least) {
        assert!(
            s.ratio >= *least,
            "{label} {name}: worst error/bound {:.3} below {least:.3}: the bound is loose",
            s.ratio
        );
    }
}

#[test]
fn f64_within_bounds_and_eps() {
    assert_tight(&check::<f64>((), "f64", 1), &TIGHT_F64, "f64");
}

#[test]
fn double_double_within_bounds_and_eps() {
    assert_tight(&check::<Dd>((), "dd", 1), &TIGHT_DD, "dd");
}

#[test]
fn mpfr_256_within_bounds_and_reference() {
    check::<Mp>(mp(256), "mpfr256", 1);
    common::assert_no_mixing();
}
