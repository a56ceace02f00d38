//! Cost of the symbolic mode: F_0 … F_30(ν) by the recurrence (36) over rational functions of ν,
//! and α_n … δ_n(e²) for n ≤ 50 by the recursion (40) over rational functions of e² (each in
//! lowest terms; target: under 1 s each), beside the same recurrences over `rug::Rational` at one
//! rational point (ν = 1/4, e² = 3/4) for the cost ratio of a symbolic run to an exact numeric one.
//!
//! Run: `cargo bench --bench symbolic -- --warm-up-time 1 --measurement-time 5`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::routes::moments::KeForm;
use moving_hertz::routes::GreenSeries;
use moving_hertz::symbolic::{green_coefficients, moment_forms};
use rug::Rational;

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("symbolic");
    g.sample_size(20);
    g.bench_function("F_n(nu)/n<=30", |b| {
        b.iter(|| green_coefficients(black_box(30)).expect("F"))
    });
    g.bench_function("rational/F_n(1|4)/n<=30", |b| {
        b.iter(|| GreenSeries::new(black_box(&Rational::from((1, 4))), Rational::from(1)).take(31))
    });
    g.bench_function("alpha..delta(e2)/n<=50", |b| {
        b.iter(|| moment_forms(black_box(50)).expect("forms"))
    });
    g.bench_function("rational/alpha..delta(3|4)/n<=50", |b| {
        b.iter(|| {
            let mut f = KeForm::new(black_box(Rational::from((1, 4)))).expect("form");
            (0..=50).map(|_| f.next_term()).last()
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
