//! Double-double arithmetic: [`Dd`], a wrapper over [`twofloat::TwoFloat`] that is accurate to
//! about 2^-104 relative for `+ − × ÷`, `sqrt` and every elementary function of [`Real`].
//!
//! What comes from `twofloat` and what is ours:
//!
//! * **Storage, addition and subtraction** are `twofloat`'s (Joldes, Muller & Popescu 2017,
//!   Algorithm 6: relative error ≤ 3·2^-106).
//! * **Multiplication** is ours: `twofloat` forms the exact product with `f64::mul_add`, which on
//!   the default x86-64 target (no `fma` target feature) is a call into libm's *software* fma —
//!   about 11× slower than the hardware instruction. Here the error-free product
//!   ([`two_prod`]) uses the hardware FMA — inlined when the crate is compiled with it
//!   (`-C target-cpu=native`), otherwise detected once at run time and issued by inline
//!   assembly — and Dekker's splitting on processors without one, out of line so that the FMA
//!   path stays a load, a compare and the instruction (a processor without FMA pays a call a
//!   product). Both are exact, so results are the same bit
//!   for bit. The `dd_arith` bench measures the variants.
//! * **Division** is ours: `twofloat`'s `TwoFloat / TwoFloat` is accurate only to ~1e-16. We use
//!   the three-quotient long division (as in Hida, Li & Bailey's QD library), error ≈ 2^-105,
//!   with the two correction quotients multiplied by 1/b.hi rather than divided by b.hi.
//! * **sqrt, cbrt, exp, expm1, ln, ln1p, sin, cos, atan2** are ours (twofloat's `ln` is ~1e-12,
//!   its `atan2` ~1e-16): an `f64` seed and one Newton or Halley step at double-double, or table
//!   reduction and a Taylor series whose constants are computed once from MPFR.
//!
//! `Dd::EPSILON` is `2^-105` (twofloat reports `f64::MIN_POSITIVE`). Decimal text is parsed and
//! printed through MPFR, exactly: "0.2" becomes the double-double nearest to 1/5, not to the
//! `f64` 0.2.
//!
//! Accuracy, measured against MPFR at 256 bits over 10^4+ random arguments by
//! `tests/dd_accuracy.rs`: see `docs/design.md` for the table.
//!
//! No item of this module implements a formula of the paper: they are the double-double arithmetic
//! every formula runs on, to the accuracies above.

use super::{Field, FieldOps, Real};
use crate::error::{Error, Result};
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::sync::OnceLock;
use twofloat::TwoFloat;

/// A double-double number: an unevaluated sum `hi + lo` of two `f64` with `|lo| ≤ ulp(hi)/2`,
/// about 106 significant bits.
#[derive(Clone, Copy, Debug, Default)]
pub struct Dd(TwoFloat);

/// Error-free sum `a + b = s + e` (Knuth's TwoSum, 6 flops, no branch).
#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// Error-free sum when `|a| ≥ |b|` (Dekker's FastTwoSum, 3 flops).
#[inline(always)]
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let e = b - (s - a);
    (s, e)
}

/// Largest magnitude Dekker's splitting handles without overflow of `SPLITTER · a`.
const SPLIT_LIMIT: f64 = 6.69692879491417e299; // 2^996

/// Veltkamp/Dekker splitting of `a` into two 26-bit halves.
#[cfg(not(target_feature = "fma"))]
#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134217729.0; // 2^27 + 1
    if a.abs() > SPLIT_LIMIT {
        let s = a * 3.725290298461914e-9; // 2^-28
        let c = SPLITTER * s;
        let hi = c - (c - s);
        let lo = s - hi;
        (hi * 268435456.0, lo * 268435456.0)
    } else {
        let c = SPLITTER * a;
        let hi = c - (c - a);
        (hi, a - hi)
    }
}

