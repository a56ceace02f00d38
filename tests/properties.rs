//! Property tests at every precision: seeded random inputs — mostly inside each domain, often at
//! or just beyond its ends, sometimes NaN, ±∞, ±0, subnormal or huge — fed to the public entry
//! points: the material and speed constructors (from numbers and from text), `integrals` with
//! every method and option, `integrals_to_tolerance`, `solve_ellipse` with every method, seeds
//! and tolerances, `ContactProblem::solve` with a load or an approach, and `sweep::ellipses`.
//! Asserted: no panic; every `Ok` holds finite values with finite bounds below 1 (at least one
//! correct digit); every `Err` is an `Error` with a message, and a non-finite number in it is an
//! input or a derived quantity refused by name, never an iteration's internal value.
//!
//! Counts: 10⁶ random input sets at `f64` (every set through the constructors, a quarter through
//! `integrals`, one in 20 through the ellipse solve, fewer through the costlier entries), 10⁴ at
//! double-double and 10³ at 256 bits (every set through the constructors, `integrals` and the
//! ellipse solve at double-double; a share of the solves at 256 bits).

mod common;

use common::SplitMix;
use moving_hertz::prelude::*;
use moving_hertz::sweep::{self, EllipsePoint, SpeedGiven};
use moving_hertz::{
    integrals, integrals_to_tolerance, solve_ellipse, Error, ExactInputs, Integrals, Method,
};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Every value finite and every bound finite; `what` names the entry.
fn finite<T: Real>(what: &str, values: &[&T], bounds: &[RelError]) {
    for v in values {
        assert!(v.is_finite(), "{what}: a non-finite value {v:?} in an Ok");
    }
    for b in bounds {
        let s = b.to_string();
        assert!(
            !s.contains("inf") && !s.contains("NaN") && *b < RelError::from_f64(1.0),
            "{what}: bound {s} in an Ok"
        );
    }
}

/// An `Err` is a typed error with a message that says what happened: a non-finite number in
/// it is the input as the user gave it ([`Error::NotFinite`]) or a derived quantity refused by
/// name ([`Error::Domain`]), never an iteration's internal value (a non-finite integrand or
/// estimate reported as [`Error::NotFinite`], [`Error::NoConvergence`] or [`Error::TermCap`] is
/// a bug: the domain checks before the work must have refused it); a non-convergence says how
/// many iterations ran (a refusal before any is another variant); no internal error.
fn typed(what: &str, e: &Error) {
    let m = e.to_string();
    assert!(!m.is_empty(), "{what}: an error without a message");
    let non_finite = |s: &str| ["inf", "NaN"].iter().any(|w| s.contains(w));
    match e {
        Error::NoConvergence {
            reached,
            iterations,
            ..
        } => {
            assert!(
                !non_finite(reached),
                "{what}: an internal non-finite value: {m}"
            );
            assert!(
                *iterations > 0,
                "{what}: a refusal as a non-convergence: {m}"
            );
        }
        Error::TermCap { reached, .. } => {
            assert!(
                !non_finite(reached),
                "{what}: an internal non-finite value: {m}"
            );
        }
        Error::NotFinite { name, .. } => {
            assert!(
                !name.contains("integrand"),
                "{what}: an internal value: {m}"
            );
        }
        Error::Internal { .. } => panic!("{what}: {m}"),
        _ => {}
    }
}

fn check_integrals<T: Real>(what: &str, r: &moving_hertz::Result<Integrals<T>>) {
    match r {
        Ok(r) => {
            let mut values = vec![&r.i1.value, &r.i2.value];
            let mut bounds = vec![r.i1.error, r.i2.error];
            for d in [&r.di1_dk, &r.di2_dk, &r.j0].into_iter().flatten() {
                values.push(&d.value);
                bounds.push(d.error);
            }
            finite(what, &values, &bounds);
        }
        Err(e) => typed(what, e),
    }
}

fn check_ellipse<T: Real>(what: &str, r: &moving_hertz::Result<moving_hertz::Ellipse<T>>) {
    match r {
        Ok(s) => {
            finite(
                what,
                &[&s.k().value, &s.e().value],
                &[s.k().error, s.e().error],
            );
            check_integrals(what, &Ok(s.integrals().clone()));
        }
        Err(e) => typed(what, e),
    }
}

