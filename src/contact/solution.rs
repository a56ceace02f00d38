//! The full moving-punch Hertz solution: from the solved k and I1, I2 (normalisation of (37)),
//! a, b, p0, d0 and P by the closed forms of (26), (31) and the corrected (28), (30), (32), with
//! J0 = k² I1 + I2 (`docs/theory.md`, "Galin's theorem and the Hertz relations";
//! `docs/errata.md` #4).
//!
//! **Error bounds.** The closed forms are evaluated at [`Real::Wide`] and each result rounded
//! once ([`Real::ROUNDING`]·ε plus the wide operations', counted in `rounded`). Each quantity's
//! bound is that rounding plus the smaller of two bounds on the shape's error: the separate one
//! (the bounds on k, I1 and J0 times their sensitivities, added as the closed form combines
//! them) and the correlated one (`ShapeErrors`: k's error and the integrals' are one error seen
//! three ways, counted once). J0's bound is the pair's compounded with three roundings plus
//! k's, or the correlated one where smaller. `tests/references.rs` prints the worst error/bound
//! of each quantity against independent references.

use super::convolution;
use super::ellipse::{solve_ellipse, Ellipse, Options};
use crate::error::{Error, Result};
use crate::estimate::{Estimated, RelError};
use crate::physics::Speed;
use crate::routes::j0_from_pair;
use crate::scalar::{check_finite, check_positive, short, FieldOps, Real};

/// What fixes the size of the contact: the load P or the approach d0 (both positive).
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum Loading<T> {
    /// The total load P (31).
    Load(T),
    /// The approach (central displacement) d0 (32).
    Approach(T),
}

/// The moving-punch contact problem of section 4: a rigid punch with principal radii of
/// curvature R1 along the motion and R2 across it, pressed by a load (or to an approach) into
/// the half-space of the speed's material with shear modulus μ, sliding at that speed. Units
/// are the caller's (SI in, SI out).
///
/// ```
/// use moving_hertz::{ContactProblem, Loading, Material, Options};
/// let speed = Material::new(0.3)?.speed(0.9)?;
/// let sol = ContactProblem {
///     speed,
///     radius_along: 0.05,
///     radius_across: 0.02,
///     loading: Loading::Load(1000.0),
///     shear_modulus: 80e9,
/// }
/// .solve(&Options::default())?;
/// assert!(sol.a().value > sol.b().value && sol.a().error.to_f64() < 1e-14);
/// # Ok::<(), moving_hertz::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct ContactProblem<T: Real> {
    /// The punch's speed, which carries the material.
    pub speed: Speed<T>,
    /// R1: the punch's radius of curvature along the motion (A1 = 1/(2R1)).
    pub radius_along: T,
    /// R2: its radius of curvature across the motion (B1 = 1/(2R2)).
    pub radius_across: T,
    /// The load P or the approach d0.
    pub loading: Loading<T>,
    /// The half-space's shear modulus μ.
    pub shear_modulus: T,
}

/// The solved contact: the ellipse, its size, the central pressure, the approach and the load,
/// each with a bound on its relative error, and the pressure and displacement fields. Every
/// quantity is read through a method of its name; the fields stay private so that the fields'
/// functions ([`ContactSolution::pressure`], …) always see the solved values.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct ContactSolution<T: Real> {
    pub(crate) ellipse: Ellipse<T>,
    pub(crate) a: Estimated<T>,
    pub(crate) b: Estimated<T>,
    pub(crate) p0: Estimated<T>,
    pub(crate) d0: Estimated<T>,
    pub(crate) load: Estimated<T>,
    pub(crate) j0: Estimated<T>,
    problem: ContactProblem<T>,
    a1: T,
    b1: T,
}

