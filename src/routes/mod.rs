//! The routes to the integrals I1, I2 of (34) that fix the contact ellipse's shape (33):
//! the series of section 5 and the direct and singularity-subtracted quadratures of sections 6–7.
//!
//! **Normalisation.** Every route returns I1, I2 in the normalisation of (37), with g = −πΓ in
//! place of −Γ: π times the paper's (34) (`docs/theory.md`, "Conventions"; `docs/errata.md` #3),
//! with Δ² = cos²α + k² sin²α and e² = 1 − k² (negative when k > 1).
//!
//! The series route: [`coefficients`] (f_n of (35)–(36)), [`moments`] (L_n, M_n of (39)–(42)),
//! [`series`] (I1, I2 by (37) with truncation control); findings in `docs/series.md`.

pub mod choose;
pub mod coefficients;
pub(crate) mod direct;
pub mod evaluate;
pub(crate) mod fast;
pub(crate) mod graded;
mod guard;
pub mod moments;
pub mod series;
mod speed_consts;

pub use choose::{integrals_to_tolerance, ExactInputs};
pub use coefficients::{GreenSeries, SpeedCoefficients};
pub use evaluate::{integrals, Evaluator, IntegralOptions};

use crate::error::{Error, Result};
use crate::estimate::{Estimated, RelError};
use crate::scalar::{check_positive, short, Precision, Real};

/// The contact ellipse's axis ratio k = b/a (b across the motion, a along it), with k² and
/// e² = 1 − k² = (1 − k)(1 + k) formed without cancellation. e² < 0 when k > 1 (the contact is
/// longer across the motion than along it).
#[derive(Clone, Debug)]
pub struct AxisRatio<T: Real> {
    /// k = b/a > 0.
    pub k: T,
    /// k².
    pub k2: T,
    /// e² = 1 − k².
    pub e2: T,
}

impl<T: Real> AxisRatio<T> {
    /// The axis ratio `k` = b/a; [`Error::Domain`] unless k⁴ and 1/k⁴ are normal numbers of
    /// the working precision (1.2·10⁻⁷⁷ ≲ k ≲ 8.2·10⁷⁶ at `f64`, 1.2·10⁻⁷³ ≲ k ≲ 8.4·10⁷² at
    /// double-double).
    /// The k of (33)–(34), kept as given; k² and e² = (1 − k)(1 + k) of (41) each within an ulp
    /// or two.
    pub fn new(k: T) -> Result<Self> {
        check_positive("axis ratio k = b/a", &k)?;
        let p = k.prec();
        let one = T::one(p);
        let k2 = k.square();
        // k⁴ and 1/k⁴ must be normal numbers of the working precision: the integrands hold
        // (k² + v²)^{3/2} and (1 + k²w²)^{3/2}, which reach k³ and k⁻³.
        // 1/k⁴ ≥ tiny ⟺ k⁴ ≤ 1/tiny, a power of 2 (exact): no division per evaluation.
        let tiny = T::min_positive(p);
        let k4 = k2.square();
        if !(k4 >= tiny && k4 <= tiny.clone().recip()) {
            return Err(Error::Domain {
                name: "axis ratio k = b/a",
                value: short(&k),
                bound: "(0, inf) with k^4 and 1/k^4 normal numbers of the working precision",
            });
        }
        let e2 = (one.clone() - &k) * (one + &k);
        Ok(AxisRatio { k2, k, e2 })
    }
}

/// The route that actually ran to produce a pair of integrals: the five ways the crate evaluates
/// I1, I2 of (34).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Route {
    /// The series (37) with the moments L_n, M_n by (39)–(42): section 5 of the paper.
    Series,
    /// Adaptive Gauss–Legendre quadrature of (46)–(47) on geometrically graded panels.
    Adaptive,
    /// (46) by adaptive quadrature, (47) by the subtraction (48) with S in closed form (53); k ≤ 1.
    AdaptiveSubtracted,
    /// Fixed Gauss–Legendre rules after the Rayleigh pole and the peak of Δ⁻³ are taken out in
    /// closed form (the fast route); 0 < k ≤ 1.
    FixedRule,
    /// Fixed rules on sinh-graded panels for the long contact across the motion; 1 ≤ k ≤ 2¹⁸⁰.
    GradedRule,
}

impl Route {
    /// `series`, `adaptive`, `adaptive-subtracted`, `fixed-rule` or `graded-rule`.
    /// Names a route for (34); exact.
    pub fn label(&self) -> &'static str {
        match self {
            Route::Series => "series",
            Route::Adaptive => "adaptive",
            Route::AdaptiveSubtracted => "adaptive-subtracted",
            Route::FixedRule => "fixed-rule",
            Route::GradedRule => "graded-rule",
        }
    }
}