/// Error-free product `a · b = p + e`: the hardware FMA when the processor has one, Dekker's
/// algorithm otherwise (never the software `fma` of libm). Both are exact, so the result is the
/// same bit for bit either way; only the cost differs (`dd_arith` bench).
///
/// Built with the `fma` target feature (`-C target-cpu=native`), the FMA is `f64::mul_add`,
/// inlined. On the default x86-64 target the processor is asked once at run time
/// ([`hw::has_fma`]) and the instruction is issued by inline assembly, so a binary built for any
/// x86-64 uses the FMA where it exists.
#[inline(always)]
pub(crate) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    #[cfg(target_feature = "fma")]
    {
        let _ = SPLIT_LIMIT;
        (p, a.mul_add(b, -p))
    }
    #[cfg(not(target_feature = "fma"))]
    {
        #[cfg(target_arch = "x86_64")]
        if hw::has_fma() {
            return (p, hw::fms(a, b, p));
        }
        (p, dekker_error_cold(a, b, p))
    }
}

/// [`dekker_error`] out of line: on x86-64 only processors without FMA (before 2013) take it,
/// and keeping it out of the products' code leaves the FMA path a load, a compare and the
/// instruction.
#[cfg(not(target_feature = "fma"))]
#[cold]
#[inline(never)]
fn dekker_error_cold(a: f64, b: f64, p: f64) -> f64 {
    dekker_error(a, b, p)
}

/// The rounding error `a·b − p` of `p = fl(a·b)` by Dekker's splitting (exact unless the
/// product under- or overflows).
#[cfg(not(target_feature = "fma"))]
#[inline(always)]
fn dekker_error(a: f64, b: f64, p: f64) -> f64 {
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    ((ah * bh - p) + ah * bl + al * bh) + al * bl
}

/// Run-time use of the x86-64 FMA instruction in a build without the `fma` target feature.
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
pub(crate) mod hw {
    use std::sync::atomic::{AtomicU8, Ordering};

    /// 0: not yet asked, 1: no FMA, 2: FMA.
    static FMA: AtomicU8 = AtomicU8::new(0);

    /// Whether the processor executes `vfmsub213sd` (CPUID, asked once and cached).
    #[inline(always)]
    pub fn has_fma() -> bool {
        match FMA.load(Ordering::Relaxed) {
            2 => true,
            1 => false,
            _ => detect(),
        }
    }

    #[cold]
    #[inline(never)]
    fn detect() -> bool {
        let yes = fma_usable();
        FMA.store(if yes { 2 } else { 1 }, Ordering::Relaxed);
        yes
    }

    /// The test of `is_x86_feature_detected!("fma")` by the one CPUID leaf it needs: leaf 1
    /// reports FMA (ECX bit 12), AVX (bit 28) and OSXSAVE (bit 27), and XCR0 bits 1 and 2 say
    /// that the operating system saves the XMM and YMM state. std's detection asks every leaf
    /// for every feature, and in a virtual machine each CPUID traps to the hypervisor, which
    /// the first solve of a process waited for (checked against std by a unit test).
    fn fma_usable() -> bool {
        use std::arch::x86_64::{__cpuid, _xgetbv};
        // SAFETY: CPUID leaf 1 exists on every x86-64 processor; XGETBV is executed only when
        // OSXSAVE says that the operating system has enabled it.
        unsafe {
            let ecx = __cpuid(1).ecx;
            let bit = |b: u32| ecx >> b & 1 == 1;
            bit(12) && bit(28) && bit(27) && _xgetbv(0) & 0b110 == 0b110
        }
    }

    /// `a·b − p` rounded once. Only called when [`has_fma`] is true.
    #[inline(always)]
    pub fn fms(a: f64, b: f64, p: f64) -> f64 {
        let mut x = a;
        // SAFETY: the instruction exists on this processor (checked by `has_fma` at the call
        // site); it reads and writes registers only.
        unsafe {
            std::arch::asm!(
                "vfmsub213sd {x}, {b}, {p}",
                x = inout(xmm_reg) x,
                b = in(xmm_reg) b,
                p = in(xmm_reg) p,
                options(pure, nomem, nostack, preserves_flags)
            );
        }
        x
    }
}

