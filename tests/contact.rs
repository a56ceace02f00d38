//! The contact solution: the static limit against classical Hertz (Johnson, Contact Mechanics
//! §4.2, E* = 2μ/(1 − ν)); the convolution (7) of the computed pressure with the moving Green's
//! function reproduces d0 − A1x² − B1y² inside the contact (≤ 1e-10 relative at f64) and leaves a
//! positive gap outside (the Signorini conditions (1)); the ellipse's monotonicity and its
//! lengthening along the motion with speed; the precision ladder; typed errors.

mod common;

use common::rel_eps;
use common::roots::brent;
use moving_hertz::numerics::elliptic::{ellipbd_mc, ellipke_mc};
use moving_hertz::prelude::*;
use moving_hertz::{integrals, solve_ellipse, ContactSolution, Ellipse, MajorAxis, Route};

/// The contact solution for `sp` with radii R1 (along), R2 (across), a loading and μ.
fn contact<T: Real>(
    sp: &Speed<T>,
    r1: &T,
    r2: &T,
    l: Loading<T>,
    mu: &T,
) -> Result<ContactSolution<T>> {
    ContactProblem {
        speed: sp.clone(),
        radius_along: r1.clone(),
        radius_across: r2.clone(),
        loading: l,
        shear_modulus: mu.clone(),
    }
    .solve(&Options::default())
}

/// The ellipse solve with default options (the precision ladder above f64).
fn ellipse<T: Real>(sp: &Speed<T>, ratio: &T) -> Ellipse<T> {
    solve_ellipse(sp, ratio, &Options::default()).unwrap()
}

/// The ellipse solve with a method.
fn ellipse_by<T: Real>(sp: &Speed<T>, ratio: &T, method: Method) -> Ellipse<T> {
    let opts = Options {
        method,
        ..Default::default()
    };
    solve_ellipse(sp, ratio, &opts).unwrap()
}

/// k's error estimate in units of ε.
fn est_eps<T: Real>(s: &Ellipse<T>, p: T::Prec) -> f64 {
    s.k().error.to_f64() / T::epsilon(p).to_f64()
}

/// Johnson §4.2 for a > b (x along a): with e² = 1 − b²/a²,
/// A = p0 b (K − E)/(E* e² a²), B = p0 b ((a/b)² E − K)/(E* e² a²), d0 = p0 b K/E*,
/// P = (2/3)π p0 a b. Solved here for (a, b, p0, d0) from (P, R1 > R2, E*).
fn johnson<T: Real>(p: T::Prec, load: &T, r1: &T, r2: &T, estar: &T) -> (T, T, T, T) {
    let one = T::one(p);
    let a_curv = (r1.clone().mul_i64(2)).recip();
    let b_curv = (r2.clone().mul_i64(2)).recip();
    let target = a_curv.clone() / &b_curv;
    // A/B = (K − E)/((a/b)²E − K) as a function of mc = b²/a² ∈ (0, 1), written without
    // cancellation: K − E = m·D(m), E/mc − K = m·B(m)/mc, so A/B = mc·D/B.
    let f = |mc: &T| {
        let (b, d) = ellipbd_mc(mc).unwrap();
        mc.clone() * d / b - &target
    };
    let tiny = T::epsilon(p);
    let mc = brent(f, &tiny, &(one.clone() - &tiny), 400);
    let (kk, ee) = ellipke_mc(&mc).unwrap();
    let e2 = one - &mc;
    let pi = T::pi(p);
    // a³ = 3P(K − E)/(2π A E* e²).
    let a3 = load.clone().mul_i64(3) * (kk.clone() - &ee)
        / (pi.clone().mul_i64(2) * &a_curv * estar * &e2);
    let a = a3.cbrt();
    let b = a.clone() * mc.sqrt();
    let p0 = load.clone().mul_i64(3) / (pi.mul_i64(2) * &a * &b);
    let d0 = p0.clone() * &b * kk / estar;
    (a, b, p0, d0)
}

fn static_limit<T: Real>(p: T::Prec, label: &str) {
    for (nu, r1, r2) in [
        ("0.25", "2", "1"),
        ("0", "10", "0.1"),
        ("0.5", "1.5", "1"),
        ("-0.5", "300", "0.001"),
    ] {
        let mat = Material::new(T::parse(nu, p).unwrap()).unwrap();
        let sp = mat.speed(T::zero(p)).unwrap();
        let (r1, r2) = (T::parse(r1, p).unwrap(), T::parse(r2, p).unwrap());
        let mu = T::parse("3.5", p).unwrap();
        let load = T::parse("0.75", p).unwrap();
        let sol = contact(&sp, &r1, &r2, Loading::Load(load.clone()), &mu).unwrap();
        let estar = mu.clone().mul_i64(2) / (T::one(p) - mat.nu());
        let (a, b, p0, d0) = johnson(p, &load, &r1, &r2, &estar);
        for (name, got, want) in [
            ("a", &sol.a().value, &a),
            ("b", &sol.b().value, &b),
            ("p0", &sol.p0().value, &p0),
            ("d0", &sol.d0().value, &d0),
        ] {
            let e = rel_eps(got, &want.to_float(400));
            assert!(e <= 64.0, "{label} nu={nu}: {name} off by {e} eps");
        }
        // And the approach-driven solve gives back the load.
        let sol2 = contact(
            &sp,
            &r1,
            &r2,
            Loading::Approach(sol.d0().value.clone()),
            &mu,
        )
        .unwrap();
        let e = rel_eps(&sol2.load().value, &load.to_float(400));
        assert!(e <= 64.0, "{label} nu={nu}: load from d0 off by {e} eps");
    }
}

