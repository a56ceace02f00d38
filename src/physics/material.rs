//! The elastic material (Poisson's ratio, wave-speed ratio) and the punch speed as Mach numbers.
//!
//! A [`Speed`] is made by its [`Material`] and carries it: every function that needs both takes
//! the speed alone, so a speed of one material can never be used with another. Near the Rayleigh
//! speed the answer is governed by the gap 1 − M_R (I2 ~ (1 − M_R²)^{−1/2}, and k's condition
//! number in M_R is about M_R/(4(1 − M_R))), so a speed holds the gap as a number of its own,
//! formed exactly from the input: [`Material::speed_from_gap`] takes it directly, and
//! [`Material::parse_speed`] forms it from the decimal text of M_R before anything is rounded.

use super::green::GreenFunction;
use super::rayleigh::RayleighRoots;
use crate::error::{Error, Result};
use crate::scalar::{check_finite, decimal_to_rational, short, FieldOps, Precision, Real};
use rug::Rational;

/// An isotropic elastic half-space, described by Poisson's ratio ν ∈ (−1, 1/2].
///
/// Holds γ = (c2/c1)² = (1 − 2ν)/(2(1 − ν)) and the roots of the Rayleigh cubic
/// ([`RayleighRoots`], section 3 of the paper), computed once at construction to within 4 ε of
/// the working precision.
#[derive(Clone, Debug)]
pub struct Material<T: Real> {
    nu: T,
    gamma: T,
    roots: RayleighRoots<T>,
    /// πG(1): the regular part of the Green's function at the Rayleigh speed.
    pi_g_rayleigh: T,
}

const NU_NAME: &str = "nu (Poisson's ratio)";
const NU_BOUND: &str = "(-1, 1/2]";

impl<T: Real> Material<T> {
    /// The material with Poisson's ratio `nu`; [`Error::Domain`] unless −1 < ν ≤ 1/2,
    /// [`Error::NotFinite`] for NaN or ∞. Builds γ (M1² = γM2² in (5)), the Rayleigh
    /// roots (the factorised (6), section 6) and πG(1) of (45); each within a few ε of the working precision.
    pub fn new(nu: T) -> Result<Self> {
        check_finite(NU_NAME, &nu)?;
        let p = nu.prec();
        if nu <= T::from_i64(-1, p) || nu > T::from_ratio(1, 2, p) {
            return Err(Error::domain(NU_NAME, short(&nu), NU_BOUND));
        }
        let gamma = gamma_of(&nu);
        let roots = RayleighRoots::new(&nu)?;
        let mut mat = Material {
            nu,
            gamma,
            roots,
            pi_g_rayleigh: T::zero(p),
        };
        let green = GreenFunction::new(&mat);
        mat.pi_g_rayleigh = green.g_regular(&T::one(p)) * T::pi(p);
        Ok(mat)
    }

    /// The material whose Poisson's ratio is the decimal text `nu` (or `p/q`), checked exactly
    /// before it is rounded to the precision `p`: errors quote the text as given
    /// (`nu (Poisson's ratio) = 0.5000000000000000001 is outside its domain (-1, 1/2]`), and a
    /// value inside the domain that rounds onto its edge at this precision says so. ν is
    /// rounded once (correctly rounded); then as [`Material::new`] (equations there).
    pub fn parse(nu: &str, p: T::Prec) -> Result<Self> {
        Material::from_exact(&decimal_to_rational(nu)?, nu, p)
    }

    /// The material with the exact Poisson's ratio `nu`, rounded once to precision `p`; `text`
    /// is the input as given, for error messages.
    pub(crate) fn from_exact(nu: &Rational, text: &str, p: T::Prec) -> Result<Self> {
        if *nu <= -1 || *nu > Rational::from((1, 2)) {
            return Err(Error::domain(NU_NAME, text.trim().to_string(), NU_BOUND));
        }
        let x: T = round_rational(nu, p);
        Material::new(x.clone()).map_err(|_| Error::domain(NU_NAME, rounds_to(text, &x), NU_BOUND))
    }

