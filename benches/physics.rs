//! Cost of the physics per precision: the Rayleigh roots (the polished default and the two closed
//! forms) and G (45), at ν = 0.25, M_R = 0.9, at f64,
//! double-double and MPFR 128 and 256 bits.
//!
//! Run: `cargo bench --bench physics -- --warm-up-time 1 --measurement-time 3`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::physics::{ClosedForm, GreenFunction, Material, RayleighRoots};
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};

fn run<T: Real>(c: &mut Criterion, label: &str, p: T::Prec) {
    let nu = T::parse("0.25", p).expect("nu");
    let mat = Material::new(nu.clone()).expect("material");
    let speed = mat
        .speed(T::parse("0.9", p).expect("speed"))
        .expect("speed");
    let green = GreenFunction::new(&mat);
    let t = speed.mr2().clone();
    let mut g = c.benchmark_group(label.to_string());
    g.bench_function("roots/default", |b| {
        b.iter(|| RayleighRoots::new(black_box(&nu)))
    });
    g.bench_function("roots/real-branches", |b| {
        b.iter(|| RayleighRoots::closed_form(black_box(&nu), ClosedForm::RealBranches))
    });
    g.bench_function("roots/complex-cardano", |b| {
        b.iter(|| RayleighRoots::closed_form(black_box(&nu), ClosedForm::ComplexCardano))
    });
    g.bench_function("G(V)", |b| b.iter(|| green.g_regular(black_box(&t))));
    g.finish();
}

fn bench(c: &mut Criterion) {
    run::<f64>(c, "physics/f64", ());
    run::<Dd>(c, "physics/dd", ());
    for bits in [128, 256] {
        run::<Mp>(
            c,
            &format!("physics/mpfr{bits}"),
            MpPrec::new(bits).expect("precision"),
        );
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
