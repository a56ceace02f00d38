//! The elementary functions of [`Dd`] (sqrt, 1/sqrt, cbrt, exp, expm1, ln, ln1p, sin, cos,
//! atan2) to about 2^-104 relative: an `f64` seed and one Newton or Halley step at
//! double-double, or table reduction and a Taylor series, whose constants are computed once
//! from MPFR (never typed in as decimals).

use super::eft::{fast_two_sum, two_prod};
use super::Dd;
use crate::scalar::{FieldOps, Real};
use std::sync::OnceLock;

pub(super) struct Consts {
    pub(super) pi: Dd,
    pub(super) ln2: Dd,
    /// π/2 as three non-overlapping doubles (for argument reduction).
    pio2: [f64; 3],
    /// ln2/64 as three non-overlapping doubles.
    ln2_64: [f64; 3],
    /// 2^(j/64), j = 0..63.
    exp2_table: [Dd; 64],
    /// 1/n!, n = 0..=29.
    inv_fact: [Dd; 30],
    /// expm1_limits[m]: the largest |x| for which e^x − 1 = x Σ_{n≤m} x^n/(n+1)! to 2^-108
    /// (first omitted term |x|^{m+1}/(m+2)! ≤ 2^-108), m = 0..=26.
    expm1_limits: [f64; 27],
}

fn three_parts(x: &rug::Float) -> [f64; 3] {
    let a = x.to_f64();
    let r1 = rug::Float::with_val(x.prec(), x - a);
    let b = r1.to_f64();
    let r2 = rug::Float::with_val(x.prec(), &r1 - b);
    [a, b, r2.to_f64()]
}

pub(super) fn consts() -> &'static Consts {
    static C: OnceLock<Consts> = OnceLock::new();
    C.get_or_init(|| {
        use rug::float::Constant;
        let bits = 320;
        let pi = rug::Float::with_val(bits, Constant::Pi);
        let ln2 = rug::Float::with_val(bits, Constant::Log2);
        let pio2 = rug::Float::with_val(bits, &pi / 2u32);
        let ln2_64 = rug::Float::with_val(bits, &ln2 / 64u32);
        let mut exp2_table = [Dd::default(); 64];
        for (j, t) in exp2_table.iter_mut().enumerate() {
            let v = rug::Float::with_val(bits, j as f64 / 64.0);
            let v = rug::Float::with_val(bits, v.exp2_ref());
            *t = Dd::from_float(&v, ());
        }
        let mut inv_fact = [Dd::default(); 30];
        let mut f = rug::Float::with_val(bits, 1u32);
        for (n, t) in inv_fact.iter_mut().enumerate() {
            if n > 0 {
                f *= n as u32;
            }
            let r = rug::Float::with_val(bits, 1u32) / &f;
            *t = Dd::from_float(&r, ());
        }
        let mut expm1_limits = [0.0; 27];
        for (m, l) in expm1_limits.iter_mut().enumerate() {
            // (2^-108 (m + 2)!)^{1/(m + 1)}, a little under (f64 logarithms).
            let ln_fact: f64 = (2..=m + 2).map(|j| (j as f64).ln()).sum();
            let ln_l = (ln_fact - 108.0 * std::f64::consts::LN_2) / (m as f64 + 1.0);
            *l = ln_l.exp() * (1.0 - 1e-6);
        }
        Consts {
            pi: Dd::from_float(&pi, ()),
            ln2: Dd::from_float(&ln2, ()),
            pio2: three_parts(&pio2),
            ln2_64: three_parts(&ln2_64),
            exp2_table,
            inv_fact,
            expm1_limits,
        }
    })
}

/// `x − n·(c0 + c1 + c2)` for an integer-valued `n`, with the products `n·c0`, `n·c1` exact.
#[inline]
fn reduce(x: Dd, n: f64, c: &[f64; 3]) -> Dd {
    let (p0, e0) = two_prod(n, c[0]);
    let (p1, e1) = two_prod(n, c[1]);
    let r = x - Dd::from_parts(p0, e0);
    let r = r - Dd::from_parts(p1, e1);
    r - Dd::from_f64_exact(n * c[2])
}

/// Horner evaluation of Σ coef[i]·x^i for i in `from..=to` (ascending powers).
#[inline]
fn horner(x: Dd, coef: &[Dd], from: usize, to: usize) -> Dd {
    let mut acc = coef[to];
    for i in (from..to).rev() {
        acc = acc * x + coef[i];
    }
    acc
}

