//! Unit tests of the error messages (`src/error.rs`).

use super::Error;

/// The iteration count and the estimate are printed only when there are some.
#[test]
fn no_convergence_prints_what_it_has() {
    let e = |iterations, reached: &str| {
        Error::NoConvergence {
            what: "x",
            iterations,
            reached: reached.into(),
        }
        .to_string()
    };
    assert_eq!(
        e(7, "1e-3"),
        "x did not converge after 7 iterations (error estimate 1e-3)"
    );
    assert_eq!(
        e(0, "unbounded"),
        "x did not converge (error estimate unbounded)"
    );
    assert_eq!(e(0, ""), "x did not converge");
}

/// A method that cannot give the k-derivatives is [`Error::Unsupported`] naming it, before
/// any work: from `integrals` asking for them and from the ellipse solve, which needs them.
#[test]
fn a_method_without_derivatives_is_unsupported() {
    use crate::{integrals, solve_ellipse, IntegralOptions, Material, Method, Options};
    let sp = Material::new(0.25).unwrap().speed(0.5).unwrap();
    for method in [Method::Series, Method::AdaptiveSubtracted] {
        let opts = IntegralOptions {
            method,
            derivatives: true,
            ..Default::default()
        };
        let solve = Options {
            method,
            ..Default::default()
        };
        for r in [
            integrals(&sp, &0.5, &opts).map(|_| ()),
            solve_ellipse(&sp, &2.0, &solve).map(|_| ()),
        ] {
            match r {
                Err(e @ Error::Unsupported { method: m, .. }) => {
                    assert_eq!(m, method.label());
                    assert!(e
                        .to_string()
                        .starts_with(&format!("method {m} cannot give")));
                }
                other => panic!("{method}: {other:?}"),
            }
        }
    }
}

/// A k at or beyond the ends of the `f64` exponent range, on every route that admits it
/// and near the Rayleigh speed, is refused as [`Error::Domain`] naming k as given: before
/// any work where k⁴ or 1/k⁴ is not a normal number, after it where a value of the route
/// overflows or vanishes; never as an internal non-finite value ("integrand = -inf is not
/// finite") nor as a non-convergence. (Without the k⁴ check the routes meet such values;
/// the count of those refusals is printed.)
#[test]
fn an_integrand_beyond_the_exponent_range_names_k() {
    use crate::{integrals, IntegralOptions, Material, Method};
    let mut refused = 0;
    for nu in [0.25, -0.9] {
        let mat = Material::new(nu).unwrap();
        for mr in [0.5, 0.999999, 1.0 - 1e-12] {
            let sp = mat.speed(mr).unwrap();
            for k in [
                1e-100, 1e-80, 1e-77, 1e-76, 1e-70, 1e70, 1e76, 1e77, 1e80, 1e100,
            ] {
                for (method, derivatives) in [
                    (Method::Adaptive, true),
                    (Method::Adaptive, false),
                    (Method::AdaptiveSubtracted, false),
                    (Method::Auto, true),
                ] {
                    let opts = IntegralOptions {
                        method,
                        derivatives,
                        j0: true,
                        ..Default::default()
                    };
                    let what = format!("nu {nu} M_R {mr} k {k:e} {method} {derivatives}");
                    match integrals(&sp, &k, &opts) {
                        Ok(_) => {}
                        Err(Error::Domain { name, bound, .. }) => {
                            assert!(name.starts_with("axis ratio k"), "{what}: {name}");
                            refused += usize::from(bound.contains("exponent range"));
                        }
                        Err(e) => panic!("{what}: {e:?}"),
                    }
                }
            }
        }
    }
    println!("{refused} refusals after the work for the exponent range");
}
