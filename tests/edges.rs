//! The library's reproducers of issue 20 (items 1, 2 and 7) as regression tests: extreme
//! curvature ratios refused before any work as a typed error naming the ratio and the
//! supported range; the ends of that range solved with an honest bound (checked against 256
//! bits); an integral or derivative that underflows the working type refused, not returned.

use moving_hertz::prelude::*;
use moving_hertz::{integrals, solve_ellipse, Error};

fn speed<T: Real>(nu: &str, gap: &str, p: T::Prec) -> Speed<T> {
    Material::parse(nu, p).unwrap().parse_gap(gap).unwrap()
}

/// The ratio's typed error: `Error::Domain` naming A1/B1 and the supported range.
fn refused_ratio<T: Real>(r: moving_hertz::Result<moving_hertz::Ellipse<T>>) {
    match r {
        Err(Error::Domain { name, bound, .. }) => {
            assert!(
                name.contains("A1/B1") && bound.contains("[1e-100, 1e100]"),
                "{name}: {bound}"
            )
        }
        other => panic!("expected the ratio's domain error, got {other:?}"),
    }
}

/// Item 1 (I1 = NaN returned as a success at A1/B1 ~ 1e-118 near c_R), item 2 (an estimate of
/// ∞ or 6.8e-3 at A1/B1 = 6.5e159) and item 7 (a minute of Newton at 256 bits, then no
/// convergence, at 1e-400): each refused before any work at every precision.
#[test]
fn extreme_ratios_are_refused_before_any_work() {
    let sp = speed::<Dd>("0.4994206", "8.47e-22", ());
    refused_ratio(solve_ellipse(
        &sp,
        &Dd::parse("4.12e-118", ()).unwrap(),
        &Options::default(),
    ));
    let sp = speed::<f64>("0.2", "1e-10", ());
    refused_ratio(solve_ellipse(&sp, &1e-118, &Options::default()));
    for nu in ["0.5", "0.2"] {
        let sp = Material::<f64>::parse(nu, ()).unwrap().speed(0.0).unwrap();
        refused_ratio(solve_ellipse(&sp, &6.5e159, &Options::default()));
    }
    let p = MpPrec::new(256).unwrap();
    let sp = Material::<Mp>::parse("0.2", p)
        .unwrap()
        .parse_speed("0.5")
        .unwrap();
    let opts = Options::default();
    refused_ratio(solve_ellipse(&sp, &Mp::parse("1e-400", p).unwrap(), &opts));
    let problem = ContactProblem {
        speed: sp,
        radius_along: Mp::parse("1e400", p).unwrap(),
        radius_across: Mp::parse("1", p).unwrap(),
        loading: Loading::Load(Mp::parse("1", p).unwrap()),
        shear_modulus: Mp::parse("1", p).unwrap(),
    };
    match problem.solve(&opts) {
        Err(Error::Domain { name, .. }) => assert!(name.contains("A1/B1")),
        other => panic!("contact with R2/R1 = 1e-400: {other:?}"),
    }
}

/// The ends of the supported range near the Rayleigh speed (k ~ 1e-53 and 1e51): at `f64` and
/// double-double the bound on k holds against the 256-bit solve of the same inputs (the
/// lower precision's ν, gap and ratio, exactly).
#[test]
fn the_ends_of_the_range_have_honest_bounds() {
    for (nu, gap, ratio) in [("0.2", "1e-10", "1e-100"), ("0.5", "8.47e-22", "1e100")] {
        let sp = speed::<f64>(nu, gap, ());
        let r = ratio.parse::<f64>().unwrap();
        let got = solve_ellipse(&sp, &r, &Options::default())
            .unwrap()
            .k()
            .clone();
        let up = |x: &f64| x.to_float(256);
        check_against_256(&got, [up(sp.material().nu()), up(sp.gap()), up(&r)], "f64");
        let sp = speed::<Dd>(nu, gap, ());
        let r = Dd::parse(ratio, ()).unwrap();
        let got = solve_ellipse(&sp, &r, &Options::default())
            .unwrap()
            .k()
            .clone();
        let up = |x: &Dd| x.to_float(256);
        check_against_256(&got, [up(sp.material().nu()), up(sp.gap()), up(&r)], "dd");
    }
}

