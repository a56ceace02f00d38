//! k > 1: the graded route's I1, I2 with dI/dk (`graded/<precision>`, k ∈ {3, 10³, 10⁶} at
//! M_R = 0.9, and k = 3 at M_R = 0.9999; `integrals` with `Method::Fixed`, the layout made
//! anew each call, for 9/8 of k as the evaluator lays it out) and the ellipse solve with roots k > 1
//! (`ellipse_wide/<precision>`: A1/B1 = 10 at M_R ∈ {0, 0.5, 0.9}, k = 3.1–4.5; A1/B1 = 10³ and
//! 10⁶ at M_R ∈ {0, 0.9, 0.9999}, k = 9–2900; ν = 0.2). Material and speed are built
//! outside the timed call.
//!
//! Run: `cargo bench --bench graded -- --warm-up-time 1 --measurement-time 2`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::physics::Material;
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};
use moving_hertz::{integrals, solve_ellipse, IntegralOptions, Method, Options};

fn run<T: Real>(c: &mut Criterion, label: &str, p: T::Prec) {
    let mat = Material::new(T::parse("0.2", p).expect("nu")).expect("material");
    let fixed = IntegralOptions {
        method: Method::Fixed,
        derivatives: true,
        ..Default::default()
    };
    let mut g = c.benchmark_group(format!("graded/{label}"));
    if T::bits(p) > 200 {
        g.sample_size(10);
    }
    for (mr, k) in [
        ("0.9", "3"),
        ("0.9", "1e3"),
        ("0.9", "1e6"),
        ("0.9999", "3"),
    ] {
        let sp = mat.speed(T::parse(mr, p).expect("speed")).expect("speed");
        let kv = T::parse(k, p).expect("k");
        g.bench_function(format!("M={mr}_k={k}"), |b| {
            b.iter(|| integrals(black_box(&sp), black_box(&kv), &fixed))
        });
    }
    g.finish();
    let mut g = c.benchmark_group(format!("ellipse_wide/{label}"));
    if T::bits(p) > 200 {
        g.sample_size(10);
    }
    for (r, mr) in [
        ("10", "0"),
        ("10", "0.5"),
        ("10", "0.9"),
        ("1e3", "0"),
        ("1e3", "0.9"),
        ("1e3", "0.9999"),
        ("1e6", "0"),
        ("1e6", "0.9"),
        ("1e6", "0.9999"),
    ] {
        let ratio = T::parse(r, p).expect("ratio");
        let sp = mat.speed(T::parse(mr, p).expect("speed")).expect("speed");
        g.bench_function(format!("ratio={r}_M={mr}"), |b| {
            b.iter(|| solve_ellipse(black_box(&sp), black_box(&ratio), &Options::default()))
        });
    }
    g.finish();
}

fn bench(c: &mut Criterion) {
    run::<f64>(c, "f64", ());
    run::<Dd>(c, "dd", ());
    run::<Mp>(c, "mpfr256", MpPrec::new(256).expect("precision"));
}

criterion_group!(benches, bench);
criterion_main!(benches);
