//! Elliptic integrals (`numerics::elliptic`) at f64, double-double and MPFR:
//!
//! * reference values from mpmath (`tools/gen_elliptic.py`, 330 digits; 2480 digits for the
//!   8192-bit spot checks) at exactly representable inputs, relative error in units of
//!   ε = 2^(1 − bits) of each precision;
//! * Legendre's relation over a grid of m in (0, 1), including m → 0 and m → 1;
//! * K and E against tanh–sinh quadrature of their defining integrals at 512 bits;
//! * bad inputs → the right error variant;
//! * no MPFR operation mixes precisions.
//!
//! `cargo test --release --test elliptic -- --nocapture` prints the table of worst and mean
//! errors per function and precision.

use moving_hertz::numerics::elliptic::*;
use moving_hertz::scalar::{mixed_precision_events, Dd, Field, FieldOps, Mp, MpPrec, Real};
use moving_hertz::{Error, Result};
use rug::Float;
use std::collections::BTreeMap;

#[allow(dead_code)]
#[path = "common/tanh_sinh.rs"]
mod tanh_sinh;

const MAIN: &str = include_str!("data/elliptic_mpmath.csv");
const SPOT: &str = include_str!("data/elliptic_mpmath_8192.csv");

fn mp(bits: u64) -> MpPrec {
    MpPrec::new(bits).expect("valid precision")
}

fn rows(text: &str) -> Vec<Vec<&str>> {
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("function"))
        .map(|l| l.split(',').collect())
        .collect()
}

/// `s` parsed at precision `p`, asserting that the decimal input is exact there.
fn input<T: Real>(s: &str, p: T::Prec) -> T {
    let x = T::parse(s, p).expect("input parses");
    let exact = Float::with_val(4096, Float::parse(s).expect("decimal"));
    assert_eq!(
        x.to_float(4096),
        exact,
        "input {s} is not exact at {} bits",
        T::bits(p)
    );
    x
}

/// |got − ref| / |ref| in units of ε = 2^(1 − bits).
fn err_eps<T: Real>(got: &T, reference: &str) -> f64 {
    let bits = T::bits(got.prec());
    let w = 8600;
    let r = Float::with_val(w, Float::parse(reference).expect("reference parses"));
    let g = got.to_float(w);
    if r.is_zero() {
        return if g.is_zero() { 0.0 } else { f64::INFINITY };
    }
    let e = Float::with_val(w, &g - &r) / &r;
    (e.abs() << (bits as i32 - 1)).to_f64()
}

/// The function a reference row names, at parameter `a`: K, E, B, D of `m` (plain names, by
/// `mc = 1 − m` rounded once, as a caller with an exact `m` forms it) or of `mc` (`_mc`).
fn eval<T: Real>(f: &str, a: &T, phi: Option<&T>) -> Result<T> {
    let ph = || phi.expect("phi column");
    let (name, mc) = match f.strip_suffix("_mc") {
        Some(name) if name != "heuman_lambda_c" => (name, a.clone()),
        _ => (f, T::one(a.prec()) - a),
    };
    match name {
        "ellipk" => ellipke_mc(&mc).map(|(k, _)| k),
        "ellipe" => ellipke_mc(&mc).map(|(_, e)| e),
        "ellipb" => ellipbd_mc(&mc).map(|(b, _)| b),
        "ellipd" => ellipbd_mc(&mc).map(|(_, d)| d),
        "heuman_lambda_c_mc" => heuman_lambda_c_mc(ph(), a),
        _ => panic!("unknown function {f}"),
    }
}

/// Worst and mean error (in ε) per function over the reference files at precision `p`.
fn sweep<T: Real>(p: T::Prec) -> BTreeMap<String, (f64, f64, usize, String)> {
    let mut stats: BTreeMap<String, (f64, f64, usize, String)> = BTreeMap::new();
    let mut record = |name: &str, e: f64, at: String| {
        let s = stats
            .entry(name.to_string())
            .or_insert((0.0, 0.0, 0, String::new()));
        if e > s.0 {
            s.0 = e;
            s.3 = at;
        }
        s.1 += e;
        s.2 += 1;
    };
    for r in rows(MAIN) {
        let a: T = input(r[1], p);
        let phi: Option<T> = (!r[2].is_empty()).then(|| input(r[2], p));
        let got = eval(r[0], &a, phi.as_ref())
            .unwrap_or_else(|e| panic!("{}({}, {}) failed: {e}", r[0], r[1], r[2]));
        record(
            r[0],
            err_eps(&got, r[3]),
            format!("arg={} phi={}", r[1], r[2]),
        );
    }
    for s in stats.values_mut() {
        s.1 /= s.2 as f64;
    }
    stats
}

