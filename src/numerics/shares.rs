//! Work on every core, run by the calling thread together with a pool of this module's own
//! ([`helpers`], one thread fewer than the cores, kept for the process); `docs/design.md`
//! ("Dependencies", `rayon`) says why the pool is shaped so:
//!
//! * [`map_on_threads`]: `f(0) … f(m − 1)` in contiguous shares, for the one-time work of a
//!   precision (the nodes of a Gauss–Legendre rule, the graded routes' e^{±x} tables), at least
//!   [`MIN_ITEMS_A_SHARE`] items a core.
//! * [`for_shares`] with [`shares`]: the fixed-rule and graded routes' node loops in contiguous
//!   shares, above [`PARALLEL_ABOVE_BITS`] only and never on a thread of a `rayon` pool.
//!
//! **Same bits on any number of threads.** Each item is computed by the same operations whatever
//! share it falls in, and sums are formed afterwards in item order (`tests/high_precision.rs`,
//! `node_loops_on_threads_give_the_same_bits`). The threads take the shares from a common list,
//! so that a share whose thread cannot be started (or starts late) is taken by another.
//!
//! No item of this module implements a formula of the paper.

use crate::error::{Error, Result};
use std::sync::{Mutex, OnceLock, PoisonError};

/// Precisions (bits) above which the fixed-rule routes' node loops run on every core; at and
/// below it every loop stays on the calling thread (docs/calibration.md has the evidence).
pub const PARALLEL_ABOVE_BITS: u32 = 448;

/// The fewest items a share (below, the items cost less than handing them to another thread).
const MIN_ITEMS_A_SHARE: usize = 16;

/// The number of cores (1 when it cannot be known), asked once a process (on Linux the question
/// reads the cgroup limits: not something to repeat for every loop).
fn cores() -> usize {
    static CORES: OnceLock<usize> = OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, |c| c.get()))
}

/// The error of an item left without a result (it cannot be: the calling thread's copy of the
/// job takes shares until none is left, and nothing in the work given to [`map_on_threads`]
/// panics).
fn stopped() -> Error {
    Error::Internal {
        what: "work on every core left a share without a result",
    }
}

/// `f(0) … f(m − 1)` in order: on every core ([`for_shares`], contiguous shares) when there are
/// at least [`MIN_ITEMS_A_SHARE`] items a core, else on the calling thread (the number of cores
/// is not even asked for fewer than two shares' items). Used for the nodes of a rule and for
/// per-node tables built from them (`routes::graded`).
pub(crate) fn map_on_threads<R: Send>(
    m: usize,
    f: &(impl Fn(usize) -> Result<R> + Sync),
) -> Result<Vec<R>> {
    let count = if m < 2 * MIN_ITEMS_A_SHARE {
        1
    } else {
        cores().min(m / MIN_ITEMS_A_SHARE)
    };
    let mut out: Vec<Option<Result<R>>> = (0..m).map(|_| None).collect();
    for_shares(count, &mut out, &mut [] as &mut [()], &|start, part, _| {
        for (k, o) in (start..).zip(part) {
            *o = Some(f(k));
        }
    });
    out.into_iter()
        .map(|o| o.unwrap_or_else(|| Err(stopped())))
        .collect()
}

/// The number of shares for a loop over `n` nodes at `bits` bits: 1 at or below
/// [`PARALLEL_ABOVE_BITS`], on a `rayon` pool's thread, or for short loops; else the number of
/// cores, at most one share per [`MIN_ITEMS_A_SHARE`] nodes.
#[inline(always)]
pub(crate) fn shares(bits: u32, n: usize) -> usize {
    if bits <= PARALLEL_ABOVE_BITS || rayon::current_thread_index().is_some() {
        return 1;
    }
    cores().min(n / MIN_ITEMS_A_SHARE).max(1)
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

/// [`for_shares`] with `count` > 1 shares: the calling thread and the threads of [`on_count`]
/// take shares from a common list until it is empty, so that a thread that starts late or not
/// at all leaves its share to the others.
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
    on_count(count, &work);
}

/// The threads that run the shares beside the calling thread (module docs); `None` when they
/// cannot be started.
fn helpers() -> Option<&'static rayon::ThreadPool> {
    static POOL: OnceLock<Option<rayon::ThreadPool>> = OnceLock::new();
    POOL.get_or_init(|| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(cores().saturating_sub(1).max(1))
            .thread_name(|i| format!("moving-hertz-shares-{i}"))
            .build()
            .ok()
    })
    .as_ref()
}

/// Runs `job` on the calling thread and on up to `count` − 1 more at once (the [`helpers`], or
/// scoped threads on a thread of a `rayon` pool or when the helpers cannot be started), and
/// returns when every copy has returned; the copies take their work from a common list.
fn on_count(count: usize, job: &(dyn Fn() + Sync)) {
    if rayon::current_thread_index().is_none() {
        if let Some(pool) = helpers() {
            pool.in_place_scope(|scope| {
                for _ in 1..count {
                    scope.spawn(|_| job());
                }
                job();
            });
            return;
        }
    }
    std::thread::scope(|scope| {
        for _ in 1..count {
            let _ = std::thread::Builder::new().spawn_scoped(scope, job);
        }
        job();
    });
}
