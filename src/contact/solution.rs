//! The full moving-punch Hertz solution.
//!
//! With g = −πΓ (g(0) = 1 − ν) and I1, I2, J0 in the normalisation of (37), the displacement
//! under the pressure p = p0 (1 − x²/a² − y²/b²)^{1/2} is, from (26),
//!
//! ```text
//! u_z = d0 − A1 x² − B1 y²,   d0 = p0 b J0/(4μ),   A1 = p0 k I2/(4μ a),   B1 = p0 k I1/(4μ a),
//! J0 = ∫_0^π g(V sin φ)/(k² cos²φ + sin²φ)^{1/2} dφ,
//! ```
//!
//! and the load is P = (2/3)π p0 a b (31). The paper's (28), (30) and (32) print these with Γ in
//! place of g and disagree with each other: (28)₁ and (32) differ by a factor −π² and (30) lacks
//! the factor π (`docs/errata.md`). In terms of Γ: d0 = −π p0 b/(4μ) ∫Γ/(…)^{1/2},
//! A1 = −π p0 k/(4μa) ∫Γ sin²φ/(…)^{3/2}.
//!
//! Given the load: a = (3P I1/(8π μ B1))^{1/3}, b = k a, p0 = 3P/(2π a b), d0 = p0 b J0/(4μ).
//! Given the approach: a = (d0 I1/(B1 J0))^{1/2}, p0 = 4μ a B1/(k I1), P = (2/3)π p0 a b.
//! In the static limit these are Johnson's (Contact Mechanics §4.2) with E* = 2μ/(1 − ν):
//! A1 = p0 b (K − E)/(E* e² a²), d0 = p0 b K/E* (tested to a few ε in `tests/contact.rs`).

use super::ellipse::{solve_ellipse, solve_ellipse_ladder, EllipseShape};
use crate::error::{Error, Result};
use crate::physics::{Material, Speed};
use crate::routes::direct::contact_integrals;
use crate::routes::AxisRatio;
use crate::scalar::{check_finite, short, Real};

/// What fixes the size of the contact: the load P or the approach d0 (both positive).
#[derive(Clone, Debug)]
pub enum Loading<T> {
    /// The total load P (31).
    Load(T),
    /// The approach (central displacement) d0 (32).
    Approach(T),
}

/// The solved contact.
#[derive(Clone, Debug)]
pub struct ContactSolution<T: Real> {
    /// The ellipse's shape (k, e, the integrals).
    pub shape: EllipseShape<T>,
    /// Semi-axis along the motion.
    pub a: T,
    /// Semi-axis across the motion.
    pub b: T,
    /// Central pressure p0 of (9) with m = 1.
    pub p0: T,
    /// Approach d0.
    pub d0: T,
    /// Load P.
    pub load: T,
    /// A1 = 1/(2 R1) (curvature along the motion).
    pub a1: T,
    /// B1 = 1/(2 R2) (curvature across the motion).
    pub b1: T,
    /// Shear modulus μ.
    pub mu: T,
}

fn positive<T: Real>(name: &'static str, x: &T) -> Result<()> {
    check_finite(name, x)?;
    if !x.is_positive() {
        return Err(Error::Domain {
            name,
            value: short(x),
            bound: "(0, inf)",
        });
    }
    Ok(())
}