    /// Poisson's ratio ν of the Green's function (4)–(6), as given (rounded once to the working
    /// precision).
    pub fn nu(&self) -> &T {
        &self.nu
    }
    /// γ = (c2/c1)² = (1 − 2ν)/(2(1 − ν)) (the ratio in M1² = γM2² of (5)); within 2 ε.
    pub fn gamma(&self) -> &T {
        &self.gamma
    }
    /// The roots m1, m2, m3 of the Rayleigh cubic (the factorised (6), section 6 of the paper,
    /// with errata #1); within 4 ε ([`RayleighRoots`]).
    pub fn roots(&self) -> &RayleighRoots<T> {
        &self.roots
    }
    /// m1 = (c_R/c2)², the Rayleigh root (the zero of (6)); within 4 ε.
    pub fn m1(&self) -> &T {
        &self.roots.m1
    }
    /// πG(1) = √(1 − γm1)·D(m1)/(m1 (m1 − m2)(m1 − m3)), G of (45) at the Rayleigh speed
    /// (t = 1): the strength of the Green's function's Rayleigh pole, the limit H of the scaled
    /// series coefficients h_n (35)–(36), and the constant of I2's growth as M_R → 1. Computed
    /// once by [`GreenFunction::g_regular`], to a few ε.
    pub fn pi_g_rayleigh(&self) -> &T {
        &self.pi_g_rayleigh
    }
    /// c_R/c2 = √m1 (the zero of (6)); within a few ε.
    pub fn cr_over_c2(&self) -> T {
        self.roots.m1.clone().sqrt()
    }
    /// c_R/c1 = √(γ m1) (the zero of (6)); within a few ε.
    pub fn cr_over_c1(&self) -> T {
        (self.gamma.clone() * &self.roots.m1).sqrt()
    }

    /// The speed with Rayleigh Mach number `mr` = V/c_R; [`Error::Domain`] unless 0 ≤ M_R < 1.
    /// The gap 1 − M_R is formed from `mr` exactly (for M_R ≥ 1/2 the subtraction is exact in
    /// binary); a decimal speed near 1 is better given as text ([`Material::parse_speed`]) or by
    /// its gap ([`Material::speed_from_gap`]), so that it is not rounded first. The Mach
    /// numbers of (5) and sections 5–6 of the paper; accuracy as the [`Speed`] accessors state.
    pub fn speed(&self, mr: T) -> Result<Speed<T>> {
        check_finite(MR_NAME, &mr)?;
        let p = mr.prec();
        if mr.is_negative() || mr >= T::one(p) {
            return Err(Error::domain(MR_NAME, short(&mr), MR_BOUND));
        }
        let gap = T::one(p) - &mr;
        Speed::new(self, mr, gap)
    }

    /// The speed whose gap to the Rayleigh speed is `gap` = 1 − M_R ∈ (0, 1]: the input that
    /// keeps every digit near the Rayleigh speed (as scipy's `ellipkm1` takes 1 − m). M_R =
    /// 1 − gap (sections 5–6 of the paper) is correctly rounded; the Mach numbers as the [`Speed`] accessors state.
    pub fn speed_from_gap(&self, gap: T) -> Result<Speed<T>> {
        check_finite(GAP_NAME, &gap)?;
        let p = gap.prec();
        if !gap.is_positive() || gap > T::one(p) {
            return Err(Error::domain(GAP_NAME, short(&gap), GAP_BOUND));
        }
        let mr = T::one(p) - &gap;
        Speed::new(self, mr, gap)
    }

    /// The speed whose M_R is the decimal text `mr` (or `p/q`): the gap 1 − M_R is formed
    /// exactly from the text, then M_R and the gap are each rounded once to the working
    /// precision, so that at `f64` the answer is accurate to the decimal given even at
    /// M_R = 0.999999999999 (M_R of sections 5–6 of the paper). Errors quote the text.
    pub fn parse_speed(&self, mr: &str) -> Result<Speed<T>> {
        let r = decimal_to_rational(mr)?;
        if !(0..1).contains(&r) {
            return Err(Error::domain(MR_NAME, mr.trim().to_string(), MR_BOUND));
        }
        self.speed_from_exact(&r, mr)
    }

    /// The speed whose gap 1 − M_R is the decimal text `gap` (or `p/q`), checked exactly
    /// (0 < gap ≤ 1); errors quote the text. The gap and M_R (sections 5–6 of the paper) each
    /// correctly rounded.
    pub fn parse_gap(&self, gap: &str) -> Result<Speed<T>> {
        let g = decimal_to_rational(gap)?;
        if g <= 0 || g > 1 {
            return Err(Error::domain(GAP_NAME, gap.trim().to_string(), GAP_BOUND));
        }
        self.speed_from_exact(&(Rational::from(1) - g), gap)
    }

