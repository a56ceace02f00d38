//! Cost of the complete elliptic integrals per precision: K and E together (`ellipke_mc`) at
//! m = 1 − 10⁻¹² (mc = 10⁻¹²), at f64, double-double and MPFR with 64, 128, 256 and 1024 bits.
//!
//! Run: `cargo bench --bench precision_cost -- --warm-up-time 1 --measurement-time 3`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::numerics::elliptic::ellipke_mc;
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};

fn run<T: Real>(c: &mut Criterion, label: &str, p: T::Prec) {
    let mc = T::parse("1e-12", p).expect("mc");
    let mut g = c.benchmark_group(label.to_string());
    g.bench_function("ellipke_mc/mc=1e-12", |b| {
        b.iter(|| ellipke_mc(black_box(&mc)))
    });
    g.finish();
}

fn bench(c: &mut Criterion) {
    run::<f64>(c, "f64", ());
    run::<Dd>(c, "dd", ());
    for bits in [64, 128, 256, 1024] {
        run::<Mp>(
            c,
            &format!("mpfr{bits}"),
            MpPrec::new(bits).expect("precision"),
        );
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