#[test]
fn static_limit_is_johnson_hertz() {
    at_all_precisions!(static_limit, [256]);
}

/// Inside: the convolution equals d0 − A1x² − B1y² to 1e-10 (measured ~1e-15); outside: the gap
/// u_z − (d0 − A1x² − B1y²) is positive; the pressure is positive inside.
#[test]
fn convolution_reproduces_the_punch_and_signorini_holds() {
    let mut worst: f64 = 0.0;
    for (nu, mr, r1, r2) in [
        (0.25, 0.0, 2.0, 1.0),
        (0.0, 0.5, 1.0, 1.0),
        (0.4, 0.9, 5.0, 1.0),
        (-0.5, 0.99, 1.0, 3.0),
        (0.2, 0.999, 1.0, 2.0),
        (0.5, 0.9, 0.5, 4.0),
    ] {
        let mat = Material::new(nu).unwrap();
        let sp = mat.speed(mr).unwrap();
        let sol = contact(&sp, &r1, &r2, Loading::Load(2.0), &1.5).unwrap();
        let (a, b) = (sol.a().value, sol.b().value);
        // A1 = 1/(2 R1), B1 = 1/(2 R2), as the solve forms them.
        let (a1, b1) = (r1.recip() / 2.0, r2.recip() / 2.0);
        let tol = |t: f64| RelError::from_f64(t);
        let inside = [
            (0.0, 0.0),
            (0.5 * a, 0.0),
            (0.0, -0.6 * b),
            (-0.4 * a, 0.5 * b),
            (0.7 * a, 0.7 * b),
        ];
        for (x, y) in inside {
            assert!(sol.inside(&x, &y) && sol.pressure(&x, &y).unwrap().value > 0.0);
            let u = sol.convolution(&x, &y, &tol(1e-13)).unwrap().value;
            let poly = sol.displacement(&x, &y, &tol(1e-13)).unwrap().value;
            let rel = ((u - poly) / sol.d0().value).abs();
            worst = worst.max(rel);
            assert!(
                rel <= 1e-10,
                "nu={nu} M_R={mr} at ({x},{y}): convolution {u} vs {poly}, rel {rel:e}"
            );
        }
        let outside = [
            (1.2 * a, 0.0),
            (-1.05 * a, 0.0),
            (0.0, 1.1 * b),
            (0.0, -2.0 * b),
            (0.9 * a, 0.9 * b),
            (3.0 * a, -b),
        ];
        for (x, y) in outside {
            assert!(!sol.inside(&x, &y) && sol.pressure(&x, &y).unwrap().value == 0.0);
            let u = sol.displacement(&x, &y, &tol(1e-12)).unwrap().value;
            let punch = sol.d0().value - a1 * x * x - b1 * y * y;
            assert!(
                u - punch > 0.0,
                "nu={nu} M_R={mr} at ({x},{y}): gap {} is not positive",
                u - punch
            );
        }
    }
    println!("worst relative mismatch inside the contact: {worst:.2e}");
}

/// F(k) = ln(I2/I1) increases with k (so the root is unique), and at fixed A1/B1 the contact
/// lengthens along the motion (k = b/a falls) as the speed rises.
#[test]
fn ellipse_is_unique_and_lengthens_with_speed() {
    for nu in [-0.9, 0.0, 0.25, 0.5] {
        let mat = Material::new(nu).unwrap();
        for ratio in [1e-6, 0.01, 0.3, 1.0, 3.0, 1e6] {
            let mut prev_k = f64::INFINITY;
            for mr in [0.0, 0.3, 0.6, 0.9, 0.99, 0.9999] {
                let sp = mat.speed(mr).unwrap();
                let s = ellipse(&sp, &ratio);
                let k = s.k().value;
                assert!(
                    k < prev_k,
                    "nu={nu} ratio={ratio} M_R={mr}: k {k} did not fall below {prev_k}"
                );
                let ci = s.integrals();
                let (d1, d2) = (ci.di1_dk.as_ref().unwrap(), ci.di2_dk.as_ref().unwrap());
                assert!(
                    d2.value / ci.i2.value - d1.value / ci.i1.value > 0.0,
                    "F not increasing"
                );
                let expect = if k <= 1.0 {
                    MajorAxis::Along
                } else {
                    MajorAxis::Across
                };
                assert_eq!(s.major(), expect);
                prev_k = k;
            }
        }
    }
}

/// The ladder: the f64 root seeds Newton at double-double and 256 bits, which converges in at
/// most 4 evaluations to the same root a seedless high-precision solve finds.
fn ladder<T: Real>(p: T::Prec, label: &str) {
    for (nu, mr, ratio) in [
        ("0.2", "0.9", "0.3"),
        ("0.35", "0.999", "1e-3"),
        ("-0.25", "0.5", "20"),
    ] {
        let mat64 = Material::new(nu.parse::<f64>().unwrap()).unwrap();
        let seed = ellipse(
            &mat64.speed(mr.parse::<f64>().unwrap()).unwrap(),
            &ratio.parse::<f64>().unwrap(),
        )
        .k()
        .value;
        let mat = Material::new(T::parse(nu, p).unwrap()).unwrap();
        let sp = mat.speed(T::parse(mr, p).unwrap()).unwrap();
        let r = T::parse(ratio, p).unwrap();
        let seeded = Options {
            seed: Some(T::from_f64(seed, p)),
            ..Default::default()
        };
        let s = solve_ellipse(&sp, &r, &seeded).unwrap();
        assert!(
            s.iterations() <= 4,
            "{label}: {} iterations from the f64 seed",
            s.iterations()
        );
        // The default solve: the ladder (a double-double stage above 106 bits, chord steps).
        let cold = ellipse(&sp, &r);
        let e = rel_eps(&s.k().value, &cold.k().value.to_float(T::bits(p) + 64));
        assert!(
            e <= 16.0,
            "{label}: seeded and ladder roots differ by {e} eps"
        );
        let est = est_eps(&s, p);
        assert!(est <= 64.0, "{label}: error estimate {est} eps");
    }
}

