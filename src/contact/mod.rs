//! The contact problem of section 4: the shape of the contact ellipse (33), the full Hertz
//! solution (semi-axes, central pressure, approach, load) with the corrected forms of (28), (30)
//! and (32), and its independent validation by the convolution (7).
//!
//! Conventions: the punch moves along x; a is the semi-axis along the motion, b across it,
//! k = b/a; R1 (A1 = 1/(2R1)) is the punch's radius of curvature along the motion, R2
//! (B1 = 1/(2R2)) across it.

mod convolution;
mod ellipse;
mod solution;
mod solve_cache;

pub use ellipse::{check_ratio, solve_ellipse, Ellipse, MajorAxis, Options, RATIO_RANGE};
pub(crate) use ellipse::{checked_options, ShapeSolver};
pub use solution::{ContactProblem, ContactSolution, Loading};
pub(crate) use solve_cache::SolveCache;
