//! The full contact solution (`ContactProblem::solve`: the ellipse (33), J0 of (32) as k² I1 + I2
//! from the ellipse's I1, I2, then a, b, p0, d0 in closed form) per precision, ν = 0.3,
//! R2/R1 = 2 (A1/B1 = 2, k < 1), under a load, at 1 − M_R = 0.5, 10⁻⁴ and 10⁻¹²; beside it the
//! ellipse solve alone at 10⁻⁴ (`ellipse_gap=1e-4`: what the contact solution adds to it is the
//! difference); and J0 by the adaptive route at the k of the 10⁻⁴ case (`integrals` with
//! `Method::Adaptive`, the k-derivatives and J0: the five integrals from one evaluation of G a
//! node).
//! At MPFR 256 bits also the solve at 1 − M_R = 10⁻¹⁰⁰⁰ (k ≈ 10⁻²⁵⁰).
//!
//! Run: `cargo bench --bench contact -- --warm-up-time 1 --measurement-time 3`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};
use moving_hertz::{
    integrals, solve_ellipse, ContactProblem, IntegralOptions, Loading, Material, Method, Options,
};

fn run<T: Real>(c: &mut Criterion, label: &str, p: T::Prec, gaps: &[&str]) {
    let mut g = c.benchmark_group(format!("contact/{label}"));
    if T::bits(p) > 200 {
        g.sample_size(10);
    }
    let x = |s: &str| T::parse(s, p).expect("number");
    let mat = Material::new(x("0.3")).expect("material");
    for gap in gaps {
        let problem = ContactProblem {
            speed: mat.parse_gap(gap).expect("speed"),
            radius_along: x("0.05"),
            radius_across: x("0.1"),
            loading: Loading::Load(x("1000")),
            shear_modulus: x("80e9"),
        };
        let opts = Options::default();
        g.bench_function(format!("solve_gap={gap}"), |b| {
            b.iter(|| black_box(&problem).solve(&opts))
        });
    }
    let speed = mat.parse_gap("1e-4").expect("speed");
    let problem = ContactProblem {
        speed: speed.clone(),
        radius_along: x("0.05"),
        radius_across: x("0.1"),
        loading: Loading::Load(x("1000")),
        shear_modulus: x("80e9"),
    };
    let ratio = problem.radius_across.clone() / &problem.radius_along;
    let opts = Options::default();
    g.bench_function("ellipse_gap=1e-4", |b| {
        b.iter(|| solve_ellipse(black_box(&speed), black_box(&ratio), &opts))
    });
    let k = problem
        .solve(&Options::default())
        .expect("solve")
        .ellipse()
        .k()
        .value
        .clone();
    let adaptive = IntegralOptions {
        method: Method::Adaptive,
        derivatives: true,
        j0: true,
        ..Default::default()
    };
    g.bench_function("j0_gap=1e-4/contact_integrals", |b| {
        b.iter(|| integrals(black_box(&speed), black_box(&k), &adaptive))
    });
    g.finish();
}

fn bench(c: &mut Criterion) {
    let gaps = ["0.5", "1e-4", "1e-12"];
    run::<f64>(c, "f64", (), &gaps);
    run::<Dd>(c, "dd", (), &gaps);
    let p = MpPrec::new(256).expect("precision");
    run::<Mp>(c, "mpfr256", p, &["0.5", "1e-4", "1e-12", "1e-1000"]);
}

criterion_group!(benches, bench);
criterion_main!(benches);