/// Solves the moving-punch Hertz problem: radii of curvature `r_along` (R1) and `r_across`
/// (R2), the load or the approach, shear modulus `mu`, for `mat` at `speed`; `seed` is an
/// optional starting k (without one, above `f64` the precision ladder supplies it). Accuracy: the ellipse's error estimate propagates
/// to a, b, p0 with factors of order one; every result carries `shape.error_estimate`.
pub fn solve_contact<T: Real>(
    mat: &Material<T>,
    speed: &Speed<T>,
    r_along: &T,
    r_across: &T,
    loading: &Loading<T>,
    mu: &T,
    seed: Option<&T>,
) -> Result<ContactSolution<T>> {
    positive("radius along the motion R1", r_along)?;
    positive("radius across the motion R2", r_across)?;
    positive("shear modulus mu", mu)?;
    match loading {
        Loading::Load(pl) => positive("load P", pl)?,
        Loading::Approach(d) => positive("approach d0", d)?,
    }
    let p = mu.prec();
    let a1 = r_along.clone().mul_pow2(1).recip();
    let b1 = r_across.clone().mul_pow2(1).recip();
    let ratio = r_across.clone() / r_along;
    let shape = match seed {
        Some(s) => solve_ellipse(mat, speed, &ratio, Some(s))?,
        None => solve_ellipse_ladder(mat, speed, &ratio)?,
    };
    let ci = &shape.integrals;
    let k = shape.k.clone();
    // J0 of (32) at the solved k, by the adaptive vector quadrature (one evaluation).
    let j0 = contact_integrals(mat, speed, &AxisRatio::new(k.clone())?, &T::zero(p))?.j0;
    let pi = T::pi(p);
    let four_mu = mu.clone().mul_i64(4);
    let (a, load) = match loading {
        Loading::Load(pl) => {
            // a³ = 3 P I1 / (8 π μ B1).
            let a3 = pl.clone().mul_i64(3) * &ci.i1 / (pi.clone().mul_i64(8) * mu * &b1);
            (a3.cbrt(), pl.clone())
        }
        Loading::Approach(d0) => {
            let a = (d0.clone() * &ci.i1 / (b1.clone() * &j0)).sqrt();
            let p0 = four_mu.clone() * &a * &b1 / (k.clone() * &ci.i1);
            let b = k.clone() * &a;
            let load = pi.clone().mul_i64(2).div_i64(3) * p0 * &a * b;
            (a, load)
        }
    };
    let b = k.clone() * &a;
    let p0 = load.clone().mul_i64(3) / (pi.mul_i64(2) * &a * &b);
    let d0 = p0.clone() * &b * &j0 / &four_mu;
    // Inputs at the edge of the format (a radius of 1e-320, a load of 1e300) can overflow or
    // underflow the scaling even though each is valid: report it rather than return ∞ or 0.
    for (name, v) in [
        ("curvature A1 = 1/(2 R1)", &a1),
        ("curvature B1 = 1/(2 R2)", &b1),
        (
            "semi-axis a (overflow or underflow: rescale the inputs)",
            &a,
        ),
        (
            "semi-axis b (overflow or underflow: rescale the inputs)",
            &b,
        ),
        (
            "central pressure p0 (overflow or underflow: rescale the inputs)",
            &p0,
        ),
        (
            "approach d0 (overflow or underflow: rescale the inputs)",
            &d0,
        ),
        ("load P (overflow or underflow: rescale the inputs)", &load),
    ] {
        if !v.is_finite() || !v.is_positive() {
            return Err(Error::NotFinite {
                name,
                value: short(v),
            });
        }
    }
    Ok(ContactSolution {
        shape,
        a,
        b,
        p0,
        d0,
        load,
        a1,
        b1,
        mu: mu.clone(),
    })
}

impl<T: Real> ContactSolution<T> {
    /// True when (x, y) lies in the closed contact ellipse.
    pub fn inside(&self, x: &T, y: &T) -> bool {
        let p = x.prec();
        let r = (x.clone() / &self.a).square() + (y.clone() / &self.b).square();
        r <= T::one(p)
    }

    /// The contact pressure p(x, y) = p0 (1 − x²/a² − y²/b²)^{1/2} of (9) (m = 1); zero outside.
    pub fn pressure(&self, x: &T, y: &T) -> T {
        let p = x.prec();
        let q = T::one(p) - (x.clone() / &self.a).square() - (y.clone() / &self.b).square();
        if q.is_positive() {
            self.p0.clone() * q.sqrt()
        } else {
            T::zero(p)
        }
    }

    /// The surface displacement in the contact, u_z = d0 − A1 x² − B1 y² (27); outside the
    /// contact the displacement is not a polynomial ([`super::convolution`] evaluates it there),
    /// so points outside give [`Error::Domain`].
    pub fn displacement_in_contact(&self, x: &T, y: &T) -> Result<T> {
        if !self.inside(x, y) {
            return Err(Error::Domain {
                name: "point (x/a)^2 + (y/b)^2",
                value: short(&((x.clone() / &self.a).square() + (y.clone() / &self.b).square())),
                bound: "[0, 1] (inside the contact)",
            });
        }
        Ok(self.d0.clone() - self.a1.clone() * x.square() - self.b1.clone() * y.square())
    }
}