/// The shape's errors as they reach the sizes. With q1, q2 the relative errors of I1, I2 at
/// the computed k (bounded by their bounds e1, e2), ρ the residual Ĩ2/(Ĩ1·A1/B1) − 1 of (33)
/// there, s_i = k I_i′/I_i and σ = s2 − s1 = F′ > 0, the computed k̃ = k*·e^δ and, to first
/// order, σδ = ρ − q2 + q1, and Ĩ_i = I_i(k*)(1 + t_i) with
///
/// ```text
/// t1 = (s2 q1 − s1 q2 + s1 ρ)/σ,   t2 = (s2 q1 − s1 q2 + s2 ρ)/σ.
/// ```
///
/// Every size's error is A t1 + B t2 + C δ for constants from its closed form (with
/// w1 = k² I1/J0, w2 = I2/J0 = 1 − w1: a³ ∝ I1 gives A = 1/3, b = k a adds C = 1, …), so it is
/// bounded by the sum over q1, q2, ρ of |coefficient|·bound: the errors of I1, I2 and k, which
/// are one error seen three ways, are counted once. The coefficients take the derivatives'
/// own errors (|s_i| times their relative bounds) at their worst, and a second-order term
/// 32(δ + e1 + e2)² covers the rest. Only where the derivatives are known and σ is positive
/// with their errors below σ/2.
struct ShapeErrors {
    s1: f64,
    s2: f64,
    /// The uncertainties of s1, s2.
    d1: f64,
    d2: f64,
    /// The least σ the derivatives' errors allow.
    sigma: f64,
    w1: f64,
    e1: RelError,
    e2: RelError,
    rho: RelError,
    second: RelError,
}

impl ShapeErrors {
    /// The errors at the solved `el` for the problem `pb` (its radii give A1/B1 = R2/R1).
    fn new<T: Real>(el: &Ellipse<T>, j0: &T, pb: &ContactProblem<T>) -> Option<Self> {
        let ints = &el.integrals;
        let (d1, d2) = (ints.di1_dk.as_ref()?, ints.di2_dk.as_ref()?);
        let k = &el.k.value;
        let p = k.prec();
        let s = |d: &Estimated<T>, i: &T| (k.clone() * &d.value / i).to_f64();
        let (s1, s2) = (s(d1, &ints.i1.value), s(d2, &ints.i2.value));
        let unc = |s: f64, d: &Estimated<T>| s.abs() * (d.error.to_f64() + 1e-14);
        let (u1, u2) = (unc(s1, d1), unc(s2, d2));
        let sigma = s2 - s1 - u1 - u2;
        if !(sigma.is_finite() && sigma > 0.5 * (s2 - s1)) {
            return None;
        }
        let w1 = (k.clone().square() * &ints.i1.value / j0).to_f64();
        if !(0.0..=1.0).contains(&w1) {
            return None;
        }
        // ρ against the exact R2/R1 (so that the solve's rounded ratio shows in it), at
        // Real::Wide: the ratio's, the product's and the quotient's roundings and the
        // difference's, on a quotient of 1 + ρ.
        let pw = T::wide_prec(p);
        let w = |x: &T| x.to_wide(pw);
        let ratio = w(&pb.radius_across) / &w(&pb.radius_along);
        let rho_hat = w(&ints.i2.value) / &(w(&ints.i1.value) * &ratio) - &T::Wide::one(pw);
        let rho_abs = RelError::of(&rho_hat);
        let rho = rho_abs.add(RelError::rounding::<T::Wide>(4.0, pw).scale(1.0 + rho_abs.to_f64()));
        let (e1, e2) = (ints.i1.error, ints.i2.error);
        let delta = rho.add(e1).add(e2).scale(1.0 / sigma);
        let first = delta.add(e1).add(e2);
        Some(ShapeErrors {
            s1,
            s2,
            d1: u1,
            d2: u2,
            sigma,
            w1,
            e1,
            e2,
            rho,
            second: first.mul(first).scale(32.0),
        })
    }