/// k from the default solve (the ladder above f64: fast or graded routes, Newton then chord
/// steps) within 10ε of a different method at higher precision — the adaptive quadrature solve
/// at 320 bits — on the same represented inputs (each decimal parsed at the working precision,
/// then carried exactly to 320 bits, so the conditioning of k in M_R near c_R does not enter).
fn ladder_accuracy<T: Real>(p: T::Prec, label: &str) {
    let q = common::mp(320);
    for (nu, mr, ratio) in [
        ("0.2", "0.5", "0.5"),
        ("0.2", "0.9999", "0.5"),
        ("0.45", "0.99", "1e-3"),
        ("0.2", "0.9", "10"),
        ("-0.5", "0.3", "1e4"),
    ] {
        let (nu, mr, ratio) = (
            T::parse(nu, p).unwrap(),
            T::parse(mr, p).unwrap(),
            T::parse(ratio, p).unwrap(),
        );
        let mat = Material::new(nu.clone()).unwrap();
        let s = ellipse(&mat.speed(mr.clone()).unwrap(), &ratio);
        let up = |x: &T| Mp::from_float(&x.to_float(T::bits(p)), q);
        let matq = Material::new(up(&nu)).unwrap();
        let spq = matq.speed(up(&mr)).unwrap();
        let want = ellipse_by(&spq, &up(&ratio), Method::Adaptive);
        let e = rel_eps(&s.k().value, &want.k().value.to_float(320));
        assert!(e <= 10.0, "{label}: k off by {e:.2} eps");
        let est = est_eps(&s, p);
        assert!(
            e <= est,
            "{label}: error {e:.2} eps above its estimate {est:.2} eps"
        );
        // The returned integrals, carried to the returned k (first or second order).
        let (si, wi) = (s.integrals(), want.integrals());
        let ei = rel_eps(&si.i1.value, &wi.i1.value.to_float(320))
            .max(rel_eps(&si.i2.value, &wi.i2.value.to_float(320)));
        assert!(ei <= 16.0, "{label}: I1, I2 off by {ei:.2} eps");
        println!(
            "{label}: k {e:.2} eps (estimate {est:.2}), I1, I2 {ei:.2} eps, {} evaluations",
            s.iterations()
        );
    }
}

#[test]
fn ladder_k_within_10_eps_of_a_320_bit_quadrature_solve() {
    ladder_accuracy::<f64>((), "f64");
    ladder_accuracy::<Dd>((), "dd");
    ladder_accuracy::<Mp>(common::mp(256), "mpfr256");
}

#[test]
fn precision_ladder_from_f64() {
    ladder::<Dd>((), "dd");
    ladder::<Mp>(common::mp(256), "mpfr256");
}

#[test]
fn bad_inputs_are_typed_errors() {
    let mat = Material::new(0.25).unwrap();
    let sp = mat.speed(0.5).unwrap();
    for (r1, r2, l, mu) in [
        (0.0, 1.0, 1.0, 1.0),
        (1.0, -1.0, 1.0, 1.0),
        (1.0, 1.0, 0.0, 1.0),
        (1.0, 1.0, 1.0, 0.0),
        (f64::NAN, 1.0, 1.0, 1.0),
        (1.0, 1.0, f64::INFINITY, 1.0),
    ] {
        let r = contact(&sp, &r1, &r2, Loading::Load(l), &mu);
        assert!(
            matches!(r, Err(Error::Domain { .. }) | Err(Error::NotFinite { .. })),
            "{r1} {r2} {l} {mu}"
        );
    }
    assert!(matches!(
        solve_ellipse(&sp, &-1.0, &Options::default()),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        solve_ellipse(&sp, &f64::NAN, &Options::default()),
        Err(Error::NotFinite { .. })
    ));
}

/// A1/B1 > 1 (unseeded start above k = 1): the default solve agrees with the all-quadrature
/// solve, and when speed brings the root below k = 1 it is found by the fast route (one
/// evaluation at k = 1 picks the side), not by adaptive evaluations above k = 1.
#[test]
fn ratio_above_one_agrees_with_quadrature_and_uses_the_fast_route_below_k1() {
    for nu in [-0.5, 0.2, 0.5] {
        let mat = Material::new(nu).unwrap();
        for mr in [0.0, 0.5, 0.9, 0.9999] {
            let sp = mat.speed(mr).unwrap();
            for ratio in [1.0, 1.5, 2.0, 10.0, 1e3] {
                let auto = ellipse_by(&sp, &ratio, Method::Auto);
                let quad = ellipse_by(&sp, &ratio, Method::Adaptive);
                let (ka, kq) = (auto.k().value, quad.k().value);
                let rel = (ka / kq - 1.0).abs();
                assert!(
                    rel <= 64.0 * f64::EPSILON,
                    "nu={nu} M_R={mr} A1/B1={ratio}: auto k {ka} vs quadrature {kq} ({rel:e})"
                );
                if ka < 1.0 - 1e-12 {
                    assert_eq!(
                        auto.integrals().route,
                        Route::FixedRule,
                        "nu={nu} M_R={mr} A1/B1={ratio}: k = {ka} < 1 not by the fast route"
                    );
                    assert!(auto.iterations() <= 8, "{} iterations", auto.iterations());
                }
            }
        }
    }
}