impl Dd {
    /// `2^-105`: the spacing of double-double numbers relative to 1 (106-bit significand).
    pub const EPSILON: f64 = 2.465190328815662e-32;

    /// The double-double `hi + lo`, renormalised exactly.
    #[inline(always)]
    pub fn from_parts(hi: f64, lo: f64) -> Dd {
        Dd(TwoFloat::new_add(hi, lo))
    }
    /// The `f64` value `x` exactly.
    #[inline(always)]
    pub const fn from_f64_exact(x: f64) -> Dd {
        Dd(TwoFloat::from_f64(x))
    }
    /// Leading component.
    #[inline(always)]
    pub fn hi(&self) -> f64 {
        self.0.hi()
    }
    /// Trailing component.
    #[inline(always)]
    pub fn lo(&self) -> f64 {
        self.0.lo()
    }
    /// The wrapped `twofloat` value.
    pub fn as_twofloat(&self) -> TwoFloat {
        self.0
    }

    /// Product with an `f64`, error ≤ 2·2^-106 relative.
    #[inline(always)]
    pub fn mul_f64(self, b: f64) -> Dd {
        let (p, e) = two_prod(self.hi(), b);
        Dd::from_parts(p, e + self.lo() * b)
    }

    /// Quotient by an `f64`, error ≈ 2^-105 relative.
    #[inline]
    pub fn div_f64(self, d: f64) -> Dd {
        let q1 = self.hi() / d;
        let (p, pe) = two_prod(q1, d);
        let (s, e) = two_sum(self.hi(), -p);
        let e = e - pe + self.lo();
        let q2 = (s + e) / d;
        let (h, l) = fast_two_sum(q1, q2);
        Dd::from_parts(h, l)
    }

    #[inline(always)]
    fn mul_dd(self, b: Dd) -> Dd {
        // Joldes et al. Algorithm 11 (the renormalisation is twofloat's exact TwoSum).
        let (p, e) = two_prod(self.hi(), b.hi());
        Dd::from_parts(p, e + (self.hi() * b.lo() + self.lo() * b.hi()))
    }

    #[inline]
    fn div_dd(self, b: Dd) -> Dd {
        // Long division with two correction quotients, q1 + q2 + q3 (as in the QD library):
        // measured worst error 2.7·2^-106 (tests/dd_accuracy.rs). The one-correction variant
        // (Joldes et al. Algorithm 17) is twice as fast but measured 6.7·2^-106.
        // The three partial quotients use one f64 division, 1/b.hi, and multiply by it: each
        // quotient is then off by 2 ulp instead of ½, which the next correction absorbs (same
        // measured error, two fewer dependent divisions).
        let q1 = self.hi() / b.hi();
        if !q1.is_finite() || b.hi() == 0.0 {
            return Dd::from_f64_exact(q1);
        }
        let inv = 1.0 / b.hi();
        if !inv.is_finite() || inv.abs() < f64::MIN_POSITIVE {
            // |b| near the ends of the exponent range: the divisions themselves.
            let r = self - b.mul_f64(q1);
            let q2 = r.hi() / b.hi();
            let r = r - b.mul_f64(q2);
            let q3 = r.hi() / b.hi();
            let (h, l) = fast_two_sum(q1, q2);
            return Dd::from_parts(h, l + q3);
        }
        let r = self - b.mul_f64(q1);
        let q2 = r.hi() * inv;
        let r = r - b.mul_f64(q2);
        let q3 = r.hi() * inv;
        let (h, l) = fast_two_sum(q1, q2);
        Dd::from_parts(h, l + q3)
    }
}

// ---------------------------------------------------------------------------------------------
// Operators.

impl Neg for Dd {
    type Output = Dd;
    #[inline(always)]
    fn neg(self) -> Dd {
        Dd(-self.0)
    }
}