/// Asserted bound (in ε) on the worst error of every function, per backend.
fn check<T: Real>(p: T::Prec, label: &str, bound: f64) {
    let stats = sweep::<T>(p);
    println!(
        "\n{label}: worst / mean relative error in ε = 2^(1 - {})",
        T::bits(p)
    );
    for (f, (worst, mean, n, at)) in &stats {
        println!("  {f:<20} {worst:7.2} {mean:6.2}  ({n} values; worst at {at})");
    }
    for (f, (worst, _, _, at)) in &stats {
        assert!(
            *worst <= bound,
            "{label} {f}: error {worst} ε > {bound} ε at {at}"
        );
    }
}

#[test]
fn reference_f64() {
    check::<f64>((), "f64", 8.0);
}

#[test]
fn reference_dd() {
    check::<Dd>((), "double-double", 16.0);
}

#[test]
fn reference_mpfr() {
    for bits in [53, 64, 128, 256, 1024] {
        check::<Mp>(mp(bits), &format!("mpfr{bits}"), 8.0);
    }
    assert_eq!(mixed_precision_events(), 0);
}

#[test]
fn reference_mpfr_8192() {
    let p = mp(8192);
    for r in rows(SPOT) {
        let a: Mp = input(r[1], p);
        let phi: Option<Mp> = (!r[2].is_empty()).then(|| input(r[2], p));
        let got = eval(r[0], &a, phi.as_ref()).expect("8192-bit value");
        let e = err_eps(&got, r[3]);
        println!("mpfr8192 {}({}, {}): {e:.2} ε", r[0], r[1], r[2]);
        assert!(
            e <= 8.0,
            "8192 bits: {}({}, {}) error {e} ε",
            r[0],
            r[1],
            r[2]
        );
    }
    assert_eq!(mixed_precision_events(), 0);
}

/// Legendre's relation E K' + E' K − K K' = π/2 with K' = K(mc), E' = E(mc), at parameters
/// whose complement is exact. Checked in the direct form (to a few ε times the size of its
/// terms relative to π/2) and in the rearranged form E'K − m D(m) K' (m ≤ 1/2) or
/// E K' − mc D(mc) K (m > 1/2), which has no cancellation (to a few ε).
fn legendre<T: Real>(p: T::Prec, label: &str) -> f64 {
    let one = T::one(p);
    let mut grid: Vec<T> = Vec::new();
    for k in [1, 2, 3, 5, 10, 20, 30, 40, 50, 60, 100, 200, 500, 1000] {
        grid.push(one.clone().mul_pow2(-k));
        grid.push(one.clone() - one.clone().mul_pow2(-k));
    }
    for j in 1..16 {
        grid.push(T::from_ratio(j, 16, p));
    }
    let half_pi = T::pi(p).mul_pow2(-1);
    let eps = T::epsilon(p);
    let (mut worst, mut n) = (0.0f64, 0);
    for m in grid {
        let mc = one.clone() - &m;
        if one.clone() - &mc != m || !mc.is_positive() || mc >= one {
            continue; // complement not exact at this precision
        }
        let (k, e) = ellipke_mc(&mc).expect("K, E");
        let (k1, e1) = ellipke_mc(&m).expect("K', E'");
        let terms = e.clone() * &k1 + e1.clone() * &k + k.clone() * &k1;
        let direct = e.clone() * &k1 + e1.clone() * &k - k.clone() * &k1;
        let cond = (terms / &half_pi).to_f64();
        let err_direct = ((direct - &half_pi) / &half_pi / &eps).abs().to_f64() / cond;
        let half = one.clone().mul_pow2(-1);
        let rearranged = if m <= half {
            e1 * &k - m.clone() * ellipbd_mc(&mc).expect("D").1 * &k1
        } else {
            e * &k1 - mc.clone() * ellipbd_mc(&m).expect("D'").1 * &k
        };
        let err = ((rearranged - &half_pi) / &half_pi / &eps).abs().to_f64();
        assert!(
            err_direct <= 8.0,
            "{label}: Legendre (direct) at m = {}: {err_direct} ε",
            m.to_f64()
        );
        assert!(
            err <= 8.0,
            "{label}: Legendre at m = {}: {err} ε",
            m.to_f64()
        );
        worst = worst.max(err).max(err_direct);
        n += 1;
    }
    println!("{label}: Legendre relation worst {worst:.2} ε over {n} parameters");
    worst
}

#[test]
fn legendre_relation() {
    legendre::<f64>((), "f64");
    legendre::<Dd>((), "double-double");
    for bits in [128, 256, 1024, 8192] {
        legendre::<Mp>(mp(bits), &format!("mpfr{bits}"));
    }
    assert_eq!(mixed_precision_events(), 0);
}

