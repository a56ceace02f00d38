//! The calibration driver of the sweep (docs/calibration.md, "Sweeps"): an A1/B1 curve of
//! POINTS points (default 1,000; 10^LO … 10^HI, log-spaced) at ν = 0.25, M_R = 0.9 (or the gap
//! 1 − M_R = GAP, the speeds of `sweep --gap`: tools/sweep_point_cost.sh), solved one point at a time
//! (`indep`), by `sweep::ellipses` on THREADS threads (`sweep`; default 1), by `sweep::ellipses_at`
//! at the one speed formed once (`at`, as the `sweep` command solves), or neither (`none`: the fixed costs
//! alone, after the same warm-up); prints the evaluations at the working precision. Per-point
//! instruction counts come from running it under callgrind and subtracting `none`:
//!
//! `valgrind --tool=callgrind target/release/examples/sweep_cost f64 sweep -3 0`
//!
//! Run: `cargo run --release --example sweep_cost -- PRECISION MODE LO HI [THREADS [POINTS [GAP]]]`
//! (PRECISION f64, dd or bits; MODE indep, sweep, at or none). `tools/python_bench.py` times the
//! Python package's sweep against `f64 sweep -3 3 2 1000000`.

use moving_hertz::prelude::*;
use moving_hertz::solve_ellipse;
use moving_hertz::sweep::{self, EllipsePoint, SpeedGiven};
use std::time::Instant;

fn run<T: Real + Send + Sync>(
    p: T::Prec,
    mode: &str,
    lo: f64,
    hi: f64,
    threads: usize,
    n: usize,
    gap: Option<f64>,
) -> Result<()> {
    let x = |v: f64| T::from_f64(v, p);
    let ratios: Vec<T> = (0..n)
        .map(|j| x(10f64.powf(lo + (hi - lo) * j as f64 / (n.max(2) - 1) as f64)))
        .collect();
    let given = gap.map_or(SpeedGiven::Mr(x(0.9)), |g| SpeedGiven::Gap(x(g)));
    let points = EllipsePoint::grid(&[x(0.25)], &[given], &ratios);
    let speed = match gap {
        Some(g) => Material::new(x(0.25))?.speed_from_gap(x(g))?,
        None => Material::new(x(0.25))?.speed(x(0.9))?,
    };
    let opts = Options::default();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a pool of THREADS threads");
    // Warm-up: the rules and constants every mode builds once.
    for j in 0..13 {
        solve_ellipse(&speed, &x(10f64.powf(-3.0 + 0.5 * j as f64)), &opts)?;
    }
    pool.install(|| sweep::ellipses(&points[..3], &opts));
    let start = Instant::now();
    let mut evaluations = 0;
    match mode {
        "indep" => {
            for r in &ratios {
                evaluations += solve_ellipse(&speed, r, &opts)?.iterations();
            }
        }
        "sweep" => {
            for r in pool.install(|| sweep::ellipses(&points, &opts)) {
                evaluations += r?.iterations();
            }
        }
        "at" => {
            let formed = Ok(speed.clone());
            let at: Vec<_> = (ratios.iter())
                .map(|ratio| sweep::AtSpeed {
                    speed: &formed,
                    ratio,
                })
                .collect();
            for r in pool.install(|| sweep::ellipses_at(&at, &opts)) {
                evaluations += r?.iterations();
            }
        }
        _ => {}
    }
    println!(
        "{mode}: {evaluations} evaluations at the working precision, {:.3} ms",
        start.elapsed().as_secs_f64() * 1e3
    );
    Ok(())
}

fn main() -> Result<()> {
    let a: Vec<String> = std::env::args().collect();
    let arg = |i: usize, default: &str| a.get(i).cloned().unwrap_or_else(|| default.into());
    let (mode, lo, hi) = (arg(2, "sweep"), arg(3, "-3"), arg(4, "3"));
    let (lo, hi): (f64, f64) = (lo.parse().unwrap_or(-3.0), hi.parse().unwrap_or(3.0));
    let threads: usize = arg(5, "1").parse().unwrap_or(1);
    let n: usize = arg(6, "1000").parse().unwrap_or(1000).max(1);
    let gap = a.get(7).and_then(|g| g.parse().ok());
    match Precision::parse(&arg(1, "f64"))? {
        Precision::F64 => run::<f64>((), &mode, lo, hi, threads, n, gap),
        Precision::DoubleDouble => run::<Dd>((), &mode, lo, hi, threads, n, gap),
        Precision::Mpfr(p) => run::<Mp>(p, &mode, lo, hi, threads, n, gap),
    }
}