impl std::fmt::Display for Route {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.label())
    }
}

/// The route a caller asks for. [`Method::Auto`] (the default) takes the cheapest route that
/// meets the request: the fixed rules where they apply and their bound meets the tolerance, the
/// adaptive quadratures otherwise.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Method {
    /// The cheapest route that meets the request, by a rule on k, the tolerance and the
    /// derivatives asked for: the table in [`crate::routes::evaluate`]'s docs.
    #[default]
    Auto,
    /// [`Route::Series`] (I1, I2 only: no k-derivatives, no J0).
    Series,
    /// [`Route::Adaptive`] (every k; with k-derivatives and J0). A reference and the fallback
    /// where the fixed rules do not apply: its work grows with |ln k| and with the sharpness of
    /// G's peak as M_R → 1, so that at MPFR precisions and the ends of the supported ranges an
    /// ellipse solve by it alone can take minutes where [`Method::Auto`] takes milliseconds.
    /// At MPFR precisions k is bounded by its evaluation cap: |log₂ k| below about
    /// 4.4·10⁵/(bits/4 + 8) (else [`crate::Error::Domain`] at once; `routes::direct::quadrature`).
    Adaptive,
    /// [`Route::AdaptiveSubtracted`] (k ≤ 1; I1, I2 only).
    AdaptiveSubtracted,
    /// The fixed rules: [`Route::FixedRule`] for 0 < k ≤ 1, [`Route::GradedRule`] for
    /// 1 < k ≤ 2¹⁸⁰ (with k-derivatives).
    Fixed,
}

impl Method {
    /// Every method, in the order of [`Method::label`]'s list.
    pub const ALL: [Method; 5] = [
        Method::Auto,
        Method::Series,
        Method::Adaptive,
        Method::AdaptiveSubtracted,
        Method::Fixed,
    ];

    /// The route for (34) by name: `auto`, `series`, `adaptive`, `adaptive-subtracted`, `fixed`.
    pub fn label(&self) -> &'static str {
        match self {
            Method::Auto => "auto",
            Method::Series => "series",
            Method::Adaptive => "adaptive",
            Method::AdaptiveSubtracted => "adaptive-subtracted",
            Method::Fixed => "fixed",
        }
    }

    /// Parses a label of [`Method::label`]. Names a route for (34); exact.
    pub fn parse(s: &str) -> Result<Method> {
        Method::ALL
            .into_iter()
            .find(|m| m.label() == s.trim())
            .ok_or_else(|| Error::Parse {
                text: s.to_string(),
                reason: "expected auto, series, adaptive, adaptive-subtracted or fixed",
            })
    }
}

impl std::fmt::Display for Method {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.label())
    }
}

/// I1, I2 (normalisation of (37)) as a route computes them at the working precision, with
/// optionally their k-derivatives and J0, and relative error estimates in the working type: the
/// one internal result of every route, turned into the public [`Integrals`] by
/// [`Evaluation::publish`].
#[derive(Clone, Debug)]
pub struct Evaluation<T: Real> {
    /// I1 (the cos² integral).
    pub i1: T,
    /// I2 (the sin² integral).
    pub i2: T,
    /// ∂I1/∂k and ∂I2/∂k, when the route computed them.
    pub dk: Option<[T; 2]>,
    /// J0 = ∫_0^π g(V sin φ)/(k² cos²φ + sin²φ)^{1/2} dφ (of (32)), when computed.
    pub j0: Option<T>,
    /// Relative error estimate of I1 and I2 (the larger of the two).
    pub error_estimate: T,
    /// Relative error estimate of the k-derivatives and J0 (zero when absent).
    pub extra_error: T,
    /// The route that ran.
    pub route: Route,
    /// Work done: series terms or integrand evaluations.
    pub work: usize,
}

impl Integrals<crate::scalar::Mp> {
    /// A result of [`integrals_to_tolerance`] (MPFR numbers holding the values of the precision
    /// that ran) as numbers of that precision, `T` and `p` naming [`Integrals::precision`]:
    /// exact (each value is representable in `T`), the bounds unchanged.
    pub fn narrow<T: Real>(self, p: T::Prec) -> Integrals<T> {
        let bits = T::bits(p) + 64;
        self.map(|e| Estimated::new(T::from_float(&e.value.to_float(bits), p), e.error))
    }
}

