//! `rug::Rational` as an exact [`Field`]: the mode in which recurrences with exact rational
//! coefficients (the paper's (36) and (40)) are run as ground truth for their rounding error.

use super::{Field, FieldOps};
use rug::Rational;
use std::cmp::Ordering;

impl FieldOps for Rational {
    type Prec = ();
    fn prec(&self) {}
    fn from_i64(n: i64, _: ()) -> Rational {
        Rational::from(n)
    }
    fn from_ratio(num: i64, den: i64, _: ()) -> Rational {
        Rational::from((num, den))
    }
    fn is_zero(&self) -> bool {
        self.cmp0() == Ordering::Equal
    }
    fn mul_i64(self, n: i64) -> Rational {
        self * Rational::from(n)
    }
    fn div_i64(self, n: i64) -> Rational {
        self / Rational::from(n)
    }
    fn recip(self) -> Rational {
        Rational::recip(self)
    }
}

impl Field for Rational {
    fn is_negative(&self) -> bool {
        self.cmp0() == Ordering::Less
    }
    fn abs(self) -> Rational {
        Rational::abs(self)
    }
    fn to_f64(&self) -> f64 {
        Rational::to_f64(self)
    }
}