/// MPFR at p and 2p agree to ε(p) (quasi-periodicity and mc → 0 included).
#[test]
fn precision_ladder() {
    for bits in [64u64, 200, 600] {
        let (p, q) = (mp(bits), mp(2 * bits));
        let eps = Mp::epsilon(p);
        for (phi, mc) in [("-7.5", "1e-30"), ("100.25", "0.999"), ("1.5", "0.75")] {
            let at = |p| -> [Mp; 2] {
                let (phi, mc) = (Mp::parse(phi, p).unwrap(), Mp::parse(mc, p).unwrap());
                [
                    ellipke_mc(&mc).unwrap().1,
                    heuman_lambda_c_mc(&phi, &mc).unwrap(),
                ]
            };
            for (a, b) in at(p).into_iter().zip(at(q)) {
                let d = (a.with_prec(q) - &b) / &b;
                let d = d.with_prec(p) / &eps;
                assert!(
                    d.abs().to_f64() <= 8.0,
                    "{bits} vs {}: phi={phi} mc={mc}",
                    2 * bits
                );
            }
        }
    }
    assert_eq!(mixed_precision_events(), 0);
}

fn bad_inputs<T: Real>(p: T::Prec, nan: T, inf: T) {
    let one = T::one(p);
    let two = T::from_i64(2, p);
    let zero = T::zero(p);
    let neg = -one.clone();
    let not_finite = |r: Result<T>| matches!(r, Err(Error::NotFinite { .. }));
    let dom = |r: Result<T>| matches!(r, Err(Error::Domain { .. }));
    assert!(not_finite(ellipke_mc(&nan).map(|r| r.0)));
    assert!(not_finite(ellipke_mc(&inf).map(|r| r.0)));
    assert!(not_finite(ellipbd_mc(&-inf.clone()).map(|r| r.0)));
    assert!(not_finite(ellipbd_mc(&nan).map(|r| r.1)));
    assert!(not_finite(heuman_lambda_c_mc(&nan, &one)));
    assert!(not_finite(heuman_lambda_c_mc(&one, &inf)));
    assert!(dom(ellipke_mc(&zero).map(|r| r.0)));
    assert!(dom(ellipke_mc(&neg).map(|r| r.0)));
    assert!(dom(ellipbd_mc(&zero).map(|r| r.0)));
    assert!(dom(heuman_lambda_c_mc(&one, &two)));
    assert!(dom(heuman_lambda_c_mc(&one, &neg)));
    // The limits mc = 0 and mc = 1 are values, not errors: Λ₀(φ | 1) = 2φ/π, Λ₀(φ | 0) = sin φ.
    let near = |got: T, want: T| ((got - &want) / want).abs() <= T::epsilon(p).mul_i64(8);
    let two_over_pi = two.clone() / T::pi(p);
    assert!(near(
        heuman_lambda_c_mc(&one, &zero).unwrap(),
        one.clone() - two_over_pi
    ));
    assert!(near(
        heuman_lambda_c_mc(&one, &one).unwrap(),
        one.clone() - one.clone().sin()
    ));
    // The error message names the value and the bound.
    let msg = ellipbd_mc(&neg).unwrap_err().to_string();
    assert!(msg.contains("mc = -1") && msg.contains("mc > 0"), "{msg}");
}

#[test]
fn bad_inputs_give_typed_errors() {
    bad_inputs::<f64>((), f64::NAN, f64::INFINITY);
    bad_inputs::<Dd>(
        (),
        Dd::from_f64_exact(f64::NAN),
        Dd::from_f64_exact(f64::INFINITY),
    );
    let p = mp(100);
    bad_inputs::<Mp>(p, Mp::from_f64(f64::NAN, p), Mp::from_f64(f64::INFINITY, p));
    assert_eq!(mixed_precision_events(), 0);
}

/// Every public function at 200 bits; then the process-wide count of MPFR operations mixing
/// precisions must still be zero.
#[test]
fn no_mixed_precision() {
    let p = mp(200);
    let x = |s: &str| Mp::parse(s, p).unwrap();
    let (mc, phi) = (x("1e-20"), x("-7.25"));
    ellipke_mc(&mc).unwrap();
    ellipbd_mc(&mc).unwrap();
    for mc in [x("0.25"), x("0.9"), x("1e-20"), x("0")] {
        heuman_lambda_c_mc(&phi, &mc).unwrap();
    }
    heuman_lambda_c_mc(&x("1e100"), &x("0.3")).unwrap();
    heuman_lambda_c_mc(&x("1.5"), &x("0.3")).unwrap();
    assert_eq!(mixed_precision_events(), 0);
}

