//! The direct route (sections 6–7): quadrature of (46)–(47), the subtracted form (48) with S by
//! (53), against independent references (tools/gen_integrals.py: mpmath quadrature of (34) with
//! Γ from (5)–(6) as printed, 40 digits), the static limit (43) and each other.

use crate::common;

use common::{mpmath_cases, read_csv, reference, rel_eps, MpmathCase};
use moving_hertz::numerics::elliptic::{ellipbd_mc, ellipke_mc, heuman_lambda_c_mc};
use moving_hertz::physics::Material;
use moving_hertz::prelude::*;
use moving_hertz::routes::{direct, AxisRatio, Evaluation};

// ---------------------------------------------------------------------------------------------
// The tests' reference quadrature of J0 alone (the library forms J0 as k² I1 + I2, or with the
// adaptive route's five integrals)

use super::{limits, DirectSetup};
use crate::numerics::quadrature::{integrate, integrate_vec_plus, Quadrature};
use crate::routes::beyond_exponent_range;

impl<T: Real> DirectSetup<T> {
    /// The right half's peak at v = ±ik, when it is taken out of J0 ([`approach_integral`]):
    /// where k² is below ε of the working precision, so that no panel needs grading about k
    /// (the remainder's kink changes the integral by about k² ln(1/k)). Above, panels graded
    /// about k cost at most a quarter of the working bits and evaluate the cheaper plain
    /// integrand.
    fn right_peak(&self) -> Option<RightPeak<T>> {
        let p = self.k.prec();
        let one = T::one(p);
        if self.k2 > T::epsilon(p) {
            return None;
        }
        let ops0 = one.clone() - &self.k2;
        let t0 = -(self.mr2.clone() * &self.k2 / &ops0);
        let r0 = ops0.clone().sqrt();
        let e0 = (one.clone() - self.eps2.clone() * &self.k2).recip();
        let g0 = self.green.g_regular(&t0);
        let b0 = self.two_pi.clone() * &g0 * &r0 * &e0;
        // ∫_0^1 dv/√(v² + k²) = asinh(1/k) = ln(1 + √(1 + k²)) − ln k.
        let log_integral = (one.clone() + (one + &self.k2).sqrt()).ln() - self.k.clone().ln();
        Some(RightPeak {
            ops0,
            t0,
            r0,
            e0,
            g0,
            value: b0 * log_integral,
        })
    }

    /// J0's right integrand with the peak taken out: (b(σ) − b(σ0))·(σ + k²)^{−1/2} =
    /// D[b]·√(σ + k²), σ = v², σ0 = −k², for b = 2πG(t)·r·e, t = M_R²σ/(1 + σ),
    /// r = √(1 + σ), e = 1/(1 + ε²σ): D[b] = 2π(D[G(t)]·r·e + G(t0)·(D[r]·e + r0·D[e])) with
    /// D[G(t)] = DG(t, t0)·M_R²/((1 + σ)(1 + σ0)), D[r] = 1/(r + r0), D[e] = −ε² e e0. No term
    /// cancels; a few ε relative.
    fn right_divided(&self, peak: &RightPeak<T>, v: &T) -> T {
        let [v2, ops, t, h] = self.right_node(v);
        let r = ops.clone().sqrt();
        let e = (T::one(v.prec()) + self.eps2.clone() * v2).recip();
        let dt = self.mr2.clone() / (ops * &peak.ops0);
        let dg = self.green.g_divided_difference(&t, &peak.t0) * dt;
        let de = -(self.eps2.clone() * &e * &peak.e0);
        let dre = e.clone() / (r.clone() + &peak.r0) + peak.r0.clone() * de;
        let db = self.two_pi.clone() * (dg * r * e + peak.g0.clone() * dre);
        db * h.sqrt()
    }
}

/// The right half's peak at v = ik (σ0 = −k²): the constants of
/// [`DirectSetup::right_divided`] and b(σ0)·asinh(1/k).
struct RightPeak<T: Real> {
    /// 1 + σ0 = 1 − k².
    ops0: T,
    /// t0 = M_R²σ0/(1 + σ0).
    t0: T,
    /// r0 = √(1 + σ0), e0 = 1/(1 + ε²σ0), G(t0).
    r0: T,
    e0: T,
    g0: T,
    value: T,
}

