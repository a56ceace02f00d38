//! Root finding at f64, double-double and MPFR 128/256/1024 bits: Brent on polynomials and
//! transcendental equations, Newton and Halley polishing from f64 seeds, and the typed errors.
//! Errors are in units of the working ε against references computed 64 bits beyond it.

mod common;

use moving_hertz::numerics::roots::{brent, halley, newton};
use moving_hertz::scalar::{FieldOps, Mp, MpPrec, Real};
use moving_hertz::Error;

/// Relative error of `got` in ε of its type, against a reference `want` at higher precision.
fn err_vs<T: Real>(got: &T, want: &Mp) -> f64 {
    let bits = want.0.prec();
    let d = rug::Float::with_val(bits, &got.to_float(bits) - &want.0);
    let e = T::epsilon(got.prec()).to_float(bits);
    (d / &want.0 / e).to_f64().abs()
}

fn hp<T: Real>(p: T::Prec) -> MpPrec {
    MpPrec::new(T::bits(p) as u64 + 64).expect("precision")
}

/// The test equations: (name, f, bracket, reference root at high precision).
fn roots_case<T: Real>(p: T::Prec, label: &str) {
    let q = hp::<T>(p);
    let tol = T::zero(p); // as accurate as the precision allows
    let mut worst = 0f64;
    let mut report = |name: &str, got: &T, want: &Mp, its: usize| {
        let e = err_vs(got, want);
        println!("{label:>8} {name:<28} err {e:6.3} eps  iterations {its}");
        assert!(e <= 4.0, "{label} {name}: {e} eps");
        worst = worst.max(e);
    };

    // x³ − 2 = 0 on [1, 2]: 2^(1/3).
    let r = brent(
        |x: &T| x.powi(3) - &T::from_i64(2, p),
        &T::one(p),
        &T::from_i64(2, p),
        &tol,
        200,
    )
    .expect("cbrt 2");
    report(
        "brent x^3 = 2",
        &r.root,
        &Mp::from_i64(2, q).cbrt(),
        r.iterations,
    );
    // Brent ends on a narrow bracket, or on an exact zero of the computed f.
    assert!(r.residual.is_zero() || r.bracket_width <= T::epsilon(p).mul_i64(8) * &r.root);

    // x⁵ − x − 1 (the Bring radical's classic): reference by Newton at high precision.
    let quintic = |x: &Mp| {
        (
            x.powi(5) - x - &Mp::one(x.prec()),
            x.powi(4).mul_i64(5) - &Mp::one(x.prec()),
        )
    };
    let want = newton(
        quintic,
        &Mp::from_f64(1.1673039782614187, q),
        &Mp::zero(q),
        50,
    )
    .expect("ref")
    .root;
    let r = brent(
        |x: &T| x.powi(5) - x - &T::one(p),
        &T::one(p),
        &T::from_i64(2, p),
        &tol,
        200,
    )
    .expect("quintic");
    report("brent x^5 - x - 1", &r.root, &want, r.iterations);

    // cos x = x (the Dottie number), bracket [0, 1]; reference by Halley at high precision.
    let dottie = |x: &Mp| {
        let (s, c) = x.clone().sin_cos();
        (c.clone() - x, -s - &Mp::one(x.prec()), -c)
    };
    let want = halley(
        dottie,
        &Mp::from_f64(0.739085133215161, q),
        &Mp::zero(q),
        50,
    )
    .expect("ref")
    .root;
    let r = brent(
        |x: &T| x.clone().cos() - x,
        &T::zero(p),
        &T::one(p),
        &tol,
        200,
    )
    .expect("dottie");
    report("brent cos x = x", &r.root, &want, r.iterations);

    // ln x = 1 on [1, 10] (bracket given in decreasing order): e.
    let r = brent(
        |x: &T| x.clone().ln() - &T::one(p),
        &T::from_i64(10, p),
        &T::one(p),
        &tol,
        200,
    )
    .expect("e");
    report("brent ln x = 1", &r.root, &Mp::one(q).exp(), r.iterations);

    // Newton from an f64 seed: x² = 2.
    let seed = T::from_f64(std::f64::consts::SQRT_2, p);
    let r = newton(
        |x: &T| (x.square() - &T::from_i64(2, p), x.clone().mul_i64(2)),
        &seed,
        &tol,
        60,
    )
    .expect("newton sqrt 2");
    report(
        "newton x^2 = 2",
        &r.root,
        &Mp::from_i64(2, q).sqrt(),
        r.iterations,
    );

    // Halley from an f64 seed: x eˣ = 1 (the omega constant), reference by Newton.
    let omega_mp = |x: &Mp| {
        let e = x.clone().exp();
        (
            x.clone() * &e - &Mp::one(x.prec()),
            (x.clone() + &Mp::one(x.prec())) * &e,
        )
    };
    let want = newton(
        omega_mp,
        &Mp::from_f64(0.5671432904097838, q),
        &Mp::zero(q),
        60,
    )
    .expect("ref")
    .root;
    let omega = |x: &T| {
        let e = x.clone().exp();
        let one = T::one(p);
        (
            x.clone() * &e - &one,
            (x.clone() + &one) * &e,
            (x.clone() + &T::from_i64(2, p)) * &e,
        )
    };
    let seed = T::from_f64(0.5671432904097838, p);
    let r = halley(omega, &seed, &tol, 60).expect("halley omega");
    report("halley x e^x = 1", &r.root, &want, r.iterations);
    // Newton and Halley from a poor start still converge (steps shrink from the first).
    let r = halley(omega, &T::one(p), &tol, 60).expect("halley omega from 1");
    report("halley x e^x = 1 from 1", &r.root, &want, r.iterations);
    let r = newton(
        |x: &T| {
            let (v, d, _) = omega(x);
            (v, d)
        },
        &T::one(p),
        &tol,
        60,
    )
    .expect("newton omega from 1");
    report("newton x e^x = 1 from 1", &r.root, &want, r.iterations);

    println!("{label:>8} roots: worst {worst:.3} eps");
}