/// Extreme arguments: a finite value or a typed error, never a panic, NaN or ∞; the values that
/// have a simple asymptotic form are checked against it.
#[test]
fn extreme_arguments() {
    let ok = |r: Result<f64>, what: &str| match r {
        Ok(v) => assert!(v.is_finite(), "{what}: {v}"),
        Err(e) => println!("{what}: {e}"),
    };
    for mc in [1e-300, 1e-100, 1e100, 1e300] {
        ok(ellipke_mc(&mc).map(|r| r.0), &format!("K(mc={mc:e})"));
        ok(ellipke_mc(&mc).map(|r| r.1), &format!("E(mc={mc:e})"));
        ok(ellipbd_mc(&mc).map(|r| r.0), &format!("B(mc={mc:e})"));
        ok(ellipbd_mc(&mc).map(|r| r.1), &format!("D(mc={mc:e})"));
    }
    for mc in [0.0, 1e-300, 1e-100, 0.5, 1.0] {
        for phi in [1e-300, 0.5, std::f64::consts::FRAC_PI_2, 3.0, 1e10, 1e300] {
            ok(
                heuman_lambda_c_mc(&phi, &mc),
                &format!("1 - L0({phi:e}|mc={mc:e})"),
            );
        }
    }
    // K(mc) ~ ln(4/√mc) as mc → 0.
    let k = ellipke_mc(&1e-300f64).unwrap().0;
    assert!((k - (4.0f64.ln() + 150.0 * 10f64.ln())).abs() < 1e-13 * k);
    // MPFR far outside the f64 exponent range.
    let p = mp(128);
    let tiny = Mp::parse("1e-1000000", p).unwrap();
    let k = ellipke_mc(&tiny).unwrap().0;
    let expect = (Mp::from_i64(4, p) / tiny.clone().sqrt()).ln();
    assert!(((k - &expect) / &expect).abs().to_f64() < 1e-30);
    // 1 − Λ₀(φ | m) = 1 − (2/π) E(m) φ + O(φ³): R_F and R_D duplicate from a ratio 10⁻²⁰⁰⁰⁰⁰⁰.
    let half = Mp::one(p).mul_pow2(-1);
    let got = heuman_lambda_c_mc(&tiny, &half).unwrap();
    let e = ellipke_mc(&half).unwrap().1;
    let expect = Mp::one(p) - e.mul_pow2(1) * &tiny / Mp::pi(p);
    assert!(((got - &expect) / &expect).abs().to_f64() < 1e-30);
    assert_eq!(mixed_precision_events(), 0);
}

/// K and E at 512 bits against tanh–sinh quadrature (`tests/common/tanh_sinh.rs`) of their
/// defining integrals ∫₀^{π/2} (1 − m sin²θ)^(∓1/2) dθ, with 1 − m sin²θ formed as
/// cos²θ + mc·sin²θ and cos θ = sin(π/2 − θ) taken from the distance to the end π/2 (so m → 1
/// keeps its digits).
#[test]
fn agreement_with_quadrature_at_512_bits() {
    use crate::tanh_sinh::{tanh_sinh_gaps, DeLimits};
    let p = mp(512);
    let one = Mp::one(p);
    let half_pi = Mp::pi(p).mul_pow2(-1);
    for m_text in ["0.5", "-3.25", "0.999", "0.9999999999"] {
        let m = Mp::parse(m_text, p).unwrap();
        let mc = one.clone() - &m;
        let delta = |theta: &Mp, to_end: &Mp| -> Mp {
            to_end.clone().sin().square() + mc.clone() * theta.clone().sin().square()
        };
        let quad = |power: i64| {
            tanh_sinh_gaps(
                |t: &Mp, _: &Mp, b: &Mp| {
                    let r = delta(t, b).sqrt();
                    if power < 0 {
                        r.recip()
                    } else {
                        r
                    }
                },
                &[Mp::zero(p), half_pi.clone()],
                &Mp::zero(p),
                DeLimits::default(),
            )
            .unwrap()
        };
        let (k, e) = ellipke_mc(&mc).unwrap();
        for (name, got, q) in [("K", &k, quad(-1)), ("E", &e, quad(1))] {
            let err = ((got.clone() - &q.value) / &q.value).abs() / Mp::epsilon(p);
            let bound = 8.0 + (q.error.clone() / q.value.clone().abs() / Mp::epsilon(p)).to_f64();
            assert!(
                err.to_f64() <= bound,
                "m = {m_text}: {name} off by {} eps",
                err.to_f64()
            );
        }
    }
}
