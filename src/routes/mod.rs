//! The two routes to the integrals I1, I2 of (34): the series of section 5 and, later, the direct
//! and singularity-subtracted quadratures of sections 6–7.

pub mod coefficients;

pub use coefficients::GreenSeries;
