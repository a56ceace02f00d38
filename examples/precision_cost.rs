//! Tutorial, step 3: the cost of precision for one solve. The same ellipse solve (ν = 0.2,
//! M_R = 0.99, A1/B1 = 0.5) at f64, double-double and MPFR from 128 to 1024 bits (or up to the
//! bits given on the command line): the time of a first call (rules built) and of a warm call,
//! their ratio to f64, and the significant digits of k each precision shares with the next.
//! Wall-clock times on a loaded machine are indicative; docs/performance.md has criterion's.
//!
//! Run: `cargo run --release --example precision_cost [max_bits]`

use moving_hertz::prelude::*;
use moving_hertz::solve_ellipse;
use std::time::{Duration, Instant};

/// (first call, median warm call, k) at precision `p`.
fn time_solve<T: Real>(p: T::Prec) -> Result<(Duration, Duration, String)> {
    let speed = Material::<T>::parse("0.2", p)?.parse_speed("0.99")?;
    let ratio = T::parse("0.5", p)?;
    let opts = Options::default();
    let t0 = Instant::now();
    let k = solve_ellipse(&speed, &ratio, &opts)?.k().to_decimal();
    let first = t0.elapsed();
    let mut warm = Vec::new();
    let start = Instant::now();
    while warm.len() < 5 || (start.elapsed() < Duration::from_millis(200) && warm.len() < 10_000) {
        let t = Instant::now();
        solve_ellipse(&speed, &ratio, &opts)?;
        warm.push(t.elapsed());
    }
    warm.sort();
    Ok((first, warm[warm.len() / 2], k))
}

pub fn main() -> Result<()> {
    let max_bits: u64 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1024);
    let mut rows = vec![("f64".to_string(), time_solve::<f64>(())?)];
    rows.push(("dd".to_string(), time_solve::<Dd>(())?));
    let mut bits = 128;
    while bits <= max_bits {
        rows.push((
            format!("{bits} bits"),
            time_solve::<Mp>(MpPrec::new(bits)?)?,
        ));
        bits *= 2;
    }
    let base = rows[0].1 .1.as_secs_f64();
    println!(
        "{:>10} {:>12} {:>12} {:>9}  digits of k shared with the next precision",
        "precision", "first call", "warm call", "warm/f64"
    );
    for (i, (label, (first, warm, k))) in rows.iter().enumerate() {
        let shared = rows.get(i + 1).map_or("-".to_string(), |next| {
            let digits = |s: &str| {
                s.chars()
                    .take_while(|c| *c != 'e')
                    .filter(char::is_ascii_digit)
                    .collect::<Vec<_>>()
            };
            let (a, b) = (digits(k), digits(&next.1 .2));
            a.iter()
                .zip(&b)
                .take_while(|(x, y)| x == y)
                .count()
                .to_string()
        });
        println!(
            "{label:>10} {:>12.3?} {:>12.3?} {:>9.0}  {shared}",
            first,
            warm,
            warm.as_secs_f64() / base,
        );
    }
    Ok(())
}