/// `c + ∫f` to relative tolerance `tol` judged against the sum (the one-component
/// `integrate_vec_plus`): the reference's remainder integrands after a closed-form part.
fn integrate_plus<T: Real>(
    mut f: impl FnMut(&T) -> T,
    points: &[T],
    offset: &T,
    tol: &T,
    limits: crate::numerics::quadrature::Limits,
) -> Result<Quadrature<T>> {
    let q = integrate_vec_plus(
        |x: &T| [f(x)],
        points,
        std::array::from_ref(offset),
        tol,
        limits,
    )?;
    let ([value], [error]) = (q.values, q.errors);
    Ok(Quadrature {
        value,
        error,
        evaluations: q.evaluations,
    })
}

/// J0 of (32) alone, J0 = ∫_0^π g(V sin φ)/(k² cos²φ + sin²φ)^{1/2} dφ in the variables of the
/// module docs (left: ∫_0^1 B(s) u^{−1/2}/(s + ε²) dw; right: ∫_0^1 b(σ)(σ + k²)^{−1/2} dv), by
/// adaptive quadrature with its two peaks taken out in closed form, so that the work depends
/// on neither the gap 1 − M_R nor k once they are small:
///
/// ```text
/// left  (ε ≤ 1/2, kε ≤ 1/2):  n(s0)·atan(1/ε)/ε + ∫_0^1 (n(s) − n(s0))/(s − s0) dw,  s0 = −ε²;
/// right (k² < ε):             b(σ0)·asinh(1/k) + ∫_0^1 (b(σ) − b(σ0))/√(σ + k²) dv,  σ0 = −k²,
/// ```
///
/// n = B u^{−1/2}. Both remainders are formed without cancellation
/// (`DirectSetup::left_pole_parts`, `DirectSetup::right_divided`). The left one is
/// analytic in |Im w| < min(1/k, δ), δ ≥ 0.3 the distance of G's branch points; the right one
/// keeps a kink √(v² + k²) whose effect, about k² ln(1/k), is below the working ε. Where
/// k² ≥ ε the right half is the plain integrand on panels graded about k.
/// Relative tolerance `tol` for each half (0: the precision's floor); the returned bound adds
/// the halves' estimated errors and 8ε for the closed forms. Accuracy: within 16ε of mpmath
/// and of the returned bound, at 1 − M_R from 1 to 2⁻¹²⁰ and k from 2⁻²⁰⁰ to 1000, and within
/// the bound of [`contact_integrals`]' J0 at 64 bits more down to 1 − M_R = 10⁻¹⁰⁰⁰⁰⁰
/// (`tests/unit/direct.rs`). The contact solution and [`crate::Evaluator`] form J0 as k² I1 + I2
/// from I1, I2 instead (no quadrature of its own); this route is their independent reference.
/// [`contact_integrals`] computes J0 together with I1, I2 and their derivatives, its right
/// half graded about k instead.
pub fn approach_integral<T: Real>(
    speed: &Speed<T>,
    axes: &AxisRatio<T>,
    tol: &T,
) -> Result<Estimated<T>> {
    let s = DirectSetup::new(speed, axes);
    let p = tol.prec();
    let lim = limits(tol);
    let half = tol.clone().mul_pow2(-1);
    let left = match s.left_pole() {
        Some(pole) => {
            let f = |w: &T| {
                let (_, db, phi, dphi) = s.left_pole_parts(&pole, w);
                db * &phi[0] + pole.b0.clone() * &dphi[0]
            };
            let pts = s.breakpoints(&s.left_scales(true), lim)?;
            integrate_plus(f, &pts, &pole.parts[2], &half, lim)?
        }
        None => {
            let f = |w: &T| {
                let n = s.left_node(w);
                s.left_factor(&n) / &n[3].clone().sqrt()
            };
            integrate(f, &s.breakpoints(&s.left_scales(false), lim)?, &half, lim)?
        }
    };
    let right = match s.right_peak() {
        Some(peak) => {
            let f = |v: &T| s.right_divided(&peak, v);
            integrate_plus(f, &s.breakpoints(&[], lim)?, &peak.value, &half, lim)?
        }
        None => {
            let f = |v: &T| {
                let n = s.right_node(v);
                s.right_factor(&n) / &n[3].clone().sqrt()
            };
            integrate(f, &s.breakpoints(&s.right_scales(), lim)?, &half, lim)?
        }
    };
    let j0 = left.value + &right.value;
    if !j0.is_finite() || !j0.is_positive() {
        return Err(beyond_exponent_range(&s.k));
    }
    let rel = (left.error + &right.error) / &j0 + &T::epsilon(p).mul_i64(8);
    Ok(Estimated::new(j0, RelError::of(&rel)))
}

