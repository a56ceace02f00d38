//! The constants of one (material, speed) that the fixed-rule and graded routes share: G's
//! cleared form at a node of either half and the Rayleigh pole's strength
//! (`docs/fixed-rules.md`).

use crate::physics::Speed;
use crate::scalar::Real;

/// Constants that depend on the material and the speed but not on k.
#[derive(Clone, Debug)]
pub(crate) struct SpeedConsts<T: Real> {
    /// 2/m1.
    pub(crate) two_over_m1: T,
    /// c = m1 M_R², c², (m2 + m3)·c, m2 + m3, m2 m3.
    pub(crate) c: T,
    pub(crate) c2: T,
    pub(crate) sc: T,
    pub(crate) s23: T,
    pub(crate) q: T,
    /// 1 − γc and δ² = 1 − c.
    pub(crate) a1: T,
    pub(crate) d2: T,
    /// ε², and the closed-form pole integrals atan(1/ε)/ε and 1 − ε atan(1/ε).
    pub(crate) eps2: T,
    pub(crate) pole_t: T,
    pub(crate) pole_1: T,
    /// 2π G(1) M_R = a0 (1 − k²ε²)^{3/2}.
    pub(crate) g0: T,
}

impl<T: Real> SpeedConsts<T> {
    pub(crate) fn new(speed: &Speed<T>) -> Self {
        let mat = speed.material();
        let p = speed.mr().prec();
        let one = T::one(p);
        let roots = mat.roots();
        let m1 = roots.m1.clone();
        let gamma = mat.gamma().clone();
        let c = speed.m2sq().clone();
        let s23 = roots.sum23.clone();
        let q = roots.prod23.clone();
        let two_over_m1 = T::from_i64(2, p) / &m1;
        let a1 = one.clone() - gamma.clone() * &c;
        let d2 = one.clone() - &c;
        let eps2 = speed.one_minus_mr2().clone();
        // The pole is subtracted only when it is near the interval (ε ≤ 1/2, i.e. M_R ≥ √3/2);
        // farther out the plain rule converges as fast, and for M_R → 0, k → 1 the pole at
        // w = iε would meet the branch point of u^{−3/2} at w = i/k, where a0 is unbounded.
        let near = eps2.clone().mul_i64(4) <= one;
        let (g0, pole_t, pole_1) = if near {
            let eps = eps2.clone().sqrt();
            let at = one.clone().atan2(&eps);
            let pole_t = at.clone() / &eps;
            let pole_1 = one.clone() - eps * at;
            // a(−ε²)·u0^{3/2} = 2π G(1) M_R: the pole's strength (Material::pi_g_rayleigh).
            let g0 = mat.pi_g_rayleigh().clone().mul_i64(2) * speed.mr();
            (g0, pole_t, pole_1)
        } else {
            (T::zero(p), T::zero(p), T::zero(p))
        };
        SpeedConsts {
            c2: c.square(),
            sc: s23.clone() * &c,
            two_over_m1,
            c,
            s23,
            q,
            a1,
            d2,
            eps2,
            pole_t,
            pole_1,
            g0,
        }
    }

    /// The Rayleigh pole's strength at the axis ratio with k² = `k2` (k²ε² < 1): a0 = a(−ε²) =
    /// g0 (1 − k²ε²)^{−3/2}, and e0 = ε² a0/(1 − k²ε²), the pole value of the left integrand's
    /// k-derivative divided by 3k (docs/fixed-rules.md). Zero for both at M_R = 0. A few ε.
    pub(crate) fn pole_values(&self, k2: &T) -> (T, T) {
        if self.g0.is_zero() {
            let p = k2.prec();
            return (T::zero(p), T::zero(p));
        }
        let u0 = T::one(k2.prec()) - k2.clone() * &self.eps2;
        let su0 = u0.clone().sqrt();
        let a0 = self.g0.clone() / (u0.clone() * &su0);
        let e0 = self.eps2.clone() * &a0 / &u0;
        (a0, e0)
    }

    /// G's cleared form at a left node s = w² (p = 1 + s; `two_p`, `four_p` = 2p, 4p): returns
    /// e1 = s + 1 − γc, D' = (2p − c)² + 4p√((s + 1 − γc)(s + δ²)) and
    /// Q' = c² − (m2 + m3)c p + m2m3 p², so that 2πG√(1 + s) = (2/m1)√e1·D'/Q' (docs/fixed-rules.md).
    /// One square root, no division.
    #[inline(always)]
    pub(crate) fn left_node(&self, s: &T, pp: &T, two_p: &T, four_p: &T) -> (T, T, T) {
        let e1 = s.clone() + &self.a1;
        let e2 = s.clone() + &self.d2;
        let sq1 = (e1.clone() * e2).sqrt();
        let t = two_p.clone() - &self.c;
        let dd = t.square() + four_p.clone() * sq1;
        let qq = (self.q.clone() * pp - &self.sc) * pp + &self.c2;
        (e1, dd, qq)
    }

    /// [`SpeedConsts::right_node`] at σ alone (p = 1 + σ, 2p and 4p formed here).
    #[inline(always)]
    pub(crate) fn right_at(&self, sg: &T, one: &T) -> (T, T, T) {
        let pp = one.clone() + sg;
        self.right_node(sg, &pp, &pp.clone().mul_i64(2), &pp.clone().mul_i64(4), one)
    }

    /// The same at a right node σ = v² (p = 1 + σ): returns f1 = 1 + (1 − γc)σ, D' and
    /// E = Q'(σ)(1 + ε²σ), so that b(σ) = (2/m1)√f1·D'/E (docs/fixed-rules.md). `one` is 1 at the
    /// working precision.
    #[inline(always)]
    pub(crate) fn right_node(&self, sg: &T, pp: &T, two_p: &T, four_p: &T, one: &T) -> (T, T, T) {
        let cs = self.c.clone() * sg;
        let f1 = one.clone() + self.a1.clone() * sg;
        let f2 = one.clone() + self.d2.clone() * sg;
        let sq1 = (f1.clone() * f2).sqrt();
        let t = two_p.clone() - &cs;
        let dd = t.square() + four_p.clone() * sq1;
        let qq = (self.q.clone() * pp - self.s23.clone() * &cs) * pp + cs.square();
        let e = qq * (one.clone() + self.eps2.clone() * sg);
        (f1, dd, e)
    }
}