/// The solve evaluates by the routing table users get: the route of its last evaluation is the
/// route `integrals` with k-derivatives takes at the root, for each method, at roots below
/// k = 1 (the fixed rule), above it (the graded rule) and far from it (k ≈ 10⁻³ and 10³).
#[test]
fn the_solve_routes_as_a_user_evaluation_does() {
    let sp = Material::new(0.25).unwrap().speed(0.9).unwrap();
    for method in [Method::Auto, Method::Fixed, Method::Adaptive] {
        for ratio in [1e-5, 0.5, 2.0, 10.0, 1e5] {
            let s = ellipse_by(&sp, &ratio, method);
            let opts = IntegralOptions {
                method,
                derivatives: true,
                ..Default::default()
            };
            let user = integrals(&sp, &s.k().value, &opts).unwrap();
            assert_eq!(
                s.integrals().route,
                user.route,
                "{method:?} A1/B1 = {ratio}: the solve's route at k = {}",
                s.k().value
            );
        }
    }
}

/// Whatever path the solve takes (the k = 1 probe, the static start,
/// the fast or graded routes, bisection), its k satisfies the shape equation (33): I2/I1 at the
/// returned k, recomputed by the adaptive quadrature at double-double (an independent route at
/// a higher precision), equals A1/B1 to within the conditioning of F = ln(I2/I1) in ln k times
/// the reported error of k, and the returned I1, I2 are those integrals. A grid of 150 cases
/// from A1/B1 = 10⁻⁶ to 10⁶ and M_R up to 0.9999.
#[test]
fn the_root_satisfies_the_shape_equation_on_a_wide_grid() {
    use moving_hertz::IntegralOptions;
    let adaptive = IntegralOptions {
        method: Method::Adaptive,
        derivatives: true,
        ..Default::default()
    };
    let (mut worst, mut worst_i) = (0.0f64, 0.0f64);
    for nu in [-0.5, 0.2, 0.5] {
        let mat = Material::new(nu).unwrap();
        let matd = Material::new(Dd::from_f64(nu, ())).unwrap();
        let ok = |s: &Ellipse<f64>| (s.k().value, s.k().error.to_f64());
        for mr in [0.0, 0.5, 0.9, 0.99, 0.9999] {
            let sp = mat.speed(mr).unwrap();
            let spd = matd.speed(Dd::from_f64(mr, ())).unwrap();
            for ratio in [1e-6, 1e-3, 0.5, 2.0, 10.0, 30.0, 100.0, 1e3, 1e4, 1e6] {
                let at = format!("nu={nu} M_R={mr} A1/B1={ratio}");
                let s = ellipse(&sp, &ratio);
                let (k, k_err) = ok(&s);
                let c = integrals(&spd, &Dd::from_f64(k, ()), &adaptive).unwrap();
                let (ci1, ci2) = (c.i1.value, c.i2.value);
                let (cd1, cd2) = (c.di1_dk.unwrap().value, c.di2_dk.unwrap().value);
                let (i1, i2) = (ci1.to_f64(), ci2.to_f64());
                // F′ = d ln(I2/I1)/d ln k, from the reference's derivatives.
                let df = (cd2 / ci2 - cd1 / ci1).to_f64() * k;
                let resid = ((ci2 / ci1).to_f64() / ratio).ln().abs();
                let allowed = df.abs() * k_err + 8.0 * f64::EPSILON;
                assert!(
                    resid <= allowed,
                    "{at}: k = {k} leaves ln(I2/I1/ratio) = {resid:e} (allowed {allowed:e})"
                );
                let (s1, s2) = (s.integrals().i1.value, s.integrals().i2.value);
                let e = (s1 / i1 - 1.0).abs().max((s2 / i2 - 1.0).abs()) / f64::EPSILON;
                assert!(e <= 16.0, "{at}: returned I1, I2 off by {e:.1} eps");
                worst = worst.max(resid / f64::EPSILON);
                if e > 3.0 {
                    println!("{at}: I err {e:.1}");
                }
                worst_i = worst_i.max(e);
            }
        }
    }
    println!("worst residual {worst:.1} eps, returned I1, I2 worst {worst_i:.1} eps");
}

