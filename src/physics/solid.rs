//! The half-space in physical units: Poisson's ratio with the shear or Young's modulus and the
//! density, or the two body-wave speeds; its wave speeds c1, c2, c_R in m/s; and a punch speed
//! from the velocity V in m/s. The relations (μ = E/(2(1 + ν)), c2 = √(μ/ρ), c1 = c2/√γ,
//! c_R = c2·√m1, M_R = V/c_R), and how every input is taken exactly and each result rounded
//! once: `docs/theory.md`, "Physical units". Each formula is written once below, generic over
//! [`Field`] where it is rational. Units: any consistent system; SI gives m/s.

use super::material::{gamma_of, round_rational, Material, Speed};
use super::rayleigh::RayleighRoots;
use crate::error::{Error, Result};
use crate::scalar::{check_finite, decimal_to_rational, short, Field, Mp, MpPrec, Precision, Real};
use rug::float::Round;
use rug::{Float, Rational};

/// The guard bits above the working precision at which the roots are taken.
const GUARD: u32 = 64;

/// The stiffness and inertia of a half-space beside its Poisson's ratio: Young's modulus or the
/// shear modulus, with the density. `T` is a number of the working type, or `&str` decimal
/// text ([`Solid::parse`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Moduli<T> {
    /// Young's modulus E > 0 (Pa) and the density ρ > 0 (kg/m³).
    Youngs {
        /// E (Pa).
        youngs_modulus: T,
        /// ρ (kg/m³).
        density: T,
    },
    /// The shear modulus μ > 0 (Pa) and the density ρ > 0 (kg/m³).
    Shear {
        /// μ (Pa).
        shear_modulus: T,
        /// ρ (kg/m³).
        density: T,
    },
}

impl<X> Moduli<X> {
    /// The stiffness (E or μ) with its name, and the density.
    fn parts(self) -> (&'static str, X, X) {
        match self {
            Moduli::Youngs {
                youngs_modulus,
                density,
            } => (E_NAME, youngs_modulus, density),
            Moduli::Shear {
                shear_modulus,
                density,
            } => (MU_NAME, shear_modulus, density),
        }
    }
}

/// μ = E/(2(1 + ν)): the shear modulus of an isotropic solid from Young's modulus and
/// Poisson's ratio; exact over [`rug::Rational`], a few ε otherwise.
pub fn shear_from_youngs<F: Field>(youngs_modulus: &F, nu: &F) -> F {
    youngs_modulus.clone() / (F::one(nu.prec()) + nu).mul_i64(2)
}

/// An isotropic elastic half-space with its wave speeds in physical units: the [`Material`]
/// (ν), the shear modulus μ and density ρ when given, and c1, c2, c_R (m/s).
///
/// ```
/// use moving_hertz::prelude::*;
/// use moving_hertz::physics::Moduli;
/// // Steel: E = 210 GPa, ν = 0.3, ρ = 7850 kg/m³.
/// let moduli = Moduli::Youngs { youngs_modulus: "210e9", density: "7850" };
/// let steel = Solid::<f64>::parse("0.3", moduli, ())?;
/// assert_eq!(steel.shear_modulus(), Some(&80.769230769230769e9)); // μ = E/(2(1 + ν)), Pa
/// assert!((steel.c2() - 3207.6586).abs() < 1e-4);  // c2 = √(μ/ρ), m/s
/// assert!((steel.c_r() - 2974.8234).abs() < 1e-4); // c_R = c2·√m1, m/s
/// let speed = steel.parse_velocity("2000")?;     // V in m/s
/// assert!((speed.mr() - 2000.0 / steel.c_r()).abs() < 1e-15);
/// assert!(steel.parse_velocity("3000").is_err()); // above c_R: refused, naming c_R
/// # Ok::<(), moving_hertz::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Solid<T: Real> {
    material: Material<T>,
    shear_modulus: Option<T>,
    c1: Option<T>,
    c2: T,
    c_r: T,
    /// ν and c2² exactly, for c_R at a higher precision (a velocity close to c_R).
    nu_exact: Rational,
    c2_squared: Rational,
    /// c_R at the working precision plus [`GUARD`] bits.
    c_r_guard: Float,
}

const E_NAME: &str = "Young's modulus E (Pa)";
const MU_NAME: &str = "shear modulus mu (Pa)";
const RHO_NAME: &str = "density rho (kg/m^3)";
const C1_NAME: &str = "dilatational wave speed c1 (m/s)";
const C2_NAME: &str = "shear wave speed c2 (m/s)";
const V_NAME: &str = "velocity V (m/s)";
const V_BOUND: &str = "[0, c_R) (below the Rayleigh wave speed)";
const POSITIVE: &str = "(0, inf)";

