//! Quadrature at f64, double-double and MPFR 128/256/1024 bits: Gauss–Legendre rules, the
//! adaptive Gauss–Legendre driver and the tanh–sinh reference of `common/tanh_sinh.rs`. Errors are asserted in units of the working ε,
//! and every error estimate must bound the true error. Run with `--nocapture` to see the
//! measured worst errors.

mod common;

use common::rel_err_eps as err_eps;
use common::tanh_sinh::{tanh_sinh, tanh_sinh_gaps, DeLimits};
use moving_hertz::numerics::quadrature::{integrate, GaussLegendre, Limits, Quadrature};
use moving_hertz::scalar::{Dd, FieldOps, Mp, MpPrec, Real};
use moving_hertz::Error;

/// Bound on relative errors, in ε.
const MAX_EPS: f64 = 16.0;

/// The precision of the references: 64 bits beyond the working precision.
fn ref_prec<T: Real>(p: T::Prec) -> MpPrec {
    MpPrec::new(T::bits(p) as u64 + 64).expect("precision")
}

/// Checks value and estimate of a quadrature result against a reference computed 64 bits
/// beyond the working precision (so the reference's own rounding does not count); returns the
/// relative error in ε.
fn check<T: Real>(q: &Quadrature<T>, want: &Mp, what: &str, label: &str) -> f64 {
    let bits = want.0.prec();
    let p = q.value.prec();
    let diff = rug::Float::with_val(bits, &q.value.to_float(bits) - &want.0).abs();
    let eps = T::epsilon(p).to_float(bits);
    let e = rug::Float::with_val(bits, &diff / &want.0).abs() / &eps;
    let e = e.to_f64();
    let est = rug::Float::with_val(bits, q.error.to_float(bits) / &want.0).abs();
    println!(
        "{label:>8} {what:<34} err {e:7.3} eps  estimate {:7.3} eps  evals {}",
        (est / &eps).to_f64(),
        q.evaluations
    );
    assert!(e <= MAX_EPS, "{label} {what}: error {e} eps");
    assert!(
        diff <= q.error.to_float(bits),
        "{label} {what}: estimate below true error"
    );
    e
}

/// K(m) = π / (2 AGM(1, √(1−m))), the AGM iterated until the gap stops shrinking.
fn agm_k<T: Real>(m: &T) -> T {
    let p = m.prec();
    let mut a = T::one(p);
    let mut b = (T::one(p) - m).sqrt();
    let mut gap = T::one(p);
    for _ in 0..200 {
        let an = (a.clone() + &b).mul_pow2(-1);
        b = (a * &b).sqrt();
        a = an;
        let g = (a.clone() - &b).abs();
        if g.is_zero() || g >= gap {
            break;
        }
        gap = g;
    }
    T::pi(p) / &a.mul_pow2(1)
}

fn gauss_polynomials<T: Real>(p: T::Prec, label: &str) {
    let (mut worst_sum, mut worst_poly) = (0f64, 0f64);
    for n in [1usize, 2, 3, 5, 8, 13, 20, 33, 64] {
        let rule = GaussLegendre::<T>::get(n, p).expect("rule");
        // Weights of the full rule sum to 2; summed exactly in MPFR, each weight's rounding
        // (≤ ε/2 relative) leaves at most ε/2 on the sum.
        let mut s = rug::Float::with_val(4000, 0);
        for (x, w) in rule.nodes().iter().zip(rule.weights()) {
            let w = w.to_float(4000);
            s += if x.is_zero() { w } else { w * 2u32 };
        }
        s -= 2u32;
        worst_sum = worst_sum.max(s.to_f64().abs() / 2.0 / T::epsilon(p).to_f64());
        // ∫_{−1}^{1} x^(2n−2) = 2/(2n−1) and ∫_0^1 x^(2n−1) = 1/(2n), exact for the rule up to
        // rounding: the nodes' rounding (ε/2 relative) is amplified by the degree k.
        let k = 2 * n as i64 - 2;
        let allow = (k + 4) as f64;
        let v = rule.integrate(|x: &T| x.powi(k), &T::from_i64(-1, p), &T::one(p));
        worst_poly = worst_poly.max(err_eps(&v, &T::from_ratio(2, k + 1, p)) / allow);
        let v = rule.integrate(|x: &T| x.powi(k + 1), &T::zero(p), &T::one(p));
        worst_poly = worst_poly.max(err_eps(&v, &T::from_ratio(1, k + 2, p)) / allow);
        // A cubic with all coefficients nonzero, positive over an asymmetric interval.
        if n >= 2 {
            let f = |x: &T| {
                ((x.clone().mul_i64(3) - &T::one(p)) * x + &T::from_i64(2, p)) * x
                    + &T::from_i64(5, p)
            };
            let v = rule.integrate(f, &T::from_ratio(-1, 3, p), &T::from_i64(2, p));
            // ∫ (3x³ − x² + 2x + 5) dx over [−1/3, 2] = 70/3 + 497/324 = 8057/324.
            let want = T::from_ratio(8057, 324, p);
            worst_poly = worst_poly.max(err_eps(&v, &want) / 4.0);
        }
    }
    println!(
        "{label:>8} Gauss-Legendre: weight sum {worst_sum:.3} eps, monomials {worst_poly:.3} x (k+4) eps"
    );
    assert!(
        worst_sum <= 1.0,
        "{label}: weight sum off by {worst_sum} eps"
    );
    assert!(
        worst_poly <= 1.0,
        "{label}: monomial off by {worst_poly} x (k+4) eps"
    );
}

