//! The Rayleigh function (6) and the roots of its rationalised cubic (section 6 of the paper):
//! R = x(x − m1)(x − m2)(x − m3)/D with x = M2², D = (2 − x)² + 4√((1 − γx)(1 − x)) (the paper
//! prints (2 − x)⁴, `docs/errata.md` #1) and (1 − ν)P(x) = (1 − ν)x³ − 8(1 − ν)x² + 8(2 − ν)x − 8
//! (`docs/theory.md`). m1 = (c_R/c2)² ∈ (0, 1) is the Rayleigh root; m2, m3 are real below
//! ν* ≈ 0.2631, where they merge, and complex conjugates above.
//!
//! Two closed forms ([`ClosedForm`]) and one default ([`RayleighRoots::new`]: an `f64` seed,
//! Halley steps in the wide type, the deflated quadratic there, one rounding) are offered;
//! `docs/rayleigh.md` charts their accuracy. The default is within 4 ε relative for m1, and for
//! m2, m3 relative to their modulus, for every −1 < ν ≤ 1/2, the merge point included.

use crate::error::{Error, Result};
use crate::scalar::{short, Complex, Real};

/// The roots of the Rayleigh cubic: m1 = (c_R/c2)² and the two others.
#[derive(Clone, Debug)]
pub struct RayleighRoots<T: Real> {
    /// The Rayleigh root m1 = (c_R/c2)² ∈ (0, 1).
    pub m1: T,
    /// The second root: the smaller real one for ν < ν*, the one with positive imaginary part
    /// above.
    pub m2: Complex<T>,
    /// The third root: the larger real one, or the conjugate of m2.
    pub m3: Complex<T>,
    /// m2 + m3 = 8 − m1 (real in both regimes).
    pub sum23: T,
    /// m2·m3 = 8/((1 − ν) m1) (real in both regimes).
    pub prod23: T,
}

/// A closed-form (Cardano) evaluation of the three roots at the working precision.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClosedForm {
    /// One formula for every ν: principal complex cube root C of −q/2 + √D and
    /// t_k = ω^k C − p/(3 ω^k C), in the crate's [`Complex`] type.
    ComplexCardano,
    /// Real branches, in the style of Rahman & Barber: the trigonometric form
    /// t_k = 2√(−p/3) cos((θ − 2πk)/3) when the discriminant allows three real roots, real
    /// Cardano with the cancellation-free cube root otherwise.
    RealBranches,
}

/// Coefficients (descending powers) of (1 − ν)·P(x) = (1 − ν)x³ − 8(1 − ν)x² + 8(2 − ν)x − 8.
/// The Rayleigh cubic (6) scaled by 1 − ν; exact in the field operations of the backend (rounded
/// once a coefficient).
fn cubic_coefficients<T: Real>(nu: &T) -> [T; 4] {
    let p = nu.prec();
    let one_m = T::one(p) - nu;
    let two_m = T::from_i64(2, p) - nu;
    [
        one_m.clone(),
        -(one_m.mul_i64(8)),
        two_m.mul_i64(8),
        T::from_i64(-8, p),
    ]
}

/// The depressed cubic t³ + p t + q = 0 with x = t + 8/3: with w = 1/(1 − ν),
/// p = 8w − 40/3 and q = 40w/3 − 448/27.
/// The Rayleigh cubic (6) shifted for Cardano's form; each coefficient rounded a few times (its
/// cancellation near ν ≈ 0.263 is the closed forms' weakness, docs/rayleigh.md).
fn depressed_cubic<T: Real>(nu: &T) -> (T, T) {
    let pr = nu.prec();
    let w = (T::one(pr) - nu).recip();
    let pp = w.clone().mul_i64(8) - T::from_ratio(40, 3, pr);
    let qq = w.mul_i64(40).div_i64(3) - T::from_ratio(448, 27, pr);
    (pp, qq)
}

/// (q/2)² + (p/3)³ of the depressed cubic's `pp` and `qq`: negative when the three roots are
/// real; a few ε absolute relative to (q/2)², so its sign is unreliable where it nearly
/// vanishes (ν ≈ 0.263).
fn discriminant<T: Real>(pp: &T, qq: &T) -> T {
    qq.clone().mul_pow2(-1).square() + pp.clone().div_i64(3).powi(3)
}