    /// A bound on |A t1 + B t2 + C δ| (first order, plus the second-order term scaled by
    /// |A| + |B| + |C| + 1).
    fn bound(&self, a: f64, b: f64, c: f64) -> RelError {
        let s = a + b;
        let c1 = (s * self.s2 + c).abs() + s.abs() * self.d2;
        let c2 = (s * self.s1 + c).abs() + s.abs() * self.d1;
        let cr = (a * self.s1 + b * self.s2 + c).abs() + a.abs() * self.d1 + b.abs() * self.d2;
        let up = 1.0 + 1e-12;
        self.e1
            .scale(up * c1 / self.sigma)
            .add(self.e2.scale(up * c2 / self.sigma))
            .add(self.rho.scale(up * cr / self.sigma))
            .add(self.second.scale(1.0 + a.abs() + b.abs() + c.abs()))
    }
}

/// The inputs' names and the message for a quantity that overflows or underflows the working
/// type although every input is valid (a radius of 1e-320, a load of 1e300).
const RESCALE: &str = "(overflow or underflow: rescale the inputs)";

impl<T: Real> ContactProblem<T> {
    /// Solves the problem: the ellipse (33) by [`solve_ellipse`] with `opts`, J0 of (32) at the
    /// solved k as k² I1 + I2 from the ellipse's own I1, I2 (no further quadrature: the
    /// integrands add up to J0's), then a, b, p0, d0 and the load in closed form at
    /// [`Real::Wide`], each rounded once (module docs).
    /// The work is the ellipse solve's and a few operations.
    ///
    /// Accuracy: every quantity to a few ε of the working precision (measured against Johnson's
    /// static solution and a 320-bit solve in `tests/contact.rs`), each with a bound.
    /// Errors: [`Error::Domain`] / [`Error::NotFinite`] for a radius, load, approach or modulus
    /// that is not positive and finite, and for a radius whose curvature 1/(2R) is not a normal
    /// number of the working type, each naming the input before any work; [`Error::Domain`]
    /// for a result that overflows or underflows the working type (intermediates are grouped
    /// so that only a result out of range does); the ellipse solve's errors.
    pub fn solve(&self, opts: &Options<T>) -> Result<ContactSolution<T>> {
        self.solve_by(|speed, ratio| solve_ellipse(speed, ratio, opts))
    }

    /// [`ContactProblem::solve`] with the ellipse (33) solved by `ellipse` (a sweep's solver,
    /// which keeps its set-up and starts from a neighbour's root) at the speed and A1/B1.
    pub(crate) fn solve_by(
        &self,
        ellipse: impl FnOnce(&Speed<T>, &T) -> Result<Ellipse<T>>,
    ) -> Result<ContactSolution<T>> {
        check_positive("radius along the motion R1", &self.radius_along)?;
        check_positive("radius across the motion R2", &self.radius_across)?;
        check_positive("shear modulus mu", &self.shear_modulus)?;
        match &self.loading {
            Loading::Load(pl) => check_positive("load P", pl)?,
            Loading::Approach(d) => check_positive("approach d0", d)?,
        }
        let p = self.shear_modulus.prec();
        let a1 = self.radius_along.clone().recip().mul_pow2(-1);
        let b1 = self.radius_across.clone().recip().mul_pow2(-1);
        for (name, r, v) in [
            ("radius along the motion R1", &self.radius_along, &a1),
            ("radius across the motion R2", &self.radius_across, &b1),
        ] {
            if !v.is_finite() || *v < T::min_positive(p) {
                return Err(Error::domain(name, short(r), "(0, inf) with the curvature 1/(2R) a normal number of the working type (R up to about 2.2e307 at f64, 2.5e291 at double-double)"));
            }
        }
        let ratio = self.radius_across.clone() / &self.radius_along;
        let ellipse = ellipse(&self.speed, &ratio)?;
        let ints = &ellipse.integrals;
        let pair_error = ints.i1.error.max(ints.i2.error);
        let mut j0 = j0_from_pair(&ellipse.k.value, &ints.i1.value, &ints.i2.value, pair_error)
            .checked("J0")?;
        let shape = ShapeErrors::new(&ellipse, &j0.value, self);
        let sizes = Sizes::new(self, &ellipse, &j0, shape.as_ref());
        // J0 as the value at the exact root: its error at the computed k plus its change over
        // k's error (|k J0′/J0| ≤ 1), or the correlated bound where it is smaller.
        let p = a1.prec();
        j0.error = j0
            .error
            .add(ellipse.k.error.add(RelError::rounding::<T>(1.0, p)));
        if let Some(sh) = &shape {
            // k̃(k̃ Ĩ1) + Ĩ2: two roundings in the share w1 of k² I1, one in the sum.
            let w1 = sh.w1;
            let tight = sh
                .bound(w1, 1.0 - w1, 2.0 * w1)
                .add(RelError::rounding::<T>(1.0 + 2.0 * w1, p));
            j0.error = j0.error.min(tight);
        }
        Ok(ContactSolution {
            a: fits("semi-axis a", sizes.a)?,
            b: fits("semi-axis b", sizes.b)?,
            p0: fits("central pressure p0", sizes.p0)?,
            d0: fits("approach d0", sizes.d0)?,
            load: fits("load P", sizes.load)?,
            ellipse,
            j0,
            problem: self.clone(),
            a1,
            b1,
        })
    }
}

