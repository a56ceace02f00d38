//! Cost of I1, I2 by the fixed rule for k ≤ 1 (`integrals` with `Method::Fixed`) against the
//! adaptive quadrature (`Method::Adaptive`, the precision's floor), at f64, double-double and
//! MPFR with 128 and 256 bits, for ν = 1/4, M_R ∈ {0.5, 0.9, 0.999, 1 − 10⁻⁸},
//! k ∈ {0.01, 0.3, 1}:
//!
//! * `fast`: I1 and I2 at one k of a new speed (made outside the timed call; the set-up, which
//!   the speed keeps, and one evaluation), the target of issue 5 (≤ 300 ns at f64);
//! * `fast_dk`: with dI1/dk, dI2/dk;
//! * `at_dk`: one further k with derivatives at a speed whose set-up is built
//!   (`Evaluator::at`), what a Newton step on (33) costs; the set-up's own cost is the difference
//!   `fast_dk` − `at_dk`;
//! * `adaptive`: the adaptive route on the same inputs.
//!
//! Each call goes through the public `integrals`/`Evaluator` (the options' check and the
//! result's finiteness check included, a few ns at f64).
//!
//! Run: `cargo bench --bench fast_integrals -- --warm-up-time 0.5 --measurement-time 1`, then
//! `python3 tools/fast_bench_table.py` for the tables of docs/performance.md.

use criterion::{black_box, criterion_group, criterion_main, BatchSize, Criterion};
use moving_hertz::physics::{Material, Speed};
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};
use moving_hertz::{integrals, Evaluator, IntegralOptions, Method};

const MRS: [(&str, f64); 4] = [
    ("0.5", 0.5),
    ("0.9", 0.9),
    ("0.999", 0.999),
    ("1-1e-8", 1.0 - 1e-8),
];
const KS: [(&str, f64); 3] = [("0.01", 0.01), ("0.3", 0.3), ("1", 1.0)];

fn inputs<T: Real>(mr: f64, k: f64, p: T::Prec) -> (Speed<T>, T) {
    let mat = Material::new(T::from_ratio(1, 4, p)).expect("nu");
    let sp = mat.speed(T::from_f64(mr, p)).expect("speed");
    (sp, T::from_f64(k, p))
}

fn options(method: Method, derivatives: bool) -> IntegralOptions {
    IntegralOptions {
        method,
        derivatives,
        ..Default::default()
    }
}

fn run<T: Real>(c: &mut Criterion, label: &str, p: T::Prec, slow_samples: usize) {
    let mut g = c.benchmark_group(format!("fast_{label}"));
    for (ms, mr) in MRS {
        for (ks, k) in KS {
            for (name, dk) in [("fast", false), ("fast_dk", true)] {
                let opts = options(Method::Fixed, dk);
                g.bench_function(format!("{name}/M={ms},k={ks}"), |b| {
                    b.iter_batched(
                        || inputs::<T>(mr, k, p),
                        |(sp, k)| integrals(black_box(&sp), black_box(&k), &opts),
                        BatchSize::SmallInput,
                    )
                });
            }
        }
        let (sp, k) = inputs::<T>(mr, 0.3, p);
        let ev = Evaluator::new(&sp, options(Method::Fixed, true)).expect("evaluator");
        ev.at(&k).expect("set-up");
        g.bench_function(format!("at_dk/M={ms},k=0.3"), |b| {
            b.iter(|| ev.at(black_box(&k)))
        });
    }
    g.finish();
    let mut g = c.benchmark_group(format!("adaptive_{label}"));
    g.sample_size(slow_samples);
    let adaptive = options(Method::Adaptive, false);
    for (ms, mr) in MRS {
        for (ks, k) in KS {
            let (sp, k) = inputs::<T>(mr, k, p);
            g.bench_function(format!("adaptive/M={ms},k={ks}"), |b| {
                b.iter(|| integrals(black_box(&sp), black_box(&k), &adaptive))
            });
        }
    }
    g.finish();
}

fn bench(c: &mut Criterion) {
    run::<f64>(c, "f64", (), 100);
    run::<Dd>(c, "dd", (), 20);
    run::<Mp>(c, "mpfr128", MpPrec::new(128).expect("precision"), 10);
    run::<Mp>(c, "mpfr256", MpPrec::new(256).expect("precision"), 10);
}

criterion_group!(benches, bench);
criterion_main!(benches);
