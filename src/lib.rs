//! # moving-hertz
//!
//! The Hertz contact problem for a rigid punch sliding without friction at a constant
//! sub-Rayleigh speed over an elastic half-space, after the paper in `../shared/paper.md`
//! (sections and equation numbers below refer to it), at any precision: `f64`, double-double
//! ([`scalar::Dd`]) and MPFR ([`scalar::Mp`]), with exact rationals where a recurrence has exact
//! coefficients.
//!
//! Layers, each importing only the ones above it:
//!
//! | module | holds |
//! |---|---|
//! | [`scalar`] | the [`scalar::Field`] / [`scalar::Real`] traits, the backends, [`scalar::Complex`] |
//! | [`numerics`] | elliptic integrals, quadrature, root finding, the series driver |
//! | [`physics`] | material and speeds, the Rayleigh function and roots, the Green's function (sections 3, 6) |
//! | [`studies`] | convergence, stability and cost studies: data and charts |
//! | [`routes`] | the series route (section 5) and the direct routes (sections 6–7) to I1, I2 |
//! | [`symbolic`] | the coefficients of (36) and (40) as exact rational functions of ν and e² |
//!
//! Conventions: the elliptic *parameter* is `m = k²` throughout [`numerics::elliptic`] (as in
//! DLMF §19, mpmath and scipy); the paper's `k = b/a` is an axis ratio, never a modulus.

#![warn(missing_docs)]

pub mod contact;
pub mod error;
pub mod numerics;
pub mod physics;
pub mod routes;
pub mod scalar;
pub mod studies;
pub mod symbolic;

pub use error::{Error, Result};

/// The README's library example, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The traits and types most programs need: `use moving_hertz::prelude::*;`.
pub mod prelude {
    pub use crate::error::{Error, Result};
    pub use crate::scalar::{Complex, Dd, Field, FieldOps, Mp, MpPrec, Precision, Real};
}
