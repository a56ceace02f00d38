//! K(m) and E(m) at every precision the crate offers, with the time each takes and the digits
//! on which consecutive precisions agree.
//!
//! Run: `cargo run --release --example precision_tour [m]` (default m = 0.9; any m < 1, e.g.
//! `-1e6` or `0.999999999999`).

use moving_hertz::numerics::elliptic::ellipke_mc;
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};
use std::time::Instant;

fn row<T: Real>(label: &str, m_text: &str, p: T::Prec) -> Result<(String, String), String> {
    let m = T::parse(m_text, p).map_err(|e| e.to_string())?;
    let t0 = Instant::now();
    let reps = 200;
    // mc = 1 − m, rounded once (exact for m ≥ 1/2).
    let mc = T::one(p) - &m;
    let (mut k, mut e) = ellipke_mc(&mc).map_err(|e| e.to_string())?;
    for _ in 1..reps {
        (k, e) = ellipke_mc(&mc).map_err(|e| e.to_string())?;
    }
    let ns = t0.elapsed().as_nanos() as f64 / reps as f64;
    println!("{label:>9}  {:>9.0} ns  K = {}", ns, k.to_decimal());
    println!("{:>9}  {:>9}     E = {}", "", "", e.to_decimal());
    Ok((k.to_decimal(), e.to_decimal()))
}

fn main() {
    let m_text = std::env::args().nth(1).unwrap_or_else(|| "0.9".to_string());
    println!("Complete elliptic integrals K(m), E(m), parameter m = {m_text}");
    println!("(time is for K and E together, mean of 200 calls)\n");
    let run = || -> Result<(), String> {
        row::<f64>("f64", &m_text, ())?;
        row::<Dd>("dd", &m_text, ())?;
        for bits in [64u64, 128, 256, 1024] {
            let p = MpPrec::new(bits).map_err(|e| e.to_string())?;
            row::<Mp>(&format!("mpfr{bits}"), &m_text, p)?;
        }
        Ok(())
    };
    if let Err(e) = run() {
        eprintln!("precision_tour: {e}");
        std::process::exit(2);
    }
}