    /// The speed with the exact M_R `mr` (0 ≤ M_R < 1): M_R and 1 − M_R each rounded once.
    /// `text` is the input as given, for error messages.
    pub(crate) fn speed_from_exact(&self, mr: &Rational, text: &str) -> Result<Speed<T>> {
        let p = self.nu.prec();
        let gap_exact = Rational::from(1) - mr;
        let gap: T = round_rational(&gap_exact, p);
        let m: T = round_rational(mr, p);
        if !gap.is_positive() || gap < T::min_positive(p) {
            return Err(Error::Domain {
                name: GAP_NAME,
                value: format!(
                    "{} (from the input {}, at {})",
                    rug::Float::with_val(64, &gap_exact).to_string_radix(10, Some(6)),
                    text.trim(),
                    Precision::of::<T>(p)
                ),
                bound: GAP_NORMAL_BOUND,
            });
        }
        Speed::new(self, m, gap)
    }

    /// This material at another precision `q` (ν rounded once). Used by the precision ladder's
    /// lower stages, whose roots only seed the working precision: a ν that rounds onto the edge
    /// −1 there is moved one unit inside.
    pub(crate) fn at<S: Real>(&self, q: S::Prec) -> Result<Material<S>> {
        let mut nu: S = S::from_float(&self.nu.to_float(T::bits(self.nu.prec()) + 8), q);
        let minus_one = S::from_i64(-1, q);
        if nu <= minus_one {
            nu = minus_one + S::epsilon(q);
        }
        Material::new(nu)
    }
}

/// γ = (c2/c1)² = (1 − 2ν)/(2(1 − ν)) (M1² = γM2² in (5)): exact over [`rug::Rational`] and
/// rational functions (the series coefficients of (36) with a symbolic ν),
/// within 2 ε otherwise. The map is its own inverse: ν = (1 − 2γ)/(2(1 − γ)) is `gamma_of(γ)`.
pub fn gamma_of<F: FieldOps>(nu: &F) -> F {
    let one = F::one(nu.prec());
    (one.clone() - nu.clone().mul_i64(2)) / (one - nu).mul_i64(2)
}

const MR_NAME: &str = "speed M_R = V/c_R";
const MR_BOUND: &str = "[0, 1) (sub-Rayleigh)";
const GAP_NAME: &str = "speed gap 1 - M_R";
const GAP_BOUND: &str = "(0, 1]";
/// The gap's domain once rounded: it must be a normal number of the working precision.
const GAP_NORMAL_BOUND: &str = "[the smallest normal number of the working precision, 1]";

/// The rational `r` rounded once to precision `p` (through MPFR with 64 guard bits).
pub(crate) fn round_rational<T: Real>(r: &Rational, p: T::Prec) -> T {
    T::from_float(&rug::Float::with_val(T::bits(p) + 64, r), p)
}

/// `text (rounds to x at this precision)`: the message for an input inside its domain that
/// rounds onto the edge at the working precision.
fn rounds_to<T: Real>(text: &str, x: &T) -> String {
    format!(
        "{} (rounds to {} at {})",
        text.trim(),
        short(x),
        Precision::of::<T>(x.prec())
    )
}

