//! Cost of I1, I2 by the fast route (`routes::fast`) against the adaptive direct quadrature
//! (`direct::quadrature`, tolerance 0 = the precision's floor), at f64, double-double and MPFR
//! with 128 and 256 bits, for ν = 1/4, M_R ∈ {0.5, 0.9, 0.999, 1 − 10⁻⁸}, k ∈ {0.01, 0.3, 1}:
//!
//! * `fast`: I1 and I2 at one k of a new speed (the set-up and one evaluation,
//!   `FastSetup::integrals`; `fast::integrals` keeps the set-up with the speed), the target of
//!   issue 5 (≤ 300 ns at f64);
//! * `fast_dk`: with dI1/dk, dI2/dk (`FastSetup::integrals_with_dk`);
//! * `setup`, `at_dk`: the k-independent part (`FastSetup::new`) and one further k with
//!   derivatives (`FastSetup::integrals_with_dk`), what a Newton step on (33) costs;
//! * `adaptive`: `direct::quadrature` on the same inputs.
//!
//! Run: `cargo bench --bench fast_integrals -- --warm-up-time 0.5 --measurement-time 1`, then
//! `python3 tools/fast_bench_table.py` for the tables of docs/performance.md.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::physics::{Material, Speed};
use moving_hertz::routes::fast::FastSetup;
use moving_hertz::routes::{direct, AxisRatio};
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};

const MRS: [(&str, f64); 4] = [
    ("0.5", 0.5),
    ("0.9", 0.9),
    ("0.999", 0.999),
    ("1-1e-8", 1.0 - 1e-8),
];
const KS: [(&str, f64); 3] = [("0.01", 0.01), ("0.3", 0.3), ("1", 1.0)];

fn inputs<T: Real>(mr: f64, k: f64, p: T::Prec) -> (Speed<T>, AxisRatio<T>) {
    let mat = Material::new(T::from_ratio(1, 4, p)).expect("nu");
    let sp = mat.speed(T::from_f64(mr, p)).expect("speed");
    let ax = AxisRatio::new(T::from_f64(k, p)).expect("k");
    (sp, ax)
}

fn run<T: Real>(c: &mut Criterion, label: &str, p: T::Prec, slow_samples: usize) {
    let mut g = c.benchmark_group(format!("fast_{label}"));
    for (ms, mr) in MRS {
        for (ks, k) in KS {
            let (sp, ax) = inputs::<T>(mr, k, p);
            g.bench_function(format!("fast/M={ms},k={ks}"), |b| {
                b.iter(|| FastSetup::new(black_box(&sp)).and_then(|s| s.integrals(&ax)))
            });
            g.bench_function(format!("fast_dk/M={ms},k={ks}"), |b| {
                b.iter(|| FastSetup::new(black_box(&sp)).and_then(|s| s.integrals_with_dk(&ax)))
            });
        }
        let (sp, ax) = inputs::<T>(mr, 0.3, p);
        g.bench_function(format!("setup/M={ms}"), |b| {
            b.iter(|| FastSetup::new(black_box(&sp)))
        });
        let setup = FastSetup::new(&sp).expect("setup");
        g.bench_function(format!("at_dk/M={ms},k=0.3"), |b| {
            b.iter(|| setup.integrals_with_dk(black_box(&ax)))
        });
    }
    g.finish();
    let mut g = c.benchmark_group(format!("adaptive_{label}"));
    g.sample_size(slow_samples);
    let zero = T::zero(p);
    for (ms, mr) in MRS {
        for (ks, k) in KS {
            let (sp, ax) = inputs::<T>(mr, k, p);
            g.bench_function(format!("adaptive/M={ms},k={ks}"), |b| {
                b.iter(|| direct::quadrature(black_box(&sp), black_box(&ax), black_box(&zero)))
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