/// An input as given: its exact value and its text (for messages).
struct Given {
    name: &'static str,
    exact: Rational,
    text: String,
}

impl Given {
    /// The decimal text `text` exactly.
    fn text(name: &'static str, text: &str) -> Result<Given> {
        Ok(Given {
            name,
            exact: decimal_to_rational(text)?,
            text: text.trim().to_string(),
        })
    }

    /// The value `x` of the working type exactly ([`Error::NotFinite`] for NaN, ∞).
    fn value<T: Real>(name: &'static str, x: &T) -> Result<Given> {
        check_finite(name, x)?;
        Ok(Given {
            name,
            exact: exact_value(x),
            text: short(x),
        })
    }

    /// [`Error::Domain`] `(0, inf)` unless positive.
    fn positive(self) -> Result<Given> {
        if self.exact > 0 {
            return Ok(self);
        }
        Err(Error::domain(self.name, self.text, POSITIVE))
    }

    /// Rounded once to precision `p`; refused when that is not a normal number there.
    fn round<T: Real>(&self, p: T::Prec) -> Result<T> {
        round_normal(&self.exact, self.name, &self.text, p)
    }
}

/// `x` as an exact rational (a finite value of any backend).
fn exact_value<T: Real>(x: &T) -> Rational {
    x.to_float(T::bits(x.prec()))
        .to_rational()
        .unwrap_or_default()
}

/// The exact positive `q` rounded once to precision `p`, refused (naming `name` and quoting
/// `text`) when it overflows or falls below the smallest normal number there.
fn round_normal<T: Real>(q: &Rational, name: &'static str, text: &str, p: T::Prec) -> Result<T> {
    let x: T = round_rational(q, p);
    if x.is_finite() && x >= T::min_positive(p) {
        return Ok(x);
    }
    let why = if x.is_finite() {
        "underflows"
    } else {
        "overflows"
    };
    Err(Error::domain(
        name,
        format!("{} ({why} {})", text, Precision::of::<T>(p)),
        "a normal number of the working precision (rescale, or use a wider precision)",
    ))
}

impl<T: Real> Solid<T> {
    /// The half-space of `material` (ν) with `moduli`: μ = E/(2(1 + ν)) when E is given,
    /// c2 = √(μ/ρ), c1 = c2/√γ, c_R = c2·√m1 (module docs). [`Error::Domain`] for a modulus
    /// or density that is not positive, or whose μ, ρ or speeds are not normal numbers of the
    /// working precision; [`Error::NotFinite`] for NaN or ∞. μ is correctly rounded, c1, c2
    /// within 1 ε, c_R within 2 ε.
    pub fn new(material: &Material<T>, moduli: Moduli<T>) -> Result<Solid<T>> {
        let (name, stiffness, density) = moduli.parts();
        let stiffness = Given::value(name, &stiffness)?;
        let density = Given::value(RHO_NAME, &density)?;
        Solid::from_moduli(
            material.clone(),
            exact_value(material.nu()),
            stiffness,
            density,
        )
    }

    /// The half-space whose Poisson's ratio is the decimal text `nu` (as [`Material::parse`])
    /// and whose moduli are decimal text (`"210e9"`, `"7850"`, or `p/q`), each taken exactly;
    /// errors quote the text. Then as [`Solid::new`]: μ correctly rounded, c1, c2 within 1 ε,
    /// c_R within 2 ε of the values of the exact inputs.
    pub fn parse(nu: &str, moduli: Moduli<&str>, p: T::Prec) -> Result<Solid<T>> {
        let material = Material::parse(nu, p)?;
        let (name, stiffness, density) = moduli.parts();
        let stiffness = Given::text(name, stiffness)?;
        let density = Given::text(RHO_NAME, density)?;
        Solid::from_moduli(material, decimal_to_rational(nu)?, stiffness, density)
    }

    /// The half-space whose dilatational and shear wave speeds are `c1` and `c2` (m/s),
    /// 0 < c2 < (√3/2)·c1: ν = (1 − 2γ)/(2(1 − γ)) with γ = (c2/c1)² formed exactly and
    /// rounded once, c_R = c2·√m1 within 2 ε; c1 and c2 as given. μ is not known
    /// ([`Solid::shear_modulus`] is `None`).
    pub fn from_wave_speeds(c1: T, c2: T) -> Result<Solid<T>> {
        let p = c2.prec();
        let c1 = Given::value(C1_NAME, &c1)?;
        let c2 = Given::value(C2_NAME, &c2)?;
        Solid::from_speeds(c1, c2, p)
    }

    /// [`Solid::from_wave_speeds`] from decimal text (m/s), each speed taken exactly (ν formed
    /// exactly from them, then rounded once); errors quote the text.
    pub fn parse_wave_speeds(c1: &str, c2: &str, p: T::Prec) -> Result<Solid<T>> {
        let c1 = Given::text(C1_NAME, c1)?;
        let c2 = Given::text(C2_NAME, c2)?;
        Solid::from_speeds(c1, c2, p)
    }

