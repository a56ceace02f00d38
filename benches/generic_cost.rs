//! The cost of writing numerics once over `T: Real`: the AGM computation of K(m), written
//! generically and instantiated at `f64`, against the same kernel hand-written for `f64`.
//! Target: generic / hand-written ≤ 1.05.
//!
//! Two pairs are measured:
//! * `kernel`: the bare AGM loop with its three stopping rules (tolerance √ε, no progress, cap);
//! * `ellipk_mc`: the library function (argument checks, `Result`, overflow guard) against a
//!   hand-written `f64` replica of it. The library function and its kernel are marked
//!   `#[inline]`: without the hint the compiler kept them out of line in this harness, and the
//!   library call measured slower than the replica (the kernel pair, inlined either way, did
//!   not differ); docs/performance.md has the figures.
//!
//! Run: `cargo bench --bench generic_cost -- --warm-up-time 1 --measurement-time 3`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::numerics::elliptic::ellipk_mc;
use moving_hertz::scalar::Real;
use moving_hertz::{Error, Result};

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

/// Hand-written replica of `ellipk_mc::<f64>`: checks, kernel, typed errors.
fn ellipk_mc_f64(mc: f64) -> Result<f64> {
    if !mc.is_finite() {
        return Err(Error::NotFinite {
            name: "mc",
            value: format!("{mc:.16e}"),
        });
    }
    if mc <= 0.0 {
        return Err(Error::Domain {
            name: "mc",
            value: format!("{mc:.16e}"),
            bound: "mc > 0",
        });
    }
    match k_agm_f64(mc.sqrt()) {
        Some(k) if k.is_finite() => Ok(k),
        _ => Err(Error::NoConvergence {
            what: "AGM for K(m)",
            iterations: 74,
            reached: String::new(),
        }),
    }
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("generic_cost");
    for (label, mc) in [("mc=0.3", 0.3f64), ("mc=1e-12", 1e-12)] {
        let kc = mc.sqrt();
        assert_eq!(k_agm_generic(&kc), k_agm_f64(kc));
        assert_eq!(ellipk_mc(&mc).ok(), ellipk_mc_f64(mc).ok());
        g.bench_function(format!("kernel/generic/{label}"), |b| {
            b.iter(|| k_agm_generic::<f64>(black_box(&kc)))
        });
        g.bench_function(format!("kernel/hand/{label}"), |b| {
            b.iter(|| k_agm_f64(black_box(kc)))
        });
        g.bench_function(format!("ellipk_mc/library/{label}"), |b| {
            b.iter(|| ellipk_mc::<f64>(black_box(&mc)).ok())
        });
        g.bench_function(format!("ellipk_mc/hand/{label}"), |b| {
            b.iter(|| ellipk_mc_f64(black_box(mc)).ok())
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