macro_rules! dd_binop {
    ($Tr:ident, $m:ident, $TrA:ident, $ma:ident, |$a:ident, $b:ident| $body:expr) => {
        impl $Tr<Dd> for Dd {
            type Output = Dd;
            #[inline(always)]
            fn $m(self, rhs: Dd) -> Dd {
                let ($a, $b) = (self, rhs);
                $body
            }
        }
        impl<'r> $Tr<&'r Dd> for Dd {
            type Output = Dd;
            #[inline(always)]
            fn $m(self, rhs: &'r Dd) -> Dd {
                let ($a, $b) = (self, *rhs);
                $body
            }
        }
        impl $TrA<Dd> for Dd {
            #[inline(always)]
            fn $ma(&mut self, rhs: Dd) {
                let ($a, $b) = (*self, rhs);
                *self = $body;
            }
        }
        impl<'r> $TrA<&'r Dd> for Dd {
            #[inline(always)]
            fn $ma(&mut self, rhs: &'r Dd) {
                let ($a, $b) = (*self, *rhs);
                *self = $body;
            }
        }
    };
}

dd_binop!(Add, add, AddAssign, add_assign, |a, b| Dd(a.0 + b.0));
dd_binop!(Sub, sub, SubAssign, sub_assign, |a, b| Dd(a.0 - b.0));
dd_binop!(Mul, mul, MulAssign, mul_assign, |a, b| a.mul_dd(b));
dd_binop!(Div, div, DivAssign, div_assign, |a, b| a.div_dd(b));

impl PartialEq for Dd {
    #[inline(always)]
    fn eq(&self, other: &Dd) -> bool {
        self.hi() == other.hi() && self.lo() == other.lo()
    }
}

impl PartialOrd for Dd {
    #[inline(always)]
    fn partial_cmp(&self, other: &Dd) -> Option<Ordering> {
        match self.hi().partial_cmp(&other.hi()) {
            Some(Ordering::Equal) => self.lo().partial_cmp(&other.lo()),
            c => c,
        }
    }
}

impl From<f64> for Dd {
    fn from(x: f64) -> Dd {
        Dd::from_f64_exact(x)
    }
}

impl From<TwoFloat> for Dd {
    fn from(x: TwoFloat) -> Dd {
        Dd(x)
    }
}

// ---------------------------------------------------------------------------------------------
// Constants, computed once from MPFR (never typed in as decimals).

struct Consts {
    pi: Dd,
    ln2: Dd,
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

fn consts() -> &'static Consts {
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
    fn expm1_small(self) -> Dd {
        let c = consts();
        // Σ_{n≥1} x^n/n! = x · Σ_{n≥0} x^n/(n+1)!, truncated after x^m/(m+1)!.
        let a = self.hi().abs();
        let m = c.expm1_limits.iter().position(|&l| a <= l).unwrap_or(26);
        let s = horner(self, &c.inv_fact[1..], 0, m);
        s * self
    }

