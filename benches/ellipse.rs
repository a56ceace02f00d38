//! The ellipse solve (33) per precision, against the targets of issue 6: f64 ≤ 2 µs for any
//! M_R ≤ 0.9999, double-double ≤ 25× f64, MPFR 256 bits ≤ 2 ms. ν = 0.2, A1/B1 = 0.5; the
//! material and speed are built outside the timed call (they are per-problem constants).
//!
//! Group `ellipse_extreme/<precision>`: the default solve (`Options::default()`) at the ends of
//! the supported curvature ratios, A1/B1 = 10⁻¹⁰⁰ (k ≈ 10⁻⁵³, the fixed rule) and 10¹⁰⁰
//! (k ≈ 10⁵¹, the graded rule), beside A1/B1 = 0.5, at M_R = 0.5 and 1 − 10⁻¹⁰: what a solve at
//! an extreme input costs against a normal one.
//!
//! Group `ellipse_cells/f64`: the 12 cells of the cost target (ν = 0.25,
//! M_R ∈ {0.5, 0.99, 0.999, 0.9999} × A1/B1 ∈ {0.01, 0.5, 2}, the cells of
//! `examples/solve_cells.rs`), the warm solve (the speed made once, its fixed-rule set-up kept
//! with it); `ellipse_cells_fresh/f64` the same with the speed made anew in each iteration (its
//! set-up built again: a single solve at a new speed).
//!
//! Run: `cargo bench --bench ellipse -- --warm-up-time 1 --measurement-time 3`
//! (`-- ellipse_cells` for the cells only). The cells' medians, with the command that
//! regenerates them: docs/data/ellipse_cells_bench.txt.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};
use moving_hertz::{solve_ellipse, Material, Method, Options};

fn run<T: Real>(c: &mut Criterion, label: &str, p: T::Prec, methods: &[Method]) {
    let mut g = c.benchmark_group(format!("ellipse/{label}"));
    if T::bits(p) > 200 {
        g.sample_size(10);
    }
    let mat = Material::new(T::parse("0.2", p).expect("nu")).expect("material");
    let ratio = T::parse("0.5", p).expect("ratio");
    for mr in ["0.5", "0.9", "0.999", "0.9999"] {
        let sp = mat.speed(T::parse(mr, p).expect("speed")).expect("speed");
        for &method in methods {
            let opts = Options {
                method,
                ..Default::default()
            };
            g.bench_function(format!("{}_M={mr}", method.label()), |b| {
                b.iter(|| solve_ellipse(black_box(&sp), black_box(&ratio), &opts))
            });
        }
    }
    g.finish();
}

fn extreme<T: Real>(c: &mut Criterion, label: &str, p: T::Prec) {
    let mut g = c.benchmark_group(format!("ellipse_extreme/{label}"));
    if T::bits(p) > 200 {
        g.sample_size(10);
    }
    let mat = Material::new(T::parse("0.2", p).expect("nu")).expect("material");
    for gap in ["0.5", "1e-10"] {
        let sp = mat
            .speed_from_gap(T::parse(gap, p).expect("gap"))
            .expect("speed");
        for r in ["0.5", "1e-100", "1e100"] {
            let ratio = T::parse(r, p).expect("ratio");
            g.bench_function(format!("ratio={r}_gap={gap}"), |b| {
                b.iter(|| solve_ellipse(black_box(&sp), black_box(&ratio), &Options::default()))
            });
        }
    }
    g.finish();
}

fn cells(c: &mut Criterion) {
    let mat = Material::new(0.25f64).expect("material");
    for fresh in [false, true] {
        let name = if fresh {
            "ellipse_cells_fresh"
        } else {
            "ellipse_cells"
        };
        let mut g = c.benchmark_group(format!("{name}/f64"));
        for mr in ["0.5", "0.99", "0.999", "0.9999"] {
            let sp = mat.parse_speed(mr).expect("speed");
            for ratio in [0.01, 0.5, 2.0] {
                let opts = Options::default();
                g.bench_function(format!("M={mr}_ratio={ratio}"), |b| {
                    if fresh {
                        b.iter(|| {
                            let sp = mat.speed_from_gap(black_box(*sp.gap())).expect("speed");
                            solve_ellipse(&sp, black_box(&ratio), &opts)
                        })
                    } else {
                        b.iter(|| solve_ellipse(black_box(&sp), black_box(&ratio), &opts))
                    }
                });
            }
        }
        g.finish();
    }
}

fn bench(c: &mut Criterion) {
    cells(c);
    let both = [Method::Fixed, Method::Adaptive];
    run::<f64>(c, "f64", (), &both);
    run::<Dd>(c, "dd", (), &both);
    run::<Mp>(
        c,
        "mpfr256",
        MpPrec::new(256).expect("precision"),
        &[Method::Fixed],
    );
    extreme::<f64>(c, "f64", ());
    extreme::<Dd>(c, "dd", ());
    extreme::<Mp>(c, "mpfr256", MpPrec::new(256).expect("precision"));
}

criterion_group!(benches, bench);
criterion_main!(benches);