/// Checks a result against the reference: error ≤ `bound` ε, and within the reported estimate
/// (plus the rounding of the reference comparison itself).
fn check<T: Real>(r: &Evaluation<T>, c: &MpmathCase, bound: f64, label: &str) -> f64 {
    let e1 = rel_eps(&r.i1, &c.i1);
    let e2 = rel_eps(&r.i2, &c.i2);
    let est = (r.error_estimate.clone() / T::epsilon(r.i1.prec())).to_f64();
    let worst = e1.max(e2);
    assert!(
        worst <= bound,
        "{label} {:?} nu={} M_R={} k={}: errors {e1:.2} {e2:.2} eps",
        r.route,
        c.nu,
        c.mr,
        c.k
    );
    assert!(
        worst <= est + 1.0,
        "{label} {:?} nu={} M_R={} k={}: error {worst:.2} eps exceeds estimate {est:.2} eps",
        r.route,
        c.nu,
        c.mr,
        c.k
    );
    worst
}

fn against_reference<T: Real>(p: T::Prec, label: &str) {
    let (mut wq, mut ws) = (0.0f64, 0.0f64);
    for c in mpmath_cases() {
        let (sp, ax) = c.inputs::<T>(p);
        let zero = T::zero(p);
        let q = direct::quadrature(&sp, &ax, &zero).expect("quadrature");
        wq = wq.max(check(&q, &c, 16.0, label));
        if ax.k <= T::one(p) {
            let s = direct::subtracted(&sp, &ax, &zero).expect("subtracted");
            ws = ws.max(check(&s, &c, 16.0, label));
        }
    }
    println!("{label}: worst error quadrature {wq:.2} eps, subtracted {ws:.2} eps");
}

#[test]
fn direct_routes_match_mpmath() {
    at_all_precisions!(against_reference, [128]);
}

/// (43): at M_R = 0, I1 = 2(1 − ν)(E/k² − K)/e² and I2 = 2(1 − ν)(K − E)/e². Written without
/// cancellation with D(e²) = (K − E)/e²: I2 = 2(1 − ν) D and I1 = 2(1 − ν)(E/k² − D)
/// (the two forms of I1 are equal since e² + k² = 1).
fn static_limit<T: Real>(p: T::Prec, label: &str) {
    for (nu, k) in [
        ("0.25", "0.5"),
        ("0", "0.001"),
        ("0.5", "0.9"),
        ("-0.75", "0.25"),
    ] {
        let mat = Material::new(T::parse(nu, p).unwrap()).unwrap();
        let sp = mat.speed(T::zero(p)).unwrap();
        let ax = AxisRatio::new(T::parse(k, p).unwrap()).unwrap();
        let r = direct::quadrature(&sp, &ax, &T::zero(p)).unwrap();
        let two_f0 = (T::one(p) - mat.nu()).mul_i64(2);
        let d = ellipbd_mc(&ax.k2).unwrap().1;
        let (_, ee) = ellipke_mc(&ax.k2).unwrap();
        let i1 = two_f0.clone() * (ee / &ax.k2 - &d);
        let i2 = two_f0 * d;
        let e1 = rel_eps(&r.i1, &i1.to_float(400));
        let e2 = rel_eps(&r.i2, &i2.to_float(400));
        assert!(
            e1.max(e2) <= 16.0,
            "{label}: static limit nu={nu} k={k}: {e1} {e2} eps"
        );
    }
}

#[test]
fn static_limit_is_classical_hertz() {
    at_all_precisions!(static_limit, [256]);
}

/// (53) for S against mpmath's quadrature of (49), and (52) for S1 against our quadrature.
fn s_closed_form<T: Real>(p: T::Prec, label: &str) {
    for r in read_csv("integrals_mpmath.csv")
        .into_iter()
        .filter(|r| r[0] == "S")
    {
        let mat = Material::new(T::parse("0.25", p).unwrap()).unwrap();
        let sp = mat.speed(T::parse(&r[2], p).unwrap()).unwrap();
        let ax = AxisRatio::new(T::parse(&r[3], p).unwrap()).unwrap();
        let s = direct::s_closed_form(&sp, &ax).unwrap();
        let e = rel_eps(&s, &reference(&r[4]));
        assert!(e <= 16.0, "{label}: S at M_R={} k={}: {e} eps", r[2], r[3]);
    }
}

#[test]
fn closed_form_53_for_s() {
    at_all_precisions!(s_closed_form, [128]);
}

