//! Sweeps (`moving_hertz::sweep`) against one independent solve per point, per precision: a
//! 1,000-point A1/B1 curve (10⁻³ … 10³, log-spaced) at ν = 0.25, M_R = 0.9, solved one by one
//! with `solve_ellipse` (`independent`), by the sweep on one thread (`sweep_1_thread`) and on two
//! (`sweep_2_threads`). Targets: per point on one thread ≤ 0.4× the independent solve at f64,
//! ≤ 0.5× at double-double, ≤ 0.6× at 256 bits; two threads ≤ 0.55× one thread.
//!
//! Each timed call runs on a thread of a pool of that many threads (the independent solves on
//! the one-thread pool); the hand-off from the bench's thread to the pool is outside the timing
//! (but for `two_sweeps_at_once`, which hands one sweep to each of two one-thread pools). The
//! pools' threads are bound to CPUs (`sweep::bind_to_cpu`: the one-thread pool's to the first,
//! the two-thread pool's to the first two, `two_sweeps_at_once`'s second pool's to the second),
//! as the `moving-hertz` binary binds them; `sweep_2_threads_unbound` runs the two-thread sweep
//! on a pool left to the operating system's placement.
//! What that hand-off adds to a sweep called from outside the pool, once per call, is
//! `sweep_1_thread_from_outside` (`install` around each call).
//!
//! **Paired ratios.** This machine's speed drifts by tens of per cent within seconds, so that a
//! ratio of two medians measured seconds apart is unreliable. `independent`, `sweep_2_threads`,
//! `sweep_2_threads_unbound` and `two_sweeps_at_once` therefore alternate each timed call with
//! a call of the one-thread sweep (not counted in their time), and each sample records the
//! ratio of the two totals: `sweep_1_thread / independent`, `sweep_2_threads / sweep_1_thread`
//! (the same for `sweep_2_threads_unbound`) and `two_sweeps_at_once / (2 × sweep_1_thread)`.
//! `two_sweeps_at_once` runs two one-thread sweeps at the same time, each on a thread of its
//! own: its ratio is the best a two-thread sweep can reach on this machine (0.5 when the two
//! cores are independent; more when they share a physical core or the host is busy). The bench
//! writes the samples' ratios to `target/criterion/sweep_paired.json`, which
//! tools/gen_performance.py reads (the median of each list).
//!
//! Run: `cargo bench --bench sweep -- --warm-up-time 1 --measurement-time 3`

use criterion::{black_box, criterion_group, criterion_main, Criterion, SamplingMode};
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};
use moving_hertz::sweep::{self, EllipsePoint, SpeedGiven};
use moving_hertz::{solve_ellipse, Material, Options};
use rayon::ThreadPool;
use std::collections::BTreeMap;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// The curve's points.
const POINTS: usize = 1000;

/// Per precision and bench, the paired ratio of each sample (written at the end).
type Paired = BTreeMap<String, BTreeMap<&'static str, Vec<f64>>>;
static PAIRED: Mutex<Paired> = Mutex::new(BTreeMap::new());

/// How long `f` takes, run on the (single or only) thread of `pool`.
fn on(pool: &ThreadPool, f: impl FnOnce() + Send) -> Duration {
    pool.install(|| {
        let t = Instant::now();
        f();
        t.elapsed()
    })
}