/// A result of valid inputs at the edge of the format that overflows or underflows the working
/// type (not finite, or below its least normal number): [`Error::Domain`] naming it and asking
/// for rescaled inputs, rather than ∞ or 0 returned.
fn fits<T: Real>(name: &'static str, x: Estimated<T>) -> Result<Estimated<T>> {
    let v = &x.value;
    if !(v.is_finite() && *v >= T::min_positive(v.prec())) {
        return Err(Error::domain(name, short(v), RESCALE));
    }
    x.checked(name)
}

/// a, b, p0, d0 and the load with their relative error bounds (module docs).
struct Sizes<T: Real> {
    a: Estimated<T>,
    b: Estimated<T>,
    p0: Estimated<T>,
    d0: Estimated<T>,
    load: Estimated<T>,
}

/// The sizes' values and the bounds on their rounding, in the order a, b, p0 and then d0 under
/// a load or P under an approach.
type Rounded<T> = [(T, RelError); 4];

/// a, b, p0 and d0 (given the load) or P (given the approach) from the inputs and the computed
/// k, I1 and I2, formed at [`Real::Wide`] and rounded once ("guard bits, then round once"), so
/// that each carries one rounding of the working type plus the wide operations', each of
/// those counted with the power of its rounded intermediate in the closed form (a rounding
/// inside a³ counts 1/3, one in a quantity that cancels counts 0). With B1 = 1/(2R2) and
/// J0 = k²I1 + I2 formed there too (1 and 3 operations), the wide operations count, in units
/// of [`Real::ROUNDING`]:
///
/// ```text
/// given P:  s = 3 I1/(8π B1) (5),  a = ∛P/∛μ·∛s: 5/3 + 3 + 2 = 20/3;  b = k a: 23/3;
///           p0 = (P/a/b)·3/(2π): a² (with π's rounding once, 1/3) 3 + 6 + 4, b's 1, own 4 = 18;
///           d0 = p0/(4μ)·b·J0 = 3P J0/(8π μ a): s's 2, the roots' 3, a's 2, p0's own 4,
///           J0's 3, own 3 = 17;
/// given d0: s = I1/(B1 J0) (6),  a = √d0·√s: 3 + 3 = 6;  b = k a: 7;
///           p0 = 4μ·(a B1/(k I1)): a's 6 (B1's rounding at the power 1/2), own 4 = 10;
///           P = (p0 a b)·(2π/3) ∝ a³ B1: the roots' and a's product 9, J0's 9/2, s's product
///           and quotient 3/2 each, B1's 1/2, b's 1, p0's own 4, own 5 = 27.
/// ```
fn rounded<T: Real>(pb: &ContactProblem<T>, el: &Ellipse<T>) -> Rounded<T> {
    let p = pb.shear_modulus.prec();
    let pw = T::wide_prec(p);
    let w = |x: &T| x.to_wide(pw);
    let ints = &el.integrals;
    let (k, i1, i2) = (w(&el.k.value), w(&ints.i1.value), w(&ints.i2.value));
    let mu = w(&pb.shear_modulus);
    let b1 = w(&pb.radius_across).recip().mul_pow2(-1);
    let j0 = k.clone() * &(k.clone() * &i1) + &i2;
    let pi = <T::Wide as Real>::pi(pw);
    // Grouped so that no intermediate leaves the working type's range unless a result does:
    // P, μ and d0 enter through their own roots, apart from the factors of order one (a load
    // of 1e308 with μ = 1e100 gives a = 1e69, whose cube, formed from 3P, would overflow).
    let (a, b, p0, last, counts) = match &pb.loading {
        Loading::Load(pl) => {
            let pl = w(pl);
            let shape = i1.mul_i64(3) / (pi.clone().mul_i64(8) * &b1);
            let a = pl.clone().cbrt() / &mu.clone().cbrt() * shape.cbrt();
            let b = k * &a;
            let p0 = (pl / &a / &b).mul_i64(3) / pi.mul_i64(2);
            let d0 = (p0.clone() / &mu.mul_i64(4)) * &b * &j0;
            (a, b, p0, d0, [20.0 / 3.0, 23.0 / 3.0, 18.0, 17.0])
        }
        Loading::Approach(d0) => {
            let shape = i1.clone() / (b1.clone() * &j0);
            let a = w(d0).sqrt() * shape.sqrt();
            let b = k.clone() * &a;
            let p0 = mu.mul_i64(4) * &(a.clone() * &b1 / (k * &i1));
            let load = (p0.clone() * &a * &b) * pi.mul_i64(2).div_i64(3);
            (a, b, p0, load, [6.0, 7.0, 10.0, 27.0])
        }
    };
    let once = RelError::rounding::<T>(1.0, p);
    let round = |x: T::Wide, n: f64| {
        let r = once.add(RelError::rounding::<T::Wide>(n, pw));
        // A wide value out of range is an overflow (double-double's renormalisation turns
        // one into NaN): ∞, which `fits` names.
        let v = match x.is_finite() {
            true => T::from_wide(&x, p),
            false => T::from_f64(f64::INFINITY, p),
        };
        (v, r)
    };
    [
        round(a, counts[0]),
        round(b, counts[1]),
        round(p0, counts[2]),
        round(last, counts[3]),
    ]
}

