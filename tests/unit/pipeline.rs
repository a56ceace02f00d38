//! Unit tests of the ordered block writer (`src/cli/pipeline.rs`).

use super::*;

/// Every block is written once, in input order, on one thread and on several, with more
/// tasks than the writer lets the threads run ahead and tasks of several blocks.
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
                10_000,
                7,
                |r, out: &mut Vec<u8>| {
                    out.extend(format!("{}-{};", r.start, r.end).bytes());
                    r.len() % 2
                },
                |rows| {
                    seen.extend_from_slice(rows);
                    Ok(())
                },
            )
        });
        let expected: String = (0..10_000)
            .step_by(7)
            .map(|s| format!("{}-{};", s, (s + 7).min(10_000)))
            .collect();
        assert_eq!(
            String::from_utf8_lossy(&seen),
            expected,
            "{threads} threads"
        );
        assert_eq!(
            failed.ok(),
            Some(1428),
            "{threads} threads: 1428 blocks of 7"
        );
        assert!(task_blocks(1429, 7, threads) > 1, "{threads} threads");
    }
}

/// A task holds at most a thousand items, and each thread gets 32 tasks where the blocks
/// allow: the f64, double-double and 256-bit sweeps on 16 threads and on one.
#[test]
fn tasks_are_large_but_many() {
    assert_eq!(task_blocks(15_625, 64, 16), 16);
    assert_eq!(task_blocks(1_563, 64, 16), 3);
    assert_eq!(task_blocks(79, 64, 16), 1);
    assert_eq!(task_blocks(79, 64, 1), 2);
    assert_eq!(task_blocks(2, 64, 2), 1);
    for (blocks, threads) in [(15_625, 16), (1_563, 16), (100_000, 128), (5_000, 2)] {
        let g = task_blocks(blocks, 64, threads);
        assert!(g * 64 <= TASK_ITEMS);
        assert!(g == 1 || blocks.div_ceil(g) >= threads * TASKS_PER_THREAD);
    }
}

/// A failed write stops the job: its error is returned, nothing is written after it, and
/// the tasks solved after it are at most those the threads had taken.
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
            |_, _: &mut Vec<u8>| {
                solved.fetch_add(1, Ordering::Relaxed);
                0
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
    let group = task_blocks(10_000, 10, 2);
    assert!(
        solved <= (3 + 2 * (2 * AHEAD_PER_THREAD + 1)) * group,
        "{solved} blocks solved in tasks of {group}"
    );
}