/// The double-double ladder (one evaluation and a Halley step from the f64 root where the
/// f64 stage's second derivatives allow it, else two chord steps) against the 256-bit ladder
/// (a double-double stage, then two chord steps: a different path to the same root) on a wide
/// grid: k and the returned I1, I2 to a few double-double ε, within the reported estimates.
#[test]
fn dd_ladder_agrees_with_256_bits_on_a_wide_grid() {
    let p = common::mp(256);
    let (mut worst_k, mut worst_i, mut one_step, mut n) = (0.0f64, 0.0f64, 0, 0);
    for nu in ["-0.5", "0.2", "0.5"] {
        for mr in ["0", "0.5", "0.9", "0.99", "0.9999"] {
            for ratio in [
                "1e-6", "1e-3", "0.5", "2", "10", "30", "100", "1e3", "1e4", "1e6",
            ] {
                let at = format!("nu={nu} M_R={mr} A1/B1={ratio}");
                let matd = Material::new(Dd::parse(nu, ()).unwrap()).unwrap();
                let spd = matd.speed(Dd::parse(mr, ()).unwrap()).unwrap();
                let s = ellipse(&spd, &Dd::parse(ratio, ()).unwrap());
                // The same inputs (the double-double values) at 256 bits.
                let up = |x: &Dd| Mp::from_float(&x.to_float(106), p);
                let matq = Material::new(up(matd.nu())).unwrap();
                let spq = matq.speed(up(spd.mr())).unwrap();
                let want = ellipse(&spq, &up(&Dd::parse(ratio, ()).unwrap()));
                let e = rel_eps(&s.k().value, &want.k().value.to_float(256));
                let est = est_eps(&s, ());
                assert!(
                    e <= 10.0 && e <= est,
                    "{at}: k off by {e:.2} eps (estimate {est:.2})"
                );
                let (si, wi) = (s.integrals(), want.integrals());
                let ei = rel_eps(&si.i1.value, &wi.i1.value.to_float(256))
                    .max(rel_eps(&si.i2.value, &wi.i2.value.to_float(256)));
                assert!(ei <= 16.0, "{at}: I1, I2 off by {ei:.2} eps");
                worst_k = worst_k.max(e);
                worst_i = worst_i.max(ei);
                one_step += usize::from(s.iterations() == 1);
                n += 1;
            }
        }
    }
    println!(
        "dd ladder against 256 bits: k worst {worst_k:.2} eps, I1, I2 worst {worst_i:.2} eps; \
         {one_step} of {n} solves in one evaluation"
    );
    assert!(one_step > 0, "the one-step path never ran");
}

/// The eccentricity's bound is absolute and says so (`BoundKind::Absolute`, printed as
/// "absolute error"), every other quantity's relative; and the absolute bound holds against a
/// 256-bit solve, including at a circular contact (M_R = 0, A1/B1 = 1, e = 0), where no
/// relative bound could.
#[test]
fn the_eccentricity_bound_is_absolute_and_labelled() {
    let p = MpPrec::new(256).unwrap();
    for (mr, ratio) in [(0.0, 1.0), (0.0, 0.999), (0.5, 0.5), (0.99, 2.0)] {
        let hi = Material::new(Mp::from_f64(0.25, p))
            .and_then(|m| m.speed(Mp::from_f64(mr, p)))
            .and_then(|sp| solve_ellipse(&sp, &Mp::from_f64(ratio, p), &Options::default()))
            .unwrap();
        let e_ref = hi.e().value.to_f64();
        let lo = ellipse(&Material::new(0.25).unwrap().speed(mr).unwrap(), &ratio);
        assert_eq!(lo.e().kind, BoundKind::Absolute);
        assert_eq!(lo.k().kind, BoundKind::Relative);
        assert_eq!(lo.integrals().i1.kind, BoundKind::Relative);
        assert!(
            format!("{}", lo.e()).contains("(absolute error <= "),
            "{}",
            lo.e()
        );
        assert!(
            format!("{}", lo.k()).contains("(relative error <= "),
            "{}",
            lo.k()
        );
        let err = (lo.e().value - e_ref).abs();
        assert!(
            err <= lo.e().error.to_f64(),
            "M_R = {mr}, A1/B1 = {ratio}: |e - e_ref| = {err:e} above the bound {}",
            lo.e().error
        );
    }
    let sp = Material::new(0.25).unwrap().speed(0.9).unwrap();
    let sol = contact(&sp, &0.05, &0.02, Loading::Load(1000.0), &80e9).unwrap();
    assert_eq!(sol.e().kind, BoundKind::Absolute);
    for q in [sol.a(), sol.b(), sol.p0(), sol.d0()] {
        assert_eq!(q.kind, BoundKind::Relative);
    }
}