fn run<T: Real + Send + Sync>(c: &mut Criterion, label: &str, p: T::Prec) {
    let mut g = c.benchmark_group(format!("sweep/{label}"));
    g.sample_size(10).sampling_mode(SamplingMode::Flat);
    let x = |v: f64| T::from_f64(v, p);
    let ratios: Vec<T> = (0..POINTS)
        .map(|j| x(10f64.powf(-3.0 + 6.0 * j as f64 / (POINTS - 1) as f64)))
        .collect();
    let points = EllipsePoint::grid(&[x(0.25)], &[SpeedGiven::Mr(x(0.9))], &ratios);
    let speed = Material::new(x(0.25))
        .and_then(|m| m.speed(x(0.9)))
        .expect("speed");
    let opts = Options::default();
    // Pools whose thread i is bound to CPU `first + i` (of those the bench may run on), or
    // unbound.
    let pool = |threads, first: Option<usize>| {
        let b = rayon::ThreadPoolBuilder::new().num_threads(threads);
        let b = match first {
            Some(first) => b.start_handler(move |i| {
                sweep::bind_to_cpu(first + i);
            }),
            None => b,
        };
        b.build().expect("thread pool")
    };
    let (one, two, other_one) = (pool(1, Some(0)), pool(2, Some(0)), pool(1, Some(1)));
    let two_unbound = pool(2, None);
    let sweep = || {
        black_box(sweep::ellipses(black_box(&points), &opts));
    };
    let one_thread = || on(&one, sweep);
    let independent = || {
        on(&one, || {
            let solved = ratios
                .iter()
                .filter(|r| solve_ellipse(black_box(&speed), r, &opts).is_ok());
            black_box(solved.count());
        })
    };
    let two_threads = || on(&two, sweep);
    let two_threads_unbound = || on(&two_unbound, sweep);
    let at_once = || {
        let t = Instant::now();
        other_one.in_place_scope(|s| {
            s.spawn(|_| sweep());
            one.install(sweep);
        });
        t.elapsed()
    };
    // (bench, its timed call, the divisor of its paired ratio's one-thread total)
    let paired: [(&'static str, &dyn Fn() -> Duration, f64); 4] = [
        ("independent", &independent, 1.0),
        ("sweep_2_threads", &two_threads, 1.0),
        ("sweep_2_threads_unbound", &two_threads_unbound, 1.0),
        ("two_sweeps_at_once", &at_once, 2.0),
    ];
    for (name, timed, twice) in paired {
        g.bench_function(name, |b| {
            b.iter_custom(|iters| {
                let (mut mine, mut base) = (Duration::ZERO, Duration::ZERO);
                for _ in 0..iters {
                    mine += timed();
                    base += one_thread();
                }
                let r = if name == "independent" {
                    base.as_secs_f64() / mine.as_secs_f64()
                } else {
                    mine.as_secs_f64() / (twice * base.as_secs_f64())
                };
                let mut all = PAIRED.lock().expect("paired ratios");
                all.entry(label.to_string())
                    .or_default()
                    .entry(name)
                    .or_default()
                    .push(r);
                mine
            })
        });
    }
    g.bench_function("sweep_1_thread", |b| {
        b.iter_custom(|iters| (0..iters).map(|_| one_thread()).sum())
    });
    g.bench_function("sweep_1_thread_from_outside", |b| {
        b.iter(|| one.install(sweep))
    });
    g.finish();
}

/// Writes the paired ratios beside criterion's output, keeping the precisions this run did not
/// measure (a filtered run).
fn write_paired() {
    let dir = std::env::var("CARGO_TARGET_DIR").unwrap_or_else(|_| "target".into());
    let path = std::path::Path::new(&dir)
        .join("criterion")
        .join("sweep_paired.json");
    let mut all: serde_json::Map<String, serde_json::Value> = std::fs::read_to_string(&path)
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .unwrap_or_default();
    for (label, ratios) in PAIRED.lock().expect("paired ratios").iter() {
        all.insert(label.clone(), serde_json::json!(ratios));
    }
    let text = serde_json::to_string_pretty(&all).expect("json");
    if let Err(e) = std::fs::create_dir_all(path.parent().expect("dir"))
        .and_then(|()| std::fs::write(&path, text))
    {
        eprintln!("could not write {}: {e}", path.display());
    }
}

fn bench(c: &mut Criterion) {
    run::<f64>(c, "f64", ());
    run::<Dd>(c, "dd", ());
    run::<Mp>(c, "mpfr256", MpPrec::new(256).expect("precision"));
    write_paired();
}

criterion_group!(benches, bench);
criterion_main!(benches);
