//! Compensated summation shared by the quadrature rules and the series driver.

use crate::scalar::Real;

/// A running sum `s + c` where `c` collects the rounding errors of the additions (Knuth's
/// TwoSum, branch free). For correctly rounded backends (`f64`, [`crate::scalar::Mp`]) each
/// correction is exact, so the error of the total is about one rounding plus `ε²·Σ|xᵢ|`,
/// instead of `n·ε·Σ|xᵢ|` for the plain sum; for double-double the correction is approximate
/// but still removes most of the accumulated error.
#[derive(Clone, Debug)]
pub(crate) struct CompSum<T: Real> {
    s: T,
    c: T,
}

impl<T: Real> CompSum<T> {
    /// The empty sum at precision `p`.
    pub(crate) fn new(p: T::Prec) -> Self {
        CompSum {
            s: T::zero(p),
            c: T::zero(p),
        }
    }

    /// Adds `x`: `s + x = t + e` exactly (TwoSum), `s ← t`, `c ← c + e`.
    pub(crate) fn add(&mut self, x: T) {
        let t = self.s.clone() + &x;
        let bb = t.clone() - &self.s;
        let s = std::mem::replace(&mut self.s, t);
        // e = (s − (t − bb)) + (x − bb)
        let e = (s - &(self.s.clone() - &bb)) + &(x - bb);
        self.c += e;
    }

    /// The compensated total `s + c`.
    pub(crate) fn total(&self) -> T {
        self.s.clone() + &self.c
    }
}
