//! The cost of precision, from `f64` to 8192 bits (issue 16): I1, I2 at one axis ratio and the
//! ellipse solve (33), warm (rules built) and cold (every rule above double-double forgotten
//! before each call, so that it is built again), and the Gauss–Legendre construction itself.
//!
//! Inputs: ν = 0.25, M_R = 0.9990234375, k = 0.5 (the integrals) and A1/B1 = 2 (the ellipse),
//! exact at every precision; material and speed are built outside the timed call.
//!
//! * `scaling_integrals/{warm,cold}/<precision>`: `moving_hertz::integrals` (the fixed rule);
//! * `scaling_ellipse/{warm,cold}/<precision>`: `solve_ellipse` (the precision ladder);
//! * `gl_rule/short_point/n=<n>,bits=<bits>`: one n-point Gauss–Legendre rule
//!   (`GaussLegendre::get`, built cold), n the rule of a 2-unit sinh-mapped panel
//!   (the graded rule's `left_nodes(bits, 2)`, [`SHORT_POINT`]: 914 nodes at 4096 bits), the largest rule a first
//!   solve at k < 1 builds above 512 bits (the construction it replaced, Newton on the
//!   three-term recurrence, is the reference of the unit test in `numerics/gauss_legendre.rs`);
//! * `node_loops/{cores,one_thread}/<bits>`: the warm `solve_ellipse` called from the bench's
//!   thread, whose node loops run on every core above
//!   `numerics::shares::PARALLEL_ABOVE_BITS` (448), and inside a one-thread `rayon` pool, where
//!   they stay on that thread (the same bits). Each timed call alternates with an untimed call
//!   of the other kind, so that both see the same machine: their ratio is the evidence for the
//!   threshold (docs/calibration.md).
//!
//! "Cold" forgets the shared rule cache and the Gauss–Legendre store
//! (`numerics::quadrature::clear_rule_caches`); the rules of `f64` and double-double stay in
//! their static slots, so that cold and warm coincide there. The comparison with Arb and
//! mpmath, in fresh processes, is `tools/compare_arb_mpmath.py` (docs/data/precision_scaling.csv).
//!
//! Run: `cargo bench --bench precision_scaling -- --warm-up-time 1 --measurement-time 3`
//! (about 20 minutes; the 8192-bit cold cases take a few seconds a call). A filter such as
//! `-- warm` or `-- /4096` runs a part.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use moving_hertz::numerics::quadrature::{clear_rule_caches, GaussLegendre};
use moving_hertz::scalar::{Dd, Mp, MpPrec, Precision, Real};
use moving_hertz::{integrals, solve_ellipse, IntegralOptions, Material, Options};
use std::time::{Duration, Instant};

/// The precisions measured.
fn precisions() -> Vec<Precision> {
    let mut v = vec![Precision::F64, Precision::DoubleDouble];
    for bits in [256, 512, 1024, 2048, 4096, 8192] {
        v.push(Precision::Mpfr(MpPrec::new(bits).expect("precision")));
    }
    v
}

/// Times `f` once per iteration after forgetting the rules (cold) or not (warm).
fn timed(cold: bool, iters: u64, mut f: impl FnMut()) -> Duration {
    let mut total = Duration::ZERO;
    for _ in 0..iters {
        if cold {
            clear_rule_caches();
        }
        let t = Instant::now();
        f();
        total += t.elapsed();
    }
    total
}

fn run<T: Real>(c: &mut Criterion, prec: Precision, p: T::Prec) {
    let mat = Material::new(T::parse("0.25", p).expect("nu")).expect("material");
    let sp = mat
        .speed(T::parse("0.9990234375", p).expect("speed"))
        .expect("speed");
    let k = T::parse("0.5", p).expect("k");
    let ratio = T::from_i64(2, p);
    let label = prec.label();
    for cold in [false, true] {
        let kind = if cold { "cold" } else { "warm" };
        let mut g = c.benchmark_group(format!("scaling_integrals/{kind}"));
        if T::bits(p) > 300 {
            g.sample_size(10);
        }
        let opts = IntegralOptions::default();
        g.bench_function(BenchmarkId::from_parameter(&label), |b| {
            b.iter_custom(|iters| {
                timed(cold, iters, || {
                    black_box(integrals(&sp, black_box(&k), &opts).expect("integrals"));
                })
            })
        });
        g.finish();
        let mut g = c.benchmark_group(format!("scaling_ellipse/{kind}"));
        if T::bits(p) > 300 {
            g.sample_size(10);
        }
        let opts = Options::default();
        g.bench_function(BenchmarkId::from_parameter(&label), |b| {
            b.iter_custom(|iters| {
                timed(cold, iters, || {
                    black_box(solve_ellipse(&sp, black_box(&ratio), &opts).expect("ellipse"));
                })
            })
        });
        g.finish();
    }
}

/// (bits, nodes of a 2-unit sinh-mapped panel of the graded rule at those bits); the unit test
/// `graded::reference_tests::left_nodes_of_the_precision_bench` holds it to the rule's formula.
const SHORT_POINT: [(u32, usize); 5] = [
    (256, 59),
    (1024, 230),
    (2048, 458),
    (4096, 914),
    (8192, 1826),
];

fn gl_rules(c: &mut Criterion) {
    let mut g = c.benchmark_group("gl_rule");
    g.sample_size(10);
    for (bits, n) in SHORT_POINT {
        let p = MpPrec::new(bits as u64).expect("precision");
        let id = format!("n={n},bits={bits}");
        g.bench_function(BenchmarkId::new("short_point", &id), |b| {
            b.iter_custom(|iters| {
                timed(true, iters, || {
                    black_box(GaussLegendre::<Mp>::get(n, p).expect("rule"));
                })
            })
        });
    }
    g.finish();
}

fn node_loops(c: &mut Criterion) {
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("thread pool");
    for kind in ["cores", "one_thread"] {
        let mut g = c.benchmark_group(format!("node_loops/{kind}"));
        g.sample_size(10);
        for bits in [384u64, 448, 512, 768, 1024] {
            let p = MpPrec::new(bits).expect("precision");
            let x = |v: &str| Mp::parse(v, p).expect("input");
            let sp = Material::new(x("0.25"))
                .and_then(|m| m.speed(x("0.9990234375")))
                .expect("speed");
            let (ratio, opts) = (x("2"), Options::default());
            let solve = || {
                let t = Instant::now();
                black_box(solve_ellipse(&sp, black_box(&ratio), &opts).expect("ellipse"));
                t.elapsed()
            };
            let serial = || one.install(solve);
            g.bench_function(BenchmarkId::from_parameter(bits), |b| {
                b.iter_custom(|iters| {
                    let mut total = Duration::ZERO;
                    for _ in 0..iters {
                        let (on_cores, alone) = (solve(), serial());
                        total += if kind == "cores" { on_cores } else { alone };
                    }
                    total
                })
            });
        }
        g.finish();
    }
}

fn bench(c: &mut Criterion) {
    for prec in precisions() {
        match prec {
            Precision::F64 => run::<f64>(c, prec, ()),
            Precision::DoubleDouble => run::<Dd>(c, prec, ()),
            Precision::Mpfr(p) => run::<Mp>(c, prec, p),
        }
    }
    gl_rules(c);
    node_loops(c);
}

criterion_group!(benches, bench);
criterion_main!(benches);