/// |k − k₂₅₆|/k₂₅₆ within the bound of `got`, k₂₅₆ solved at 256 bits for ν, gap, ratio.
fn check_against_256<T: Real>(got: &Estimated<T>, inputs: [rug::Float; 3], label: &str) {
    let p = MpPrec::new(256).unwrap();
    let [nu, gap, ratio] = inputs.map(|x| Mp::from_float(&x, p));
    let sp = Material::new(nu).unwrap().speed_from_gap(gap).unwrap();
    let want = solve_ellipse(&sp, &ratio, &Options::default())
        .unwrap()
        .k()
        .value
        .to_float(256);
    let err = rug::Float::with_val(256, (got.value.to_float(256) - &want) / &want)
        .abs()
        .to_f64();
    let bound = got.error.to_f64();
    assert!(
        err <= bound,
        "{label} at A1/B1 = {ratio:?}: error {err:e} > bound {bound:e}"
    );
}

/// k to a few ε where |ln k| is large (the Newton iteration runs in λ = ln k, whose rounding,
/// half an ulp of λ, would leave k a relative error up to |λ|ε/2 without the final step in k
/// itself): at A1/B1 = 10^±100 (|λ| ≈ 118), at 1 − M_R = 10⁻²⁵⁰ (`f64`, λ ≈ −143) and, at 256
/// bits, at 1 − M_R = 10⁻¹⁰⁰⁰ and 10⁻⁵⁰⁰⁰ (λ ≈ −575, −2878): k within 4ε of the solve 64 bits
/// higher of the same inputs, its bound within 64ε.
#[test]
fn k_is_within_a_few_eps_where_ln_k_is_large() {
    fn check<T: Real>(p: T::Prec, nu: &str, gap: &str, ratio: &str) {
        let bits = T::bits(p);
        let sp = speed::<T>(nu, gap, p);
        let r = T::parse(ratio, p).unwrap();
        let got = solve_ellipse(&sp, &r, &Options::default())
            .unwrap()
            .k()
            .clone();
        let hp = MpPrec::new(u64::from(bits) + 64).unwrap();
        let up = |x: &T| Mp::from_float(&x.to_float(bits), hp);
        let sp_hi = Material::new(up(sp.material().nu()))
            .and_then(|m| m.speed_from_gap(up(sp.gap())))
            .unwrap();
        let want = solve_ellipse(&sp_hi, &up(&r), &Options::default())
            .unwrap()
            .k()
            .value
            .clone();
        let want = want.to_float(bits + 64);
        let err = rug::Float::with_val(bits + 64, (got.value.to_float(bits + 64) - &want) / &want)
            .abs()
            .to_f64()
            / T::epsilon(p).to_f64();
        let bound = got.error.to_f64() / T::epsilon(p).to_f64();
        let at = format!("{bits} bits, nu = {nu}, 1 - M_R = {gap}, A1/B1 = {ratio}");
        assert!(err <= 4.0, "{at}: k off by {err:.2} eps");
        assert!(
            err <= bound && bound <= 64.0,
            "{at}: error {err:.2} eps, bound {bound:.2} eps"
        );
    }
    for (nu, gap, ratio) in [
        ("0.2", "0.5", "1e-100"),
        ("0.2", "0.5", "1e100"),
        ("0.5", "1e-15", "1e-100"),
        ("-0.9", "1e-10", "1e100"),
    ] {
        check::<f64>((), nu, gap, ratio);
        check::<Dd>((), nu, gap, ratio);
        check::<Mp>(MpPrec::new(256).unwrap(), nu, gap, ratio);
    }
    check::<f64>((), "0.25", "1e-250", "2");
    for gap in ["1e-1000", "1e-5000"] {
        check::<Mp>(MpPrec::new(256).unwrap(), "0.25", gap, "2");
    }
}

/// Item 2's library half: dI1/dk ~ k⁻⁴ underflows `f64` at k = 1.8e83; refused as a typed
/// error before any work (k⁴ is not a normal number; a result that underflows anyway is refused
/// after the work); at 256 bits it is a normal number.
#[test]
fn an_underflowing_derivative_is_refused() {
    let opts = IntegralOptions {
        derivatives: true,
        ..Default::default()
    };
    let sp = Material::new(0.2).unwrap().speed(0.5).unwrap();
    match integrals(&sp, &1.8e83, &opts) {
        Err(Error::Domain { name, bound, .. }) => {
            assert!(
                name.starts_with("axis ratio k") && bound.contains("k^4"),
                "{name}"
            )
        }
        other => panic!("k = 1.8e83 at f64: {other:?}"),
    }
    let p = MpPrec::new(256).unwrap();
    let sp = Material::<Mp>::parse("0.2", p)
        .unwrap()
        .parse_speed("0.5")
        .unwrap();
    let r = integrals(&sp, &Mp::parse("1.8e83", p).unwrap(), &opts).unwrap();
    let d = r.di1_dk.unwrap().value;
    assert!(d.is_negative() && d.is_finite(), "dI1/dk = {d:?}");
}