impl<T: Real> RayleighRoots<T> {
    /// The default: an `f64` seed, Halley polish of m1 in `T::Wide`, deflation, one rounding.
    /// Accuracy ≤ 4 ε (checked over a dense ν grid in `tests/rayleigh.rs`).
    /// The roots of the Rayleigh cubic (6).
    pub fn new(nu: &T) -> Result<Self> {
        let p = nu.prec();
        let pw = T::wide_prec(p);
        let nu_w = nu.to_wide(pw);
        let seed = RayleighRoots::<f64>::closed_form(&nu.to_f64(), ClosedForm::RealBranches).m1;
        let seed = if seed.is_finite() && seed > 0.0 && seed < 1.0 {
            seed
        } else {
            0.9
        };
        let m1_w = polish_m1(&nu_w, <T::Wide as Real>::from_f64(seed, pw))?;
        let wide = RayleighRoots::from_m1(&nu_w, m1_w);
        Ok(RayleighRoots {
            m1: T::from_wide(&wide.m1, p),
            m2: Complex::new(T::from_wide(&wide.m2.re, p), T::from_wide(&wide.m2.im, p)),
            m3: Complex::new(T::from_wide(&wide.m3.re, p), T::from_wide(&wide.m3.im, p)),
            sum23: T::from_wide(&wide.sum23, p),
            prod23: T::from_wide(&wide.prod23, p),
        })
    }

    /// All three roots from m1 by deflation: m2 + m3 = 8 − m1, m2·m3 = 8/((1 − ν)m1).
    fn from_m1(nu: &T, m1: T) -> Self {
        let p = nu.prec();
        let sum23 = T::from_i64(8, p) - &m1;
        let prod23 = T::from_i64(8, p) / ((T::one(p) - nu) * &m1);
        let half = sum23.clone().mul_pow2(-1);
        let disc = half.square() - &prod23;
        let (m2, m3) = if disc.is_negative() {
            let im = (-disc).sqrt();
            (
                Complex::new(half.clone(), im.clone()),
                Complex::new(half, -im),
            )
        } else {
            // Larger root first, then the smaller one by the product (no cancellation).
            let big = half + disc.sqrt();
            let small = prod23.clone() / &big;
            (Complex::from_real(small), Complex::from_real(big))
        };
        RayleighRoots {
            m1,
            m2,
            m3,
            sum23,
            prod23,
        }
    }