#[test]
fn roots_at_every_precision() {
    at_all_precisions!(roots_case);
}

#[test]
fn brent_handles_exact_hits_and_double_roots() {
    // f(a) = 0: returned at once.
    let r = brent(|x: &f64| x - 1.0, &1.0, &2.0, &0.0, 50).expect("exact");
    assert_eq!((r.root, r.iterations), (1.0, 0));
    // An odd-multiplicity root (x − 1)³ still brackets; the residual is tiny.
    let r = brent(|x: &f64| (x - 1.0).powi(3), &0.0, &3.0, &0.0, 400).expect("triple");
    assert!((r.root - 1.0).abs() < 1e-5, "{}", r.root);
    // A root at zero converges (the tolerance is relative, so the bracket shrinks to the root).
    let r = brent(|x: &f64| x.sin(), &-1.0, &2.0, &0.0, 400).expect("zero");
    assert!(r.root.abs() < 1e-300 || r.residual == 0.0, "{}", r.root);
}

#[test]
fn typed_errors_no_panics() {
    // No sign change.
    assert!(matches!(
        brent(|x: &f64| x * x + 1.0, &-1.0, &1.0, &0.0, 50),
        Err(Error::Domain { .. })
    ));
    // NaN from f, NaN bracket, negative tolerance.
    assert!(matches!(
        brent(|x: &f64| x.ln(), &-1.0, &2.0, &0.0, 50),
        Err(Error::NotFinite { .. })
    ));
    assert!(matches!(
        brent(|x: &f64| *x, &f64::NAN, &2.0, &0.0, 50),
        Err(Error::NotFinite { .. })
    ));
    assert!(matches!(
        brent(|x: &f64| *x, &-1.0, &2.0, &-1.0, 50),
        Err(Error::Domain { .. })
    ));
    // Iteration cap.
    assert!(matches!(
        brent(|x: &f64| x.powi(5) - x - 1.0, &1.0, &2.0, &0.0, 2),
        Err(Error::NoConvergence { .. })
    ));
    // Newton: zero derivative, divergence (x^(1/3) overshoots), cap, NaN.
    assert!(matches!(
        newton(|x: &f64| (x * x + 1.0, 0.0), &1.0, &0.0, 50),
        Err(Error::NotFinite { .. })
    ));
    let cube_root = |x: &f64| (x.cbrt(), 1.0 / (3.0 * x.cbrt() * x.cbrt()));
    assert!(matches!(
        newton(cube_root, &1.0, &0.0, 50),
        Err(Error::NoConvergence { .. })
    ));
    assert!(matches!(
        newton(|x: &f64| (x * x - 2.0, 2.0 * x), &100.0, &0.0, 3),
        Err(Error::NoConvergence { .. })
    ));
    assert!(matches!(
        newton(|x: &f64| (x.ln(), 1.0 / x), &-1.0, &0.0, 50),
        Err(Error::NotFinite { .. })
    ));
    // x² + 1 has no real root: Newton wanders and fails, never panics.
    assert!(newton(|x: &f64| (x * x + 1.0, 2.0 * x), &0.5, &0.0, 100).is_err());
    assert!(halley(|x: &f64| (x * x + 1.0, 2.0 * x, 2.0), &0.5, &0.0, 100).is_err());
    // The same at MPFR, and no precision was mixed anywhere in this binary's MPFR work.
    let p = MpPrec::new(256).expect("precision");
    let one = Mp::one(p);
    assert!(matches!(
        brent(
            |x: &Mp| x.square() + &one,
            &-one.clone(),
            &one,
            &Mp::zero(p),
            50
        ),
        Err(Error::Domain { .. })
    ));
    common::assert_no_mixing();
}