/// Every bound the ellipse solve returns holds at any tolerance and any supported curvature
/// ratio: at `f64`, k within its bound of the double-double solve, and I1, I2 within theirs of
/// the double-double integrals at the returned k — at the default tolerance, at 10⁻¹² … 10⁻⁶,
/// and at tolerances looser than the solve works to (0.5 and ∞, met as 2⁻²⁰, so k's bound is
/// at most 2⁻²⁰). The solve carries I1, I2 from its last evaluation to the root; the carry's
/// error belongs in their bounds (without it, A1/B1 = 10⁻⁹⁵ … 10⁻⁷⁰ broke I1's bound by up to
/// 15× at the default tolerance, and a tolerance of ∞ returned I1 of the wrong sign).
#[test]
fn every_bound_holds_at_any_tolerance() {
    let rel = |got: f64, want: &Dd| ((Dd::from_f64(got, ()) - want) / want).abs().to_f64();
    let tolerances = [
        None,
        Some(RelError::from_f64(1e-12)),
        Some(RelError::from_f64(1e-8)),
        Some(RelError::from_f64(1e-6)),
        Some(RelError::from_f64(0.5)),
        Some(RelError::INFINITE),
    ];
    let mut ratios: Vec<f64> = (0..=20)
        .map(|j| format!("1e{}", 10 * j - 100).parse().unwrap())
        .collect();
    ratios.extend([1e-95, 1e-75, 1e-35]);
    let mut worst = 0.0f64;
    for nu in [-0.9, 0.25] {
        for gap in [1.0, 1e-6] {
            let sp = Material::new(nu).unwrap().speed_from_gap(gap).unwrap();
            let spd = Material::new(Dd::from_f64(nu, ()))
                .unwrap()
                .speed_from_gap(Dd::from_f64(gap, ()))
                .unwrap();
            for &ratio in &ratios {
                let want = ellipse(&spd, &Dd::from_f64(ratio, ()));
                for tol in &tolerances {
                    let at = format!("nu={nu} gap={gap} A1/B1={ratio:e} tolerance {tol:?}");
                    let opts = Options {
                        tolerance: *tol,
                        ..Default::default()
                    };
                    let s = solve_ellipse(&sp, &ratio, &opts).unwrap();
                    let ints = integrals(&spd, &Dd::from_f64(s.k().value, ()), &Default::default())
                        .unwrap();
                    for (name, err, bound) in [
                        ("k", rel(s.k().value, &want.k().value), s.k().error),
                        (
                            "I1",
                            rel(s.integrals().i1.value, &ints.i1.value),
                            s.integrals().i1.error,
                        ),
                        (
                            "I2",
                            rel(s.integrals().i2.value, &ints.i2.value),
                            s.integrals().i2.error,
                        ),
                    ] {
                        assert!(
                            err <= bound.to_f64(),
                            "{at}: {name} off by {err:.3e}, bound {bound}"
                        );
                        worst = worst.max(err / bound.to_f64());
                    }
                    if let Some(t) = tol {
                        assert!(
                            s.k().error <= t.min(RelError::pow2(-20)),
                            "{at}: k's bound {} misses the tolerance",
                            s.k().error
                        );
                    }
                }
            }
        }
    }
    println!("worst true error / bound over k, I1, I2: {worst:.3}");
}

/// The pressure field (9) at any finite point: within its bound (relative to p0) of the 256-bit
/// solution's pressure on a grid across the edge, exactly 0 far outside (|x| up to 10³⁰⁰,
/// where x² overflows `f64` and double-double, with a finite bound), and a typed error for a
/// coordinate that is not finite — from the pressure, the displacement and the convolution.
#[test]
fn the_pressure_field_is_finite_everywhere() {
    let problem = |p| ContactProblem {
        speed: Material::new(Mp::from_f64(0.25, p))
            .unwrap()
            .speed(Mp::from_f64(0.9, p))
            .unwrap(),
        radius_along: Mp::from_f64(2.0, p),
        radius_across: Mp::from_f64(1.0, p),
        loading: Loading::Load(Mp::from_f64(2.0, p)),
        shear_modulus: Mp::from_f64(1.5, p),
    };
    let hi = problem(MpPrec::new(256).unwrap())
        .solve(&Options::default())
        .unwrap();
    let sp = Material::new(0.25).unwrap().speed(0.9).unwrap();
    let lo = contact(&sp, &2.0, &1.0, Loading::Load(2.0), &1.5).unwrap();
    let (a, b, p0) = (lo.a().value, lo.b().value, lo.p0().value);
    let mut worst = 0.0f64;
    for s in [
        0.0,
        0.3,
        0.9,
        0.999,
        1.0 - 1e-12,
        1.0,
        1.0 + 1e-12,
        1.001,
        2.0,
    ] {
        for (cx, cy) in [(1.0, 0.0), (0.0, 1.0), (0.6, 0.8)] {
            let (x, y) = (s * cx * a, s * cy * b);
            let got = lo.pressure(&x, &y).unwrap();
            let up = |v: f64| Mp::from_f64(v, MpPrec::new(256).unwrap());
            let want = hi.pressure(&up(x), &up(y)).unwrap().value.to_f64();
            let err = (got.value - want).abs() / p0;
            assert!(
                err <= got.error.to_f64(),
                "at ({x:e}, {y:e}): off by {err:e} p0, bound {}",
                got.error
            );
            worst = worst.max(err / got.error.to_f64().max(f64::MIN_POSITIVE));
        }
    }
    for x in [1e10, 1e155, 1e200, -1e300, f64::MAX] {
        let got = lo.pressure(&x, &0.5).unwrap();
        assert!(
            got.value == 0.0 && got.error.is_finite(),
            "at x = {x:e}: {got:?}"
        );
        let dd = Dd::from_f64(x, ());
        let got = lo_dd().pressure(&dd, &dd).unwrap();
        assert!(
            got.value.is_zero() && got.error.is_finite(),
            "dd at {x:e}: {got:?}"
        );
    }
    let far = Mp::parse("1e1000", MpPrec::new(256).unwrap()).unwrap();
    let got = hi.pressure(&far, &far).unwrap();
    assert!(got.value.is_zero() && got.error.is_finite());
    let tol = RelError::from_f64(1e-10);
    for (x, y) in [
        (f64::NAN, 0.0),
        (0.0, f64::INFINITY),
        (f64::NEG_INFINITY, f64::NAN),
    ] {
        for r in [
            lo.pressure(&x, &y),
            lo.displacement(&x, &y, &tol),
            lo.convolution(&x, &y, &tol),
        ] {
            assert!(
                matches!(r, Err(moving_hertz::Error::NotFinite { .. })),
                "({x}, {y}): {r:?}"
            );
        }
    }
    println!("pressure: worst error / bound {worst:.3}");
}

