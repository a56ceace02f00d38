//! A long job cut into blocks, solved on every thread of `rayon`'s pool while the calling thread
//! writes each block's output in input order as soon as it and every block before it are done.
//! A thread takes a task of consecutive blocks at a time and writes their rows into one buffer,
//! passed on in one write; no barrier; solved tasks wait at most [`AHEAD_PER_THREAD`] tasks a
//! thread ahead of the writer. A failed write (a closed pipe, a full disk) stops the job: no task
//! is taken after it. What a block computes depends only on its range, never on the thread count
//! or on its task. Why: docs/design.md, "Many cores".

use super::CliError;
use std::collections::BTreeMap;
use std::ops::Range;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{mpsc, Condvar, Mutex, PoisonError};

/// How many tasks a thread may run ahead of the writer (solved tasks waiting to be written,
/// per thread of the pool).
const AHEAD_PER_THREAD: usize = 4;

/// How many tasks each thread gets at least (when the job has the blocks for it): the last
/// task to finish then ends within about 1/32 of the job after the others.
const TASKS_PER_THREAD: usize = 32;

/// The items a task holds at most: a thousand f64 sweep points (about a millisecond of work)
/// make the hand-over of a task (a message, a wake-up, a write of about 130 kB) a fraction of a
/// per cent of it; the writer's system calls per block were the serial part that bounded a
/// 16-thread sweep (docs/design.md, "Many cores").
const TASK_ITEMS: usize = 1024;

/// Solves `0..total` in blocks of `block` (`solve` appends a block's output to the buffer it is
/// given and returns its count of failed items) and passes the outputs to `write` in input
/// order. Returns the count of failed items, or the first error of `write`. A job of one block
/// runs on the calling thread (where the solves may share their node loops among the cores);
/// any other on the pool's threads.
pub fn solve_in_order<S>(
    total: usize,
    block: usize,
    solve: S,
    mut write: impl FnMut(&[u8]) -> Result<(), CliError>,
) -> Result<usize, CliError>
where
    S: Fn(Range<usize>, &mut Vec<u8>) -> usize + Sync,
{
    let block = block.max(1);
    let blocks = total.div_ceil(block);
    if blocks <= 1 {
        let mut out = Vec::new();
        let failed = solve(0..total, &mut out);
        return write(&out).map(|()| failed);
    }
    let threads = rayon::current_num_threads().clamp(1, blocks);
    let group = task_blocks(blocks, block, threads);
    let tasks = blocks.div_ceil(group);
    // A task's blocks solved one after another into one buffer, sized after the first block.
    let task = |t: usize| {
        let (mut out, mut failed) = (Vec::new(), 0);
        for b in t * group..((t + 1) * group).min(blocks) {
            failed += solve(b * block..((b + 1) * block).min(total), &mut out);
            if b == t * group {
                out.reserve(out.len() * (group - 1));
            }
        }
        (out, failed)
    };
    let shared = Shared {
        next: AtomicUsize::new(0),
        stop: AtomicBool::new(false),
        written: Mutex::new(0),
        room: Condvar::new(),
        ahead: threads * AHEAD_PER_THREAD,
    };
    let (tx, rx) = mpsc::channel::<(usize, (Vec<u8>, usize))>();
    std::thread::scope(|s| {
        let (shared, task) = (&shared, &task);
        s.spawn(move || {
            rayon::scope(|rs| {
                for _ in 0..threads {
                    let tx = tx.clone();
                    rs.spawn(move |_| shared.take_tasks(tasks, task, &tx));
                }
            })
        });
        shared.write_in_order(rx, &mut write)
    })
}

/// How many consecutive blocks of `block` items make a task, for `blocks` blocks on `threads`
/// threads: at most [`TASK_ITEMS`] items, and at least [`TASKS_PER_THREAD`] tasks a thread
/// when there are the blocks for them; never less than one block.
fn task_blocks(blocks: usize, block: usize, threads: usize) -> usize {
    (TASK_ITEMS / block)
        .min(blocks / (threads * TASKS_PER_THREAD))
        .max(1)
}

/// What the threads of [`solve_in_order`] share.
struct Shared {
    /// The next task to take.
    next: AtomicUsize,
    /// Set when a write failed: no task is taken after it.
    stop: AtomicBool,
    /// How many tasks have been written (all before the first not written).
    written: Mutex<usize>,
    /// Signalled when `written` grows or `stop` is set.
    room: Condvar,
    /// How far ahead of `written` a task may be taken.
    ahead: usize,
}

impl Shared {
    /// One thread's loop: takes the next task, waits while it is too far ahead of the writer,
    /// solves it and sends its output; until no task is left or the job stops.
    fn take_tasks<O>(
        &self,
        tasks: usize,
        solve: impl Fn(usize) -> O,
        tx: &mpsc::Sender<(usize, O)>,
    ) {
        loop {
            let t = self.next.fetch_add(1, Ordering::Relaxed);
            if t >= tasks {
                return;
            }
            let mut written = self.written.lock().unwrap_or_else(PoisonError::into_inner);
            while t >= *written + self.ahead && !self.stop.load(Ordering::Relaxed) {
                written = self
                    .room
                    .wait(written)
                    .unwrap_or_else(PoisonError::into_inner);
            }
            drop(written);
            if self.stop.load(Ordering::Relaxed) || tx.send((t, solve(t))).is_err() {
                return;
            }
        }
    }

    /// The writer: receives the solved tasks, writes each once every task before it is
    /// written, and stops the job at the first failed write (the tasks still arriving are
    /// dropped). Returns the count of failed items written, or that write's error.
    fn write_in_order(
        &self,
        rx: mpsc::Receiver<(usize, (Vec<u8>, usize))>,
        write: &mut impl FnMut(&[u8]) -> Result<(), CliError>,
    ) -> Result<usize, CliError> {
        let mut pending = BTreeMap::new();
        let (mut next, mut failed, mut result) = (0, 0, Ok(()));
        for (t, out) in rx {
            pending.insert(t, out);
            while let Some((rows, f)) = pending.remove(&next) {
                if result.is_ok() {
                    result = write(&rows);
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
#[path = "../../tests/unit/pipeline.rs"]
mod tests;