    fn exp_dd(self) -> Dd {
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

    fn ln_dd(self) -> Dd {
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

    fn ln1p_dd(self) -> Dd {
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

    fn sin_cos_dd(self) -> (Dd, Dd) {
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

    fn atan2_dd(self, x: Dd) -> Dd {
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

    fn sqrt_dd(self) -> Dd {
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
    fn recip_sqrt_dd(self) -> Dd {
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

    fn cbrt_dd(self) -> Dd {
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

impl FieldOps for Dd {
    type Prec = ();
    #[inline(always)]
    fn prec(&self) {}
    #[inline(always)]
    fn from_i64(n: i64, _: ()) -> Dd {
        let hi = n as f64;
        let lo = (n - hi as i64) as f64;
        Dd::from_parts(hi, lo)
    }
    #[inline]
    fn from_ratio(num: i64, den: i64, _: ()) -> Dd {
        Dd::from_i64(num, ()).div_dd(Dd::from_i64(den, ()))
    }
    #[inline(always)]
    fn zero(_: ()) -> Dd {
        Dd::from_f64_exact(0.0)
    }
    #[inline(always)]
    fn one(_: ()) -> Dd {
        Dd::from_f64_exact(1.0)
    }
    #[inline(always)]
    fn is_zero(&self) -> bool {
        self.hi() == 0.0
    }
    #[inline(always)]
    fn mul_i64(self, n: i64) -> Dd {
        if n.unsigned_abs() < (1u64 << 53) {
            self.mul_f64(n as f64)
        } else {
            self * Dd::from_i64(n, ())
        }
    }
    #[inline(always)]
    fn div_i64(self, n: i64) -> Dd {
        if n.unsigned_abs() < (1u64 << 53) {
            self.div_f64(n as f64)
        } else {
            self / Dd::from_i64(n, ())
        }
    }
    #[inline(always)]
    fn square(&self) -> Dd {
        self.mul_dd(*self)
    }
}

impl Field for Dd {
    #[inline(always)]
    fn is_negative(&self) -> bool {
        self.hi() < 0.0
    }
    #[inline(always)]
    fn abs(self) -> Dd {
        if self.hi() < 0.0 {
            -self
        } else {
            self
        }
    }
    #[inline(always)]
    fn to_f64(&self) -> f64 {
        self.hi() + self.lo()
    }
}

impl Real for Dd {
    type Wide = super::Mp;
    fn wide_prec(_: ()) -> super::MpPrec {
        super::MpPrec::DD_WIDE
    }
    fn to_wide(&self, pw: super::MpPrec) -> super::Mp {
        super::Mp(self.to_float(pw.bits()))
    }
    fn from_wide(w: &super::Mp, _: ()) -> Dd {
        Dd::from_float(&w.0, ())
    }
    #[inline(always)]
    fn bits(_: ()) -> u32 {
        106
    }
    #[inline(always)]
    fn epsilon(_: ()) -> Dd {
        Dd::from_f64_exact(Dd::EPSILON)
    }
    #[inline(always)]
    fn min_positive(_: ()) -> Dd {
        // Below 2^-969 the trailing word is subnormal and accuracy degrades.
        Dd::from_f64_exact(f64::MIN_POSITIVE * 9007199254740992.0)
    }
    #[inline]
    fn pi(_: ()) -> Dd {
        consts().pi
    }
    #[inline]
    fn ln2(_: ()) -> Dd {
        consts().ln2
    }
    #[inline(always)]
    fn from_f64(x: f64, _: ()) -> Dd {
        Dd::from_f64_exact(x)
    }
    fn parse(s: &str, _: ()) -> Result<Dd> {
        let parsed = rug::Float::parse(s.trim()).map_err(|_| Error::Parse {
            text: s.to_string(),
            reason: "not a decimal number",
        })?;
        let f = rug::Float::with_val(320, parsed);
        Ok(Dd::from_float(&f, ()))
    }
    fn to_decimal(&self) -> String {
        if !self.hi().is_finite() {
            return format!("{}", self.hi());
        }
        self.to_float(128).to_string_radix(10, Some(32))
    }
    fn to_float(&self, bits: u32) -> rug::Float {
        let (hi, lo) = (self.hi(), self.lo());
        let need = if lo == 0.0 || !hi.is_finite() {
            53
        } else {
            let eh = hi.abs().log2().floor() as i64;
            let el = lo.abs().log2().floor() as i64;
            ((eh - el) + 54).clamp(53, 2200) as u32
        };
        let mut f = rug::Float::with_val(bits.max(need), hi);
        f += lo;
        f
    }
    fn from_float(x: &rug::Float, _: ()) -> Dd {
        let hi = x.to_f64();
        if !hi.is_finite() {
            return Dd::from_f64_exact(hi);
        }
        let r = rug::Float::with_val(x.prec().max(64), x - hi);
        Dd::from_parts(hi, r.to_f64())
    }
    #[inline(always)]
    fn mul_pow2(self, k: i32) -> Dd {
        Dd::from_parts(self.hi().mul_pow2(k), self.lo().mul_pow2(k))
    }
    #[inline(always)]
    fn is_finite(&self) -> bool {
        self.hi().is_finite()
    }
    #[inline(always)]
    fn is_nan(&self) -> bool {
        self.hi().is_nan()
    }
    fn floor(self) -> Dd {
        let f = self.hi().floor();
        if f == self.hi() {
            Dd::from_parts(f, self.lo().floor())
        } else {
            Dd::from_f64_exact(f)
        }
    }
    fn round(self) -> Dd {
        let half = Dd::from_f64_exact(0.5);
        if self.is_negative() {
            -((-self) + half).floor()
        } else {
            (self + half).floor()
        }
    }
    fn sqrt(self) -> Dd {
        self.sqrt_dd()
    }
    fn recip_sqrt(self) -> Dd {
        self.recip_sqrt_dd()
    }
    fn sqrt_div(self, b: &Dd) -> Dd {
        if !(self.hi() > 0.0 && b.hi() != 0.0 && self.is_finite() && b.is_finite()) {
            return self.sqrt_dd() / *b;
        }
        let q = self * (self * b.square()).recip_sqrt_dd();
        if b.hi() < 0.0 {
            -q
        } else {
            q
        }
    }
    fn pow_m3_2(self) -> Dd {
        let y = self.recip_sqrt_dd();
        y.square() * y
    }
    fn pow_m3_2_m5_2(self) -> (Dd, Dd) {
        let y = self.recip_sqrt_dd();
        let y2 = y.square();
        let y3 = y2 * y;
        (y3, y3 * y2)
    }
    fn cbrt(self) -> Dd {
        self.cbrt_dd()
    }
    fn exp(self) -> Dd {
        self.exp_dd()
    }
    fn exp_m1(self) -> Dd {
        if self.hi().abs() <= 0.5 {
            self.expm1_small()
        } else {
            self.exp_dd() - Dd::from_f64_exact(1.0)
        }
    }
    fn ln(self) -> Dd {
        self.ln_dd()
    }
    fn ln_1p(self) -> Dd {
        self.ln1p_dd()
    }
    fn sin(self) -> Dd {
        self.sin_cos_dd().0
    }
    fn cos(self) -> Dd {
        self.sin_cos_dd().1
    }
    fn sin_cos(self) -> (Dd, Dd) {
        self.sin_cos_dd()
    }
    fn atan2(self, x: &Dd) -> Dd {
        self.atan2_dd(*x)
    }
    fn with_prec(&self, _: ()) -> Dd {
        *self
    }
}

#[cfg(test)]
mod tests {
    /// Both error-free products — Dekker's and the hardware FMA's, whichever this processor
    /// runs by default — give the exact error of the rounded product, checked in exact
    /// arithmetic over random and extreme arguments.
    #[cfg(not(target_feature = "fma"))]
    #[test]
    fn both_error_free_products_are_exact() {
        let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut args = vec![
            (1.0 + 2f64.powi(-52), 1.0 - 2f64.powi(-53)),
            (1e300, 3e-301),
        ];
        args.push((6.7e299, 1.3e-5));
        for _ in 0..20000 {
            let m = |r: u64| (r >> 11) as f64 / (1u64 << 53) as f64 + 0.5;
            let (r1, r2) = (next(), next());
            let e1 = (r1 % 600) as i32 - 300;
            let e2 = (r2 % 600) as i32 - 300;
            let s = if r1 & 1 == 1 { -1.0 } else { 1.0 };
            args.push((s * m(next()) * 2f64.powi(e1), m(next()) * 2f64.powi(e2)));
        }
        for (a, b) in args {
            let p = a * b;
            let exact = rug::Float::with_val(256, a) * b - p;
            let want = exact.to_f64();
            assert_eq!(super::dekker_error(a, b, p), want, "Dekker at {a:e}·{b:e}");
            assert_eq!(super::two_prod(a, b).1, want, "two_prod at {a:e}·{b:e}");
            #[cfg(target_arch = "x86_64")]
            if super::hw::has_fma() {
                assert_eq!(super::hw::fms(a, b, p), want, "FMA at {a:e}·{b:e}");
            }
        }
    }

    /// The one-leaf FMA test answers as std's detection does on this processor.
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    #[test]
    fn fma_detection_agrees_with_std() {
        assert_eq!(
            super::hw::has_fma(),
            std::arch::is_x86_feature_detected!("fma")
        );
    }
}
