//! Rational functions of one variable over ℚ, always in lowest terms, as a [`FieldOps`] backend:
//! N(x) / Π q_i(x)^{e_i}, the denominator kept factored over a *coprime base* (monic, pairwise
//! coprime q_i; the numerator coprime to each), which is lowest terms by construction and keeps
//! every gcd against a linear base (why: `docs/design.md`, "Symbolic mode").
//!
//! No item of this module implements a formula of the paper: they are the exact arithmetic
//! under the recurrences (36) and (40) ([`super::green_coefficients`], [`super::moment_forms`]).

use super::poly::Poly;
use crate::scalar::FieldOps;
use rug::Rational;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A rational function of one variable with exact rational coefficients, in lowest terms
/// (see the module docs). Arithmetic is exact; division by the zero function panics, as
/// `rug::Rational` does (the recurrences check their divisors first).
#[derive(Clone, Debug, Default)]
pub struct RatFunc {
    num: Poly,
    den: Vec<(Poly, u32)>,
}

/// A coprime base shared by two denominators: (q, exponent in the first, in the second).
type Base2 = Vec<(Poly, [u32; 2])>;

/// Inserts the monic `f` with exponents `e` into the coprime base `list`, splitting bases that
/// share a factor with it (factor refinement); constants are dropped.
fn insert(list: &mut Base2, f: Poly, e: [u32; 2]) {
    if f.degree() == 0 {
        return;
    }
    for i in 0..list.len() {
        if list[i].0 == f {
            list[i].1[0] += e[0];
            list[i].1[1] += e[1];
            return;
        }
        let g = list[i].0.gcd(&f);
        if g.degree() == 0 {
            continue;
        }
        let (q, eq) = list.swap_remove(i);
        let q_rest = q.div_rem(&g).0;
        let f_rest = f.div_rem(&g).0;
        insert(list, g, [eq[0] + e[0], eq[1] + e[1]]);
        insert(list, q_rest, eq);
        insert(list, f_rest, e);
        return;
    }
    list.push((f, e));
}

/// The two denominators over one coprime base.
fn common_base(a: &[(Poly, u32)], b: &[(Poly, u32)]) -> Base2 {
    let mut list: Base2 = a.iter().map(|(q, e)| (q.clone(), [*e, 0])).collect();
    for (q, e) in b {
        insert(&mut list, q.clone(), [0, *e]);
    }
    list
}

/// Π q^e over a base.
fn expand(factors: impl Iterator<Item = (Poly, u32)>) -> Poly {
    let mut acc = Poly::constant(Rational::from(1));
    for (q, e) in factors {
        acc = acc.mul(&q.pow(e));
    }
    acc
}

/// N / Π q^e brought to lowest terms: divides N by each q while it divides, and splits a base
/// that shares only part of its factors with N.
fn reduce(mut num: Poly, mut den: Vec<(Poly, u32)>) -> RatFunc {
    if num.is_zero() {
        return RatFunc::default();
    }
    let mut i = 0;
    while i < den.len() {
        let mut rem = Poly::default();
        while den[i].1 > 0 {
            let (q, r) = num.div_rem(&den[i].0);
            if !r.is_zero() {
                rem = r;
                break;
            }
            num = q;
            den[i].1 -= 1;
        }
        if den[i].1 == 0 {
            den.swap_remove(i);
            continue;
        }
        let g = den[i].0.gcd(&rem);
        if g.degree() > 0 {
            // gcd(N, q) is a proper factor of q: refine the base and start again.
            let (q, e) = den.swap_remove(i);
            let mut list: Base2 = den.iter().map(|(p, k)| (p.clone(), [*k, 0])).collect();
            let rest = q.div_rem(&g).0;
            insert(&mut list, g, [e, 0]);
            insert(&mut list, rest, [e, 0]);
            den = list.into_iter().map(|(p, k)| (p, k[0])).collect();
            i = 0;
            continue;
        }
        i += 1;
    }
    RatFunc { num, den }
}

impl RatFunc {
    /// The variable x itself.
    pub fn var() -> RatFunc {
        RatFunc::from_poly(Poly::x())
    }

    /// The rational constant `r`.
    pub fn constant(r: Rational) -> RatFunc {
        RatFunc::from_poly(Poly::constant(r))
    }

    /// The polynomial `p`.
    pub fn from_poly(p: Poly) -> RatFunc {
        RatFunc {
            num: p,
            den: Vec::new(),
        }
    }

    /// The quotient `num / den` (den ≠ 0), brought to lowest terms.
    pub fn from_polys(num: Poly, den: Poly) -> RatFunc {
        RatFunc::from_poly(num) / RatFunc::from_poly(den)
    }

    /// The numerator N (coprime to the denominator; the leading coefficient of the denominator
    /// is 1, so (N, D) is the canonical pair).
    pub fn numer(&self) -> &Poly {
        &self.num
    }

    /// The denominator D, expanded and monic.
    pub fn denom(&self) -> Poly {
        expand(self.den.iter().cloned())
    }

