//! The moments L_n (39), M_n (41) and D_n = L_n − L_{n+1}: the recursion (40) and starting values
//! (42) against quadrature, the default against mpmath's ₂F₁ (tools/gen_moments.py) at every
//! precision, the exact form in rationals, and the instability of the forward recursion.

mod common;

use common::tanh_sinh::{tanh_sinh, DeLimits};
use common::{read_csv, reference, rel_eps};
use moving_hertz::numerics::elliptic::ellipke_mc;
use moving_hertz::routes::moments::{
    ke_condition_bits, moments, moments_with, plan, KeForm, MomentMethod,
};
use moving_hertz::scalar::{Dd, FieldOps, Mp, Real};
use moving_hertz::Error;
use rug::{Float, Rational};
use std::collections::BTreeMap;

struct Row {
    n: usize,
    m: Float,
    l: Float,
    d: Float,
}

/// The reference table grouped by k² (kept as its decimal text, exact in binary).
fn table() -> BTreeMap<String, Vec<Row>> {
    let mut out: BTreeMap<String, Vec<Row>> = BTreeMap::new();
    for r in read_csv("moments_mpmath.csv") {
        out.entry(r[0].clone()).or_default().push(Row {
            n: r[1].parse().expect("n"),
            m: reference(&r[2]),
            l: reference(&r[3]),
            d: reference(&r[4]),
        });
    }
    out
}

/// The default at precision `p` against the references: M_n, L_n, D_n within 8 ε for every
/// k² of the table (k from 9.5e-7 to 10^6) and n ≤ 10^4.
fn default_vs_mpmath<T: Real>(p: T::Prec, label: &str) {
    let mut worst: BTreeMap<&'static str, (f64, String)> = BTreeMap::new();
    let mut sum = 0.0;
    let mut count = 0usize;
    for (mc_s, rows) in table() {
        let mc = T::parse(&mc_s, p).expect("mc");
        let n_max = rows.iter().map(|r| r.n).max().expect("rows");
        let mom = moments(&mc, n_max).expect("moments");
        for r in &rows {
            let errs = [
                rel_eps(&mom.m()[r.n], &r.m),
                rel_eps(&mom.l()[r.n], &r.l),
                rel_eps(&mom.d()[r.n], &r.d),
            ];
            for (name, e) in ["M", "L", "D"].into_iter().zip(errs) {
                sum += e;
                count += 1;
                let w = worst.entry(name).or_insert((0.0, String::new()));
                if e > w.0 {
                    *w = (
                        e,
                        format!("k2 = {mc_s}, n = {} ({})", r.n, mom.method.label()),
                    );
                }
                assert!(
                    e <= 8.0,
                    "{label}: {name}_{} at k2 = {mc_s} ({}, {} guard bits): {e:.2} eps",
                    r.n,
                    mom.method.label(),
                    mom.guard_bits
                );
            }
        }
    }
    for (name, (e, at)) in worst {
        println!("{label}: worst {name}_n error {e:.2} eps at {at}");
    }
    println!("{label}: mean error {:.2} eps", sum / count as f64);
}

#[test]
fn default_within_8_eps_of_mpmath_at_every_precision() {
    at_all_precisions!(default_vs_mpmath, [53, 128, 256]);
}

/// Quadrature of (39), (41) at 160 bits (the crate's tanh–sinh) for n ≤ 4.
fn quad_moments(mc: &Mp, n: i64) -> (Mp, Mp) {
    let p = mc.prec();
    let e2 = Mp::one(p) - mc;
    let tol = Mp::epsilon(p);
    let pts = [Mp::zero(p), Mp::pi(p).mul_pow2(-1)];
    let f = |s: f64, a: &Mp| -> Mp {
        let (sn, cs) = a.clone().sin_cos();
        let d2 = Mp::one(p) - e2.clone() * sn.square();
        let c2n = cs.square().powi(n);
        // Δ^{-1} or Δ^{-3}
        let dd = d2.clone().sqrt();
        if s == 1.0 {
            c2n / dd
        } else {
            c2n / (dd * d2)
        }
    };
    let m = tanh_sinh(|a| f(1.0, a), &pts, &tol, DeLimits::default()).expect("quad M");
    let l = tanh_sinh(|a| f(3.0, a), &pts, &tol, DeLimits::default()).expect("quad L");
    (m.value, l.value)
}

/// The starting values (42) formed exactly as printed from K and E:
/// `(L0, L1, M0, M1) = (E/k², (K − E)/e², K, (E − k²K)/e²)` (e² ≠ 0). L1 and M1 lose about
/// log₂(1/|e²|) bits to cancellation as e → 0; the crate forms them from cel instead.
fn starting_values_printed<T: Real>(mc: &T) -> (T, T, T, T) {
    let e2 = T::one(mc.prec()) - mc;
    let (k, e) = ellipke_mc(mc).expect("K, E");
    (
        e.clone() / mc,
        (k.clone() - &e) / &e2,
        k.clone(),
        (e - mc.clone() * &k) / &e2,
    )
}