#[test]
fn gauss_legendre_exact_for_polynomials() {
    at_all_precisions!(gauss_polynomials);
}

/// Largest relative error, in ε of `T`, of the rule's nodes and weights against a reference
/// rule at `ref_bits`.
fn rule_vs_reference<T: Real>(n: usize, p: T::Prec, ref_bits: u64) -> (f64, f64) {
    let rule = GaussLegendre::<T>::get(n, p).expect("rule");
    let q = MpPrec::new(ref_bits).expect("precision");
    let reference = GaussLegendre::<Mp>::get(n, q).expect("reference");
    let eps = T::epsilon(p).to_f64();
    let rel = |a: &T, b: &Mp| {
        let a = a.to_float(ref_bits as u32);
        let d = rug::Float::with_val(ref_bits as u32, &a - &b.0);
        if b.0.is_zero() {
            d.to_f64().abs() / eps
        } else {
            (d / &b.0).to_f64().abs() / eps
        }
    };
    let (mut ex, mut ew) = (0f64, 0f64);
    for i in 0..rule.nodes().len() {
        ex = ex.max(rel(&rule.nodes()[i], &reference.nodes()[i]));
        ew = ew.max(rel(&rule.weights()[i], &reference.weights()[i]));
    }
    (ex, ew)
}

#[test]
fn gauss_legendre_nodes_and_weights_correctly_rounded() {
    // Built at guard precision and rounded once: every node and weight within half an ulp
    // (ε/2 relative) of a rule computed at much higher precision, for n up to the cap.
    for n in [2usize, 7, 64, 100, 1000, 4096] {
        let (x, w) = rule_vs_reference::<f64>(n, (), 120);
        println!("     f64 n = {n:4}: nodes {x:.4} eps, weights {w:.4} eps");
        assert!(x <= 0.5001 && w <= 0.5001, "f64 n = {n}: {x} {w}");
    }
    for n in [2usize, 7, 64, 500] {
        let (x, w) = rule_vs_reference::<Dd>(n, (), 300);
        println!("      dd n = {n:4}: nodes {x:.4} eps, weights {w:.4} eps");
        assert!(x <= 0.51 && w <= 0.51, "dd n = {n}: {x} {w}");
        let (x, w) = rule_vs_reference::<Mp>(n, MpPrec::new(256).expect("precision"), 400);
        println!("   mp256 n = {n:4}: nodes {x:.4} eps, weights {w:.4} eps");
        assert!(x <= 0.5001 && w <= 0.5001, "mp256 n = {n}: {x} {w}");
    }
    common::assert_no_mixing();
}

#[test]
fn gauss_legendre_rejects_bad_n_and_caches() {
    assert!(matches!(
        GaussLegendre::<f64>::get(0, ()),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        GaussLegendre::<f64>::get(4097, ()),
        Err(Error::Domain { .. })
    ));
    let p = MpPrec::new(200).expect("precision");
    let a = GaussLegendre::<Mp>::get(17, p).expect("rule");
    let b = GaussLegendre::<Mp>::get(17, p).expect("rule");
    assert!(std::sync::Arc::ptr_eq(&a, &b));
    let c = GaussLegendre::<Mp>::get(17, MpPrec::new(201).expect("precision")).expect("rule");
    assert_eq!(Mp::bits(c.prec()), 201);
    assert_eq!(c.nodes()[0].prec(), MpPrec::new(201).expect("precision"));
    common::assert_no_mixing();
}

