//! The physics of sections 3 and 6 of the paper: the material and its wave speeds, the Rayleigh
//! function (6) and the three roots of its rationalised cubic, and the moving-load surface Green's
//! function Γ (5) with its regular part G (44)–(45).
//!
//! Conventions: the load moves along x at speed V; Mach numbers M1 = V/c1, M2 = V/c2,
//! M_R = V/c_R; `x = M2²` is the variable of the Rayleigh cubic; γ = (c2/c1)².

pub mod green;
pub mod material;
pub mod rayleigh;
pub mod solid;

pub use green::GreenFunction;
pub use material::{Material, Speed};
pub use rayleigh::{ClosedForm, RayleighRoots};
pub use solid::{Moduli, Solid};
