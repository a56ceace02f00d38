//! Cost of the series route per precision: the coefficients f_0 … f_n of (35)–(36) for n = 100
//! and 1000 (M_R² = 0.81, binomial terms flushed below ε·2⁻³⁰ as the route does); the moment tables M_n, L_n, D_n to n = 1000 by the default (forward at k² = 1/4,
//! Gauss-backward at k² = 3/4, Pfaff-backward at k² = 4); I1 and I2 together by the series (37)
//! at M_R = 0.5 and 0.9 (ν = 1/4, k = 1/2); at f64, double-double, MPFR 128 and 256 bits.
//!
//! Run: `cargo bench --bench series -- --warm-up-time 1 --measurement-time 3`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::physics::Material;
use moving_hertz::routes::moments::moments;
use moving_hertz::routes::series::{integrals, SeriesOptions};
use moving_hertz::routes::{AxisRatio, SpeedCoefficients};
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};

fn run<T: Real>(c: &mut Criterion, label: &str, p: T::Prec) {
    let mat = Material::new(T::parse("0.25", p).expect("nu")).expect("material");
    let axis = AxisRatio::new(T::parse("0.5", p).expect("k")).expect("axis");
    let mr2 = T::parse("0.81", p).expect("mr2");
    let tiny = T::epsilon(p).mul_pow2(-30);
    let mut g = c.benchmark_group(format!("series-{label}"));
    for n in [100usize, 1000] {
        g.bench_function(format!("f_n/n={n}"), |b| {
            b.iter(|| {
                let mut gen = SpeedCoefficients::new(mat.nu(), mat.m1().clone(), mr2.clone())
                    .flush_below(tiny.clone());
                let mut last = T::zero(p);
                for _ in 0..=n {
                    last = gen.next_pair().1;
                }
                black_box(last)
            })
        });
    }
    for mc in ["0.25", "0.75", "4"] {
        let x = T::parse(mc, p).expect("mc");
        g.bench_function(format!("moments/n=1000,k2={mc}"), |b| {
            b.iter(|| moments(black_box(&x), 1000).expect("moments"))
        });
    }
    for mr in ["0.5", "0.9"] {
        let speed = mat.speed(T::parse(mr, p).expect("mr")).expect("speed");
        let opts = SeriesOptions::default();
        g.bench_function(format!("integrals/M_R={mr}"), |b| {
            b.iter(|| integrals(black_box(&speed), &axis, &opts).expect("series"))
        });
    }
    g.finish();
}

fn bench(c: &mut Criterion) {
    run::<f64>(c, "f64", ());
    run::<Dd>(c, "dd", ());
    for bits in [128, 256] {
        run::<Mp>(
            c,
            &format!("mpfr{bits}"),
            MpPrec::new(bits).expect("precision"),
        );
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
