//! Generic numerical building blocks: elliptic integrals, quadrature and the
//! series driver. Every routine is written once over [`crate::scalar::Real`], takes its
//! tolerance from the working precision, bounds its work and returns a typed error when it does
//! not converge.

pub mod elliptic;
pub mod gauss_legendre;
pub mod quadrature;
pub mod series;
pub(crate) mod shares;
mod sum;