    /// The roots by a closed form at the working precision, without polishing (for the
    /// stability study; prefer [`RayleighRoots::new`]).
    /// The roots of (6) by Cardano's or the trigonometric form; accuracy: docs/rayleigh.md (all
    /// digits of m1 can be lost near ν = 2/5 by the one-formula form).
    pub fn closed_form(nu: &T, form: ClosedForm) -> Self {
        let pr = nu.prec();
        let (pp, qq) = depressed_cubic(nu);
        let d = discriminant(&pp, &qq);
        let complex_pair = !d.is_negative();
        let (p3, mq2) = (pp.div_i64(3), -(qq.clone().mul_pow2(-1)));
        let sqrt3_2 = || T::from_i64(3, pr).sqrt().mul_pow2(-1);
        // The roots t of the depressed cubic.
        let ts: [Complex<T>; 3] = match form {
            ClosedForm::ComplexCardano => {
                let (sd, mq2) = (Complex::from_real(d).sqrt(), Complex::from_real(mq2));
                let mut c = (mq2.clone() + &sd).cbrt();
                if c.re.is_zero() && c.im.is_zero() {
                    c = (mq2 - sd).cbrt();
                }
                let omega = Complex::new(-T::from_ratio(1, 2, pr), sqrt3_2());
                let p3 = Complex::from_real(p3);
                std::array::from_fn(|_| {
                    let t = c.clone() - p3.clone() / &c;
                    c = c.clone() * &omega;
                    t
                })
            }
            ClosedForm::RealBranches if d.is_negative() => {
                let r = (-p3).sqrt();
                let one = T::one(pr);
                let c = (mq2 / r.clone().powi(3)).min_of(one.clone()).max_of(-one);
                let (theta, two_pi) = (c.acos(), T::pi(pr).mul_pow2(1));
                std::array::from_fn(|k| {
                    let ang = (theta.clone() - two_pi.clone().mul_i64(k as i64)).div_i64(3);
                    Complex::from_real(r.clone().mul_pow2(1) * ang.cos())
                })
            }
            ClosedForm::RealBranches => {
                // Cube root of the term without cancellation, the other from A·B = −p/3.
                let sd = d.sqrt();
                let w = if qq.is_negative() {
                    mq2 + &sd
                } else {
                    mq2 - &sd
                };
                let a = w.cbrt();
                let b = if a.is_zero() { T::zero(pr) } else { -p3 / &a };
                let re = -((a.clone() + &b).mul_pow2(-1));
                let im = sqrt3_2() * (a.clone() - &b).abs();
                let pair = Complex::new(re.clone(), im.clone());
                [Complex::from_real(a + b), pair, Complex::new(re, -im)]
            }
        };
        let shift = T::from_ratio(8, 3, pr);
        let mut roots = ts.map(|t| Complex::new(t.re + &shift, t.im));
        // m1 has the smallest real part; the others ascend (three real roots) or come as the
        // pair with Im m2 > 0 (complex regime, decided by the sign of the discriminant).
        roots.sort_by(|a, b| a.re.partial_cmp(&b.re).unwrap_or(std::cmp::Ordering::Equal));
        let [m1, m2, m3] = roots;
        let (m2, m3) = if complex_pair && m2.im.is_negative() {
            (m3, m2)
        } else {
            (m2, m3)
        };
        let sum23 = m2.re.clone() + &m3.re;
        let prod23 = (m2.clone() * &m3).re;
        RayleighRoots {
            m1: m1.re,
            m2,
            m3,
            sum23,
            prod23,
        }
    }

    /// The three roots as complex numbers, m1 first.
    /// The roots of (6), as [`RayleighRoots::new`] computed them.
    pub fn all(&self) -> [Complex<T>; 3] {
        [
            Complex::from_real(self.m1.clone()),
            self.m2.clone(),
            self.m3.clone(),
        ]
    }
}

/// Halley iteration for the Rayleigh root of (1 − ν)P(x) from `x`, in whatever precision `x`
/// carries. Stops when the step falls below 4 ε|x| or stops shrinking; at most 64 steps.
fn polish_m1<W: Real>(nu: &W, mut x: W) -> Result<W> {
    let p = x.prec();
    let [c3, c2, c1, c0] = cubic_coefficients(nu);
    let tol = W::epsilon(p).mul_i64(4);
    let mut last_step: Option<W> = None;
    for it in 0..64 {
        // P, P', P'' by Horner.
        let f = ((c3.clone() * &x + &c2) * &x + &c1) * &x + &c0;
        let d1 = (c3.clone().mul_i64(3) * &x + c2.clone().mul_i64(2)) * &x + &c1;
        let d2 = c3.clone().mul_i64(6) * &x + c2.clone().mul_i64(2);
        let den = d1.square().mul_i64(2) - f.clone() * &d2;
        if den.is_zero() {
            return Err(Error::NoConvergence {
                what: "Halley polish of the Rayleigh root",
                iterations: it,
                reached: "zero denominator".into(),
            });
        }
        let step = (f * &d1).mul_i64(2) / den;
        x -= &step;
        let size = step.abs();
        if size <= tol.clone() * &x.clone().abs() {
            return Ok(x);
        }
        if let Some(prev) = &last_step {
            if size >= *prev {
                // Rounding level reached: the step no longer shrinks.
                return Ok(x);
            }
        }
        last_step = Some(size);
    }
    Err(Error::NoConvergence {
        what: "Halley polish of the Rayleigh root",
        iterations: 64,
        reached: last_step.map(|s| short(&s)).unwrap_or_default(),
    })
}