/// A punch speed below the Rayleigh speed, made by (and carrying) its [`Material`]: the Mach
/// numbers the formulas use, with the gap 1 − M_R held as a number of its own.
///
/// Accessors give M_R, 1 − M_R, M_R², 1 − M_R² (formed as (1 − M_R)(1 + M_R) from the gap,
/// so accurate to a few ε relative however close M_R is to 1) and M2² = m1·M_R² (M1² of (5)
/// is γ·M2², [`Material::gamma`]).
///
/// A speed cannot be paired with a material other than its own: every solver takes the
/// material from the speed, and neither can be changed after construction.
///
/// A speed keeps the fixed rule's k-independent set-up (G at the rule's nodes) once a solve or
/// an evaluation has used it, shared by its clones, so that further solves at that speed skip
/// it: about 1 KB at `f64` and 3 KB at double-double, a few MB at thousands of bits, freed with
/// the last clone.
///
/// ```
/// use moving_hertz::prelude::*;
/// let steel = Material::new(0.3_f64)?;
/// let rubber = Material::new(0.49_f64)?;
/// let v = steel.speed(0.9)?;
/// assert_eq!(v.material().nu(), steel.nu());
/// // The same M_R in another material is another speed: M2² = m1·M_R² follows the material.
/// assert_ne!(v.m2sq(), rubber.speed(0.9)?.m2sq());
/// # Ok::<(), moving_hertz::Error>(())
/// ```
///
/// ```compile_fail
/// use moving_hertz::prelude::*;
/// let mut v = Material::new(0.3_f64).unwrap().speed(0.9).unwrap();
/// v.material = Material::new(0.49_f64).unwrap(); // private: a speed keeps its material
/// ```
#[derive(Clone, Debug)]
pub struct Speed<T: Real> {
    material: Material<T>,
    mr: T,
    gap: T,
    mr2: T,
    one_minus_mr2: T,
    m2sq: T,
    /// The fixed rule's k-independent part at this speed, built on first use and shared by
    /// clones.
    fast: crate::routes::fast::SetupCache<T>,
    /// What the ellipse solves at this speed keep, built on first use and shared by clones.
    solves: crate::contact::SolveCache<T>,
}

impl<T: Real> Speed<T> {
    /// From M_R and its gap, both at the working precision (validated by the caller).
    pub(crate) fn new(mat: &Material<T>, mr: T, gap: T) -> Result<Speed<T>> {
        let p = mr.prec();
        let one = T::one(p);
        let mr2 = mr.square();
        let one_minus_mr2 = gap.clone() * (one + &mr);
        if one_minus_mr2 < T::min_positive(p) {
            return Err(Error::domain(
                GAP_NAME,
                short(&gap),
                "1 - M_R^2 a normal number of the working precision",
            ));
        }
        let m2sq = mat.m1().clone() * &mr2;
        Ok(Speed {
            material: mat.clone(),
            mr,
            gap,
            mr2,
            one_minus_mr2,
            m2sq,
            fast: crate::routes::fast::SetupCache::new(),
            solves: crate::contact::SolveCache::new(),
        })
    }

    /// The fixed rule's k-independent part at this speed ([`crate::routes::fast::FastSetup`]),
    /// built on first use and kept (shared by the speed's clones).
    pub(crate) fn fast_setup(&self) -> &Result<Box<crate::routes::fast::FastSetup<T>>> {
        self.fast.get(self)
    }

    /// What the ellipse solves at this speed keep ([`crate::contact::SolveCache`]).
    pub(crate) fn solve_cache(&self) -> &crate::contact::SolveCache<T> {
        &self.solves
    }

    /// The material this speed belongs to (exactly the one that made it; ν of (4)–(6)).
    pub fn material(&self) -> &Material<T> {
        &self.material
    }
    /// M_R = V/c_R ∈ [0, 1) (sections 5–6 of the paper), as given or correctly rounded.
    pub fn mr(&self) -> &T {
        &self.mr
    }
    /// 1 − M_R ∈ (0, 1] (ε² = (1 − M_R)(1 + M_R) in (48)–(53)), as given or formed exactly from the input, then
    /// correctly rounded.
    pub fn gap(&self) -> &T {
        &self.gap
    }
    /// M_R² (G(M_R²) is the value subtracted in (48)); within 1 ε of M_R's square.
    pub fn mr2(&self) -> &T {
        &self.mr2
    }
    /// ε² = 1 − M_R² = (1 − M_R)(1 + M_R) of (48)–(53), without cancellation: within 2 ε of
    /// the value at the stored gap.
    pub fn one_minus_mr2(&self) -> &T {
        &self.one_minus_mr2
    }
    /// x = M2² = m1·M_R² (the squared shear Mach number of (4)–(6) and (35)); within a few ε.
    pub fn m2sq(&self) -> &T {
        &self.m2sq
    }

    /// This speed (and its material) at another precision `q`, the gap rounded on its own: the
    /// precision ladder's lower stages and the guarded precision of the series route.
    pub(crate) fn at<S: Real>(&self, q: S::Prec) -> Result<Speed<S>> {
        let mat = self.material.at::<S>(q)?;
        let bits = T::bits(self.mr.prec()) + 8;
        let gap: S = S::from_float(&self.gap.to_float(bits), q);
        let mr: S = S::from_float(&self.mr.to_float(bits), q);
        Speed::new(&mat, mr, gap)
    }
}