/// Which of the costlier entries a case runs, one in `n` cases for each.
struct Shares {
    integrals: u64,
    options: u64,
    ellipse: u64,
    contact: u64,
    tolerance: u64,
    sweep: u64,
    /// Draws of k and A1/B1 beyond 2^±span are moved to 2^±span (at 256 bits, where an
    /// adaptive quadrature at k = 10^±300 costs seconds; tests/edges.rs covers the ends there).
    span: i32,
}

impl Shares {
    fn clamp(&self, x: f64) -> f64 {
        let (lo, hi) = (2f64.powi(-self.span), 2f64.powi(self.span));
        match x.abs() {
            a if !x.is_finite() || a == 0.0 || (lo..=hi).contains(&a) => x,
            a => x.signum() * if a < lo { lo } else { hi },
        }
    }
}

/// One random input set at precision `p` through the entries `shares` selects for case `i`.
/// One case in this many builds a [`Solid`] and a speed from a velocity.
const SOLID_EVERY: u64 = 16;

fn case<T: Real + Send + Sync>(g: &mut SplitMix, p: T::Prec, i: u64, shares: &Shares) {
    let x = |v: f64| T::from_f64(v, p);
    let (nu, mr, gap) = (g.value(-1.0, 0.5), g.value(0.0, 1.0), g.value(0.0, 1.0));
    let (k, ratio) = (
        shares.clamp(g.value(2f64.powi(-40), 2f64.powi(40))),
        shares.clamp(g.value(1e-100, 1e100)),
    );
    let mat = match Material::new(x(nu)) {
        Ok(m) => {
            finite("material", &[m.m1(), m.gamma(), m.pi_g_rayleigh()], &[]);
            m
        }
        Err(e) => return typed("material", &e),
    };
    if let Err(e) = Material::<T>::parse(&format!("{nu:e}"), p) {
        typed("Material::parse", &e);
    }
    // V and c2 (μ = c2², ρ = 1): the half-space's speeds, then the velocity's, in one case of
    // SOLID_EVERY (a `Solid` takes its Rayleigh root in MPFR with guard bits, ~80 µs); the
    // values are drawn in every case, so that the other draws do not depend on it.
    let (v, c2) = (g.value(0.0, 3e3), g.value(0.0, 3e3));
    let by_velocity = i.is_multiple_of(SOLID_EVERY).then(|| {
        let moduli = Moduli::Shear {
            shear_modulus: x(c2 * c2),
            density: x(1.0),
        };
        Solid::new(&mat, moduli).and_then(|s| {
            finite("solid", &[s.c2(), s.c_r()], &[]);
            s.speed_from_velocity(x(v))
        })
    });
    let speeds = [
        mat.speed_from_gap(x(gap)),
        mat.speed(x(g.value(0.0, 1.0)) / mat.cr_over_c2()),
        mat.parse_speed(&format!("{mr:e}")),
    ];
    for r in speeds.into_iter().chain(by_velocity) {
        match r {
            Ok(s) => finite("speed", &[s.mr(), s.gap(), s.one_minus_mr2()], &[]),
            Err(e) => typed("speed", &e),
        }
    }
    let sp = match mat.speed(x(mr)) {
        Ok(s) => s,
        Err(e) => return typed("speed", &e),
    };
    if i.is_multiple_of(shares.integrals) {
        check_integrals(
            "integrals",
            &integrals(&sp, &x(k), &IntegralOptions::default()),
        );
    }
    if i.is_multiple_of(shares.options) {
        let method = Method::ALL[g.below(Method::ALL.len() as u64) as usize];
        let tolerance = (g.below(2) == 0).then(|| RelError::from_f64(10f64.powf(-20.0 * g.unit())));
        let opts = IntegralOptions {
            method,
            tolerance,
            derivatives: g.below(2) == 0,
            j0: g.below(3) == 0,
        };
        check_integrals("integrals with options", &integrals(&sp, &x(k), &opts));
    }
    if i.is_multiple_of(shares.ellipse) {
        let method = [
            Method::Auto,
            Method::Fixed,
            Method::Adaptive,
            Method::Series,
        ][g.below(4) as usize];
        let opts = Options {
            method,
            seed: (g.below(4) == 0).then(|| x(g.value(1e-3, 1e3))),
            tolerance: (g.below(4) == 0).then(|| RelError::from_f64(10f64.powf(-18.0 * g.unit()))),
        };
        let what = format!("solve_ellipse nu={nu:e} M_R={mr:e} A1/B1={ratio:e} {opts:?}");
        check_ellipse(&what, &solve_ellipse(&sp, &x(ratio), &opts));
    }
    if i.is_multiple_of(shares.contact) {
        let size = g.value(1e-3, 1e3);
        let problem = ContactProblem {
            speed: sp.clone(),
            radius_along: x(size),
            radius_across: x(size * g.value(1e-3, 1e3)),
            loading: if g.below(2) == 0 {
                Loading::Load(x(g.value(1e-3, 1e6)))
            } else {
                Loading::Approach(x(g.value(1e-9, 1e-3)))
            },
            shear_modulus: x(g.value(1e6, 1e12)),
        };
        match problem.solve(&Options::default()) {
            Ok(s) => finite(
                "contact",
                &[
                    &s.a().value,
                    &s.b().value,
                    &s.p0().value,
                    &s.d0().value,
                    &s.load().value,
                ],
                &[
                    s.a().error,
                    s.b().error,
                    s.p0().error,
                    s.d0().error,
                    s.load().error,
                ],
            ),
            Err(e) => typed("contact", &e),
        }
    }
    if i.is_multiple_of(shares.tolerance) {
        if let Ok(inputs) = ExactInputs::from_f64(nu, mr, k) {
            let tol = RelError::from_f64(10f64.powf(-3.0 - 30.0 * g.unit()));
            check_integrals(
                "integrals_to_tolerance",
                &integrals_to_tolerance(&inputs, tol, Method::Auto),
            );
        }
    }
    if i.is_multiple_of(shares.sweep) {
        let points: Vec<EllipsePoint<T>> = (0..8)
            .map(|j| EllipsePoint {
                nu: x(if j == 5 { g.value(-1.0, 0.5) } else { nu }),
                speed: SpeedGiven::Gap(x(gap)),
                ratio: x(ratio * (1.0 + j as f64 / 8.0)),
            })
            .collect();
        for r in sweep::ellipses(&points, &Options::default()) {
            check_ellipse("sweep", &r);
        }
    }
}

