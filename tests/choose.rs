//! The automatic choice of method and precision: a loose request runs in f64, a tight one at the
//! lowest sufficient precision, and the returned error estimate bounds the true error, measured
//! against a computation 64 bits above the one used, from the same exact inputs.

use moving_hertz::prelude::*;
use moving_hertz::routes::choose::{self, Inputs, MethodRequest};
use moving_hertz::routes::Method;
use rug::Float;

#[test]
fn precision_follows_the_request() {
    let i = Inputs::parse("0.2", "0.5", "0.5").unwrap();
    assert_eq!(choose::choose_precision(&i, 1e-6).unwrap(), Precision::F64);
    assert_eq!(choose::choose_precision(&i, 1e-12).unwrap(), Precision::F64);
    assert_eq!(
        choose::choose_precision(&i, 1e-20).unwrap(),
        Precision::DoubleDouble
    );
    match choose::choose_precision(&i, 1e-60).unwrap() {
        Precision::Mpfr(p) => assert!((200..=256).contains(&p.bits()), "{}", p.bits()),
        other => panic!("1e-60 answered at {other}"),
    }
    // Near the Rayleigh speed the inputs' rounding is amplified: 1e-12 needs double-double.
    let fast = Inputs::parse("0.2", "0.99999999", "0.01").unwrap();
    assert_eq!(
        choose::choose_precision(&fast, 1e-12).unwrap(),
        Precision::DoubleDouble
    );
    // And the runs themselves land there.
    let a = choose::integrals(&i, 1e-6, MethodRequest::Auto).unwrap();
    assert_eq!(a.precision, Precision::F64);
    let a = choose::integrals(&i, 1e-60, MethodRequest::Auto).unwrap();
    assert!(matches!(a.precision, Precision::Mpfr(p) if p.bits() <= 256));
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
        let inputs = Inputs::parse(nu, mr, k).unwrap();
        for tol in [1e-6, 1e-13, 1e-25, 1e-45] {
            let a = choose::integrals(&inputs, tol, MethodRequest::Auto).unwrap();
            assert!(a.error_estimate <= tol);
            let bits = a.precision.bits() as u64 + 64;
            let p = MpPrec::new(bits).unwrap();
            let r = choose::run_at::<Mp>(&inputs, p, Method::Quadrature, 0.0).unwrap();
            for (got, want) in [(&a.i1, r.i1.as_float()), (&a.i2, r.i2.as_float())] {
                let err = Float::with_val(bits as u32, got - want) / want;
                let err = err.abs().to_f64();
                assert!(
                    err <= a.error_estimate,
                    "nu={nu} M_R={mr} k={k} tol={tol:e}: true error {err:e} > estimate {:e} ({} at {})",
                    a.error_estimate,
                    a.method.label(),
                    a.precision
                );
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 32);
}

#[test]
fn bad_requests_are_typed_errors() {
    assert!(matches!(
        Inputs::parse("0.6", "0.5", "1"),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        Inputs::parse("0.2", "1", "1"),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        Inputs::parse("0.2", "0.5", "0"),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        Inputs::parse("0.2", "x", "1"),
        Err(Error::Parse { .. })
    ));
    assert!(matches!(
        Inputs::from_f64(f64::NAN, 0.5, 1.0),
        Err(Error::NotFinite { .. })
    ));
    let i = Inputs::parse("0.2", "0.5", "1").unwrap();
    for tol in [0.0, -1.0, 1.0, f64::NAN] {
        assert!(matches!(
            choose::integrals(&i, tol, MethodRequest::Auto),
            Err(Error::Domain { .. })
        ));
    }
    assert!(MethodRequest::parse("magic").is_err());
}