#[test]
fn bad_axis_ratio_is_a_typed_error() {
    for k in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(AxisRatio::new(k).is_err(), "k = {k}");
    }
    let sp = Material::new(0.25).unwrap().speed(0.5).unwrap();
    assert!(matches!(
        direct::s_closed_form(&sp, &AxisRatio::new(2.0).unwrap()),
        Err(Error::Domain { .. })
    ));
}

/// S1 of (51) by the closed form (52): S1 = π/2·Λ₀(β, k²)/(M_R ε √(1 − k²ε²)), with
/// ε² = 1 − M_R², β = atan2(ε, M_R) (the bracket of `direct::s_closed_form`), for 0 < k ≤ 1 and
/// M_R > 0.
fn s1_closed_form<T: Real>(speed: &Speed<T>, axes: &AxisRatio<T>) -> T {
    let p = speed.mr().prec();
    let eps = speed.one_minus_mr2().clone().sqrt();
    let q = T::one(p) - axes.k2.clone() * speed.one_minus_mr2();
    let beta = eps.clone().atan2(speed.mr());
    let bracket = T::pi(p).mul_pow2(-1) * heuman_lambda_c_mc(&beta, &axes.k2).unwrap();
    bracket / (speed.mr().clone() * eps * q.sqrt())
}

/// (52) for S1 against the crate's quadrature of (51), and the two derivative rules quoted after
/// (53) (modulus p) against a centred difference of F(β, p) and E(β, p) by the crate's
/// quadrature of their defining integrals, at 256 bits.
#[test]
fn closed_form_52_and_the_quoted_derivative_rules() {
    use moving_hertz::numerics::quadrature::{integrate, Limits};
    let p = common::mp(256);
    let eps = Mp::epsilon(p);
    let mat = Material::new(Mp::parse("0.25", p).unwrap()).unwrap();
    for (mr, k) in [
        ("0.5", "0.6"),
        ("0.9", "0.3"),
        ("0.99", "0.8"),
        ("0.3", "0.95"),
    ] {
        let sp = mat.speed(Mp::parse(mr, p).unwrap()).unwrap();
        let ax = AxisRatio::new(Mp::parse(k, p).unwrap()).unwrap();
        let s1 = s1_closed_form(&sp, &ax);
        // (51): ∫ cos²α / ((1 − M_R² cos²α) Δ) dα.
        let f = |a: &Mp| {
            let (s, c) = a.clone().sin_cos();
            let c2 = c.square();
            let d = (c2.clone() + ax.k2.clone() * s.square()).sqrt();
            c2.clone() / ((Mp::one(p) - sp.mr2().clone() * &c2) * d)
        };
        let q = integrate(
            f,
            &[Mp::zero(p), Mp::pi(p).mul_pow2(-1)],
            &Mp::zero(p),
            Limits::default(),
        )
        .unwrap();
        let e = ((s1 - &q.value) / &q.value).abs() / &eps;
        assert!(
            e.to_f64() <= 16.0,
            "S1 at M_R={mr}, k={k}: {} eps",
            e.to_f64()
        );
    }
    // ∂E(β,p)/∂p = (E − F)/p;  ∂F/∂p = [E/p − (1 − p²)F/p − p sin2β/(2√(1 − p² sin²β))]/(1 − p²).
    let beta = Mp::parse("0.7", p).unwrap();
    for pm in ["0.6", "0.3", "0.9"] {
        let pp = Mp::parse(pm, p).unwrap();
        let h = Mp::one(p).mul_pow2(-60);
        // E(β, q) and F(β, q): ∫₀^β (1 − q² sin²θ)^(±1/2) dθ.
        let at = |q: &Mp| {
            let quad = |inverse: bool| {
                let f = |t: &Mp| {
                    let r = (Mp::one(p) - q.square() * t.clone().sin().square()).sqrt();
                    if inverse {
                        r.recip()
                    } else {
                        r
                    }
                };
                let ends = [Mp::zero(p), beta.clone()];
                integrate(f, &ends, &Mp::zero(p), Limits::default())
                    .unwrap()
                    .value
            };
            (quad(false), quad(true))
        };
        let (ep, fp) = at(&(pp.clone() + &h));
        let (em, fm) = at(&(pp.clone() - &h));
        let (e0, f0) = at(&pp);
        let de = (ep - em) / h.clone().mul_pow2(1);
        let df = (fp - fm) / h.clone().mul_pow2(1);
        let one = Mp::one(p);
        let rule_e = (e0.clone() - &f0) / &pp;
        let sb = beta.clone().sin();
        let root = (one.clone() - pp.square() * sb.square()).sqrt();
        let sin2b = beta.clone().mul_pow2(1).sin();
        let rule_f = (e0 / &pp
            - (one.clone() - pp.square()) * f0 / &pp
            - pp.clone() * sin2b / root.mul_pow2(1))
            / (one - pp.square());
        // The centred difference is accurate to h² ≈ 2^-120.
        for (name, num, rule) in [("dE/dp", de, rule_e), ("dF/dp", df, rule_f)] {
            let rel = ((num - &rule) / &rule).abs().to_f64();
            assert!(rel < 1e-30, "{name} at p = {pm}: {rel:e}");
        }
    }
}