/// The test integrals for one precision, both drivers.
fn integrals<T: Real>(p: T::Prec, label: &str) {
    let eps = T::epsilon(p);
    let bits = T::bits(p);
    let zero = T::zero(p);
    let one = T::one(p);
    let lim = Limits::default();
    let de = DeLimits::default();
    let hp = ref_prec::<T>(p);
    let mut worst = 0f64;

    // ∫_0^1 ln x = −1 and ∫_0^1 √x = 2/3: endpoint singularities, tanh–sinh.
    let (ln_ref, sqrt_ref) = (Mp::from_i64(-1, hp), Mp::from_ratio(2, 3, hp));
    let ends = [zero.clone(), one.clone()];
    let q = tanh_sinh(|x: &T| x.clone().ln(), &ends, &eps, de).expect("log");
    worst = worst.max(check(&q, &ln_ref, "tanh-sinh  int_0^1 ln x", label));
    let q = tanh_sinh(|x: &T| x.clone().sqrt(), &ends, &eps, de).expect("sqrt");
    worst = worst.max(check(&q, &sqrt_ref, "tanh-sinh  int_0^1 sqrt x", label));
    // ∫_1^2 ln(x − 1)/√(2 − x) dx = ∫_0^1 ln u/√(1−u) du = 4 ln 2 − 4, through the gaps.
    let q = tanh_sinh_gaps(
        |_: &T, da: &T, db: &T| da.clone().ln() / &db.clone().sqrt(),
        &[one.clone(), T::from_i64(2, p)],
        &eps,
        de,
    )
    .expect("gaps");
    let want = Mp::ln2(hp).mul_i64(4) - &Mp::from_i64(4, hp);
    worst = worst.max(check(&q, &want, "tanh-sinh  ln(x-1)/sqrt(2-x) gaps", label));

    // Adaptive Gauss–Legendre copes with ln x by geometric refinement (≈ bits levels).
    if bits <= 256 {
        let q = integrate(|x: &T| x.clone().ln(), &ends, &eps, lim).expect("GL log");
        worst = worst.max(check(&q, &ln_ref, "adaptive GL int_0^1 ln x", label));
        let q = integrate(|x: &T| x.clone().sqrt(), &ends, &eps, lim).expect("GL sqrt");
        worst = worst.max(check(&q, &sqrt_ref, "adaptive GL int_0^1 sqrt x", label));
    }

    // K(m) = ∫_0^{π/2} dθ / √(1 − m sin²θ) against the AGM, m = 1/2 and 99/100; the radicand
    // is written (1 − m) + m cos²θ, free of cancellation near π/2.
    for (num, den) in [(1i64, 2i64), (99, 100)] {
        let m = T::from_ratio(num, den, p);
        let m1 = T::from_ratio(den - num, den, p);
        let f = |t: &T| {
            (m1.clone() + &(m.clone() * &t.clone().cos().square()))
                .sqrt()
                .recip()
        };
        let ends = [zero.clone(), T::pi(p).mul_pow2(-1)];
        let want = agm_k(&Mp::from_ratio(num, den, hp));
        let q = integrate(f, &ends, &eps, lim).expect("GL K");
        worst = worst.max(check(
            &q,
            &want,
            &format!("adaptive GL K(m = {num}/{den})"),
            label,
        ));
        let q = tanh_sinh(f, &ends, &eps, de).expect("DE K");
        worst = worst.max(check(
            &q,
            &want,
            &format!("tanh-sinh  K(m = {num}/{den})"),
            label,
        ));
    }

    // A peak: ∫_{−1}^{1} dx / (e² + x²) = 2 atan(1/e)/e, e = 2^-10, breakpoint at the peak.
    let e2 = T::one(p).mul_pow2(-20);
    let f = |x: &T| (e2.clone() + &x.square()).recip();
    let pts = [-one.clone(), zero.clone(), one.clone()];
    let e_hp = Mp::one(hp).mul_pow2(-10);
    let want = e_hp.clone().recip().atan().mul_pow2(1) / &e_hp;
    let q = integrate(f, &pts, &eps, lim).expect("GL peak");
    worst = worst.max(check(&q, &want, "adaptive GL peak 1/(e^2+x^2)", label));
    let q = tanh_sinh(f, &pts, &eps, de).expect("DE peak");
    worst = worst.max(check(&q, &want, "tanh-sinh  peak 1/(e^2+x^2)", label));
    // Reversed breakpoints negate the integral.
    let rev = [one.clone(), zero.clone(), -one.clone()];
    let q = integrate(f, &rev, &eps, lim).expect("GL peak reversed");
    worst = worst.max(check(
        &q,
        &-want.clone(),
        "adaptive GL peak, reversed",
        label,
    ));

    // An odd integrand integrates to zero: the absolute rounding floor stops both drivers.
    let sym = [-one.clone(), one.clone()];
    let q = integrate(|x: &T| x.clone().sin(), &sym, &eps, lim).expect("odd GL");
    assert!(
        q.value.clone().abs() <= q.error.clone().max_of(eps.clone()),
        "{label} odd GL"
    );
    let q = tanh_sinh(|x: &T| x.clone().sin(), &sym, &eps, de).expect("odd DE");
    assert!(
        q.value.clone().abs() <= q.error.clone().max_of(eps.clone()),
        "{label} odd DE"
    );

    println!("{label:>8} integrals: worst {worst:.3} eps");
}