impl Dd {
    /// e^x − 1 by its Taylor series, for |x| ≤ 1/2 (relative error ≈ 2^-105), with as many
    /// terms as |x| needs (2 at |x| ≈ 10^-16, 26 at 1/2).
    pub(super) fn expm1_small(self) -> Dd {
        let c = consts();
        // Σ_{n≥1} x^n/n! = x · Σ_{n≥0} x^n/(n+1)!, truncated after x^m/(m+1)!.
        let a = self.hi().abs();
        let m = c.expm1_limits.iter().position(|&l| a <= l).unwrap_or(26);
        let s = horner(self, &c.inv_fact[1..], 0, m);
        s * self
    }

    pub(super) fn exp_dd(self) -> Dd {
        let x = self.hi();
        if x.is_nan() {
            return self;
        }
        if x > 709.8 {
            return Dd::from_f64_exact(f64::INFINITY);
        }
        if x < -745.2 {
            return Dd::from_f64_exact(0.0);
        }
        let c = consts();
        // x = n·ln2/64 + r, |r| ≤ ln2/128; n = 64k + j.
        let n = (x * (64.0 / std::f64::consts::LN_2)).round();
        let r = reduce(self, n, &c.ln2_64);
        let ni = n as i64;
        let k = ni.div_euclid(64) as i32;
        let j = ni.rem_euclid(64) as usize;
        // e^r − 1 by Taylor: |r| ≤ 0.0055 needs terms up to r^11.
        let p = horner(r, &c.inv_fact[1..], 0, 11) * r;
        let t = c.exp2_table[j];
        (t + t * p).mul_pow2(k)
    }

    pub(super) fn ln_dd(self) -> Dd {
        let x = self.hi();
        if x.is_nan() || x < 0.0 {
            return Dd::from_f64_exact(f64::NAN);
        }
        if x == 0.0 {
            return Dd::from_f64_exact(f64::NEG_INFINITY);
        }
        if x.is_infinite() {
            return self;
        }
        // x = 2^k · f with f in [1/√2, √2): ln x = k·ln 2 + ln f, no subnormal intermediate.
        let k = x.log2().round() as i32;
        let f = self.mul_pow2(-k);
        let y0 = Dd::from_f64_exact(f.hi().ln());
        // One Halley step on e^y = f, written with f − 1 and e^y0 − 1 so that the difference
        // keeps its digits: y1 = y0 + 2 (f − e^y0)/(f + e^y0) (cubic convergence).
        let one = Dd::from_f64_exact(1.0);
        let fm1 = f - one;
        let em1 = y0.expm1_small();
        let num = fm1 - em1;
        let den = fm1 + em1 + Dd::from_f64_exact(2.0);
        let lnf = y0 + (num / den).mul_pow2(1);
        if k == 0 {
            lnf
        } else {
            consts().ln2.mul_f64(k as f64) + lnf
        }
    }

    pub(super) fn ln1p_dd(self) -> Dd {
        let x = self.hi();
        if x.is_nan() || x < -1.0 {
            return Dd::from_f64_exact(f64::NAN);
        }
        if x == -1.0 && self.lo() == 0.0 {
            return Dd::from_f64_exact(f64::NEG_INFINITY);
        }
        if x.is_infinite() {
            return self;
        }
        if x.abs() > 0.25 {
            // 1 + x keeps every digit of x here.
            return (self + Dd::from_f64_exact(1.0)).ln_dd();
        }
        let y0 = x.ln_1p();
        let y0d = Dd::from_f64_exact(y0);
        // Halley on e^y − 1 = x.
        let em1 = y0d.expm1_small();
        let num = self - em1;
        let den = self + em1 + Dd::from_f64_exact(2.0);
        y0d + (num / den).mul_pow2(1)
    }

    /// sin and cos of the reduced argument |r| ≤ π/4 (Taylor series in r²).
    fn sin_cos_reduced(r: Dd) -> (Dd, Dd) {
        let c = consts();
        let r2 = r * r;
        // sin r = r Σ (−1)^i r^(2i)/(2i+1)!, cos r = Σ (−1)^i r^(2i)/(2i)!, i ≤ 14; the first
        // omitted terms are below 2^-110 relative for |r| ≤ π/4.
        let mut s = c.inv_fact[29];
        let mut co = c.inv_fact[28];
        for i in (0..14).rev() {
            let sgn = if i % 2 == 0 { 1.0 } else { -1.0 };
            s = s * r2 + c.inv_fact[2 * i + 1].mul_f64_sign(sgn);
            co = co * r2 + c.inv_fact[2 * i].mul_f64_sign(sgn);
        }
        (s * r, co)
    }