/// J0 of (32) against mpmath's quadrature in φ (tests/data/j0_mpmath.csv, tools/gen_integrals.py
/// --j0, 40 digits): `approach_integral` (both peaks taken out in closed form where they are
/// near) and the J0 of `contact_integrals` (the pole taken out, the k-peak graded), on cases on
/// both sides of each threshold (ε ≤ 1/2 and kε ≤ 1/2; k² against ε of the working
/// precision), 1 − M_R from 1 to 2⁻¹²⁰ and k from 2⁻²⁰⁰ to 1000: within 16ε and within the
/// reported bounds.
fn j0_against_mpmath<T: Real>(p: T::Prec, label: &str) {
    let (mut wa, mut wc) = (0.0f64, 0.0f64);
    for r in read_csv("j0_mpmath.csv") {
        let mat = Material::new(T::parse(&r[0], p).unwrap()).unwrap();
        let sp = mat.parse_gap(&r[1]).unwrap();
        let ax = AxisRatio::new(T::parse(&r[2], p).unwrap()).unwrap();
        let want = reference(&r[3]);
        let zero = T::zero(p);
        let a = approach_integral(&sp, &ax, &zero).expect("approach_integral");
        let c = direct::contact_integrals(&sp, &ax, &zero).expect("contact_integrals");
        let est_c = (c.error_estimate.clone() / T::epsilon(p)).to_f64();
        let cj = c.j0.expect("J0");
        for (route, got, est, worst) in [
            (
                "approach_integral",
                &a.value,
                a.error.to_f64() / T::epsilon(p).to_f64(),
                &mut wa,
            ),
            ("contact_integrals", &cj, est_c, &mut wc),
        ] {
            let e = rel_eps(got, &want);
            let at = format!("{label} {route} nu={} gap={} k={}", r[0], r[1], r[2]);
            assert!(e <= 16.0, "{at}: J0 off by {e:.2} eps");
            assert!(
                e <= est + 1.0,
                "{at}: J0 off by {e:.2} eps, estimate {est:.2} eps"
            );
            *worst = worst.max(e);
        }
    }
    println!(
        "{label}: J0 worst error approach_integral {wa:.2} eps, contact_integrals {wc:.2} eps"
    );
}

#[test]
fn j0_matches_mpmath() {
    at_all_precisions!(j0_against_mpmath, [128]);
}