/// Runs `n` cases at precision `p`, each under `catch_unwind`, reporting the seed of a panic.
fn run<T: Real + Send + Sync>(seed: u64, n: u64, p: T::Prec, shares: Shares) {
    let mut g = SplitMix(seed);
    for i in 0..n {
        let state = g.0;
        let r = catch_unwind(AssertUnwindSafe(|| case::<T>(&mut g, p, i, &shares)));
        assert!(r.is_ok(), "case {i} panicked (generator state {state:#x})");
    }
}

#[test]
fn a_million_random_inputs_at_f64() {
    let shares = Shares {
        integrals: 4,
        options: 200,
        ellipse: 20,
        contact: 500,
        tolerance: 2000,
        sweep: 10_000,
        span: 1100,
    };
    run::<f64>(0x5eed_0001, 1_000_000, (), shares);
}

#[test]
fn ten_thousand_random_inputs_at_double_double() {
    let shares = Shares {
        integrals: 1,
        options: 10,
        ellipse: 1,
        contact: 50,
        tolerance: 100,
        sweep: 500,
        span: 1100,
    };
    run::<Dd>(0x5eed_0002, 10_000, (), shares);
}

#[test]
fn a_thousand_random_inputs_at_256_bits() {
    let shares = Shares {
        integrals: 1,
        options: 10,
        ellipse: 4,
        contact: 100,
        tolerance: 200,
        sweep: 500,
        span: 80,
    };
    run::<Mp>(0x5eed_0003, 1_000, MpPrec::new(256).unwrap(), shares);
}