impl<T: Real> Integrals<T> {
    /// Every value with its bound converted by `g`; the route, precision and work kept.
    pub(crate) fn map<U: Real>(self, g: impl Fn(Estimated<T>) -> Estimated<U>) -> Integrals<U> {
        Integrals {
            i1: g(self.i1),
            i2: g(self.i2),
            di1_dk: self.di1_dk.map(&g),
            di2_dk: self.di2_dk.map(&g),
            j0: self.j0.map(&g),
            route: self.route,
            precision: self.precision,
            work: self.work,
        }
    }
}

impl<T: Real> Evaluation<T> {
    /// I1, I2 of (34) as a route computed them, with an error estimate and nothing else.
    pub fn pair(i1: T, i2: T, error_estimate: T, route: Route, work: usize) -> Self {
        let z = T::zero(i1.prec());
        Evaluation {
            i1,
            i2,
            dk: None,
            j0: None,
            error_estimate,
            extra_error: z,
            route,
            work,
        }
    }

    /// The result of a fixed rule ([`fast`] or [`graded`]) at the axis ratio `k`: I1 and I2
    /// checked finite and positive (else [`beyond_exponent_range`] naming k), the a-priori
    /// bounds `bounds[0]`·ε on I1, I2 and `bounds[1]`·ε on the k-derivatives, the route and
    /// the nodes.
    #[inline]
    pub(crate) fn from_rule(
        k: &T,
        [i1, i2]: [T; 2],
        dk: Option<[T; 2]>,
        bounds: [i64; 2],
        route: Route,
        work: usize,
    ) -> Result<Self> {
        if !(i1.is_finite() && i1.is_positive() && i2.is_finite() && i2.is_positive()) {
            return Err(beyond_exponent_range(k));
        }
        let eps = T::epsilon(i1.prec());
        let extra = if dk.is_some() {
            eps.clone().mul_i64(bounds[1])
        } else {
            T::zero(i1.prec())
        };
        Ok(Evaluation {
            i1,
            i2,
            dk,
            j0: None,
            error_estimate: eps.mul_i64(bounds[0]),
            extra_error: extra,
            route,
            work,
        })
    }

    /// ∂I1/∂k of (34) as the route computed it (zero when not computed).
    pub fn di1_dk(&self) -> T {
        self.dk
            .as_ref()
            .map_or_else(|| T::zero(self.i1.prec()), |d| d[0].clone())
    }

    /// ∂I2/∂k of (34) as the route computed it (zero when not computed).
    pub fn di2_dk(&self) -> T {
        self.dk
            .as_ref()
            .map_or_else(|| T::zero(self.i1.prec()), |d| d[1].clone())
    }

    /// The same evaluation without its k-derivatives and J0 when their bound is not below 1
    /// (not one correct digit: at a loose tolerance far from k = 1 the adaptive route's
    /// derivatives can be that poor), for a caller that did not ask for them.
    pub(crate) fn without_poor_extras(mut self) -> Self {
        if self.extra_error >= T::one(self.i1.prec()) {
            self.dk = None;
            self.j0 = None;
            self.extra_error = T::zero(self.i1.prec());
        }
        self
    }

    /// The public result at the axis ratio `k`: every value finite and normal and every
    /// estimate finite and below 1 (else a typed error naming k: [`Error::Domain`],
    /// or [`Error::Unreachable`] naming the bounds), estimates as [`RelError`].
    /// I1, I2 of (34) (normalisation of (37)); the estimates are the route's, rounded upwards.
    pub fn publish(self, k: &T) -> Result<Integrals<T>> {
        let dk_finite = self
            .dk
            .as_ref()
            .is_none_or(|[a, b]| a.is_finite() && b.is_finite());
        let finite = self.i1.is_finite()
            && self.i2.is_finite()
            && dk_finite
            && self.j0.as_ref().is_none_or(|j| j.is_finite())
            && self.error_estimate.is_finite()
            && self.extra_error.is_finite();
        if !finite || self.underflowed() {
            return Err(beyond_exponent_range(k));
        }
        let one = T::one(self.i1.prec());
        if self.error_estimate >= one || self.extra_error >= one {
            return Err(Error::Unreachable {
                what: "the integrals I1, I2 (or their k-derivatives and J0)",
                tolerance: "1 (one correct digit)".into(),
                reason: format!(
                    "the route's bounds are {} and {}",
                    RelError::of(&self.error_estimate),
                    RelError::of(&self.extra_error)
                ),
            });
        }
        let precision = Precision::of::<T>(self.i1.prec());
        let err = RelError::of(&self.error_estimate);
        let extra = RelError::of(&self.extra_error);
        let (di1_dk, di2_dk) = match self.dk {
            Some([a, b]) => (
                Some(Estimated::new(a, extra)),
                Some(Estimated::new(b, extra)),
            ),
            None => (None, None),
        };
        Ok(Integrals {
            i1: Estimated::new(self.i1, err),
            i2: Estimated::new(self.i2, err),
            di1_dk,
            di2_dk,
            j0: self.j0.map(|j| Estimated::new(j, extra)),
            route: self.route,
            precision,
            work: self.work,
        })
    }

