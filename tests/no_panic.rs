//! Property test: the public entry points, fed random `f64` inputs with the extremes mixed in
//! (NaN, ±∞, ±0, subnormals, huge and tiny values, the ends of every range), never panic and
//! never return NaN: either a finite result or a typed error.

mod common;

use moving_hertz::physics::GreenFunction;
use moving_hertz::Real;
use moving_hertz::{
    integrals, integrals_to_tolerance, solve_ellipse, ContactProblem, ExactInputs, IntegralOptions,
    Loading, Material, Method, Options, RelError,
};
use std::panic::{catch_unwind, AssertUnwindSafe};

fn finite_or_err<T>(what: &str, r: moving_hertz::Result<T>, values: impl Fn(&T) -> Vec<f64>) {
    if let Ok(v) = r {
        for x in values(&v) {
            assert!(x.is_finite(), "{what}: returned a non-finite value {x}");
        }
    }
}

#[test]
fn random_inputs_never_panic_nor_return_nan() {
    let mut rng = common::SplitMix(2026); // the shared generator of tests/common
    let mut ok = 0usize;
    for case in 0..400 {
        let nu = rng.value(-1.0, 0.5);
        let mr = rng.value(0.0, 1.0);
        let k = rng.value(1e-6, 1e6);
        let ratio = rng.value(1e-6, 1e6);
        let r1 = rng.value(1e-3, 1e3);
        let mu = rng.value(1e-3, 1e12);
        let load = rng.value(1e-3, 1e6);
        eprintln!("case {case}: nu={nu:e} M_R={mr:e} k={k:e} ratio={ratio:e} R1={r1:e} mu={mu:e} P={load:e}");
        let run = AssertUnwindSafe(|| {
            finite_or_err("material", Material::new(nu), |m| vec![*m.m1(), *m.gamma()]);
            let Ok(mat) = Material::new(nu) else { return 0 };
            let Ok(sp) = mat.speed(mr) else { return 0 };
            let g = GreenFunction::new(&mat);
            assert!((g.g_regular(sp.mr2()) / sp.one_minus_mr2()).is_finite());
            let adaptive = IntegralOptions {
                method: Method::Adaptive,
                ..Default::default()
            };
            finite_or_err("quadrature", integrals(&sp, &k, &adaptive), |r| {
                vec![r.i1.value, r.i2.value, r.i1.error.to_f64()]
            });
            finite_or_err(
                "ellipse",
                solve_ellipse(&sp, &ratio, &Options::default()),
                |s| vec![s.k().value, s.e().value, s.k().error.to_f64()],
            );
            let problem = ContactProblem {
                speed: sp.clone(),
                radius_along: r1,
                radius_across: r1 * ratio,
                loading: Loading::Load(load),
                shear_modulus: mu,
            };
            finite_or_err("contact", problem.solve(&Options::default()), |s| {
                vec![
                    s.a().value,
                    s.b().value,
                    s.p0().value,
                    s.d0().value,
                    s.load().value,
                ]
            });
            1
        });
        match catch_unwind(run) {
            Ok(n) => ok += n,
            Err(_) => panic!("case {case}: panicked for nu={nu:e} M_R={mr:e} k={k:e} ratio={ratio:e} R1={r1:e} mu={mu:e} P={load:e}"),
        }
        // The automatic route, from exact inputs.
        if let Ok(inputs) = ExactInputs::from_f64(nu, mr, k) {
            let tol = RelError::from_f64(10f64.powf(-3.0 - 30.0 * rng.unit()));
            let r = catch_unwind(AssertUnwindSafe(|| {
                integrals_to_tolerance(&inputs, tol, Method::Auto)
            }));
            match r {
                Ok(Ok(a)) => assert!(
                    a.i1.value.is_finite()
                        && a.i2.value.is_finite()
                        && a.i1.error <= tol
                        && a.i2.error <= tol
                ),
                Ok(Err(_)) => {}
                Err(_) => panic!(
                    "case {case}: choose::integrals panicked for nu={nu:e} M_R={mr:e} k={k:e}"
                ),
            }
        }
    }
    // Enough valid cases went through the whole chain.
    assert!(ok > 60, "only {ok} cases reached the solvers");
}