/// Far below the f64 range (1 − M_R down to 10⁻¹⁰⁰⁰⁰⁰) and at small k: `approach_integral` at 256
/// bits against the J0 of `contact_integrals` at 320 bits, whose right half is not subtracted but
/// graded about k (an independent treatment of the k-peak), within the reported bound; and the
/// M_R → 1 law J0·ε → constant, to O(ε) (so equal to 256 bits from 10⁻¹⁰⁰⁰ on).
#[test]
fn j0_far_below_the_f64_range() {
    let (lo, hi) = (common::mp(256), common::mp(320));
    let at = |p, nu: &str, gap: &str, k: &str| {
        let mat = Material::new(Mp::parse(nu, p).unwrap()).unwrap();
        (
            mat.parse_gap(gap).unwrap(),
            AxisRatio::new(Mp::parse(k, p).unwrap()).unwrap(),
        )
    };
    for (nu, k) in [
        ("0.25", "0.5"),
        ("-0.5", "1e-3"),
        ("0.5", "1e-40"),
        ("0.3", "1e-100"),
        ("0", "7"),
    ] {
        let mut scaled: Vec<rug::Float> = vec![];
        for gap in ["1e-30", "1e-1000", "1e-100000"] {
            let (sp, ax) = at(lo, nu, gap, k);
            let got = approach_integral(&sp, &ax, &Mp::zero(lo)).unwrap();
            let (sp2, ax2) = at(hi, nu, gap, k);
            let want = direct::contact_integrals(&sp2, &ax2, &Mp::zero(hi))
                .unwrap()
                .j0
                .unwrap();
            let w = want.to_float(320);
            let err = rug::Float::with_val(320, (got.value.to_float(320) - &w) / &w)
                .abs()
                .to_f64();
            let bound = got.error.to_f64();
            assert!(
                bound < 1e-74 && err <= bound,
                "nu={nu} k={k} gap={gap}: J0 error {err:e}, bound {bound:e}"
            );
            let eps = sp.one_minus_mr2().clone().sqrt();
            scaled.push((got.value * eps).to_float(320));
        }
        // J0·ε at 10⁻¹⁰⁰⁰ and 10⁻¹⁰⁰⁰⁰⁰ agree to 256 bits; at 10⁻³⁰ J0·ε differs from its limit
        // by O(ε(1 + |ln k|)) (the right half, ~ asinh(1/k), against the pole's π/(2ε)).
        let d = |a: &rug::Float, b: &rug::Float| {
            rug::Float::with_val(320, (a.clone() - b) / b)
                .abs()
                .to_f64()
        };
        let (far, near) = (d(&scaled[1], &scaled[2]), d(&scaled[0], &scaled[2]));
        let eps30 = (2e-30f64).sqrt();
        let allowed = 4.0 * eps30 * (1.0 + k.parse::<f64>().unwrap().ln().abs());
        assert!(
            far < 1e-75,
            "nu={nu} k={k}: J0·ε at 1e-1000 and 1e-100000 differ by {far:e}"
        );
        assert!(
            near < allowed,
            "nu={nu} k={k}: J0·ε at 1e-30 off its limit by {near:e}"
        );
    }
}

/// `IntegralOptions::j0` with every method: J0 (k² I1 + I2 from the route's I1, I2) within
/// 16ε of mpmath and of its bound, and I1, I2 exactly those of the same call without J0 (which
/// returns no J0, nor does the adaptive route with derivatives alone), at `f64` and
/// double-double.
fn j0_by_every_method<T: Real>(p: T::Prec, label: &str) {
    use moving_hertz::{integrals, IntegralOptions, Method};
    for r in read_csv("j0_mpmath.csv") {
        let mat = Material::new(T::parse(&r[0], p).unwrap()).unwrap();
        let sp = mat.parse_gap(&r[1]).unwrap();
        let k = T::parse(&r[2], p).unwrap();
        let want = reference(&r[3]);
        let gap: f64 = r[1].parse().unwrap();
        let dk_only = IntegralOptions {
            method: Method::Adaptive,
            derivatives: true,
            ..Default::default()
        };
        let d = integrals(&sp, &k, &dk_only).unwrap();
        assert!(
            d.di1_dk.is_some() && d.j0.is_none(),
            "{label}: J0 returned unasked"
        );
        let mut methods = vec![Method::Auto, Method::Adaptive, Method::Fixed];
        if k <= T::one(p) {
            methods.push(Method::AdaptiveSubtracted);
        }
        if gap > 1e-3 {
            methods.push(Method::Series);
        }
        for method in methods {
            let at = format!("{label} {method:?} nu={} gap={} k={}", r[0], r[1], r[2]);
            let plain = IntegralOptions {
                method,
                ..Default::default()
            };
            let with = IntegralOptions { j0: true, ..plain };
            let a = integrals(&sp, &k, &with).unwrap_or_else(|e| panic!("{at}: {e}"));
            let b = integrals(&sp, &k, &plain).unwrap();
            assert!(
                a.i1.value == b.i1.value && a.i2.value == b.i2.value,
                "{at}: I1, I2 changed"
            );
            let j = a.j0.unwrap_or_else(|| panic!("{at}: no J0"));
            assert!(b.j0.is_none(), "{at}: J0 returned unasked");
            let e = rel_eps(&j.value, &want);
            let est = j.error.to_f64() / T::epsilon(p).to_f64();
            assert!(
                e <= 16.0 && e <= est + 1.0,
                "{at}: J0 off by {e:.2} eps, bound {est:.2} eps"
            );
        }
    }
}

#[test]
fn j0_with_every_method() {
    j0_by_every_method::<f64>((), "f64");
    j0_by_every_method::<moving_hertz::scalar::Dd>((), "dd");
}