/// The f64 problem of `the_pressure_field_is_finite_everywhere` at double-double.
fn lo_dd() -> ContactSolution<Dd> {
    let d = |v: f64| Dd::from_f64(v, ());
    let sp = Material::new(d(0.25)).unwrap().speed(d(0.9)).unwrap();
    contact(&sp, &d(2.0), &d(1.0), Loading::Load(d(2.0)), &d(1.5)).unwrap()
}

/// Inputs at the ends of the format whose results fit: solved within every bound of the same
/// problem at 256 bits (a load of 1e308 with μ = 1e100 failed with "a = inf", its cube formed
/// from 3P, at double-double with NaN; an approach of 1e300 with R2 = 1e10 overflowed a² at
/// `f64`, and one of 1e-250 with R2 = 1e-200 underflowed it at double-double). A radius whose curvature 1/(2R) is not a normal number is
/// refused naming the radius as given; a result beyond the format names the result.
#[test]
fn extreme_scales_solve_or_name_the_input() {
    fn problem<T: Real>(p: T::Prec, r: [f64; 3], load: Loading<f64>) -> ContactProblem<T> {
        let x = |v: f64| T::from_f64(v, p);
        ContactProblem {
            speed: Material::new(x(0.25)).unwrap().speed(x(0.5)).unwrap(),
            radius_along: x(r[0]),
            radius_across: x(r[1]),
            loading: match load {
                Loading::Load(v) => Loading::Load(x(v)),
                Loading::Approach(v) => Loading::Approach(x(v)),
                other => panic!("a loading this test does not convert: {other:?}"),
            },
            shear_modulus: x(r[2]),
        }
    }
    fn check<T: Real>(p: T::Prec, r: [f64; 3], load: Loading<f64>) {
        let got = problem::<T>(p, r, load.clone())
            .solve(&Options::default())
            .unwrap();
        let hi = MpPrec::new(256).unwrap();
        let want = problem::<Mp>(hi, r, load)
            .solve(&Options::default())
            .unwrap();
        for (name, g, w) in [
            ("a", got.a(), want.a()),
            ("b", got.b(), want.b()),
            ("p0", got.p0(), want.p0()),
            ("d0", got.d0(), want.d0()),
            ("load", got.load(), want.load()),
        ] {
            let e = rel_eps(&g.value, &w.value.to_float(256)) * T::epsilon(p).to_f64();
            assert!(
                e <= g.error.to_f64(),
                "{r:?}: {name} off by {e:e}, bound {}",
                g.error
            );
        }
    }
    check::<f64>((), [2.0, 1.0, 1e100], Loading::Load(1e308));
    check::<Dd>((), [2.0, 1.0, 1e100], Loading::Load(1e308));
    check::<f64>((), [2.0, 1.0, 1e-300], Loading::Load(1e-10));
    check::<f64>((), [2e10, 1e10, 1e-200], Loading::Approach(1e300));
    check::<Dd>((), [1e-200, 1e-200, 1e200], Loading::Approach(1e-250));
    let refused = |r: Result<ContactSolution<f64>>, name: &str, value: &str| match r {
        Err(e @ moving_hertz::Error::Domain { .. }) => {
            let text = e.to_string();
            assert!(text.contains(name) && text.contains(value), "{text}");
        }
        other => panic!("expected a domain error naming {name}, got {other:?}"),
    };
    let solve = |r: [f64; 3], l| problem::<f64>((), r, l).solve(&Options::default());
    refused(
        solve([1.797e308, 1.0, 1.0], Loading::Load(1.0)),
        "R1",
        "1.797e308",
    );
    refused(solve([1.0, 5e307, 1.0], Loading::Load(1.0)), "R2", "5e307");
    refused(solve([2.0, 1.0, 1e-300], Loading::Load(1e308)), "d0", "inf");
    match problem::<Dd>((), [1e300, 1.0, 1.0], Loading::Load(1.0)).solve(&Options::default()) {
        Err(e @ moving_hertz::Error::Domain { .. }) => assert!(e.to_string().contains("R1")),
        other => panic!("double-double R1 = 1e300: {other:?}"),
    }
}

/// The problem of [`displacement_holds_its_bound_near_and_far`] at the working type's rounding of
/// the f64 inputs (so that every precision solves the same problem).
fn far_problem<T: Real>(p: T::Prec, nu: f64, mr: f64, r1: f64) -> ContactSolution<T> {
    let v = |x: f64| T::from_f64(x, p);
    let sp = Material::new(v(nu)).unwrap().speed(v(mr)).unwrap();
    contact(&sp, &v(r1), &v(1.0), Loading::Load(v(2.0)), &v(1.5)).unwrap()
}

