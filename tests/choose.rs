//! The automatic choice of precision: a loose request runs in f64, a tight one at the lowest
//! sufficient precision, and the returned error estimate bounds the true error, measured
//! against a computation 64 bits above the one used, from the same exact inputs.

use moving_hertz::prelude::*;
use moving_hertz::routes::choose::choose_precision;
use moving_hertz::{integrals, integrals_to_tolerance, ExactInputs, Route};
use rug::Float;

fn tol(text: &str) -> RelError {
    RelError::parse(text).unwrap()
}

#[test]
fn precision_follows_the_request() {
    assert_eq!(choose_precision(tol("1e-6")).unwrap(), Precision::F64);
    assert_eq!(choose_precision(tol("1e-12")).unwrap(), Precision::F64);
    assert_eq!(
        choose_precision(tol("1e-20")).unwrap(),
        Precision::DoubleDouble
    );
    match choose_precision(tol("1e-60")).unwrap() {
        Precision::Mpfr(p) => assert!((200..=256).contains(&p.bits()), "{}", p.bits()),
        other => panic!("1e-60 answered at {other}"),
    }
    // Tolerances far below the f64 range: bits from the exponent, no overflow.
    let cases = [
        ("1e-300", 990, 1010),
        ("1e-5000", 16600, 16630),
        ("1e-10000", 33220, 33250),
    ];
    for (t, lo, hi) in cases {
        match choose_precision(tol(t)).unwrap() {
            Precision::Mpfr(p) => assert!((lo..=hi).contains(&p.bits()), "{t}: {}", p.bits()),
            other => panic!("{t} answered at {other}"),
        }
    }
    // Near the Rayleigh speed the gap 1 − M_R is formed exactly from the text: 1e-12 is met
    // at f64, as far from it.
    let i = ExactInputs::parse("0.2", "0.5", "0.5").unwrap();
    let fast = ExactInputs::parse("0.2", "0.99999999", "0.01").unwrap();
    for inputs in [&i, &fast] {
        let a = integrals_to_tolerance(inputs, tol("1e-12"), Method::Auto).unwrap();
        assert_eq!(a.precision, Precision::F64);
    }
    let a = integrals_to_tolerance(&i, tol("1e-60"), Method::Auto).unwrap();
    assert!(matches!(a.precision, Precision::Mpfr(p) if p.bits() <= 256));
    // The precision is not oversized: the estimate lies within 10³ of the tolerance.
    assert!(a.i1.error.scale(1000.0) >= tol("1e-60"), "{}", a.i1.error);
}

/// The reference: the adaptive quadrature 64 bits above the precision `a` ran at.
fn check_against_reference(inputs: &ExactInputs, a: &moving_hertz::Integrals<Mp>, what: &str) {
    let bits = a.precision.bits() as u64 + 64;
    let p = MpPrec::new(bits).unwrap();
    let (sp, k) = inputs.at::<Mp>(p).unwrap();
    let opts = IntegralOptions {
        method: Method::Adaptive,
        ..Default::default()
    };
    let r = integrals(&sp, &k, &opts).unwrap();
    for (got, want) in [(&a.i1, &r.i1.value), (&a.i2, &r.i2.value)] {
        let want = want.as_float();
        let err = Float::with_val(bits as u32, got.value.as_float() - want) / want;
        let err = RelError::of(&Mp::from_float(&err.abs(), p));
        assert!(
            err <= got.error,
            "{what}: true error {err} > estimate {} ({} at {})",
            got.error,
            a.route,
            a.precision
        );
    }
}

#[test]
fn error_estimate_bounds_the_true_error() {
    let grid = [
        ("0.2", "0", "0.5"),
        ("0.2", "0.5", "0.5"),
        ("0.45", "0.9", "0.1"),
        ("-0.6", "0.99", "0.02"),
        ("0.3", "0.999999", "0.001"),
        ("0", "0.7", "3"),
        ("0.25", "0.25", "1000"),
        ("0.5", "0.9999999999", "0.003"),
    ];
    let mut checked = 0;
    for (nu, mr, k) in grid {
        let inputs = ExactInputs::parse(nu, mr, k).unwrap();
        for t in ["1e-6", "1e-13", "1e-25", "1e-45"] {
            let a = integrals_to_tolerance(&inputs, tol(t), Method::Auto).unwrap();
            assert!(a.i1.error <= tol(t) && a.i2.error <= tol(t));
            check_against_reference(&inputs, &a, &format!("nu={nu} M_R={mr} k={k} tol={t}"));
            checked += 1;
        }
    }
    assert_eq!(checked, 32);
}

/// Tolerances far below the f64 range succeed, meet the tolerance and are not oversized.
#[test]
fn tolerances_below_the_f64_range() {
    let inputs = ExactInputs::parse("0.25", "0.9990234375", "0.5").unwrap();
    for t in ["1e-300", "1e-1000"] {
        let a = integrals_to_tolerance(&inputs, tol(t), Method::Auto).unwrap();
        assert!(
            a.i1.error <= tol(t) && a.i2.error <= tol(t),
            "{t}: {}",
            a.i1.error
        );
        assert_eq!(a.route, Route::FixedRule);
        // The lowest sufficient precision: the estimate lies within 10³ of the tolerance.
        assert!(a.i1.error.scale(1000.0) >= tol(t), "{t}: {}", a.i1.error);
        check_against_reference(&inputs, &a, t);
    }
}

#[test]
fn bad_requests_are_typed_errors() {
    assert!(matches!(
        ExactInputs::parse("0.6", "0.5", "1"),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        ExactInputs::parse("0.2", "1", "1"),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        ExactInputs::parse("0.2", "0.5", "0"),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        ExactInputs::parse("0.2", "x", "1"),
        Err(Error::Parse { .. })
    ));
    assert!(matches!(
        ExactInputs::from_f64(f64::NAN, 0.5, 1.0),
        Err(Error::NotFinite { .. })
    ));
    let i = ExactInputs::parse("0.2", "0.5", "1").unwrap();
    // Beyond the largest precision the rules are built for: refused before any work, naming
    // the tolerance and the bound.
    match integrals_to_tolerance(&i, tol("1e-10000"), Method::Auto) {
        Err(e @ Error::Unreachable { .. }) => {
            let text = e.to_string();
            assert!(
                text.contains("1.00e-10000") && text.contains("32768"),
                "{text}"
            );
        }
        other => panic!("1e-10000: {other:?}"),
    }
    // Far beyond it (2^20 bits, MPFR's limit): refused before the inputs are rounded to that
    // precision, which alone took half a minute, by every method that builds rules.
    let t = std::time::Instant::now();
    for method in [Method::AdaptiveSubtracted, Method::Adaptive, Method::Fixed] {
        match integrals_to_tolerance(&i, RelError::pow2(-1_040_000), method) {
            Err(e @ Error::Unreachable { .. }) => assert!(e.to_string().contains("32768")),
            other => panic!("2^-1040000 by {method:?}: {other:?}"),
        }
    }
    assert!(
        t.elapsed().as_secs_f64() < 5.0,
        "refused after {:?}",
        t.elapsed()
    );
    for t in ["1", "2"] {
        assert!(matches!(
            integrals_to_tolerance(&i, tol(t), Method::Auto),
            Err(Error::Domain { .. })
        ));
    }
    for t in ["0", "-1", "nan"] {
        assert!(RelError::parse(t).is_err(), "{t}");
    }
    assert!(Method::parse("magic").is_err());
}