/// The plain adaptive route (`quadrature`) far below the f64 range: with the left half's pole
/// in closed form its work does not depend on 1 − M_R (the same evaluations at 10⁻¹⁰⁰⁰ and
/// 10⁻¹⁰⁰⁰⁰⁰; graded about ε it needed some 10⁶ at 10⁻³⁰⁰⁰), and I1, I2 agree with the fixed
/// rules (an independent route) within the two bounds, at 256 bits.
#[test]
fn plain_quadrature_far_below_the_f64_range() {
    use moving_hertz::{integrals, IntegralOptions, Method};
    let p = common::mp(256);
    let eps = Mp::epsilon(p).to_f64();
    let fixed = IntegralOptions {
        method: Method::Fixed,
        ..Default::default()
    };
    for (nu, k) in [("0.25", "0.5"), ("-0.5", "1e-3"), ("0", "7")] {
        let mut work = vec![];
        for gap in ["1e-1000", "1e-100000"] {
            let mat = Material::new(Mp::parse(nu, p).unwrap()).unwrap();
            let sp = mat.parse_gap(gap).unwrap();
            let kk = Mp::parse(k, p).unwrap();
            let ax = AxisRatio::new(kk.clone()).unwrap();
            let q = direct::quadrature(&sp, &ax, &Mp::zero(p)).unwrap();
            let f = integrals(&sp, &kk, &fixed).unwrap();
            for (name, a, b, eb) in [
                ("I1", &q.i1, &f.i1.value, f.i1.error.to_f64()),
                ("I2", &q.i2, &f.i2.value, f.i2.error.to_f64()),
            ] {
                let d = ((a.clone() - b) / b).abs().to_f64();
                let allowed = q.error_estimate.to_f64() + eb;
                assert!(
                    allowed < 100.0 * eps && d <= allowed,
                    "nu={nu} k={k} gap={gap} {name}: {d:e} > {allowed:e}"
                );
            }
            work.push(q.work);
        }
        assert_eq!(work[0], work[1], "nu={nu} k={k}: work depends on the gap");
    }
}

/// k far beyond the fixed rules (2^180) at 256 bits: the adaptive route's panels about 1/k grow
/// like log k, and beyond about |log2 k| = 4.4·10⁵/(bits/4 + 8) (about 6150 at 256 bits) their first
/// pass alone would take a third of the evaluation cap — refused as a domain error naming k
/// before any evaluation, for I1, I2 (every method that takes k > 2^180) on both sides of k = 1
/// and for J0 at k > 1 (at k < 1 its k-peak is in closed form); the subtracted route's panels
/// about ε = √(1 − M_R²) likewise name 1 − M_R². Below the bound the route succeeds, and I2 follows its limit I2 ~ −2Γ(V)/k (the
/// peak at φ = π/2 alone; the rest is O(ln k/k³)): k·I2 agrees at k = 2^1000 and 2^5900.
#[test]
fn huge_k_beyond_the_adaptive_cap_is_refused_before_any_work() {
    use moving_hertz::{integrals, Error, IntegralOptions, Method};
    let p = MpPrec::new(256).unwrap();
    let sp = Material::new(Mp::parse("0.25", p).unwrap())
        .unwrap()
        .speed(Mp::parse("0.5", p).unwrap())
        .unwrap();
    let one = Mp::one(p);
    let opts = |method| IntegralOptions {
        method,
        ..Default::default()
    };
    let refused = |r: moving_hertz::Result<_>| {
        matches!(
            r,
            Err(Error::Domain {
                name: "axis ratio k for the adaptive route",
                ..
            })
        )
    };
    for l in [6300, -6300] {
        let k = one.clone().mul_pow2(l);
        assert!(refused(
            integrals(&sp, &k, &opts(Method::Adaptive)).map(|_| ())
        ));
        let axes = AxisRatio::new(k.clone()).unwrap();
        let tol = Mp::epsilon(p);
        let j0 = approach_integral(&sp, &axes, &tol);
        if l > 0 {
            assert!(refused(j0.map(|_| ())));
            assert!(refused(integrals(&sp, &k, &opts(Method::Auto)).map(|_| ())));
        } else {
            // J0's k-peak is taken out in closed form at k² < ε: no panels about k.
            assert!(j0.is_ok_and(|j| j.error.to_f64() < 1e-70));
        }
    }
    let k_i2 = |l: i32| {
        let k = one.clone().mul_pow2(l);
        let r = integrals(&sp, &k, &opts(Method::Adaptive)).unwrap();
        assert!(
            r.i2.error.to_f64() < 1e-70,
            "2^{l}: I2 bound {}",
            r.i2.error
        );
        r.i2.value * &k
    };
    // The subtracted route (48) grades I1's left half about ε = √(1 − M_R²): where those panels
    // exhaust the cap, the refusal names 1 − M_R².
    let near = Material::new(Mp::parse("0.25", p).unwrap())
        .unwrap()
        .parse_gap("1e-5000")
        .unwrap();
    let half = Mp::parse("0.5", p).unwrap();
    assert!(matches!(
        integrals(&near, &half, &opts(Method::AdaptiveSubtracted)),
        Err(Error::Domain {
            name: "1 - M_R^2 for the adaptive route's panels about its square root",
            ..
        })
    ));
    let (a, b) = (k_i2(1000), k_i2(5900));
    let rel = ((a.clone() - &b) / &a).abs().to_f64();
    assert!(rel < 1e-70, "k·I2 at 2^1000 and 2^5900 differ by {rel:e}");
}

