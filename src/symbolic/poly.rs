//! Dense univariate polynomials over ℚ with exact `rug::Rational` coefficients: the few
//! operations the rational functions of [`super::RatFunc`] need (ring operations, division with
//! remainder, the monic gcd, exact evaluation). Every operation is exact.
//!
//! No item of this module implements a formula of the paper: they are the polynomial arithmetic
//! under the exact runs of (36) and (40), and every operation is exact.

use rug::{Integer, Rational};
use std::cmp::Ordering;

/// A polynomial Σ c_i x^i over ℚ, coefficients stored from x⁰ upwards with no trailing zero
/// (the zero polynomial has none). Exact.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Poly {
    c: Vec<Rational>,
}

impl Poly {
    /// The polynomial with coefficients `c` (from x⁰ upwards); trailing zeros are dropped.
    pub fn new(c: Vec<Rational>) -> Poly {
        let mut p = Poly { c };
        p.trim();
        p
    }

    /// The constant `r`.
    pub fn constant(r: Rational) -> Poly {
        Poly::new(vec![r])
    }

    /// The variable x.
    pub fn x() -> Poly {
        Poly::new(vec![Rational::new(), Rational::from(1)])
    }

    fn trim(&mut self) {
        while self.c.last().is_some_and(|r| r.cmp0() == Ordering::Equal) {
            self.c.pop();
        }
    }

    /// The coefficients from x⁰ upwards (empty for zero).
    pub fn coeffs(&self) -> &[Rational] {
        &self.c
    }

    /// True for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.c.is_empty()
    }

    /// The degree (0 for constants, including zero).
    pub fn degree(&self) -> usize {
        self.c.len().saturating_sub(1)
    }

    /// The leading coefficient (0 for the zero polynomial).
    pub fn lead(&self) -> Rational {
        self.c.last().cloned().unwrap_or_default()
    }

    /// `self · r`.
    pub fn scale(&self, r: &Rational) -> Poly {
        if r.cmp0() == Ordering::Equal {
            return Poly::default();
        }
        Poly {
            c: self.c.iter().map(|a| Rational::from(a * r)).collect(),
        }
    }

    /// `self + other`.
    pub fn add(&self, other: &Poly) -> Poly {
        let (long, short) = if self.c.len() >= other.c.len() {
            (self, other)
        } else {
            (other, self)
        };
        let mut c = long.c.clone();
        for (a, b) in c.iter_mut().zip(&short.c) {
            *a += b;
        }
        Poly::new(c)
    }

    /// `−self`.
    pub fn neg(&self) -> Poly {
        Poly {
            c: self.c.iter().map(|a| Rational::from(-a)).collect(),
        }
    }

    /// `self · other` (schoolbook).
    pub fn mul(&self, other: &Poly) -> Poly {
        if self.is_zero() || other.is_zero() {
            return Poly::default();
        }
        let mut c = vec![Rational::new(); self.c.len() + other.c.len() - 1];
        for (i, a) in self.c.iter().enumerate() {
            if a.cmp0() == Ordering::Equal {
                continue;
            }
            for (j, b) in other.c.iter().enumerate() {
                c[i + j] += Rational::from(a * b);
            }
        }
        Poly::new(c)
    }

    /// `self^e`.
    pub fn pow(&self, e: u32) -> Poly {
        let mut acc = Poly::constant(Rational::from(1));
        for _ in 0..e {
            acc = acc.mul(self);
        }
        acc
    }

    /// Quotient and remainder of the division by `d` ≠ 0: self = q·d + r, deg r < deg d.
    pub fn div_rem(&self, d: &Poly) -> (Poly, Poly) {
        assert!(!d.is_zero(), "polynomial division by zero");
        if self.c.len() < d.c.len() {
            return (Poly::default(), self.clone());
        }
        let inv_lead = Rational::from(d.lead().recip_ref());
        let dn = d.c.len() - 1;
        let mut r = self.c.clone();
        let mut q = vec![Rational::new(); self.c.len() - dn];
        for k in (0..q.len()).rev() {
            let t = Rational::from(&r[k + dn] * &inv_lead);
            if t.cmp0() != Ordering::Equal {
                for (j, dj) in d.c.iter().enumerate().take(dn) {
                    r[k + j] -= Rational::from(&t * dj);
                }
            }
            r[k + dn] = Rational::new();
            q[k] = t;
        }
        r.truncate(dn);
        (Poly::new(q), Poly::new(r))
    }

    /// `self` divided by its leading coefficient (zero stays zero).
    pub fn monic(&self) -> Poly {
        if self.is_zero() {
            return Poly::default();
        }
        self.scale(&Rational::from(self.lead().recip_ref()))
    }

    /// The monic greatest common divisor (Euclid over ℚ); gcd(0, 0) = 0.
    pub fn gcd(&self, other: &Poly) -> Poly {
        let (mut a, mut b) = (self.monic(), other.monic());
        while !b.is_zero() {
            let r = a.div_rem(&b).1.monic();
            a = b;
            b = r;
        }
        a
    }

    /// The value at the rational `x` = a/b, exact: Horner on the integer polynomial
    /// b^d·P(a/b) (no rational canonicalisation until the one final division).
    pub fn eval(&self, x: &Rational) -> Rational {
        if self.is_zero() {
            return Rational::new();
        }
        let (content, ints) = self.primitive();
        let (a, b) = (x.numer(), x.denom());
        let mut acc = Integer::new();
        let mut bpow = Integer::from(1);
        for c in ints.iter().rev() {
            // acc = Σ_{j ≥ i} C_j a^{j−i} b^{(d−i)−(d−j)} after processing coefficient i.
            acc *= a;
            acc += Integer::from(c * &bpow);
            bpow *= b;
        }
        // Each step multiplied the earlier terms by a and the new one by b^(steps so far):
        // acc = Σ_i C_i a^i b^{d−i}.
        bpow /= b;
        Rational::from((acc, bpow)) * content
    }

    /// (content, primitive part): self = content · P with P of coprime integer coefficients and a
    /// positive leading coefficient (P = 0 and content 0 for zero).
    pub fn primitive(&self) -> (Rational, Vec<Integer>) {
        if self.is_zero() {
            return (Rational::new(), Vec::new());
        }
        let mut lcm = Integer::from(1);
        for a in &self.c {
            lcm.lcm_mut(a.denom());
        }
        let ints: Vec<Integer> = self
            .c
            .iter()
            .map(|a| a.numer() * Integer::from(&lcm / a.denom()))
            .collect();
        let mut g = Integer::new();
        for a in &ints {
            g.gcd_mut(a);
        }
        if self.lead().cmp0() == Ordering::Less {
            g = -g;
        }
        let prim = ints.iter().map(|a| Integer::from(a / &g)).collect();
        (Rational::from((g, lcm)), prim)
    }
}