    #[inline(always)]
    fn mul_f64_sign(self, s: f64) -> Dd {
        if s < 0.0 {
            -self
        } else {
            self
        }
    }

    pub(super) fn sin_cos_dd(self) -> (Dd, Dd) {
        let x = self.hi();
        if !x.is_finite() {
            let nan = Dd::from_f64_exact(f64::NAN);
            return (nan, nan);
        }
        let c = consts();
        let n = (x * std::f64::consts::FRAC_2_PI).round();
        let r = reduce(self, n, &c.pio2);
        let (s, co) = Dd::sin_cos_reduced(r);
        match (n as i64).rem_euclid(4) {
            0 => (s, co),
            1 => (co, -s),
            2 => (-s, -co),
            _ => (-co, s),
        }
    }

    pub(super) fn atan2_dd(self, x: Dd) -> Dd {
        let (yh, xh) = (self.hi(), x.hi());
        if yh.is_nan() || xh.is_nan() {
            return Dd::from_f64_exact(f64::NAN);
        }
        if yh == 0.0 || yh.is_infinite() || xh.is_infinite() {
            // Exact cases and limits handled by f64 atan2, corrected to full π when needed.
            let z = yh.atan2(xh);
            return Dd::scale_pi(z);
        }
        if xh == 0.0 {
            let half = consts().pi.mul_pow2(-1);
            return if yh > 0.0 { half } else { -half };
        }
        let z0 = Dd::from_f64_exact(yh.atan2(xh));
        let (s, c) = z0.sin_cos_dd();
        // Newton on f(z) = y cos z − x sin z.
        let num = self * c - x * s;
        let den = x * c + self * s;
        z0 + num / den
    }

    /// Maps an `f64` multiple of π/4 returned by `atan2` in a limit case to full precision.
    fn scale_pi(z: f64) -> Dd {
        let q = (z / std::f64::consts::FRAC_PI_4).round();
        if (z - q * std::f64::consts::FRAC_PI_4).abs() < 1e-15 {
            consts().pi.mul_f64(q / 4.0)
        } else {
            Dd::from_f64_exact(z)
        }
    }

    pub(super) fn sqrt_dd(self) -> Dd {
        let a = self.hi();
        if a <= 0.0 {
            return if a == 0.0 && self.lo() == 0.0 {
                self
            } else if a < 0.0 || (a == 0.0 && self.lo() < 0.0) {
                Dd::from_f64_exact(f64::NAN)
            } else {
                self
            };
        }
        if a.is_infinite() || a.is_nan() {
            return self;
        }
        // One Newton step from the correctly rounded f64 root: s + (a − s²)/(2s).
        let s = a.sqrt();
        let (p, e) = two_prod(s, s);
        let d = self - Dd::from_parts(p, e);
        let corr = d.hi() / (2.0 * s);
        Dd::from_parts(s, corr)
    }

    /// 1/√x from the f64 value y = 1/√hi (error δ ≲ 1 ulp) by one third-order Newton step:
    /// with r = 1 − x·y² (formed in double-double, y² exact), y·(1 + r/2 + 3r²/8) leaves
    /// O(δ³) and the rounding of r (~2⁻¹⁰⁶ relative) — no double-double division.
    pub(super) fn recip_sqrt_dd(self) -> Dd {
        let a = self.hi();
        // Above 1e290 (where y² would be subnormal), zero, negative or not finite: the general
        // path.
        if !(f64::MIN_POSITIVE..=1e290).contains(&a) {
            return self.sqrt_dd().recip();
        }
        let y = 1.0 / a.sqrt();
        let (p, e) = two_prod(y, y);
        let xy2 = self.mul_dd(Dd::from_parts(p, e));
        // 1 − hi is exact (hi ∈ [1/2, 2]); r ≈ −2δ.
        let r = (1.0 - xy2.hi()) - xy2.lo();
        let c = y * (r * (0.5 + 0.375 * r));
        let (h, l) = fast_two_sum(y, c);
        Dd::from_parts(h, l)
    }

    pub(super) fn cbrt_dd(self) -> Dd {
        let a = self.hi();
        if a == 0.0 || !a.is_finite() {
            return self;
        }
        let x = a.cbrt();
        // One Newton step: x − (x³ − a)/(3x²), x³ formed in double-double.
        let (p, e) = two_prod(x, x);
        let x2 = Dd::from_parts(p, e);
        let d = x2.mul_f64(x) - self;
        let corr = (d / x2.mul_f64(3.0)).hi();
        Dd::from_parts(x, -corr)
    }
}
