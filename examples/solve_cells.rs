//! The ellipse solve (33) on the 12 cells of the cost target (ν = 0.25,
//! M_R ∈ {0.5, 0.99, 0.999, 0.9999} × A1/B1 ∈ {0.01, 0.5, 2}) at `f64`, double-double or
//! MPFR 256 bits: prints each cell's k, its bound and the evaluations, or runs one cell's warm
//! solve `REPEAT` times inside `measured`, for an instruction count by callgrind
//! (docs/calibration.md, docs/data/solve_cells_instructions.txt). Warm: the speed is made once,
//! so that its fixed-rule set-up (kept with the speed) is built by the first solve, outside
//! `measured`; precision `f64-fresh` makes the speed anew for each solve (a single solve at a
//! new speed, set-up included):
//!
//! ```text
//! cargo run --release --example solve_cells -- f64            # every cell's k
//! valgrind --tool=callgrind --toggle-collect='*measured*' \
//!     target/release/examples/solve_cells f64 3 10           # cell 3, 10 warm solves
//! ```

use moving_hertz::prelude::*;
use moving_hertz::solve_ellipse;

const SPEEDS: [&str; 4] = ["0.5", "0.99", "0.999", "0.9999"];
const RATIOS: [&str; 3] = ["0.01", "0.5", "2"];

/// The speed and ratio of cell `i` (speeds outer, ratios inner) at precision `p`.
fn cell<T: Real>(i: usize, p: T::Prec) -> Result<(Speed<T>, T)> {
    let speed = Material::<T>::parse("0.25", p)?.parse_speed(SPEEDS[i / RATIOS.len()])?;
    Ok((speed, T::parse(RATIOS[i % RATIOS.len()], p)?))
}

/// `n` warm solves of one cell (`fresh`: each at a speed made anew): the region callgrind
/// counts.
#[inline(never)]
fn measured<T: Real>(speed: &Speed<T>, ratio: &T, n: usize, fresh: bool) -> usize {
    let mut iterations = 0;
    for _ in 0..n {
        let new_speed = || speed.material().speed_from_gap(speed.gap().clone());
        let made = if fresh { new_speed().ok() } else { None };
        let speed = made.as_ref().unwrap_or(speed);
        let e = solve_ellipse(std::hint::black_box(speed), ratio, &Options::default());
        iterations += e.map_or(0, |e| e.iterations());
    }
    iterations
}

fn run<T: Real>(p: T::Prec, which: Option<usize>, repeat: usize, fresh: bool) -> Result<()> {
    let cells = match which {
        Some(i) => i..i + 1,
        None => 0..SPEEDS.len() * RATIOS.len(),
    };
    for i in cells {
        let (speed, ratio) = cell::<T>(i, p)?;
        let e = solve_ellipse(&speed, &ratio, &Options::default())?;
        println!(
            "M_R = {:>6}, A1/B1 = {:>4}: k = {} (bound {}, {} evaluations)",
            SPEEDS[i / RATIOS.len()],
            RATIOS[i % RATIOS.len()],
            e.k().value.to_float(T::bits(p)).to_string_radix(16, None),
            e.k().error,
            e.iterations()
        );
        if which.is_some() {
            measured(&speed, &ratio, repeat, fresh);
        }
    }
    Ok(())
}

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let which = args.get(1).and_then(|s| s.parse().ok());
    let repeat = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(10);
    match args.first().map(String::as_str).unwrap_or("f64") {
        "dd" => run::<Dd>((), which, repeat, false),
        "256" => run::<Mp>(MpPrec::new(256)?, which, repeat, false),
        "f64-fresh" => run::<f64>((), which, repeat, true),
        _ => run::<f64>((), which, repeat, false),
    }
}