impl<T: Real> Sizes<T> {
    /// The sizes of [`rounded`] with the bounds of [`Sizes::separate`], each replaced by the
    /// correlated bound of [`ShapeErrors`] plus the same rounding where that is smaller.
    fn new(
        pb: &ContactProblem<T>,
        el: &Ellipse<T>,
        j0: &Estimated<T>,
        shape: Option<&ShapeErrors>,
    ) -> Self {
        let r = rounded(pb, el);
        let mut s = Self::separate(pb, el, j0, r.clone());
        let Some(sh) = shape else { return s };
        let w1 = sh.w1;
        let w2 = 1.0 - w1;
        // (A, B, C) of each quantity's error A t1 + B t2 + C δ (module docs) and its rounding.
        let rows: [(&mut Estimated<T>, [f64; 3]); 4] = match &pb.loading {
            Loading::Load(_) => [
                (&mut s.a, [1.0 / 3.0, 0.0, 0.0]),
                (&mut s.b, [1.0 / 3.0, 0.0, 1.0]),
                (&mut s.p0, [-2.0 / 3.0, 0.0, -1.0]),
                (&mut s.d0, [w1 - 1.0 / 3.0, w2, 2.0 * w1]),
            ],
            Loading::Approach(_) => {
                let (ah, bh) = ((1.0 - w1) / 2.0, -w2 / 2.0);
                [
                    (&mut s.a, [ah, bh, -w1]),
                    (&mut s.b, [ah, bh, 1.0 - w1]),
                    (&mut s.p0, [ah - 1.0, bh, -w1 - 1.0]),
                    (&mut s.load, [(1.0 - 3.0 * w1) / 2.0, -1.5 * w2, -3.0 * w1]),
                ]
            }
        };
        for ((q, [a, b, c]), (_, round)) in rows.into_iter().zip(r) {
            q.error = q.error.min(sh.bound(a, b, c).add(round));
        }
        s
    }

