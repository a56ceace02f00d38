//! A convergence study from the library: how many terms the series (37) needs as the speed
//! approaches the Rayleigh speed, at f64 and at 256 bits, against the direct quadrature at twice
//! the precision (each backend's `Real::Wide`) — and the typed error it returns once the term cap
//! is exceeded.
//!
//! Run: `cargo run --release --example series_convergence`

use moving_hertz::physics::Material;
use moving_hertz::prelude::*;
use moving_hertz::routes::series::{integrals, SeriesOptions};
use moving_hertz::routes::{direct, AxisRatio};

fn study<T: Real>(label: &str, p: T::Prec) -> Result<()> {
    println!("\n{label}: nu = 0.2, k = 0.3");
    println!(
        "{:>10} {:>8} {:>12} {:>12}",
        "M_R", "terms", "rel. error", "estimate"
    );
    let pw = T::wide_prec(p);
    let mat = Material::new(T::parse("0.2", p)?)?;
    let axes = AxisRatio::new(T::parse("0.3", p)?)?;
    // The same (rounded) inputs at the wide precision, for the reference.
    let mat_w = Material::new(mat.nu().to_wide(pw))?;
    let axes_w = AxisRatio::new(axes.k.to_wide(pw))?;
    for mr in ["0.1", "0.5", "0.9", "0.99", "0.999", "0.9999"] {
        let speed = mat.speed(T::parse(mr, p)?)?;
        let speed_w = mat_w.speed(speed.mr.to_wide(pw))?;
        let r = direct::quadrature(&mat_w, &speed_w, &axes_w, &<T::Wide as Field>::zero(pw))?;
        match integrals(&mat, &speed, &axes, &SeriesOptions::default()) {
            Ok(s) => {
                // Errors measured at the wide precision.
                let (i1w, i2w) = (s.i1.to_wide(pw), s.i2.to_wide(pw));
                let err = ((i2w - &r.i2) / &r.i2)
                    .abs()
                    .max_of(((i1w - &r.i1) / &r.i1).abs());
                println!(
                    "{mr:>10} {:>8} {:>12.2e} {:>12.2e}",
                    s.work,
                    err.to_f64(),
                    s.error_estimate.to_f64()
                );
            }
            Err(e) => println!("{mr:>10}   refused: {e}"),
        }
    }
    Ok(())
}

fn main() -> Result<()> {
    study::<f64>("f64", ())?;
    study::<Mp>("MPFR 256 bits", MpPrec::new(256)?)?;
    Ok(())
}
