//! Many cores: the `moving-hertz` binary's parallel jobs, each a whole process run with
//! `RAYON_NUM_THREADS` = 1, 2 and every CPU (output to /dev/null), as a user runs them:
//!
//! * `sweep_f64`: `sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio log:1e-2:1e2:20000` (10⁶ points);
//! * `sweep_dd`: the same with `--ratio log:1e-2:1e2:2000 --precision dd` (10⁵ points);
//! * `sweep_256`: the same with `--ratio log:1e-2:1e2:100 --precision 256` (5,000 points);
//! * `fig2_256`: `fig2 --precision 256`; `fig2_f64`: `fig2` (a job too small for many threads,
//!   which must not be slower on them).
//!
//! Targets: at 16 threads ≥ 13× one thread for the four large jobs; on 2 cores two threads
//! ≤ 0.55× one thread; `fig2_f64` never slower on all threads than on one. The ratios are the
//! medians' (tools/scaling_table.py prints them as a table).
//!
//! Run: `cargo bench --bench scaling` (about ten minutes on 2 cores; `SCALING_JOBS=fig2_f64,sweep_dd`
//! runs some of the jobs only).

use criterion::{criterion_group, criterion_main, Criterion, SamplingMode};
use std::process::{Command, Stdio};
use std::time::Duration;

/// The jobs: name and arguments.
const JOBS: [(&str, &str); 5] = [
    (
        "sweep_f64",
        "sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio log:1e-2:1e2:20000",
    ),
    (
        "sweep_dd",
        "sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio log:1e-2:1e2:2000 --precision dd",
    ),
    (
        "sweep_256",
        "sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio log:1e-2:1e2:100 --precision 256",
    ),
    ("fig2_256", "fig2 --precision 256"),
    ("fig2_f64", "fig2"),
];

/// Runs the binary once with `args` on `threads` threads; fig2 writes under `out`.
fn run_job(args: &str, threads: usize, out: &std::path::Path) {
    let mut words: Vec<String> = args.split(' ').map(String::from).collect();
    if words[0] == "fig2" {
        words.push("--out".into());
        words.push(out.display().to_string());
    }
    let status = Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .args(&words)
        .env("RAYON_NUM_THREADS", threads.to_string())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .expect("the moving-hertz binary runs");
    assert!(status.success(), "moving-hertz {args}: {status}");
}

fn scaling(c: &mut Criterion) {
    let cpus = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut counts = vec![1, 2, cpus];
    counts.dedup();
    let chosen = std::env::var("SCALING_JOBS").ok();
    let out = std::env::temp_dir().join(format!("moving-hertz-scaling-{}", std::process::id()));
    std::fs::create_dir_all(&out).expect("a scratch directory");
    for (name, args) in JOBS {
        if chosen
            .as_ref()
            .is_some_and(|c| !c.split(',').any(|j| j == name))
        {
            continue;
        }
        let mut g = c.benchmark_group(format!("scaling/{name}"));
        g.sample_size(10)
            .sampling_mode(SamplingMode::Flat)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(5));
        for &threads in &counts {
            g.bench_function(format!("threads={threads}"), |b| {
                b.iter(|| run_job(args, threads, &out))
            });
        }
        g.finish();
    }
    let _ = std::fs::remove_dir_all(&out);
}

criterion_group!(benches, scaling);
criterion_main!(benches);