    /// From the material, its exact ν, the stiffness (E or μ) and the density: μ rounded
    /// once (and ρ, to refuse one that is not a normal number), the speeds from the exact μ/ρ.
    fn from_moduli(
        material: Material<T>,
        nu_exact: Rational,
        stiffness: Given,
        rho: Given,
    ) -> Result<Self> {
        let p = material.nu().prec();
        let mut mu = stiffness.positive()?;
        if mu.name == E_NAME {
            let exact = shear_from_youngs(&mu.exact, &nu_exact);
            let text = format!("{} (from E = {})", short_rational(&exact), mu.text);
            mu = Given {
                name: MU_NAME,
                exact,
                text,
            };
        }
        let (mu, rho) = (mu.positive()?, rho.positive()?);
        let c2_squared = mu.exact.clone() / &rho.exact; // c2² = μ/ρ, exact
        let (mu, _) = (mu.round::<T>(p)?, rho.round::<T>(p)?);
        Solid::finish(material, nu_exact, c2_squared, Some(mu))
    }

    /// From (c1, c2): checks 0 < c2, 0 < c1 and γ = (c2/c1)² < 3/4 exactly, then ν of γ.
    fn from_speeds(c1: Given, c2: Given, p: T::Prec) -> Result<Self> {
        let (c1, c2) = (c1.positive()?, c2.positive()?);
        let c2_squared = c2.exact.clone().square();
        let gamma = c2_squared.clone() / c1.exact.clone().square();
        if gamma >= Rational::from((3, 4)) {
            return Err(Error::domain(
                "wave-speed ratio c2/c1",
                format!("{}/{}", c2.text, c1.text),
                "(0, sqrt(3)/2)",
            ));
        }
        let nu_exact = gamma_of(&gamma); // its own inverse: ν of γ
        let text = format!(
            "{} (from c1 = {}, c2 = {})",
            short_rational(&nu_exact),
            c1.text,
            c2.text
        );
        let material = Material::from_exact(&nu_exact, &text, p)?;
        Solid::finish(material, nu_exact, c2_squared, None)
    }

    /// The speeds from the exact ν and c2²: c2, c1 = c2/√γ and c_R = c2·√m1 taken
    /// [`GUARD`] bits above the working precision, each rounded once.
    fn finish(
        material: Material<T>,
        nu_exact: Rational,
        c2_squared: Rational,
        shear_modulus: Option<T>,
    ) -> Result<Self> {
        let p = material.nu().prec();
        let bits = T::bits(p) + GUARD;
        let (c2, c1, c_r_guard) = speeds_at(&nu_exact, &c2_squared, bits)?;
        let round = |x: &Mp, name| {
            round_normal(&exact_value(x), name, &x.0.to_string_radix(10, Some(6)), p)
        };
        let c1 = c1.map(|c1| round(&c1, C1_NAME)).transpose()?;
        Ok(Solid {
            material,
            shear_modulus,
            c1,
            c2: round(&c2, C2_NAME)?,
            c_r: round(&c_r_guard, "Rayleigh wave speed c_R (m/s)")?,
            nu_exact,
            c2_squared,
            c_r_guard: c_r_guard.0,
        })
    }

    /// The material (Poisson's ratio ν, the Rayleigh roots; (4)–(6)).
    pub fn material(&self) -> &Material<T> {
        &self.material
    }
    /// Poisson's ratio ν, rounded once.
    pub fn nu(&self) -> &T {
        self.material.nu()
    }
    /// The shear modulus μ (Pa), correctly rounded from the inputs (μ = E/(2(1 + ν)) when E
    /// was given); `None` for a half-space given by its wave speeds.
    pub fn shear_modulus(&self) -> Option<&T> {
        self.shear_modulus.as_ref()
    }
    /// The dilatational wave speed c1 = c2/√γ (m/s; c1 of (5)), within 1 ε (as given when
    /// the half-space was given by its wave speeds); `None` for ν = 1/2 (incompressible: γ = 0,
    /// c1 infinite).
    pub fn c1(&self) -> Option<&T> {
        self.c1.as_ref()
    }
    /// The shear wave speed c2 = √(μ/ρ) (m/s; c2 of (5)), within 1 ε (as given when the
    /// half-space was given by its wave speeds).
    pub fn c2(&self) -> &T {
        &self.c2
    }
    /// The Rayleigh wave speed c_R = c2·√m1 (m/s; m1 the zero of (6)), within 2 ε.
    pub fn c_r(&self) -> &T {
        &self.c_r
    }

