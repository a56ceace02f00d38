//! The routes to the integrals I1, I2 of (34) that fix the contact ellipse's shape (33):
//! the series of section 5 and the direct and singularity-subtracted quadratures of sections 6–7.
//!
//! **Normalisation.** Every route returns I1, I2 in the normalisation of (37), i.e. with
//! g = −πΓ (g(0) = f0 = 1 − ν) in place of −Γ: π times the paper's (34),
//!
//! ```text
//! I1 = ∫_0^π g(V sin φ) cos²φ / (k² cos²φ + sin²φ)^{3/2} dφ = 2 ∫_0^{π/2} g(V cos α) sin²α / Δ³ dα,
//! I2 = ∫_0^π g(V sin φ) sin²φ / (k² cos²φ + sin²φ)^{3/2} dφ = 2 ∫_0^{π/2} g(V cos α) cos²α / Δ³ dα,
//! ```
//!
//! with Δ² = 1 − e² sin²α = cos²α + k² sin²α, e² = 1 − k² (negative when k > 1), so that in the
//! static limit I1 = 2(1 − ν)(E/k² − K)/e² and I2 = 2(1 − ν)(K − E)/e² (43), and A1/B1 = I2/I1 (33).
//! (The paper's (35) expands −πΓ, not Γ: `docs/errata.md` #3.)
//!
//! The series route: [`coefficients`] (f_n of (35)–(36)), [`moments`] (L_n, M_n of (39)–(42)),
//! [`series`] (I1, I2 by (37) with truncation control); findings in `docs/series.md`.

pub mod asymptotic;
pub mod choose;
pub mod coefficients;
pub mod direct;
pub mod fast;
pub mod graded;
mod guard;
pub mod moments;
pub mod series;

pub use coefficients::{GreenSeries, SpeedCoefficients};

use crate::error::{Error, Result};
use crate::scalar::{check_finite, short, Real};

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
    /// The axis ratio `k` = b/a; [`Error::Domain`] unless 0 < k < ∞.
    pub fn new(k: T) -> Result<Self> {
        check_finite("axis ratio k = b/a", &k)?;
        if !k.is_positive() {
            return Err(Error::Domain {
                name: "axis ratio k = b/a",
                value: short(&k),
                bound: "(0, inf)",
            });
        }
        let p = k.prec();
        let one = T::one(p);
        let k2 = k.square();
        // k² and 1/k² must be normal numbers of the working precision (the integrals scale
        // like 1/k² and k).
        let tiny = T::min_positive(p);
        if !(k2.is_finite()
            && k2 >= tiny
            && k2.clone().recip().is_finite()
            && k2.clone().recip() >= tiny)
        {
            return Err(Error::Domain {
                name: "axis ratio k = b/a",
                value: short(&k),
                bound: "(0, inf) with k^2 and 1/k^2 normal numbers of the working precision",
            });
        }
        let e2 = (one.clone() - &k) * (one + &k);
        Ok(AxisRatio { k2, k, e2 })
    }
}

/// Which route produced a pair of integrals.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// The series (37) with L_n by (39)–(42): section 5.
    Series,
    /// Direct quadrature of (46)–(47).
    Quadrature,
    /// (46) by quadrature, (47) by the subtraction (48) with S in closed form (53).
    Subtracted,
}

impl Method {
    /// `series`, `quadrature` or `subtracted`.
    pub fn label(&self) -> &'static str {
        match self {
            Method::Series => "series",
            Method::Quadrature => "quadrature",
            Method::Subtracted => "subtracted",
        }
    }
}

/// I1 and I2 (normalisation of (37)) with a bound on their relative error.
#[derive(Clone, Debug)]
pub struct Integrals<T: Real> {
    /// I1 (the cos² integral).
    pub i1: T,
    /// I2 (the sin² integral).
    pub i2: T,
    /// An estimate of the larger relative error of the two.
    pub error_estimate: T,
    /// The route used.
    pub method: Method,
    /// Work done: series terms or integrand evaluations.
    pub work: usize,
}
