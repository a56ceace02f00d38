//! Node loops on every core above [`PARALLEL_ABOVE_BITS`]: the per-node work of the fixed-rule
//! routes (the k-independent set-up, the integrand values of an evaluation, their chunk sums)
//! cut into contiguous shares, one a thread.
//!
//! **Same bits on any number of threads.** Each node's value is computed by the same operations
//! whatever share it falls in, and the sums are formed afterwards in node order (the chunk sums
//! of `routes::graded::power_sums` added in chunk order), so that a result does not depend on
//! the number of threads; `tests/high_precision.rs` (`node_loops_on_threads_give_the_same_bits`)
//! compares a solve on the cores with one on a single thread, bit for bit.
//!
//! **When.** Above [`PARALLEL_ABOVE_BITS`] only (below it starting the threads costs more than
//! they take over: docs/calibration.md), never on a thread of a `rayon` pool (a sweep already runs its
//! blocks on every core: a solve inside it keeps its loops on its own thread), and only with at
//! least [`MIN_NODES_A_SHARE`] nodes a share. The shares run on scoped threads of their own, as
//! the rules' construction does (`numerics::gauss_legendre`); a share whose thread cannot be
//! started runs on the calling thread.
//!
//! No item of this module implements a formula of the paper.

use std::sync::{Mutex, PoisonError};

/// Precisions (bits) above which the fixed-rule routes' node loops run on every core; at and
/// below it every loop stays on the calling thread (docs/calibration.md has the evidence).
pub const PARALLEL_ABOVE_BITS: u32 = 448;

/// The fewest nodes a share (a share's work must outweigh starting its thread).
const MIN_NODES_A_SHARE: usize = 16;

/// The number of shares for a loop over `n` nodes at `bits` bits: 1 at or below
/// [`PARALLEL_ABOVE_BITS`], on a `rayon` pool's thread, or for short loops; else the number of
/// cores, at most one share per [`MIN_NODES_A_SHARE`] nodes.
#[inline(always)]
pub(crate) fn shares(bits: u32, n: usize) -> usize {
    if bits <= PARALLEL_ABOVE_BITS || rayon::current_thread_index().is_some() {
        return 1;
    }
    let cores = std::thread::available_parallelism().map_or(1, |c| c.get());
    cores.min(n / MIN_NODES_A_SHARE).max(1)
}

/// Runs `share(start, &mut a[start..end], &mut b[start..end])` over `count` contiguous shares
/// that cover `a` (and `b`, which is empty or as long as `a`: an empty `b` gives each share an
/// empty slice); with one share, on the calling thread. `count` comes from [`shares`].
#[inline(always)]
pub(crate) fn for_shares<A: Send, B: Send>(
    count: usize,
    a: &mut [A],
    b: &mut [B],
    share: &(impl Fn(usize, &mut [A], &mut [B]) + Sync),
) {
    match count {
        0 | 1 => share(0, a, b),
        count => on_threads(count, a, b, share),
    }
}

/// [`for_shares`] with `count` > 1 shares: the calling thread and the started ones take shares
/// from a common list until it is empty, so that a thread that cannot be started leaves its
/// share to the others.
fn on_threads<A: Send, B: Send>(
    count: usize,
    a: &mut [A],
    b: &mut [B],
    share: &(impl Fn(usize, &mut [A], &mut [B]) + Sync),
) {
    let len = a.len().div_ceil(count);
    let paired = !b.is_empty();
    let mut b_rest = b;
    let mut list = Vec::with_capacity(count);
    for (i, a_part) in a.chunks_mut(len).enumerate() {
        let b_part: &mut [B] = if paired {
            let (head, tail) = std::mem::take(&mut b_rest).split_at_mut(a_part.len());
            b_rest = tail;
            head
        } else {
            &mut []
        };
        list.push((i * len, a_part, b_part));
    }
    let list = Mutex::new(list);
    let work = || loop {
        let next = list.lock().unwrap_or_else(PoisonError::into_inner).pop();
        match next {
            Some((start, a_part, b_part)) => share(start, a_part, b_part),
            None => break,
        }
    };
    std::thread::scope(|scope| {
        for _ in 1..count {
            // A thread that cannot be started leaves its share in the list.
            let _ = std::thread::Builder::new().spawn_scoped(scope, work);
        }
        work();
    });
}