    /// Whether a returned value lies below the smallest normal number of the working precision
    /// (I1, I2, J0 > 0 and the k-derivatives < 0 never vanish: such a value has lost its
    /// relative accuracy, e.g. dI1/dk ~ k⁻⁴ at k ≳ 10⁸⁰ in `f64`).
    fn underflowed(&self) -> bool {
        let tiny = T::min_positive(self.i1.prec());
        let dk = self.dk.iter().flatten();
        [&self.i1, &self.i2]
            .into_iter()
            .chain(dk)
            .chain(self.j0.as_ref())
            .any(|v| v.clone().abs() < tiny)
    }
}

/// The typed refusal for a route whose values at the axis ratio `k` left the working type's
/// exponent range (an integrand, I1, I2, a k-derivative or an estimate that overflowed or
/// vanished): k, as the user gave it, lies outside the domain the route serves at this speed
/// and precision ([`Error::Domain`]); MPFR's exponent range holds it.
#[cold]
pub(crate) fn beyond_exponent_range<T: Real>(k: &T) -> Error {
    Error::Domain {
        name: "axis ratio k = b/a",
        value: short(k),
        bound: BEYOND_EXPONENT_RANGE,
    }
}

/// The bound [`beyond_exponent_range`] names: a refusal that a wider exponent range lifts
/// ([`integrals_to_tolerance`] tries the next precision on it).
pub(crate) const BEYOND_EXPONENT_RANGE: &str = "a k whose integrals stay within the working type's exponent range at this speed (a value overflowed or vanished; MPFR's exponent range is wider)";

/// J0 of (32) from I1 and I2 of (34) at the same axis ratio k (normalisation of (37)):
/// J0 = k² I1 + I2 (`docs/theory.md`, "Galin's theorem and the Hertz relations"), formed as
/// k·(k·I1) + I2, whose intermediates stay within the working type wherever I1, I2
/// and 1/k do (I1 ≈ 2(1 − ν)/k² as k → 0). Below the Rayleigh speed g > 0, so I1 and I2 are
/// positive and J0's relative error is at most the larger q of theirs compounded with the three
/// roundings (k·I1, k·(k·I1), the sum; k is exact): (1 + q)(1 + γ3) − 1 = q + γ3 + q·γ3 with
/// γ3 = [`RelError::rounding`] of 3 operations (1.5ε at `f64` and MPFR, 4.9ε at double-double);
/// a pair that is not positive gets [`RelError::INFINITE`] (an error at the public boundary).
/// Tested against an independent quadrature of J0 alone (both peaks in closed form),
/// the adaptive route's own J0 and mpmath (`tests/unit/direct.rs`, `tests/identities.rs`).
pub(crate) fn j0_from_pair<T: Real>(k: &T, i1: &T, i2: &T, pair_error: RelError) -> Estimated<T> {
    let value = k.clone() * &(k.clone() * i1) + i2;
    let error = if i1.is_positive() && i2.is_positive() {
        let gamma = RelError::rounding::<T>(3.0, k.prec());
        pair_error.add(gamma).add(pair_error.mul(gamma))
    } else {
        RelError::INFINITE
    };
    Estimated::new(value, error)
}

/// I1, I2 of (34) in the normalisation of (37) at one axis ratio k, each with a bound on its
/// relative error, optionally with ∂I1/∂k, ∂I2/∂k and J0 (of (32)), and the route that ran.
/// Returned by [`integrals`] and [`Evaluator::at`].
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Integrals<T: Real> {
    /// I1 (the cos² integral, (46)).
    pub i1: Estimated<T>,
    /// I2 (the sin² integral, (47)).
    pub i2: Estimated<T>,
    /// ∂I1/∂k, when asked for ([`IntegralOptions::derivatives`]).
    pub di1_dk: Option<Estimated<T>>,
    /// ∂I2/∂k, when asked for.
    pub di2_dk: Option<Estimated<T>>,
    /// J0 of (32) (the approach integral), when asked for ([`IntegralOptions::j0`]).
    pub j0: Option<Estimated<T>>,
    /// The route that ran.
    pub route: Route,
    /// The precision it ran at.
    pub precision: Precision,
    /// Work done: series terms or integrand evaluations.
    pub work: usize,
}

#[cfg(test)]
#[path = "../../tests/unit/j0_rounding.rs"]
mod j0_rounding_tests;
