//! # moving-hertz
//!
//! The Hertz contact problem for a rigid punch sliding without friction at a constant
//! sub-Rayleigh speed over an elastic half-space, after the paper "Hertz problem for a rigid
//! punch moving across the surface of a semi-infinite elastic solid" (sections and equation
//! numbers below refer to it; `docs/theory.md` states every formula the crate implements, with
//! the corrections of `docs/errata.md`), at any precision: `f64`, double-double ([`Dd`]) and
//! MPFR ([`Mp`]), with exact rationals where a recurrence has exact coefficients.
//!
//! ## The library in six nouns
//!
//! * [`Material`] (Poisson's ratio) makes a [`Speed`], which carries it: from M_R, from the gap
//!   1 − M_R, or from decimal text with the gap formed exactly. A [`Solid`] (ν with Young's or
//!   the shear modulus and the density, [`Moduli`], or the wave speeds c1, c2) gives c1, c2,
//!   c_R in m/s and makes a speed from the velocity V in m/s.
//! * [`ContactProblem`] — the punch's radii along and across the motion, the [`Loading`], the
//!   shear modulus and the speed — is solved by [`ContactProblem::solve`] into a
//!   [`ContactSolution`]: a, b, k, e, p0, d0, the load, each an [`Estimated`] value with a bound
//!   on its error, and the pressure and displacement fields.
//! * [`solve_ellipse`] gives the shape alone ([`Ellipse`]: k, e, the integrals), with
//!   [`Options`] (method, seed, tolerance; the precision ladder above `f64` by default).
//! * [`integrals`] / [`Evaluator`] evaluate I1, I2 of (34) (with k-derivatives and J0 on
//!   request) by the [`Route`] the [`Method`] and [`IntegralOptions`] select;
//!   [`integrals_to_tolerance`] picks the precision for a tolerance from [`ExactInputs`].
//! * [`sweep`] solves many points at once — ellipses over (ν, speed, A1/B1), contact problems,
//!   I1, I2 over k — in parallel, sharing set-ups and starting each root from its neighbours',
//!   each point with its own result or typed error.
//! * [`RelError`] is every error bound and tolerance: a mantissa and a binary exponent, so that
//!   it neither underflows nor overflows at any precision.
//!
//! ```
//! use moving_hertz::prelude::*;
//!
//! let p = MpPrec::new(256)?;                                  // working precision
//! let num = |text: &str| Mp::parse(text, p);                  // decimals parsed at 256 bits
//! let speed = Material::parse("0.3", p)?.parse_speed("0.9")?; // ν, and V = 0.9 c_R
//! let problem = ContactProblem {
//!     speed,
//!     radius_along: num("0.05")?,                             // R1 (m)
//!     radius_across: num("0.02")?,                            // R2 (m)
//!     loading: Loading::Load(num("1000")?),                   // P (N)
//!     shear_modulus: num("80e9")?,                            // μ (Pa)
//! };
//! let sol = problem.solve(&Options::default())?;
//! assert!(sol.a().error < RelError::parse("1e-70")?);
//! # Ok::<(), moving_hertz::Error>(())
//! ```
//!
//! ## Layers
//!
//! Each module imports only the ones above it:
//!
//! | module | holds |
//! |---|---|
//! | [`scalar`] | the [`Field`] / [`Real`] traits, the backends `f64`, [`Dd`], [`Mp`], `rug::Rational`, complex numbers, decimal parsing |
//! | [`estimate`] | [`RelError`] and [`Estimated`]: error bounds at any precision |
//! | [`numerics`] | the elliptic integrals of (42)–(43) and (52)–(53) at any precision; adaptive and fixed Gauss–Legendre quadrature |
//! | [`physics`] | [`Material`] and [`Speed`], the Rayleigh function and roots, the Green's function (sections 3, 6) |
//! | [`routes`] | the integrals I1, I2: the series route (section 5), the direct, subtracted and fixed-rule quadratures (sections 6–7), the evaluator and the choice of precision |
//! | [`contact`] | the ellipse (33), the full solution with the corrected (28), (30), (32), the convolution (7) check, the precision ladder (section 4) |
//! | [`sweep`] | many ellipses, contact solutions or integrals at once, in parallel blocks |
//! | [`symbolic`] | the coefficients of (36) and (40) as exact rational functions of ν and e² |
//!
//! The command-line tool (`moving-hertz`, the binary of this package) adds the studies and
//! charts that `docs/` shows; the library does not carry them.
//!
//! Conventions: the elliptic *parameter* is `m = k²` throughout the elliptic integrals (as in
//! DLMF §19, mpmath and scipy); the paper's `k = b/a` is an axis ratio, never a modulus.

#![warn(missing_docs)]

// Unit tests of internals (tests/unit/, named by `#[path]` in their modules) share the
// integration tests' helpers and spell the crate `moving_hertz` as those do.
#[cfg(test)]
extern crate self as moving_hertz;
#[cfg(test)]
#[macro_use]
#[path = "../tests/common/mod.rs"]
#[allow(unreachable_patterns)] // the crate's `#[non_exhaustive]` enums are exhaustive inside it
mod common;

pub mod contact;
pub mod error;
pub mod estimate;
pub mod numerics;
pub mod physics;
pub mod routes;
pub mod scalar;
pub mod sweep;
pub mod symbolic;

pub use contact::{
    solve_ellipse, ContactProblem, ContactSolution, Ellipse, Loading, MajorAxis, Options,
};
pub use error::{Error, Result};
pub use estimate::{BoundKind, Estimated, RelError};
pub use physics::{Material, Moduli, Solid, Speed};
pub use routes::{
    integrals, integrals_to_tolerance, Evaluator, ExactInputs, IntegralOptions, Integrals, Method,
    Route,
};
pub use scalar::{Dd, Field, FieldOps, Mp, MpPrec, Precision, Real};

/// The README's library example, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The types and traits most programs need: `use moving_hertz::prelude::*;`.
pub mod prelude {
    pub use crate::contact::{ContactProblem, Loading, Options};
    pub use crate::error::{Error, Result};
    pub use crate::estimate::{BoundKind, Estimated, RelError};
    pub use crate::physics::{Material, Moduli, Solid, Speed};
    pub use crate::routes::{IntegralOptions, Method};
    pub use crate::scalar::{Complex, Dd, Field, FieldOps, Mp, MpPrec, Precision, Real};
}