/// Tiny speeds and axis ratios at `f64` (cases from tests/properties.rs): at M_R = 1e-100 and
/// k = 1e-100 the subtracted integrand's M_R²·v² underflows, and at k = 1e-110 an integrand
/// would be NaN. k⁴ and 1/k⁴ must be normal numbers (refused before any work), and inside that
/// range the integrals hold their bound against 256 bits, with every speed down to 0.
#[test]
fn tiny_k_and_tiny_speed_hold_their_bounds() {
    for k in [1e-100, 1e-110, 1e110] {
        let sp = Material::new(0.25).unwrap().speed(0.5).unwrap();
        match integrals(&sp, &k, &IntegralOptions::default()) {
            Err(Error::Domain { name, .. }) => assert!(name.starts_with("axis ratio k")),
            other => panic!("k = {k:e} at f64: {other:?}"),
        }
    }
    let p = MpPrec::new(256).unwrap();
    for (mr, k) in [(1e-100, 1e-76), (0.0, 1e-76), (1e-100, 1e76), (0.5, 1e-60)] {
        let sp = Material::new(0.25).unwrap().speed(mr).unwrap();
        let got = integrals(&sp, &k, &IntegralOptions::default()).unwrap();
        let sp = Material::new(Mp::from_f64(0.25, p)).unwrap();
        let sp = sp.speed(Mp::from_f64(mr, p)).unwrap();
        let want = integrals(&sp, &Mp::from_f64(k, p), &IntegralOptions::default()).unwrap();
        for (g, w) in [(&got.i1, &want.i1), (&got.i2, &want.i2)] {
            let w = w.value.to_f64();
            let err = ((g.value - w) / w).abs();
            assert!(
                err <= g.error.to_f64(),
                "M_R = {mr:e}, k = {k:e}: {err:e} > {}",
                g.error
            );
        }
    }
}

/// Above the rules' limit (32,768 bits) the ellipse solve, a sweep and a contact solve refuse
/// before any work, naming the precision and the bound (the ladder's lower stages would
/// otherwise run for a minute first).
#[test]
fn precision_above_the_rules_limit_is_refused_first() {
    let p = MpPrec::new(32769).unwrap();
    let x = |s: &str| Mp::parse(s, p).unwrap();
    let speed = Material::new(x("0.25")).unwrap().speed(x("0.5")).unwrap();
    let t = std::time::Instant::now();
    let refused = |r: std::result::Result<(), Error>| match r {
        Err(e @ Error::Precision { bits: 32769, .. }) => assert!(e.to_string().contains("32768")),
        other => panic!("expected a precision error, got {other:?}"),
    };
    refused(solve_ellipse(&speed, &x("2"), &Options::default()).map(drop));
    let points = moving_hertz::sweep::EllipsePoint::grid(
        &[x("0.25")],
        &[moving_hertz::sweep::SpeedGiven::Mr(x("0.5"))],
        &[x("2")],
    );
    let swept = moving_hertz::sweep::ellipses(&points, &Options::default());
    refused(swept.into_iter().next().unwrap().map(drop));
    assert!(
        t.elapsed().as_secs_f64() < 1.0,
        "refused after {:?}",
        t.elapsed()
    );
}