    /// Each size with a bound that adds the bounds of its parts (k's, I1's with its change
    /// over k's error, J0's) as its closed form combines them, plus its rounding.
    fn separate(pb: &ContactProblem<T>, el: &Ellipse<T>, j0: &Estimated<T>, r: Rounded<T>) -> Self {
        let p = pb.shear_modulus.prec();
        let k = &el.k.value;
        let ints = &el.integrals;
        let i1 = &ints.i1.value;
        // The integrals' errors at the computed k, plus their change over k's error
        // (|k I1′/I1| from the computed derivative, |k J0′/J0| ≤ 1), plus the ratio's
        // rounding (|d ln k/d ln(A1/B1)| ≤ 1).
        let dk = el.k.error.add(RelError::rounding::<T>(1.0, p));
        // Formed at the working precision: k, I1′ and I1 may each lie outside the f64 range
        // (near the Rayleigh speed, k ~ 1e-250 and I1 ~ 1e500 at 1 − M_R = 1e-1000).
        let sens = |d: &Option<Estimated<T>>| {
            d.as_ref()
                .map_or(4.0, |d| (k.clone() * &d.value / i1).to_f64().abs())
        };
        let e_i1 = ints.i1.error.add(dk.scale(sens(&ints.di1_dk)));
        let e_j0 = j0.error.add(dk);
        let [(av, ra), (bv, rb), (pv, rp), (lv, rl)] = r;
        let est = Estimated::new;
        let exact = |x: &T| est(x.clone(), RelError::ZERO);
        match &pb.loading {
            Loading::Load(pl) => {
                // a³ ∝ I1, b = k a, p0 ∝ 1/(a b), d0 = 3P J0/(8π μ a).
                let ea = e_i1.scale(1.0 / 3.0);
                let eb = ea.add(dk);
                Sizes {
                    a: est(av, ea.add(ra)),
                    b: est(bv, eb.add(rb)),
                    p0: est(pv, ea.add(eb).add(rp)),
                    d0: est(lv, ea.add(e_j0).add(rl)),
                    load: exact(pl),
                }
            }
            Loading::Approach(d0) => {
                // a² ∝ I1/J0, b = k a, p0 ∝ a/(k I1), P = (8π/3) μ d0 a/J0.
                let ea = e_i1.add(e_j0).scale(0.5);
                Sizes {
                    a: est(av, ea.add(ra)),
                    b: est(bv, ea.add(dk).add(rb)),
                    p0: est(pv, ea.add(dk).add(e_i1).add(rp)),
                    load: est(lv, ea.add(e_j0).add(rl)),
                    d0: exact(d0),
                }
            }
        }
    }
}