    /// The denominator as its coprime base: monic, pairwise coprime q_i with exponents e_i,
    /// D = Π q_i^{e_i}.
    pub fn denom_factors(&self) -> &[(Poly, u32)] {
        &self.den
    }

    /// The value at the rational `x`, exactly; `None` where the denominator vanishes.
    pub fn eval(&self, x: &Rational) -> Option<Rational> {
        let mut d = Rational::from(1);
        for (q, e) in &self.den {
            d *= rug::ops::Pow::pow(q.eval(x), *e);
        }
        if d.cmp0() == std::cmp::Ordering::Equal {
            return None;
        }
        Some(self.num.eval(x) / d)
    }

    fn mul_ref(&self, other: &RatFunc) -> RatFunc {
        if self.num.is_zero() || other.num.is_zero() {
            return RatFunc::default();
        }
        let num = self.num.mul(&other.num);
        let den = if other.den.is_empty() {
            self.den.clone()
        } else if self.den.is_empty() {
            other.den.clone()
        } else {
            common_base(&self.den, &other.den)
                .into_iter()
                .map(|(q, e)| (q, e[0] + e[1]))
                .collect()
        };
        reduce(num, den)
    }

    fn add_ref(&self, other: &RatFunc) -> RatFunc {
        if other.num.is_zero() {
            return self.clone();
        }
        if self.num.is_zero() {
            return other.clone();
        }
        if self.den == other.den {
            return reduce(self.num.add(&other.num), self.den.clone());
        }
        let base = common_base(&self.den, &other.den);
        let lift = |n: &Poly, k: usize| {
            let m = base.iter().map(|(q, e)| (q.clone(), e[0].max(e[1]) - e[k]));
            n.mul(&expand(m))
        };
        let num = lift(&self.num, 0).add(&lift(&other.num, 1));
        let den = base.iter().map(|(q, e)| (q.clone(), e[0].max(e[1])));
        reduce(num, den.collect())
    }

    fn recip_ref(&self) -> RatFunc {
        assert!(!self.num.is_zero(), "rational function: division by zero");
        let lead = self.num.lead();
        let num = expand(self.den.iter().cloned()).scale(&Rational::from(lead.recip_ref()));
        let den = if self.num.degree() == 0 {
            Vec::new()
        } else {
            vec![(self.num.monic(), 1)]
        };
        RatFunc { num, den }
    }

    fn scale(&self, r: &Rational) -> RatFunc {
        if r.cmp0() == std::cmp::Ordering::Equal {
            return RatFunc::default();
        }
        RatFunc {
            num: self.num.scale(r),
            den: self.den.clone(),
        }
    }
}

impl PartialEq for RatFunc {
    /// Equality of the functions (lowest terms with a monic denominator are unique).
    fn eq(&self, other: &RatFunc) -> bool {
        self.num == other.num && self.denom() == other.denom()
    }
}

impl Neg for RatFunc {
    type Output = RatFunc;
    fn neg(self) -> RatFunc {
        RatFunc {
            num: self.num.neg(),
            den: self.den,
        }
    }
}

macro_rules! ratfunc_op {
    ($Op:ident, $op:ident, $OpAssign:ident, $op_assign:ident, |$a:ident, $b:ident| $body:expr) => {
        impl $Op<&RatFunc> for RatFunc {
            type Output = RatFunc;
            fn $op(self, $b: &RatFunc) -> RatFunc {
                let $a = &self;
                $body
            }
        }
        impl $Op for RatFunc {
            type Output = RatFunc;
            fn $op(self, b: RatFunc) -> RatFunc {
                self.$op(&b)
            }
        }
        impl $OpAssign<&RatFunc> for RatFunc {
            fn $op_assign(&mut self, b: &RatFunc) {
                *self = self.clone().$op(b);
            }
        }
        impl $OpAssign for RatFunc {
            fn $op_assign(&mut self, b: RatFunc) {
                *self = self.clone().$op(&b);
            }
        }
    };
}

ratfunc_op!(Add, add, AddAssign, add_assign, |a, b| a.add_ref(b));
ratfunc_op!(Sub, sub, SubAssign, sub_assign, |a, b| a
    .add_ref(&-b.clone()));
ratfunc_op!(Mul, mul, MulAssign, mul_assign, |a, b| a.mul_ref(b));
ratfunc_op!(Div, div, DivAssign, div_assign, |a, b| a
    .mul_ref(&b.recip_ref()));

impl FieldOps for RatFunc {
    type Prec = ();
    fn prec(&self) {}
    fn from_i64(n: i64, _: ()) -> RatFunc {
        RatFunc::constant(Rational::from(n))
    }
    fn from_ratio(num: i64, den: i64, _: ()) -> RatFunc {
        RatFunc::constant(Rational::from((num, den)))
    }
    fn is_zero(&self) -> bool {
        self.num.is_zero()
    }
    fn mul_i64(self, n: i64) -> RatFunc {
        self.scale(&Rational::from(n))
    }
    fn div_i64(self, n: i64) -> RatFunc {
        self.scale(&Rational::from((1, n)))
    }
    fn recip(self) -> RatFunc {
        self.recip_ref()
    }
}