/// The surface displacement outside the contact, near it (points within max(a, b) of the centre
/// of a contact 10³ times longer than wide) and far from it (10 to 2⁶⁰ semi-axes), at speeds up
/// to M_R = 1 − 10⁻¹²: at `f64` and double-double within its bound of the same problem solved
/// at 320 bits, and 2⁶⁰ semi-axes away within a few ε of the point load's displacement
/// P·g/(2πμr) by the Green's function (4) alone (relative to u, the neglected terms are
/// (a/r)²/(1 − M_R²) and below). Beyond
/// 2^(bits + 20)·max(a, b) the point is refused, named as given.
#[test]
fn displacement_holds_its_bound_near_and_far() {
    use moving_hertz::physics::GreenFunction;
    let q = MpPrec::new(320).unwrap();
    let tol = RelError::from_f64(1e-12);
    let mut worst: f64 = 0.0;
    for (nu, mr, r1) in [
        (0.25, 0.0, 2.0),
        (0.25, 0.9, 2.0),
        (0.25, 1.0 - 1e-7, 2.0),
        (0.5, 1.0 - 1e-9, 1.0),
        (0.25, 1.0 - 1e-12, 2.0),
    ] {
        let lo: ContactSolution<f64> = far_problem((), nu, mr, r1);
        let dd: ContactSolution<Dd> = far_problem((), nu, mr, r1);
        let hi: ContactSolution<Mp> = far_problem(q, nu, mr, r1);
        let (a, b) = (lo.a().value, lo.b().value);
        let mut pts = vec![
            (0.3 * a, 1.5 * b),
            (0.99 * a, 0.2 * b),
            (-0.7 * a, -0.75 * b),
            (0.0, 3.0 * b),
            (1.0001 * a, 0.0),
            (-2.0 * a, 1e-3 * b),
            (1.5 * a, 1.5 * b),
            (0.0, 0.3 * a),
            (0.1 * a, 0.2 * a),
            (-0.6 * a, 1.2 * a),
        ];
        for e in [1, 4, 12, 30, 60] {
            let r = 2f64.powi(e) * a;
            pts.extend([(r, 0.0), (0.0, -r), (0.6 * r, 0.8 * r), (-r, 1e-3 * r)]);
        }
        for (x, y) in pts {
            let truth = hi
                .displacement(
                    &Mp::from_f64(x, q),
                    &Mp::from_f64(y, q),
                    &RelError::from_f64(1e-40),
                )
                .unwrap();
            let d0 = lo.d0().value;
            let got = lo.displacement(&x, &y, &tol).unwrap();
            let err = (got.value - truth.value.to_f64()).abs() / d0;
            let r = err / got.error.to_f64();
            worst = worst.max(r);
            assert!(
                r <= 1.0,
                "M_R={mr} f64 at ({x:e},{y:e}): {got:?} off by {err:e}"
            );
            let (xd, yd) = (Dd::from_f64(x, ()), Dd::from_f64(y, ()));
            let got = dd
                .displacement(&xd, &yd, &RelError::from_f64(1e-24))
                .unwrap();
            let diff = Mp::from_float(&got.value.to_float(320), q) - truth.value.clone();
            let err = diff.abs().to_f64() / d0;
            assert!(
                err <= got.error.to_f64(),
                "M_R={mr} dd at ({x:e},{y:e}): off by {err:e}, bound {}",
                got.error
            );
            let rr = (x * x + y * y).sqrt();
            if rr >= 1e15 * a {
                // The point load at the centre: u = P g(V|sin θ|)/(2πμr), up to terms of order
                // (a/(r·√(1 − M_R²)))² (g peaks with width √(1 − M_R²) in angle).
                let s = y / rr;
                let t = lo.problem().speed.mr2() * s * s;
                let omt = lo.problem().speed.one_minus_mr2()
                    + lo.problem().speed.mr2() * (x / rr).powi(2);
                let g = GreenFunction::new(lo.problem().speed.material()).g_normalised(&t, &omt);
                let point = 2.0 * g / (2.0 * std::f64::consts::PI * 1.5 * rr);
                let got = lo.displacement(&x, &y, &tol).unwrap().value;
                assert!(
                    ((got - point) / point).abs() <= 1e-14,
                    "M_R={mr} at ({x:e},{y:e}): {got:e} against the point load's {point:e}"
                );
            }
        }
        let m = a.max(b);
        for (x, y) in [(2f64.powi(75) * m, 0.0), (1e300, -1e300)] {
            let r = lo.displacement(&x, &y, &tol);
            assert!(
                matches!(&r, Err(Error::Domain { value, .. })
                    if *value == format!("({}, {})", x.to_decimal(), y.to_decimal())),
                "({x:e}, {y:e}): {r:?}"
            );
        }
    }
    println!("displacement: worst f64 error / bound {worst:.3}");
}

/// A seed for k that is not a positive finite number is refused before any work, named, at
/// every precision (not ignored in favour of the static ellipse).
#[test]
fn a_seed_must_be_a_positive_number() {
    fn check<T: Real>(p: T::Prec) {
        let sp = Material::new(T::from_f64(0.25, p))
            .unwrap()
            .speed(T::from_f64(0.5, p))
            .unwrap();
        let ratio = T::from_f64(2.0, p);
        for (seed, finite) in [
            (f64::NAN, false),
            (f64::INFINITY, false),
            (0.0, true),
            (-1.0, true),
        ] {
            let o = Options {
                seed: Some(T::from_f64(seed, p)),
                ..Default::default()
            };
            let r = solve_ellipse(&sp, &ratio, &o);
            let named = match &r {
                Err(Error::NotFinite { name, .. }) => !finite && name.contains("seed"),
                Err(Error::Domain { name, bound, .. }) => {
                    finite && name.contains("seed") && *bound == "(0, inf)"
                }
                _ => false,
            };
            assert!(named, "seed {seed}: {r:?}");
        }
        let o = Options {
            seed: Some(T::from_f64(0.3, p)),
            ..Default::default()
        };
        assert!(solve_ellipse(&sp, &ratio, &o).is_ok());
    }
    check::<f64>(());
    check::<Dd>(());
    check::<Mp>(MpPrec::new(256).unwrap());
}
