//! The cost of writing numerics once over `T: Real`: the AGM computation of K(m) with its three
//! stopping rules (tolerance √ε, no progress, cap), written generically and instantiated at
//! `f64`, against the same kernel hand-written for `f64`.
//! Target: generic / hand-written ≤ 1.05.
//!
//! Run: `cargo bench --bench generic_cost -- --warm-up-time 1 --measurement-time 3`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::scalar::Real;

/// K = π / (2 AGM(1, kc)), generic.
fn k_agm_generic<T: Real>(kc: &T) -> Option<T> {
    let p = kc.prec();
    let tol = T::epsilon_root(p, 2);
    let half = T::from_ratio(1, 2, p);
    let (mut a, mut b) = (T::one(p), kc.clone());
    let mut prev: Option<T> = None;
    for _ in 0..64 + 2 * T::bits(p).ilog2() as usize {
        let gap = (a.clone() - &b).abs();
        let done = gap <= tol.clone() * &a || prev.as_ref().is_some_and(|g| gap > *g);
        let mean = (a.clone() + &b) * &half;
        if done {
            return Some(T::pi(p) * &half / mean);
        }
        b = (a * &b).sqrt();
        a = mean;
        prev = Some(gap);
    }
    None
}

/// The same kernel, hand-written for f64.
fn k_agm_f64(kc: f64) -> Option<f64> {
    let tol = 1.0 / 67108864.0; // 2^-26 = √ε
    let (mut a, mut b) = (1.0f64, kc);
    let mut prev = f64::INFINITY;
    for _ in 0..64 + 2 * 5 {
        let gap = (a - b).abs();
        let mean = 0.5 * (a + b);
        if gap <= tol * a || gap > prev {
            return Some(std::f64::consts::FRAC_PI_2 / mean);
        }
        b = (a * b).sqrt();
        a = mean;
        prev = gap;
    }
    None
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("generic_cost");
    for (label, mc) in [("mc=0.3", 0.3f64), ("mc=1e-12", 1e-12)] {
        let kc = mc.sqrt();
        assert_eq!(k_agm_generic(&kc), k_agm_f64(kc));
        g.bench_function(format!("kernel/generic/{label}"), |b| {
            b.iter(|| k_agm_generic::<f64>(black_box(&kc)))
        });
        g.bench_function(format!("kernel/hand/{label}"), |b| {
            b.iter(|| k_agm_f64(black_box(kc)))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
