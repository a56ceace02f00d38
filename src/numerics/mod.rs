//! Generic numerical building blocks, public for their own use: the elliptic integrals at any
//! precision ([`elliptic`]: K, E, B, D of the static limit (43) and Heuman's Lambda of the
//! subtraction (53)), and Gauss–Legendre quadrature with rules built at the working
//! precision ([`quadrature`]). Inside the crate they also hold the series driver and the
//! rules' construction. Every routine is written once over [`crate::scalar::Real`], takes its
//! tolerance from the working precision, bounds its work and returns a typed error when it does
//! not converge.

pub mod elliptic;
pub(crate) mod gauss_legendre;
pub mod quadrature;
pub(crate) mod series;
pub(crate) mod shares;
mod sum;
