//! Cost of the elliptic integrals per precision: K and E at m = 0.7 (m-form) and at
//! m = 1 − 10⁻¹² (mc-form, mc = 10⁻¹²), K and E together (`ellipke_mc`), and the incomplete
//! F and E at φ = 1.25, m = 0.7, at f64, double-double and MPFR with 64, 128, 256 and 1024 bits.
//!
//! Run: `cargo bench --bench precision_cost -- --warm-up-time 1 --measurement-time 3`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::numerics::elliptic::{
    ellipe, ellipe_inc, ellipe_mc, ellipf, ellipk, ellipk_mc, ellipke_mc,
};
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};

fn run<T: Real>(c: &mut Criterion, label: &str, p: T::Prec) {
    let m = T::parse("0.7", p).expect("m");
    let mc = T::parse("1e-12", p).expect("mc");
    let phi = T::parse("1.25", p).expect("phi");
    let mut g = c.benchmark_group(label.to_string());
    g.bench_function("ellipk/m=0.7", |b| b.iter(|| ellipk(black_box(&m))));
    g.bench_function("ellipe/m=0.7", |b| b.iter(|| ellipe(black_box(&m))));
    g.bench_function("ellipk_mc/mc=1e-12", |b| {
        b.iter(|| ellipk_mc(black_box(&mc)))
    });
    g.bench_function("ellipe_mc/mc=1e-12", |b| {
        b.iter(|| ellipe_mc(black_box(&mc)))
    });
    g.bench_function("ellipke_mc/mc=1e-12", |b| {
        b.iter(|| ellipke_mc(black_box(&mc)))
    });
    g.bench_function("ellipf/phi=1.25,m=0.7", |b| {
        b.iter(|| ellipf(black_box(&phi), black_box(&m)))
    });
    g.bench_function("ellipe_inc/phi=1.25,m=0.7", |b| {
        b.iter(|| ellipe_inc(black_box(&phi), black_box(&m)))
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
