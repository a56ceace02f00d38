//! [`Complex`]: a complex number over any [`Real`] backend (`num_complex::Complex` cannot serve
//! `rug`-backed reals, which are not `Copy` and lack `num_traits::Num`).
//!
//! The Rayleigh cubic has a complex-conjugate pair of roots for ν above about 0.263; its closed
//! form (Cardano) needs principal square and cube roots, provided here.
//!
//! No item of this module implements a formula of the paper: they are complex arithmetic for the
//! Rayleigh cubic's closed form (6); each operation is the textbook formula over the backend's
//! operations, with the rounding error those formulas carry (the Rayleigh roots are polished
//! afterwards: `physics::rayleigh`).

use super::Real;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// `re + i·im` over a real backend `T`.
#[derive(Clone, Debug, PartialEq)]
pub struct Complex<T> {
    /// Real part.
    pub re: T,
    /// Imaginary part.
    pub im: T,
}

impl<T: Real> Complex<T> {
    /// `re + i·im`.
    pub fn new(re: T, im: T) -> Self {
        Complex { re, im }
    }
    /// The real number `re` as a complex number.
    pub fn from_real(re: T) -> Self {
        let im = T::zero(re.prec());
        Complex { re, im }
    }
    /// Zero at precision `p`.
    pub fn zero(p: T::Prec) -> Self {
        Complex::new(T::zero(p), T::zero(p))
    }
    /// |z| without undue overflow.
    pub fn abs(&self) -> T {
        self.re.clone().hypot(&self.im)
    }
    /// Principal argument in (−π, π].
    pub fn arg(&self) -> T {
        self.im.clone().atan2(&self.re)
    }
    /// `z · s` for a real `s`.
    pub fn scale(self, s: &T) -> Self {
        Complex::new(self.re * s, self.im * s)
    }
    /// True when both parts are finite.
    pub fn is_finite(&self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }
    /// Principal square root (branch cut on the negative real axis, Re √z ≥ 0), computed
    /// without cancellation: √((|z| + |re|)/2) first, the other part by division.
    pub fn sqrt(self) -> Self {
        let p = self.re.prec();
        if self.re.is_zero() && self.im.is_zero() {
            return Complex::zero(p);
        }
        let r = self.abs();
        let t = ((r + self.re.clone().abs()).mul_pow2(-1)).sqrt();
        if !self.re.is_negative() {
            let im = self.im / t.clone().mul_pow2(1);
            Complex::new(t, im)
        } else {
            let re = self.im.clone().abs() / t.clone().mul_pow2(1);
            let im = if self.im.is_negative() { -t } else { t };
            Complex::new(re, im)
        }
    }
    /// Principal cube root: |z|^(1/3) · e^(i·arg(z)/3), arg in (−π, π].
    pub fn cbrt(self) -> Self {
        let p = self.re.prec();
        if self.im.is_zero() && !self.re.is_negative() {
            return Complex::new(self.re.cbrt(), T::zero(p));
        }
        let rho = self.abs().cbrt();
        let th = self.arg().div_i64(3);
        let (s, c) = th.sin_cos();
        Complex::new(rho.clone() * c, rho * s)
    }
    /// Multiplicative inverse (Smith's scaling, no undue overflow).
    pub fn recip(self) -> Self {
        let p = self.re.prec();
        Complex::new(T::one(p), T::zero(p)) / self
    }
}

impl<T: Real> Neg for Complex<T> {
    type Output = Complex<T>;
    fn neg(self) -> Self {
        Complex::new(-self.re, -self.im)
    }
}

impl<'r, T: Real> Add<&'r Complex<T>> for Complex<T> {
    type Output = Complex<T>;
    fn add(self, b: &'r Complex<T>) -> Self {
        Complex::new(self.re + &b.re, self.im + &b.im)
    }
}
impl<'r, T: Real> Sub<&'r Complex<T>> for Complex<T> {
    type Output = Complex<T>;
    fn sub(self, b: &'r Complex<T>) -> Self {
        Complex::new(self.re - &b.re, self.im - &b.im)
    }
}
impl<'r, T: Real> Mul<&'r Complex<T>> for Complex<T> {
    type Output = Complex<T>;
    fn mul(self, b: &'r Complex<T>) -> Self {
        let re = self.re.clone() * &b.re - self.im.clone() * &b.im;
        let im = self.re * &b.im + self.im * &b.re;
        Complex::new(re, im)
    }
}
impl<'r, T: Real> Div<&'r Complex<T>> for Complex<T> {
    type Output = Complex<T>;
    /// Smith's algorithm.
    fn div(self, b: &'r Complex<T>) -> Self {
        if b.re.clone().abs() >= b.im.clone().abs() {
            let r = b.im.clone() / &b.re;
            let d = b.re.clone() + r.clone() * &b.im;
            let re = (self.re.clone() + self.im.clone() * &r) / &d;
            let im = (self.im - self.re * &r) / &d;
            Complex::new(re, im)
        } else {
            let r = b.re.clone() / &b.im;
            let d = b.im.clone() + r.clone() * &b.re;
            let re = (self.re.clone() * &r + &self.im) / &d;
            let im = (self.im * &r - self.re) / &d;
            Complex::new(re, im)
        }
    }
}

/// The by-value operators, through the by-reference ones above.
macro_rules! by_value {
    ($($Tr:ident $m:ident),*) => {$(
        impl<T: Real> $Tr for Complex<T> {
            type Output = Complex<T>;
            fn $m(self, b: Complex<T>) -> Self {
                self.$m(&b)
            }
        }
    )*};
}

by_value!(Add add, Sub sub, Mul mul, Div div);
