//! Sweeps (`moving_hertz::sweep`) against one independent solve per point, per precision: a
//! 1,000-point A1/B1 curve (10⁻³ … 10³, log-spaced) at ν = 0.25, M_R = 0.9, solved one by one
//! with `solve_ellipse` (`independent`), by the sweep on one thread (`sweep_1_thread`) and on two
//! (`sweep_2_threads`). Targets: per point on one thread ≤ 0.4× the independent solve at f64,
//! ≤ 0.5× at double-double, ≤ 0.6× at 256 bits; two threads ≤ 0.55× one thread (the ratios are
//! computed by tools/gen_performance.py from one run).
//!
//! Each of these runs its timing loop inside `ThreadPool::install` of a pool of that many
//! threads, the independent solves on the one-thread pool: every measured call runs on a pool
//! thread, and none pays a hand-off from the caller's thread. What that hand-off adds to a
//! sweep called from outside the pool, once per call, is `sweep_1_thread_from_outside`
//! (`install` around each call).
//!
//! Run: `cargo bench --bench sweep -- --warm-up-time 1 --measurement-time 5`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};
use moving_hertz::sweep::{self, EllipsePoint, SpeedGiven};
use moving_hertz::{solve_ellipse, Material, Options};

/// The curve's points.
const POINTS: usize = 1000;

fn run<T: Real + Send + Sync>(c: &mut Criterion, label: &str, p: T::Prec) {
    let mut g = c.benchmark_group(format!("sweep/{label}"));
    g.sample_size(10);
    let x = |v: f64| T::from_f64(v, p);
    let ratios: Vec<T> = (0..POINTS)
        .map(|j| x(10f64.powf(-3.0 + 6.0 * j as f64 / (POINTS - 1) as f64)))
        .collect();
    let points = EllipsePoint::grid(&[x(0.25)], &[SpeedGiven::Mr(x(0.9))], &ratios);
    let speed = Material::new(x(0.25))
        .and_then(|m| m.speed(x(0.9)))
        .expect("speed");
    let opts = Options::default();
    let pools = [1, 2].map(|threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("thread pool")
    });
    g.bench_function("independent", |b| {
        pools[0].install(|| {
            b.iter(|| {
                ratios
                    .iter()
                    .filter(|r| solve_ellipse(black_box(&speed), r, &opts).is_ok())
                    .count()
            })
        })
    });
    for (pool, name) in pools.iter().zip(["sweep_1_thread", "sweep_2_threads"]) {
        g.bench_function(name, |b| {
            pool.install(|| b.iter(|| sweep::ellipses(black_box(&points), &opts).len()))
        });
    }
    g.bench_function("sweep_1_thread_from_outside", |b| {
        b.iter(|| pools[0].install(|| sweep::ellipses(black_box(&points), &opts).len()))
    });
    g.finish();
}

fn bench(c: &mut Criterion) {
    run::<f64>(c, "f64", ());
    run::<Dd>(c, "dd", ());
    run::<Mp>(c, "mpfr256", MpPrec::new(256).expect("precision"));
}

criterion_group!(benches, bench);
criterion_main!(benches);
