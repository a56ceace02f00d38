//! Guard precision for the routes ("guard bits, then round once"): a computation whose rounding
//! errors accumulate over many steps (a long recursion, a long sum, a difference of nearly equal
//! moments) runs at the working precision plus `g` guard bits and is rounded once at the end.
//!
//! The guarded type is [`Real::Wide`] when its precision covers the request without being more
//! than 64 bits too wide (`f64` → double-double), MPFR at exactly `bits + g` otherwise.

use crate::error::Result;
use crate::scalar::{Mp, MpPrec, Real};

/// A computation that can run at any guarded precision `W` and be rounded back to `T`.
pub(crate) trait GuardedJob<T: Real> {
    /// What the job returns (at precision `T`).
    type Output;
    /// Runs at precision `pw` of type `W`; `up` converts an input exactly (or to within ε_W),
    /// `down` rounds a result once to the working precision of `T`.
    fn run<W: Real>(
        self,
        pw: W::Prec,
        up: &dyn Fn(&T) -> W,
        down: &dyn Fn(&W) -> T,
    ) -> Result<Self::Output>;
}

/// Runs `job` at the precision `p` of `T` plus `guard` bits (at `T` itself when `guard` = 0)
/// and returns its output.
///
/// Errors: [`crate::Error::Precision`] when `bits(p) + guard` exceeds the MPFR maximum;
/// otherwise whatever the job returns.
pub(crate) fn run_guarded<T: Real, J: GuardedJob<T>>(
    p: T::Prec,
    guard: u32,
    job: J,
) -> Result<J::Output> {
    if guard == 0 {
        return job.run::<T>(p, &|x: &T| x.clone(), &|w: &T| w.clone());
    }
    let bits = T::bits(p);
    let need = bits.saturating_add(guard);
    let pw = T::wide_prec(p);
    let wide_bits = <T::Wide as Real>::bits(pw);
    if wide_bits >= need && wide_bits <= need + 64 {
        job.run::<T::Wide>(pw, &|x: &T| x.to_wide(pw), &|w: &T::Wide| {
            T::from_wide(w, p)
        })
    } else {
        let pm = MpPrec::new(need as u64)?;
        job.run::<Mp>(
            pm,
            &|x: &T| Mp::from_float(&x.to_float(bits), pm),
            &|w: &Mp| T::from_float(&w.0, p),
        )
    }
}

/// Bits of ⌈log₂ x⌉ for x ≥ 1 (0 below).
pub(crate) fn ceil_log2(x: f64) -> u32 {
    if x > 1.0 {
        x.log2().ceil().min(1e6) as u32
    } else {
        0
    }
}
