//! A long job cut into blocks, solved on every thread of `rayon`'s pool while the calling thread
//! writes each block's output in input order as soon as it and every block before it are done.
//!
//! There is no barrier: a thread that finishes a block takes the next one at once, so that the
//! threads finish within one block of each other at the end of the job, not at the end of every
//! batch, and writing overlaps solving. Solved blocks wait for the writer at most
//! [`AHEAD_PER_THREAD`] blocks a thread ahead of it, so that the memory held stays a few blocks
//! a thread whatever the job's size. A write that fails (a closed pipe, a full disk) stops the
//! job: no thread takes a block after it, and the error is returned once the blocks being
//! solved are done. What a block computes depends only on its range, never on the thread count.

use super::CliError;
use std::collections::BTreeMap;
use std::ops::Range;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{mpsc, Condvar, Mutex, PoisonError};

/// How many blocks a thread may run ahead of the writer (solved blocks waiting to be written,
/// per thread of the pool).
const AHEAD_PER_THREAD: usize = 4;

/// Solves `0..total` in blocks of `block` (`solve` gives a block's output and its count of
/// failed items) and passes the outputs to `write` in input order. Returns the count of failed
/// items, or the first error of `write`. A job of one block runs on the calling thread (where
/// the solves may share their node loops among the cores); any other on the pool's threads.
pub fn solve_in_order<S, O: Send>(
    total: usize,
    block: usize,
    solve: S,
    mut write: impl FnMut(O) -> Result<(), CliError>,
) -> Result<usize, CliError>
where
    S: Fn(Range<usize>) -> (O, usize) + Sync,
{
    let blocks = total.div_ceil(block.max(1));
    let range = |b: usize| b * block..((b + 1) * block).min(total);
    if blocks <= 1 {
        let (rows, failed) = solve(0..total);
        return write(rows).map(|()| failed);
    }
    let threads = rayon::current_num_threads().clamp(1, blocks);
    let shared = Shared {
        next: AtomicUsize::new(0),
        stop: AtomicBool::new(false),
        written: Mutex::new(0),
        room: Condvar::new(),
        ahead: threads * AHEAD_PER_THREAD,
    };
    let (tx, rx) = mpsc::channel::<(usize, (O, usize))>();
    std::thread::scope(|s| {
        let (shared, solve, range) = (&shared, &solve, &range);
        s.spawn(move || {
            rayon::scope(|rs| {
                for _ in 0..threads {
                    let tx = tx.clone();
                    rs.spawn(move |_| shared.take_blocks(blocks, |b| solve(range(b)), &tx));
                }
            })
        });
        shared.write_in_order(rx, &mut write)
    })
}

/// What the threads of [`solve_in_order`] share.
struct Shared {
    /// The next block to take.
    next: AtomicUsize,
    /// Set when a write failed: no block is taken after it.
    stop: AtomicBool,
    /// How many blocks have been written (all before the first not written).
    written: Mutex<usize>,
    /// Signalled when `written` grows or `stop` is set.
    room: Condvar,
    /// How far ahead of `written` a block may be taken.
    ahead: usize,
}

impl Shared {
    /// One thread's loop: takes the next block, waits while it is too far ahead of the writer,
    /// solves it and sends its output; until no block is left or the job stops.
    fn take_blocks<O>(
        &self,
        blocks: usize,
        solve: impl Fn(usize) -> O,
        tx: &mpsc::Sender<(usize, O)>,
    ) {
        loop {
            let b = self.next.fetch_add(1, Ordering::Relaxed);
            if b >= blocks {
                return;
            }
            let mut written = self.written.lock().unwrap_or_else(PoisonError::into_inner);
            while b >= *written + self.ahead && !self.stop.load(Ordering::Relaxed) {
                written = self
                    .room
                    .wait(written)
                    .unwrap_or_else(PoisonError::into_inner);
            }
            drop(written);
            if self.stop.load(Ordering::Relaxed) || tx.send((b, solve(b))).is_err() {
                return;
            }
        }
    }

    /// The writer: receives the solved blocks, writes each once every block before it is
    /// written, and stops the job at the first failed write (the blocks still arriving are
    /// dropped). Returns the count of failed items written, or that write's error.
    fn write_in_order<O>(
        &self,
        rx: mpsc::Receiver<(usize, (O, usize))>,
        write: &mut impl FnMut(O) -> Result<(), CliError>,
    ) -> Result<usize, CliError> {
        let mut pending = BTreeMap::new();
        let (mut next, mut failed, mut result) = (0, 0, Ok(()));
        for (b, out) in rx {
            pending.insert(b, out);
            while let Some((rows, f)) = pending.remove(&next) {
                if result.is_ok() {
                    result = write(rows);
                    failed += f;
                }
                next += 1;
                *self.written.lock().unwrap_or_else(PoisonError::into_inner) = next;
                if result.is_err() {
                    self.stop.store(true, Ordering::Relaxed);
                }
                self.room.notify_all();
            }
        }
        result.map(|()| failed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every block is written once, in input order, on one thread and on several, with more
    /// blocks than the writer lets the threads run ahead.
    #[test]
    fn blocks_are_written_in_input_order() {
        for threads in [1, 2, 5] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("pool");
            let mut seen = Vec::new();
            let failed = pool.install(|| {
                solve_in_order(
                    1000,
                    7,
                    |r| (format!("{}-{};", r.start, r.end), r.len() % 2),
                    |rows| {
                        seen.push(rows);
                        Ok(())
                    },
                )
            });
            let expected: Vec<String> = (0..1000)
                .step_by(7)
                .map(|s| format!("{}-{};", s, (s + 7).min(1000)))
                .collect();
            assert_eq!(seen, expected, "{threads} threads");
            assert_eq!(failed.ok(), Some(142), "{threads} threads: 142 blocks of 7");
        }
    }

    /// A failed write stops the job: its error is returned, nothing is written after it, and
    /// the blocks solved after it are at most those the threads had taken.
    #[test]
    fn a_failed_write_stops_the_job() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .expect("pool");
        let solved = AtomicUsize::new(0);
        let mut writes = 0;
        let r = pool.install(|| {
            solve_in_order(
                100_000,
                10,
                |_| {
                    solved.fetch_add(1, Ordering::Relaxed);
                    (String::new(), 0)
                },
                |_| {
                    writes += 1;
                    match writes {
                        3 => Err(CliError::Failed("closed".into())),
                        _ => Ok(()),
                    }
                },
            )
        });
        assert!(matches!(r, Err(CliError::Failed(m)) if m == "closed"));
        assert_eq!(writes, 3);
        let solved = solved.load(Ordering::Relaxed);
        assert!(
            solved <= 3 + 2 * (2 * AHEAD_PER_THREAD + 1),
            "{solved} blocks solved"
        );
    }
}