/// Near the Rayleigh speed the root falls far below the static seed, k ~ (1 − M_R)^{1/4} (I2 ~
/// (1 − M_R)^{−1/2}, I1 ~ k^{−2}): λ = ln k ≈ −576 at 1 − M_R = 10⁻¹⁰⁰⁰. An unbracketed Newton
/// step in λ is cut to 2 (a factor e² in k), a reach that doubles after each cut step (a fixed
/// reach of 2 would need more than Newton's 200 evaluations below 1 − M_R ≈ 10⁻⁶⁵⁰), so the
/// solve takes a few dozen evaluations at any gap. The roots are checked against the law k·(1 − M_R)^{−1/4} =
/// constant, whose corrections are O((1 − M_R)^{1/2}) relative: at 256 bits the solves at
/// 10⁻¹⁰⁰⁰ … 10⁻¹⁰⁰⁰⁰⁰ must agree with the one at 10⁻³⁰⁰ within their two bounds. At `f64`
/// (1 − M_R = 10⁻²⁵⁰, k ~ 10⁻⁶³ and at A1/B1 = 10⁵⁰) the bound holds against 256 bits.
#[test]
fn roots_far_below_the_seed_near_the_rayleigh_speed() {
    let p = MpPrec::new(256).unwrap();
    let scaled = |gap: &str| {
        let sp = speed::<Mp>("0.25", gap, p);
        let s = solve_ellipse(&sp, &Mp::from_i64(2, p), &Options::default()).unwrap();
        assert!(
            s.iterations() <= 40,
            "gap {gap}: {} evaluations",
            s.iterations()
        );
        let g = Mp::parse(gap, p).unwrap();
        let c = s.k().value.clone() / g.sqrt().sqrt();
        (c.to_float(256), s.k().error.to_f64())
    };
    let (c0, e0) = scaled("1e-300");
    for gap in ["1e-1000", "1e-5000", "1e-100000"] {
        let (c, e) = scaled(gap);
        let d = rug::Float::with_val(256, (c - &c0) / &c0).abs().to_f64();
        assert!(
            d <= e + e0,
            "gap {gap}: k/gap^(1/4) moved by {d:e} (bounds {e:e} + {e0:e})"
        );
    }
    for ratio in ["2", "1e50"] {
        let sp = speed::<f64>("0.25", "1e-250", ());
        let r = ratio.parse::<f64>().unwrap();
        let s = solve_ellipse(&sp, &r, &Options::default()).unwrap();
        assert!(
            s.iterations() <= 20,
            "f64 A1/B1 = {ratio}: {} evaluations",
            s.iterations()
        );
        let up = |x: &f64| x.to_float(256);
        check_against_256(s.k(), [up(sp.material().nu()), up(sp.gap()), up(&r)], "f64");
    }
}

/// The full contact solution at 1 − M_R = 10⁻⁷⁰⁰ (k ≈ 10⁻¹⁷⁵, I1 ≈ 10³⁵⁰) and 10⁻¹⁰⁰⁰⁰
/// (k ≈ 10⁻²⁵⁰⁰): a, b, p0 and d0 within their bounds of the same problem at 320 bits.
/// The sensitivity of I1 to k's error, k·I1′/I1 ≈ −2, must be formed at the working precision
/// (k, I1′ and I1 each lie outside the `f64` range, so that converting them one by one would make
/// a's bound infinite), and J0 of (32) must not need panels graded down to ε and to k (their
/// number grows with log(1/ε) and |log k| up to the evaluation cap).
#[test]
fn contact_far_below_the_f64_range_near_the_rayleigh_speed() {
    for gap in ["1e-700", "1e-10000"] {
        contact_at_gap(gap);
    }
}

fn contact_at_gap(gap: &str) {
    let solve = |bits: u32| {
        let p = MpPrec::new(bits.into()).unwrap();
        let x = |s: &str| Mp::parse(s, p).unwrap();
        ContactProblem {
            speed: speed::<Mp>("0.3", gap, p),
            radius_along: x("0.05"),
            radius_across: x("0.02"),
            loading: Loading::Load(x("1000")),
            shear_modulus: x("80e9"),
        }
        .solve(&Options::default())
        .unwrap()
    };
    let (lo, hi) = (solve(256), solve(320));
    for (name, got, want) in [
        ("a", lo.a(), hi.a()),
        ("b", lo.b(), hi.b()),
        ("p0", lo.p0(), hi.p0()),
        ("d0", lo.d0(), hi.d0()),
    ] {
        let w = want.value.to_float(320);
        let err = rug::Float::with_val(320, (got.value.to_float(320) - &w) / &w)
            .abs()
            .to_f64();
        let bound = got.error.to_f64();
        assert!(
            bound < 1e-70 && err <= bound,
            "gap {gap}, {name}: error {err:e}, bound {bound:e}"
        );
    }
}
