//! Tutorial, step 5: many points at once. The axis ratio k against A1/B1 (10⁻³ … 10³, 1,000
//! points log-spaced) at three speeds approaching c_R, given by their gaps 1 − M_R, solved by one
//! call of `sweep::ellipses` in double-double — in parallel, each root started from its
//! neighbours' — and one point given a ν outside (−1, 1/2] to show that it fails alone.
//!
//! Run: `cargo run --release --example sweep_curves`

use moving_hertz::prelude::*;
use moving_hertz::sweep::{self, EllipsePoint, SpeedGiven};

pub fn main() -> Result<()> {
    let x = |v: f64| Dd::from_f64(v, ());
    let ratios: Vec<Dd> = (0..1000)
        .map(|j| x(10f64.powf(-3.0 + 6.0 * j as f64 / 999.0)))
        .collect();
    let gaps = [1e-2, 1e-5, 1e-10].map(|g| SpeedGiven::Gap(x(g)));
    let mut points = EllipsePoint::grid(&[x(0.25)], &gaps, &ratios);
    points[1234].nu = x(0.7); // one invalid point in the middle
    let solved = sweep::ellipses(&points, &Options::default());

    for (curve, gap) in ["1e-2", "1e-5", "1e-10"].iter().enumerate() {
        println!("1 - M_R = {gap}:");
        for j in [0, 500, 999] {
            let (pt, r) = (&points[curve * 1000 + j], &solved[curve * 1000 + j]);
            let k = r.as_ref().map_err(Clone::clone)?;
            println!("  A1/B1 = {:<10.4e} k = {}", pt.ratio.to_f64(), k.k());
        }
    }
    let worst = solved
        .iter()
        .filter_map(|r| r.as_ref().ok())
        .map(|e| e.k().error)
        .fold(RelError::ZERO, RelError::max);
    let failed: Vec<String> = solved
        .iter()
        .enumerate()
        .filter_map(|(i, r)| r.as_ref().err().map(|e| format!("point {i}: {e}")))
        .collect();
    println!(
        "{} points, worst bound on k {worst}; failed: {failed:?}",
        solved.len()
    );
    Ok(())
}
