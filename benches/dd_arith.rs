//! Double-double arithmetic cost: our `Dd` against `twofloat::TwoFloat` used directly.
//!
//! On the default x86-64 target (no `fma` target feature) twofloat's multiply forms the exact
//! product with `f64::mul_add`, a call into libm's software fma; `Dd` uses Dekker's splitting
//! on processors without an FMA; with one it issues the hardware instruction, detected at run
//! time (group `dd_arith_fma-runtime`) or inlined when compiled with `-C target-feature=+fma` (or
//! `-C target-cpu=native`). Run both ways:
//!
//! ```text
//! cargo bench --bench dd_arith
//! RUSTFLAGS="-C target-cpu=native" cargo bench --bench dd_arith
//! ```
//!
//! Each benchmark runs a dependent chain of 64 operations (so latency, not throughput, is
//! measured, as in a recurrence).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use moving_hertz::scalar::Dd;
use twofloat::TwoFloat;

/// The `twofloat` value of a double-double (hi + lo exactly: the pair is normalised).
fn twofloat(x: Dd) -> TwoFloat {
    TwoFloat::new_add(x.hi(), x.lo())
}

const CHAIN: usize = 64;

fn bench(c: &mut Criterion) {
    // How `Dd` forms its exact products in this build on this processor.
    #[cfg(target_arch = "x86_64")]
    let runtime = std::arch::is_x86_feature_detected!("fma");
    #[cfg(not(target_arch = "x86_64"))]
    let runtime = false;
    let fma = if cfg!(target_feature = "fma") {
        "fma"
    } else if runtime {
        "fma-runtime"
    } else {
        "nofma"
    };
    let mut g = c.benchmark_group(format!("dd_arith_{fma}"));
    let a = Dd::from_parts(1.000_000_1, 1.0e-17);
    let b = Dd::from_parts(0.999_999_9, -3.0e-18);
    let ta = twofloat(a);
    let tb = twofloat(b);
    g.bench_function("mul/Dd", |bch| {
        bch.iter(|| {
            let mut x = black_box(a);
            let y = black_box(b);
            for _ in 0..CHAIN {
                x *= y;
            }
            x
        })
    });
    g.bench_function("mul/twofloat", |bch| {
        bch.iter(|| {
            let mut x = black_box(ta);
            let y = black_box(tb);
            for _ in 0..CHAIN {
                x *= y;
            }
            x
        })
    });
    g.bench_function("add/Dd", |bch| {
        bch.iter(|| {
            let mut x = black_box(a);
            let y = black_box(b);
            for _ in 0..CHAIN {
                x += y;
            }
            x
        })
    });
    g.bench_function("div/Dd", |bch| {
        bch.iter(|| {
            let mut x = black_box(a);
            let y = black_box(b);
            for _ in 0..CHAIN {
                x /= y;
            }
            x
        })
    });
    g.bench_function("div/twofloat(1e-16 accurate)", |bch| {
        bch.iter(|| {
            let mut x = black_box(ta);
            let y = black_box(tb);
            for _ in 0..CHAIN {
                x /= y;
            }
            x
        })
    });
    // Throughput: 64 independent products (as in a quadrature sum over nodes).
    let xs: Vec<Dd> = (0..CHAIN)
        .map(|i| Dd::from_parts(1.0 + i as f64 / 7.0, 1.0e-18 * i as f64))
        .collect();
    let txs: Vec<TwoFloat> = xs.iter().map(|&x| twofloat(x)).collect();
    g.bench_function("mul-throughput/Dd", |bch| {
        bch.iter(|| {
            let y = black_box(b);
            let mut out = [Dd::default(); CHAIN];
            for (o, x) in out.iter_mut().zip(black_box(&xs)) {
                *o = *x * y;
            }
            out
        })
    });
    g.bench_function("mul-throughput/twofloat", |bch| {
        bch.iter(|| {
            let y = black_box(tb);
            let mut out = [TwoFloat::default(); CHAIN];
            for (o, x) in out.iter_mut().zip(black_box(&txs)) {
                *o = *x * y;
            }
            out
        })
    });
    g.bench_function("mul/f64", |bch| {
        bch.iter(|| {
            let mut x = black_box(1.000_000_1f64);
            let y = black_box(0.999_999_9f64);
            for _ in 0..CHAIN {
                x *= y;
            }
            x
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