/// (42): the starting values; (40) = (A.2), (A.7): the recursions, each against quadrature.
#[test]
fn recursion_and_starting_values_against_quadrature() {
    let p = common::mp(160);
    for mc_s in ["0.25", "0.75", "1.75", "0.0625", "16"] {
        let mc = Mp::parse(mc_s, p).expect("mc");
        let e2 = Mp::one(p) - &mc;
        let q: Vec<(Mp, Mp)> = (0..5).map(|n| quad_moments(&mc, n)).collect();
        let (l0, l1, m0, m1) = starting_values_printed(&mc);
        for (got, want, what) in [
            (&l0, &q[0].1, "L0 = E/k^2"),
            (&l1, &q[1].1, "L1 = (K - E)/e^2"),
            (&m0, &q[0].0, "M0 = K"),
            (&m1, &q[1].0, "M1 = (E - k^2 K)/e^2"),
        ] {
            let e = rel_eps(got, &want.to_float(400));
            assert!(e < 64.0, "k2 = {mc_s}: {what}: {e} eps");
        }
        for n in 2..5usize {
            let ni = n as i64;
            let den = e2.clone().mul_i64(2 * ni - 1);
            let c = e2.clone().mul_i64(2) - Mp::one(p);
            // (A.2)
            let mn = (c.clone().mul_i64(2 * ni - 2) * &q[n - 1].0
                + (Mp::one(p) - &e2).mul_i64(2 * ni - 3) * &q[n - 2].0)
                / &den;
            // (A.7)
            let ln = (q[n - 1].0.clone().mul_i64(4 * (ni - 1))
                + c.mul_i64(2 * (ni - 1)) * &q[n - 1].1
                - q[n - 2].0.clone().mul_i64(2 * (2 * ni - 3))
                + (Mp::one(p) - &e2).mul_i64(2 * ni - 3) * &q[n - 2].1)
                / &den;
            let (em, el) = (
                rel_eps(&mn, &q[n].0.to_float(400)),
                rel_eps(&ln, &q[n].1.to_float(400)),
            );
            assert!(
                em < 256.0 && el < 256.0,
                "k2 = {mc_s}, n = {n}: {em} {el} eps"
            );
        }
    }
}

/// The exact form in rationals: α_n K + β_n E evaluated at 512 bits equals the default at 256
/// bits; the floating generator at 256 bits reproduces the rationals.
#[test]
fn exact_form_in_rationals() {
    let p = common::mp(512);
    let p256 = common::mp(256);
    for (num, den) in [(7i64, 10i64), (1, 4), (3, 2), (1, 2)] {
        let mc_q = Rational::from((num, den));
        let mut form = KeForm::new(mc_q.clone()).expect("form");
        let mc = Mp::from_float(&Float::with_val(600, &mc_q), p);
        let (k, e) = moving_hertz::numerics::elliptic::ellipke_mc(&mc).expect("K, E");
        let mc256 = Mp::from_float(&Float::with_val(600, &mc_q), p256);
        let mom = moments(&mc256, 40).expect("moments");
        let mut fl = KeForm::new(mc256.clone()).expect("float form");
        for n in 0..=40usize {
            let t = form.next_term();
            let tf = fl.next_term();
            let to = |q: &Rational| Mp::from_float(&Float::with_val(600, q), p);
            let l = to(&t.l.0) * &k + to(&t.l.1) * &e;
            let m = to(&t.m.0) * &k + to(&t.m.1) * &e;
            let (el, em) = (
                rel_eps(&mom.l()[n], &l.to_float(600)),
                rel_eps(&mom.m()[n], &m.to_float(600)),
            );
            assert!(
                el <= 8.0 && em <= 8.0,
                "k2 = {num}/{den}, n = {n}: {el} {em}"
            );
            // The float generator's coefficients are the rationals to a few ε·n.
            let scale = Float::with_val(600, t.l.0.clone().abs() + t.l.1.clone().abs());
            let ea = common::err_eps(&tf.l.0, &Float::with_val(600, &t.l.0), &scale);
            assert!(ea <= 4.0 * (n as f64 + 4.0), "alpha_{n}: {ea}");
        }
    }
}

