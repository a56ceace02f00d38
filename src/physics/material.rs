//! The elastic material (Poisson's ratio, wave-speed ratio) and the punch speed as Mach numbers.

use super::rayleigh::RayleighRoots;
use crate::error::{Error, Result};
use crate::scalar::{check_finite, short, Real};

/// An isotropic elastic half-space, described by Poisson's ratio ν ∈ (−1, 1/2].
///
/// Holds γ = (c2/c1)² = (1 − 2ν)/(2(1 − ν)) and the roots of the Rayleigh cubic
/// ([`RayleighRoots`]), computed once at construction to within 4 ε of the working precision.
#[derive(Clone, Debug)]
pub struct Material<T: Real> {
    nu: T,
    one_minus_nu: T,
    gamma: T,
    roots: RayleighRoots<T>,
}

impl<T: Real> Material<T> {
    /// The material with Poisson's ratio `nu`; [`Error::Domain`] unless −1 < ν ≤ 1/2,
    /// [`Error::NotFinite`] for NaN or ∞.
    pub fn new(nu: T) -> Result<Self> {
        check_finite("nu", &nu)?;
        let p = nu.prec();
        let half = T::from_ratio(1, 2, p);
        if nu <= T::from_i64(-1, p) || nu > half {
            return Err(Error::Domain {
                name: "nu (Poisson's ratio)",
                value: short(&nu),
                bound: "(-1, 1/2]",
            });
        }
        let one = T::one(p);
        let one_minus_nu = one.clone() - &nu;
        // γ = (1 − 2ν)/(2(1 − ν)).
        let gamma = (one - nu.clone().mul_i64(2)) / one_minus_nu.clone().mul_i64(2);
        let roots = RayleighRoots::new(&nu)?;
        Ok(Material {
            nu,
            one_minus_nu,
            gamma,
            roots,
        })
    }

    /// The material whose wave-speed ratio is c2/c1 = `ratio`, 0 ≤ ratio < √3/2
    /// (ν = (1 − 2γ)/(2(1 − γ)) with γ = ratio²).
    pub fn from_speed_ratio(ratio: T) -> Result<Self> {
        check_finite("c2/c1", &ratio)?;
        let p = ratio.prec();
        let gamma = ratio.square();
        if ratio.is_negative() || gamma.clone().mul_i64(4) >= T::from_i64(3, p) {
            return Err(Error::Domain {
                name: "c2/c1",
                value: short(&ratio),
                bound: "[0, sqrt(3)/2)",
            });
        }
        let one = T::one(p);
        let nu = (one.clone() - gamma.clone().mul_i64(2)) / (one - gamma).mul_i64(2);
        Material::new(nu)
    }

    /// Poisson's ratio ν.
    pub fn nu(&self) -> &T {
        &self.nu
    }
    /// 1 − ν (the static value f0 of the normalised Green's function g = −πΓ).
    pub fn one_minus_nu(&self) -> &T {
        &self.one_minus_nu
    }
    /// γ = (c2/c1)² = (1 − 2ν)/(2(1 − ν)).
    pub fn gamma(&self) -> &T {
        &self.gamma
    }
    /// The roots of the Rayleigh cubic.
    pub fn roots(&self) -> &RayleighRoots<T> {
        &self.roots
    }
    /// m1 = (c_R/c2)², the Rayleigh root.
    pub fn m1(&self) -> &T {
        &self.roots.m1
    }
    /// c_R/c2 = √m1.
    pub fn cr_over_c2(&self) -> T {
        self.roots.m1.clone().sqrt()
    }
    /// c_R/c1 = √(γ m1).
    pub fn cr_over_c1(&self) -> T {
        (self.gamma.clone() * &self.roots.m1).sqrt()
    }

    /// The speed with Rayleigh Mach number `mr` = V/c_R; [`Error::Domain`] unless 0 ≤ M_R < 1.
    pub fn speed(&self, mr: T) -> Result<Speed<T>> {
        check_finite("speed M_R", &mr)?;
        let p = mr.prec();
        if mr.is_negative() || mr >= T::one(p) {
            return Err(Error::Domain {
                name: "speed M_R = V/c_R",
                value: short(&mr),
                bound: "[0, 1) (sub-Rayleigh)",
            });
        }
        Ok(Speed::new(self, mr))
    }

    /// The speed with shear Mach number `m2` = V/c2 (must be below c_R/c2).
    pub fn speed_from_m2(&self, m2: T) -> Result<Speed<T>> {
        check_finite("speed M2", &m2)?;
        if m2.is_negative() {
            return Err(Error::Domain {
                name: "speed M2 = V/c2",
                value: short(&m2),
                bound: "[0, c_R/c2)",
            });
        }
        let mr = m2.clone() / self.cr_over_c2();
        if mr >= T::one(m2.prec()) {
            return Err(Error::Domain {
                name: "speed M2 = V/c2",
                value: short(&m2),
                bound: "[0, c_R/c2) (sub-Rayleigh)",
            });
        }
        Ok(Speed::new(self, mr))
    }

    /// The speed `v` in the units of the shear-wave speed `c2` (both positive, v < c_R).
    pub fn speed_from_velocity(&self, v: T, c2: T) -> Result<Speed<T>> {
        check_finite("velocity V", &v)?;
        check_finite("shear wave speed c2", &c2)?;
        if !c2.is_positive() {
            return Err(Error::Domain {
                name: "shear wave speed c2",
                value: short(&c2),
                bound: "(0, inf)",
            });
        }
        if v.is_negative() {
            return Err(Error::Domain {
                name: "velocity V",
                value: short(&v),
                bound: "[0, c_R)",
            });
        }
        self.speed_from_m2(v / c2)
    }
}

/// A punch speed below the Rayleigh speed, in the Mach numbers the formulas use.
#[derive(Clone, Debug)]
pub struct Speed<T: Real> {
    /// M_R = V/c_R ∈ [0, 1).
    pub mr: T,
    /// M_R².
    pub mr2: T,
    /// 1 − M_R², formed as (1 − M_R)(1 + M_R) without cancellation.
    pub one_minus_mr2: T,
    /// x = M2² = m1·M_R².
    pub m2sq: T,
    /// M1² = γ·x.
    pub m1sq: T,
}

impl<T: Real> Speed<T> {
    fn new(mat: &Material<T>, mr: T) -> Speed<T> {
        let p = mr.prec();
        let one = T::one(p);
        let mr2 = mr.square();
        let one_minus_mr2 = (one.clone() - &mr) * (one + &mr);
        let m2sq = mat.m1().clone() * &mr2;
        let m1sq = mat.gamma().clone() * &m2sq;
        Speed {
            mr,
            mr2,
            one_minus_mr2,
            m2sq,
            m1sq,
        }
    }
    /// M2 = V/c2.
    pub fn m2(&self) -> T {
        self.m2sq.clone().sqrt()
    }
    /// M1 = V/c1.
    pub fn m1(&self) -> T {
        self.m1sq.clone().sqrt()
    }
}
