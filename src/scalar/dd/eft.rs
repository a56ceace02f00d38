//! Error-free transformations of `f64` sums and products, the ground [`Dd`](super::Dd)'s
//! arithmetic stands on: TwoSum, FastTwoSum and the error-free product (the hardware FMA,
//! detected once at run time on x86-64, or Dekker's splitting). Exact, so every path gives the
//! same bits.

/// Error-free sum `a + b = s + e` (Knuth's TwoSum, 6 flops, no branch).
#[inline(always)]
pub(super) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// Error-free sum when `|a| ≥ |b|` (Dekker's FastTwoSum, 3 flops).
#[inline(always)]
pub(super) fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
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
pub(super) fn two_prod(a: f64, b: f64) -> (f64, f64) {
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
mod hw {
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

#[cfg(test)]
#[path = "../../../tests/unit/eft.rs"]
mod tests;