#[test]
fn integrals_at_every_precision() {
    at_all_precisions!(integrals);
}

#[test]
fn typed_errors_and_no_panics() {
    let lim = Limits::default();
    let de = DeLimits::default();
    let tol = f64::EPSILON;
    // Breakpoints and tolerance.
    assert!(matches!(
        integrate(|x: &f64| *x, &[0.0], &tol, lim),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        integrate(|x: &f64| *x, &[0.0, 2.0, 1.0], &tol, lim),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        tanh_sinh(|x: &f64| *x, &[0.0, 0.0], &tol, de),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        integrate(|x: &f64| *x, &[0.0, 1.0], &-1.0, lim),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        integrate(|x: &f64| *x, &[0.0, f64::NAN], &tol, lim),
        Err(Error::NotFinite { .. })
    ));
    // Integrand values.
    assert!(matches!(
        integrate(|_: &f64| f64::NAN, &[0.0, 1.0], &tol, lim),
        Err(Error::NotFinite { .. })
    ));
    assert!(tanh_sinh(|x: &f64| 1.0 / (x - 0.5), &[0.0, 1.0], &tol, de).is_err());
    // A non-integrable singularity exhausts the work bound.
    let small = Limits {
        max_evals: 20_000,
        ..lim
    };
    let de_small = DeLimits {
        max_evals: 20_000,
        ..de
    };
    assert!(matches!(
        integrate(|x: &f64| 1.0 / x, &[0.0, 1.0], &tol, small),
        Err(Error::NoConvergence { .. })
    ));
    assert!(matches!(
        tanh_sinh(|x: &f64| 1.0 / x, &[0.0, 1.0], &tol, de_small),
        Err(Error::NoConvergence { .. })
    ));
    // A discontinuity inside a panel converges only algebraically: cap on levels.
    let few = DeLimits {
        max_levels: 6,
        ..de
    };
    let step = |x: &f64| if *x < 1.0 / 3.0 { 0.0 } else { 1.0 };
    assert!(matches!(
        tanh_sinh(step, &[0.0, 1.0], &tol, few),
        Err(Error::NoConvergence { .. })
    ));
    // A sharp peak away from every breakpoint: either a typed error or a result whose estimate
    // bounds its error, never a silently wrong value.
    let e2 = 2f64.powi(-30);
    let peak = |x: &f64| 1.0 / (e2 + (x - 1.0 / 3.0).powi(2));
    let exact = ((2.0f64 / 3.0) / e2.sqrt()).atan() / e2.sqrt()
        + ((1.0f64 / 3.0) / e2.sqrt()).atan() / e2.sqrt();
    for r in [
        tanh_sinh(peak, &[0.0, 1.0], &tol, de),
        integrate(peak, &[0.0, 1.0], &tol, lim),
    ] {
        match r {
            Ok(q) => assert!(
                (q.value - exact).abs() <= q.error + 4.0 * f64::EPSILON * exact,
                "{q:?}"
            ),
            Err(e) => assert!(matches!(e, Error::NoConvergence { .. }), "{e}"),
        }
    }
    // ... and succeeds with the jump as a breakpoint.
    let q = integrate(step, &[0.0, 1.0 / 3.0, 1.0], &tol, lim).expect("step");
    assert!((q.value - 2.0 / 3.0).abs() <= 4.0 * f64::EPSILON);
    let _ = Dd::from_f64(0.0, ());
}
