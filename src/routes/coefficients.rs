//! Taylor coefficients of the normalised Green's function, (35)–(36) of the paper, corrected
//! (`docs/errata.md` #2): [`GreenSeries`] runs the recurrence `docs/theory.md` states ("The
//! series route"), c_l = G_l·x0^l from c_0 = 1 − ν, for any scale x0, in about 25 field
//! operations a step (no factorial is formed):
//!
//! * x0 = M2² gives the paper's f_n (coefficients of sin^{2n} φ);
//! * x0 = 1 gives F_n (coefficients of x^n), exact in `rug::Rational` for rational ν, and as
//!   rational functions of ν over [`crate::symbolic::RatFunc`] ([`crate::symbolic::green_coefficients`]);
//! * x0 = m1 gives the scaled h_n = f_n / M_R^{2n} ([`SpeedCoefficients`]), which tend to πG(1)
//!   and neither overflow nor underflow for any n.
//!
//! The wanted solution is the dominant one (g's nearest singularity is the simple pole x = m1),
//! so the forward recurrence is stable: each c_n within a few ε (`tests/series_coefficients.rs`,
//! against the exact rational run).

use crate::physics::material::gamma_of;
use crate::scalar::{Field, FieldOps};

/// Generator of the Taylor coefficients c_n = G_n·x0^n of g = −πΓ (see the module docs).
///
/// Generic over [`FieldOps`]: rounded (`f64`, double-double, MPFR: relative error a few ε per
/// coefficient, the recurrence being stable), exact over `rug::Rational` for rational ν and x0,
/// and symbolic over [`crate::symbolic::RatFunc`] (F_n as rational functions of ν, exact).
#[derive(Clone, Debug)]
pub struct GreenSeries<F: FieldOps> {
    one_minus_nu_8: F,
    two_minus_nu: F,
    x0: F,
    x0_2: F,
    x0_3: F,
    gx0: F,
    /// c_{l−1}, c_{l−2}, c_{l−3}.
    c: [F; 3],
    /// u_l, u_{l−1}, u_{l−2} and v_l, v_{l−1} for the next l.
    u: [F; 3],
    v: [F; 2],
    /// The next index l.
    l: u64,
}

impl<F: FieldOps> GreenSeries<F> {
    /// The generator for Poisson's ratio `nu` and scale `x0` (validated by the caller:
    /// −1 < ν ≤ 1/2, 0 ≤ x0 ≤ 1; or ν the variable of a rational function). γ and 1 − ν are
    /// formed from `nu` by field operations, so a symbolic ν gives them as expressions.
    /// The recurrence (36) (errata #2) for the coefficients of (35).
    pub fn new(nu: &F, x0: F) -> Self {
        let p = nu.prec();
        let one = F::one(p);
        let one_minus_nu = one - nu;
        let gx0 = gamma_of(nu) * &x0;
        let zero = F::zero(p);
        GreenSeries {
            one_minus_nu_8: one_minus_nu.div_i64(8),
            two_minus_nu: F::from_i64(2, p) - nu,
            x0_2: x0.square(),
            x0_3: x0.square() * &x0,
            x0,
            gx0,
            c: [zero.clone(), zero.clone(), zero.clone()],
            u: [F::one(p), zero.clone(), zero.clone()],
            v: [F::one(p), zero],
            l: 0,
        }
    }

    /// Returns c_l and advances to l + 1.
    /// One step of (36): c_l = F_l x0^l of (35), exact over an exact field, a few ε per step
    /// relative to the largest term otherwise (the recurrence is stable: docs/series.md).
    pub fn next_coefficient(&mut self) -> F {
        self.advance(|t| t)
    }