impl<T: Real> ContactSolution<T> {
    /// The problem this solves. The inputs of (26)–(33) as given; no rounding.
    pub fn problem(&self) -> &ContactProblem<T> {
        &self.problem
    }
    /// The ellipse's shape (33): k, e, the integrals I1, I2 at the root.
    pub fn ellipse(&self) -> &Ellipse<T> {
        &self.ellipse
    }
    /// The semi-axis a along the motion (m), from (31) given the load or (32) given the
    /// approach (module docs), with a bound on its relative error.
    pub fn a(&self) -> &Estimated<T> {
        &self.a
    }
    /// The semi-axis b = k a across the motion (m), with a bound on its relative error.
    pub fn b(&self) -> &Estimated<T> {
        &self.b
    }
    /// The central pressure p0 of (9) (m = 1) (Pa), with a bound on its relative error.
    pub fn p0(&self) -> &Estimated<T> {
        &self.p0
    }
    /// The approach d0 of (32) (m; the given one, exact, when [`Loading::Approach`] fixed
    /// the size), with a bound on its relative error.
    pub fn d0(&self) -> &Estimated<T> {
        &self.d0
    }
    /// The load P of (31) (N; the given one, exact, when [`Loading::Load`] fixed the size),
    /// with a bound on its relative error.
    pub fn load(&self) -> &Estimated<T> {
        &self.load
    }
    /// J0 of (32) at the solved k (normalisation of (37)), as k² I1 + I2, with a bound on its
    /// relative error as a value at the exact root.
    pub fn j0(&self) -> &Estimated<T> {
        &self.j0
    }
    /// k = b/a, the root of (33), with its bound as in [`Ellipse::k`].
    pub fn k(&self) -> &Estimated<T> {
        &self.ellipse.k
    }
    /// The eccentricity e at the root of (33), with its bound (absolute: see [`Ellipse::e`]).
    pub fn e(&self) -> &Estimated<T> {
        &self.ellipse.e
    }

    /// True when (x, y) lies in the closed contact region of (9), x²/a² + y²/b² ≤ 1.
    pub fn inside(&self, x: &T, y: &T) -> bool {
        self.q(x, y) >= T::zero(x.prec())
    }

    /// 1 − x²/a² − y²/b².
    fn q(&self, x: &T, y: &T) -> T {
        let p = x.prec();
        T::one(p) - (x.clone() / &self.a.value).square() - (y.clone() / &self.b.value).square()
    }

    /// The contact pressure p(x, y) = p0 (1 − x²/a² − y²/b²)^{1/2} of (9) (m = 1), zero
    /// outside. Its bound is relative to p0 (the pressure vanishes on the edge, where a relative
    /// bound would be unbounded): |p̃ − p| ≤ error·p0, from p0's bound and the shift of the edge
    /// by a's and b's; 0 where the point lies outside every ellipse those bounds allow.
    ///
    /// Errors: [`Error::NotFinite`] for a coordinate that is not finite.
    pub fn pressure(&self, x: &T, y: &T) -> Result<Estimated<T>> {
        check_point(x, y)?;
        let p = x.prec();
        // Outside the ellipse with both axes at their upper bounds: exactly zero (and no
        // squares formed that could overflow far away).
        let beyond = |c: &T, axis: &Estimated<T>| {
            let reach = T::one(p)
                + &axis
                    .error
                    .scale(2.0)
                    .add(RelError::rounding::<T>(8.0, p))
                    .to_real(p);
            c.clone().abs() > axis.value.clone() * &reach
        };
        if beyond(x, &self.a) || beyond(y, &self.b) {
            return Ok(Estimated::new(T::zero(p), RelError::from_f64(0.0)));
        }
        let q = self.q(x, y);
        let (xa, yb) = (
            (x.clone() / &self.a.value).square().to_f64(),
            (y.clone() / &self.b.value).square().to_f64(),
        );
        // |δq| ≤ 2(x²/a²)δa + 2(y²/b²)δb + the roundings: 3 in each square's share (the
        // quotient's twice, the square's), |1 − x²/a²| ≤ 1 + x²/a² and |q| ≤ 1 for the two
        // subtractions; |δ√q| ≤ min(√|δq|, |δq|/(2√q)).
        let dq = self
            .a
            .error
            .scale(2.0 * xa)
            .add(self.b.error.scale(2.0 * yb))
            .add(RelError::rounding::<T>(4.0 * (xa + yb) + 2.0, p));
        let qf = q.to_f64().max(0.0);
        let droot = if qf > 0.0 {
            dq.sqrt().min(dq.scale(0.5 / qf.sqrt()))
        } else {
            dq.sqrt()
        };
        let value = if q.is_positive() {
            self.p0.value.clone() * q.sqrt()
        } else {
            T::zero(p)
        };
        let err = self
            .p0
            .error
            .scale(qf.sqrt())
            .add(droot)
            .add(RelError::rounding::<T>(2.0, p));
        Ok(Estimated::new(value, err))
    }