/// As printed, L1 = (K − E)/e² and M1 = (E − k²K)/e² lose about log₂(1/e²) bits as e → 0;
/// the cel forms keep every digit.
#[test]
fn printed_starting_values_cancel_as_e_goes_to_zero() {
    let mc = 1.0 - 2f64.powi(-30);
    let (_, l1, _, m1) = starting_values_printed(&mc);
    let mom = moments(&mc, 1).expect("moments");
    let p = common::mp(256);
    let refm = moments(&Mp::from_f64(mc, p), 1).expect("ref");
    let lost_l = rel_eps(&l1, &refm.l()[1].to_float(300));
    let lost_m = rel_eps(&m1, &refm.m()[1].to_float(300));
    println!("e^2 = 2^-30: printed L1 off by {lost_l:.3e} eps, M1 by {lost_m:.3e} eps");
    assert!(lost_l > 1e5 && lost_m > 1e5);
    assert!(rel_eps(&mom.l()[1], &refm.l()[1].to_float(300)) <= 2.0);
    assert!(rel_eps(&mom.m()[1], &refm.m()[1].to_float(300)) <= 2.0);
}

/// Forward (40) at f64 for e² = 0.3 (|r| = 7/3) loses everything within 60 steps; backward holds.
#[test]
fn forward_is_unstable_below_one_half_and_backward_is_not() {
    let mc = 0.7f64;
    let n = 60;
    let p = common::mp(256);
    let r = moments(&Mp::from_f64(mc, p), n).expect("ref");
    let fwd = moments_with(&mc, n, MomentMethod::Forward, 0).expect("fwd");
    let bwd = moments_with(&mc, n, MomentMethod::BackwardGauss, 0).expect("bwd");
    let ef = rel_eps(&fwd.m()[n], &r.m()[n].to_float(300));
    let eb = rel_eps(&bwd.m()[n], &r.m()[n].to_float(300));
    println!("e^2 = 0.3, n = {n}: forward {ef:.3e} eps, backward {eb:.2} eps");
    assert!(ef > 1e15 && eb < 64.0);
    // Predicted growth (7/3)^60 ≈ 1e22 relative: the forward value is pure noise.
}

/// The default plan: forward above e² = 1/2, Gauss-backward down to −3/4, then by cost.
#[test]
fn plan_regions() {
    assert_eq!(plan(0.25, 1000, 53).method, MomentMethod::Forward);
    assert_eq!(plan(0.75, 1000, 53).method, MomentMethod::BackwardGauss);
    assert_eq!(plan(1.0, 1000, 53).method, MomentMethod::BackwardGauss);
    assert_eq!(plan(1.5, 1000, 53).method, MomentMethod::BackwardGauss);
    assert_eq!(plan(2.0, 10000, 53).method, MomentMethod::BackwardPfaff);
    assert_eq!(plan(1e12, 10000, 53).method, MomentMethod::Forward);
}

/// The K, E condition numbers grow like |k²/e²|^n below e² = 1/2 (the one-index series are
/// checked against the table by the unit test in `src/routes/moments.rs`).
#[test]
fn condition_growth() {
    let mc = Mp::parse("0.75", common::mp(64)).expect("mc");
    let bits = ke_condition_bits(&mc, 200).expect("kappa");
    // |r| = k²/e² = 3: log₂ 3 = 1.585 bits per step.
    let slope = (bits[200].0 - bits[100].0) / 100.0;
    assert!((slope - 3f64.log2()).abs() < 0.02, "slope {slope}");
    let mc = Mp::parse("0.25", common::mp(64)).expect("mc");
    let bits = ke_condition_bits(&mc, 200).expect("kappa");
    assert!(bits.iter().all(|b| b.0 < 4.0 && b.1 < 4.0), "stable side");
}

#[test]
fn typed_errors() {
    assert!(matches!(moments(&0.0f64, 3), Err(Error::Domain { .. })));
    assert!(matches!(moments(&-1.0f64, 3), Err(Error::Domain { .. })));
    assert!(matches!(
        moments(&f64::NAN, 3),
        Err(Error::NotFinite { .. })
    ));
    assert!(matches!(
        moments(&0.5f64, 2_000_000),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        moments_with(&1.0f64, 3, MomentMethod::Forward, 0),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        moments_with(&0.25f64, 3, MomentMethod::BackwardPfaff, 0),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        moments_with(&Dd::from_f64(3.0, ()), 3, MomentMethod::BackwardGauss, 0),
        Err(Error::Domain { .. })
    ));
    // Top-value series that would run for minutes are refused at once, with an estimate.
    let t0 = std::time::Instant::now();
    match moments_with(&1e12f64, 10, MomentMethod::BackwardPfaff, 0) {
        Err(Error::TermCap {
            needed: Some(n), ..
        }) => assert!(n > 1e13 as u64, "{n}"),
        other => panic!("expected TermCap, got {other:?}"),
    }
    assert!(matches!(
        moments_with(&(2.0 - 1e-9), 0, MomentMethod::BackwardGauss, 0),
        Err(Error::TermCap { .. })
    ));
    assert!(t0.elapsed().as_secs_f64() < 2.0);
}