    /// The speed of a punch moving at `v` (m/s), 0 ≤ V < c_R: M_R = V/c_R and
    /// 1 − M_R = (c_R − V)/c_R, each rounded once from a precision high enough that the gap is
    /// within a few ε however close V is to c_R (module docs). [`Error::Domain`] naming the
    /// velocity and c_R for V ≥ c_R or V < 0; [`Error::NotFinite`] for NaN or ∞.
    pub fn speed_from_velocity(&self, v: T) -> Result<Speed<T>> {
        let v = Given::value(V_NAME, &v)?;
        self.velocity(&v)
    }

    /// [`Solid::speed_from_velocity`] with V as decimal text (m/s, or `p/q`), taken exactly;
    /// errors quote the text.
    pub fn parse_velocity(&self, v: &str) -> Result<Speed<T>> {
        let v = Given::text(V_NAME, v)?;
        self.velocity(&v)
    }

    /// M_R and the gap of the exact velocity `v`, at a precision raised until the gap's
    /// cancellation leaves [`GUARD`] bits above the working precision (at most three passes).
    fn velocity(&self, v: &Given) -> Result<Speed<T>> {
        if v.exact < 0 {
            return Err(Error::domain(V_NAME, v.text.clone(), V_BOUND));
        }
        let p = self.material.nu().prec();
        let base = T::bits(p) + GUARD;
        let c_r_at = |bits| speeds_at(&self.nu_exact, &self.c2_squared, bits).map(|s| s.2 .0);
        let mut c_r = self.c_r_guard.clone();
        for _ in 0..3 {
            let bits = c_r.prec();
            let vf = Float::with_val(bits, &v.exact);
            let diff = Float::with_val(bits, &c_r - &vf);
            if !diff.is_sign_positive() || diff.is_zero() {
                if diff.is_zero() && bits < MpPrec::MAX_BITS {
                    c_r = c_r_at(bits.saturating_mul(2).min(MpPrec::MAX_BITS))?;
                    continue;
                }
                return Err(self.above_rayleigh(&v.text));
            }
            // The gap's cancellation costs the bits by which c_R − V is below c_R.
            let lost = (c_r.get_exp().unwrap_or(0) - diff.get_exp().unwrap_or(0)).max(0) as u32;
            let need = base.saturating_add(lost).min(MpPrec::MAX_BITS);
            if need > bits {
                c_r = c_r_at(need)?;
                continue;
            }
            let mr = Float::with_val(bits, &vf / &c_r);
            let gap = Float::with_val(bits, &diff / &c_r);
            let gap_t = T::from_float(&gap, p);
            if gap_t < T::min_positive(p) {
                return Err(Error::Domain {
                    name: V_NAME,
                    value: format!(
                        "{} (1 - V/c_R = {} underflows {})",
                        v.text,
                        gap.to_string_radix(10, Some(6)),
                        Precision::of::<T>(p)
                    ),
                    bound: "1 - V/c_R a normal number of the working precision",
                });
            }
            return Speed::new(&self.material, T::from_float(&mr, p), gap_t);
        }
        Err(Error::domain(
            V_NAME,
            v.text.clone(),
            "a velocity whose gap 1 - V/c_R is resolved within the supported precision",
        ))
    }

    /// The refusal of a velocity at or above c_R, stating c_R (rounded down, so that the
    /// value shown is never above V).
    fn above_rayleigh(&self, text: &str) -> Error {
        let c_r = self
            .c_r_guard
            .to_string_radix_round(10, Some(12), Round::Down);
        Error::Domain {
            name: V_NAME,
            value: format!(
                "{text} (the Rayleigh wave speed of this half-space is c_R = {c_r} m/s)"
            ),
            bound: V_BOUND,
        }
    }
}

/// c2 = √(c2²), c1 = c2/√γ (`None` at γ = 0, ν = 1/2) and c_R = c2·√m1 from the exact ν
/// and c2², at `bits` bits.
fn speeds_at(nu: &Rational, c2_squared: &Rational, bits: u32) -> Result<(Mp, Option<Mp>, Mp)> {
    let q = MpPrec::clamped(bits);
    let nu_q: Mp = round_rational(nu, q);
    let gamma = gamma_of(nu);
    let c2: Mp = round_rational::<Mp>(c2_squared, q).sqrt();
    let c1 = (gamma != 0).then(|| c2.clone() / round_rational::<Mp>(&gamma, q).sqrt());
    let m1 = RayleighRoots::new(&nu_q)?.m1;
    let c_r = c2.clone() * &m1.sqrt();
    Ok((c2, c1, c_r))
}

/// A rational to 6 significant digits, for messages.
fn short_rational(q: &Rational) -> String {
    Float::with_val(64, q).to_string_radix(10, Some(6))
}