    /// The surface displacement u_z(x, y): inside the contact the punch's surface
    /// d0 − A1 x² − B1 y² (27); outside it the convolution (7) of the pressure with the
    /// moving-load Green's function (4), by adaptive quadrature to relative tolerance `tol`
    /// ([`ContactSolution::convolution`]; `tol` is unused inside). Its bound is relative to d0
    /// (the displacement decays to zero far away).
    ///
    /// Errors: [`Error::NotFinite`] for a coordinate that is not finite; the convolution's
    /// (outside the contact).
    pub fn displacement(&self, x: &T, y: &T, tol: &RelError) -> Result<Estimated<T>> {
        check_point(x, y)?;
        let p = x.prec();
        if self.inside(x, y) {
            let curv = self.a1.clone() * x.square() + self.b1.clone() * y.square();
            let scale = (curv.clone() / &self.d0.value).to_f64();
            // Each term's square, curvature (1/(2R), rounded) and product, the positive sum's
            // rounding (4 relative to curv), and the difference's (at most d0, inside).
            let rounding = RelError::rounding::<T>(1.0 + 4.0 * scale, p);
            let err = self.d0.error.add(rounding);
            return Ok(Estimated::new(self.d0.value.clone() - curv, err));
        }
        self.convolution(x, y, tol)
    }

    /// The surface displacement u_z(x, y) by the convolution (7) of the computed pressure with
    /// the moving-load Green's function (4), inside or outside the contact, by adaptive
    /// quadrature to relative tolerance `tol`: the physics' own check of the solution (inside,
    /// it reproduces the punch's surface (27); outside, it stays above it: the Signorini
    /// conditions (1)). Its bound is relative to d0. Accuracy: within its bound of the same
    /// problem at 320 bits at `f64` and double-double, from the contact out to 2⁶⁰ semi-axes
    /// and for M_R up to 1 − 10⁻¹² (`tests/contact.rs`,
    /// `displacement_holds_its_bound_near_and_far`, tolerance 10⁻¹²: the worst `f64` error is
    /// 0.87 of its bound, at M_R = 1 − 10⁻¹²).
    ///
    /// Errors: [`Error::NotFinite`] for a coordinate that is not finite; [`Error::Domain`]
    /// naming the point for one farther than 2^(bits + 20)·max(a, b) from the centre, where
    /// u_z is below 2^−bits·d0; [`Error::NoConvergence`] from the quadrature when it cannot
    /// reach `tol` (near M_R = 1 the angular peak of g amplifies rounding of the angle by
    /// about 1/√(1 − M_R²), which bounds the reachable tolerance).
    pub fn convolution(&self, x: &T, y: &T, tol: &RelError) -> Result<Estimated<T>> {
        check_point(x, y)?;
        let p = x.prec();
        let t = tol.max(RelError::eps::<T>(4, p)).to_real::<T>(p);
        let q = convolution::displacement(self, x, y, &t)?;
        // The quadrature's error, and the pressure's: p0's bound and the edge's shift.
        let err = RelError::of(&(q.error / &self.d0.value))
            .add(self.p0.error)
            .add(self.a.error.add(self.b.error).scale(2.0));
        Estimated::new(q.value, err).checked("displacement u_z")
    }
}

/// A point (x, y) of the surface: both coordinates finite ([`Error::NotFinite`] naming the one
/// that is not).
fn check_point<T: Real>(x: &T, y: &T) -> Result<()> {
    check_finite("x (along the motion)", x)?;
    check_finite("y (across the motion)", y)
}