/// The material ν and the speed 2^`gap_log2` below the Rayleigh speed, exact at precision `q`.
fn dyadic_speed<S: Real>(nu: f64, gap_log2: i32, q: S::Prec) -> Speed<S> {
    let gap = S::one(q).mul_pow2(gap_log2);
    Material::new(S::from_f64(nu, q))
        .and_then(|m| m.speed_from_gap(gap))
        .unwrap()
}

/// J0 of the contact solution, k² I1 + I2 from the ellipse's own I1, I2, against J0 by its own
/// quadrature (`approach_integral`, both peaks in closed form) at 64 bits more, at the solved k
/// carried over exactly: within its bound, the bound within 40ε, and the true error within 16ε.
/// Dyadic inputs (exact at every precision): ν from −0.5 to 0.5, speeds from 0 to 2⁻⁴⁰ below the
/// Rayleigh speed (2⁻³⁰⁰⁰ at MPFR, k from 10⁻²²⁹ to 10⁻²²³), R2/R1 from 2⁻²⁰ to 2²⁰ (k on both
/// sides of 1 at the other speeds).
fn j0_against_its_quadrature<T: Real>(p: T::Prec, label: &str) {
    let bits = T::bits(p);
    let hi = common::mp(u64::from(bits) + 64);
    let x = |v: f64| T::from_f64(v, p);
    let mut gaps = vec![0, -3, -40];
    if bits > 106 {
        gaps.push(-3000);
    }
    let mut worst = 0.0f64;
    for nu in [-0.5, 0.0, 0.25, 0.5] {
        for &gap in &gaps {
            let (sp, sp_hi) = (
                dyadic_speed::<T>(nu, gap, p),
                dyadic_speed::<Mp>(nu, gap, hi),
            );
            for ratio in [2f64.powi(-20), 0.125, 1.0, 8.0, 2f64.powi(20)] {
                let at = format!("{label} nu={nu} gap=2^{gap} R2/R1={ratio:e}");
                let load = Loading::Load(x(1000.0));
                let sol = ContactProblem {
                    speed: sp.clone(),
                    radius_along: x(1.0),
                    radius_across: x(ratio),
                    loading: load,
                    shear_modulus: x(80e9),
                }
                .solve(&Options::default())
                .unwrap();
                let k_hi = AxisRatio::new(Mp::from_float(&sol.k().value.to_float(bits), hi));
                let want = approach_integral(&sp_hi, &k_hi.unwrap(), &Mp::zero(hi))
                    .unwrap()
                    .value
                    .to_float(bits + 64);
                let err = rel_eps(&sol.j0().value, &want);
                let bound = sol.j0().error.to_f64() / T::epsilon(p).to_f64();
                assert!(
                    err <= bound,
                    "{at}: J0 off by {err:.2} eps, bound {bound:.2} eps"
                );
                assert!(bound <= 40.0, "{at}: J0 bound {bound:.2} eps");
                assert!(err <= 16.0, "{at}: J0 off by {err:.2} eps");
                worst = worst.max(err);
            }
        }
    }
    println!("{label}: J0 = k² I1 + I2 worst error {worst:.2} eps");
}

#[test]
fn j0_is_k2_i1_plus_i2_within_its_bound_of_its_own_quadrature() {
    j0_against_its_quadrature::<f64>((), "f64");
    j0_against_its_quadrature::<Dd>((), "dd");
    j0_against_its_quadrature::<Mp>(common::mp(256), "mpfr256");
}