    /// One step of the recurrence; `trim` is applied to the new binomial terms u_{l+1}, v_{l+1}
    /// (the identity, or the flush of [`SpeedCoefficients::flush_below`]).
    #[inline(always)]
    fn advance(&mut self, trim: impl Fn(F) -> F) -> F {
        let l = self.l;
        let [u0, u1, u2] = &self.u;
        let [v0, v1] = &self.v;
        // r_l = 4u_l − 4x0 u_{l−1} + x0² u_{l−2} + 4v_l − 4γx0 v_{l−1}
        let r = (u0.clone() + v0).mul_i64(4) - (self.x0.clone() * u1).mul_i64(4)
            + self.x0_2.clone() * u2
            - (self.gx0.clone() * v1).mul_i64(4);
        let [c1, c2, c3] = &self.c;
        let bracket = r - (self.x0_2.clone() * c2).mul_i64(8) + self.x0_3.clone() * c3;
        let c = self.one_minus_nu_8.clone() * bracket + self.two_minus_nu.clone() * &self.x0 * c1;
        // Shift the histories and advance the binomial terms: b_{l+1} = b_l (2l − 1)/(2l + 2).
        let (num, den) = if l == 0 {
            (-1i64, 2i64)
        } else {
            (2 * l as i64 - 1, 2 * l as i64 + 2)
        };
        let u_next = trim((self.u[0].clone() * &self.gx0).mul_i64(num).div_i64(den));
        let v_next = trim((self.v[0].clone() * &self.x0).mul_i64(num).div_i64(den));
        self.u = [u_next, self.u[0].clone(), self.u[1].clone()];
        self.v = [v_next, self.v[0].clone()];
        self.c = [c.clone(), self.c[0].clone(), self.c[1].clone()];
        self.l += 1;
        c
    }

    /// The first `n` coefficients c_0 … c_{n−1} of (35), by (36).
    pub fn take(mut self, n: usize) -> Vec<F> {
        (0..n).map(|_| self.next_coefficient()).collect()
    }
}

/// The coefficients f_n = h_n·M_R^{2n} of g(V cos α) = Σ f_n cos^{2n}α ((35) with sin φ = cos α),
/// generated progressively from the scaled h_n = f_n/M_R^{2n} (the run of [`GreenSeries`] with
/// x0 = m1): no factorial, no overflow; f_n underflows only where M_R^{2n} itself does.
///
/// Accuracy: the relative error of h_n grows at most linearly, ≤ (n + 4) ε (the recurrence is
/// stable, `tests/series_coefficients.rs`); the power M_R^{2n} adds n roundings. The series route
/// runs it with ⌈2 log₂ n⌉ + 12 guard bits.
///
/// The h_n decrease monotonically from h_0 = 1 − ν to their limit H = πG(1) > 0 (G of (45) at the
/// Rayleigh speed; h_n are the partial sums of the Taylor coefficients of πG(t), t = x/m1):
/// checked for ν on a grid of (−1, 1/2] in `tests/series_route.rs`, and used by the tail bound
/// of the series route.
#[derive(Clone, Debug)]
pub struct SpeedCoefficients<F: Field> {
    gen: GreenSeries<F>,
    mr2: F,
    pow: F,
    /// Binomial terms below this magnitude are set to zero ([`SpeedCoefficients::flush_below`]).
    flush: Option<F>,
}

impl<F: Field> SpeedCoefficients<F> {
    /// The generator for Poisson's ratio `nu`, the Rayleigh root `m1` = (c_R/c2)² and
    /// `mr2` = M_R² (validated by the caller: −1 < ν ≤ 1/2, 0 ≤ M_R² < 1).
    /// The recurrence (36) (errata #2) for the coefficients of (35).
    pub fn new(nu: &F, m1: F, mr2: F) -> Self {
        let p = nu.prec();
        SpeedCoefficients {
            gen: GreenSeries::new(nu, m1),
            mr2,
            pow: F::one(p),
            flush: None,
        }
    }

    /// Sets the binomial-series terms u_l = b_l(γx0)^l, v_l = b_l x0^l inside the recurrence to
    /// zero once they fall below `tiny` (> 0). They enter each h_l additively with a weight below
    /// 5, so the change in h_l is at most 5·`tiny` per step; with `tiny` far below ε·|h| it is
    /// invisible, and it stops u_l, v_l (which decay like (γm1)^l and m1^l) from wandering through
    /// the subnormal range of `f64` and double-double, where each operation costs a hundred times
    /// more. Not for exact (`Rational`) runs.
    /// A cut-off inside (36); the change it makes is bounded above.
    pub fn flush_below(mut self, tiny: F) -> Self {
        self.flush = Some(tiny.abs());
        self
    }

    /// (h_n, f_n) = (f_n/M_R^{2n}, f_n) of (35) by (36) at x0 = m1, advancing to n + 1.
    pub fn next_pair(&mut self) -> (F, F) {
        let h = match &self.flush {
            None => self.gen.next_coefficient(),
            Some(tiny) => self.gen.advance(|t| {
                if t.clone().abs() < *tiny {
                    F::zero(tiny.prec())
                } else {
                    t
                }
            }),
        };
        let f = h.clone() * &self.pow;
        self.pow *= &self.mr2;
        (h, f)
    }
}
