//! A convergence study from the library: how many terms the series (37) needs as the speed
//! approaches the Rayleigh speed, at f64 and at 256 bits, against the adaptive quadrature 64 bits
//! higher on the inputs as rounded to each precision — and the typed error the series returns
//! once its term cap is exceeded.
//!
//! Run: `cargo run --release --example series_convergence`

use moving_hertz::prelude::*;
use moving_hertz::{integrals, ExactInputs};

fn study<T: Real>(label: &str, p: T::Prec) -> Result<()> {
    println!("\n{label}: nu = 0.2, k = 0.3");
    println!(
        "{:>10} {:>8} {:>12} {:>12}",
        "M_R", "terms", "rel. error", "estimate"
    );
    let series = IntegralOptions {
        method: Method::Series,
        ..Default::default()
    };
    let adaptive = IntegralOptions {
        method: Method::Adaptive,
        ..Default::default()
    };
    let pw = MpPrec::new(Precision::of::<T>(p).bits() as u64 + 64)?;
    for mr in ["0.1", "0.5", "0.9", "0.99", "0.999", "0.9999"] {
        // The decimal inputs held exactly, rounded once to each precision.
        let inputs = ExactInputs::parse("0.2", mr, "0.3")?;
        let (speed, k) = inputs.at::<T>(p)?;
        // The reference: the adaptive quadrature 64 bits higher on the inputs as rounded to `p`
        // (an error estimate is for the inputs as represented at the working precision).
        let (speed_w, k_w) = inputs.rounded::<T>(p)?.at::<Mp>(pw)?;
        let r = integrals(&speed_w, &k_w, &adaptive)?;
        match integrals(&speed, &k, &series) {
            Ok(s) => {
                let rel = |got: &T, want: &Mp| {
                    let g = Mp::from_float(&got.to_float(pw.bits()), pw);
                    ((g - want) / want).abs().to_f64()
                };
                let err = rel(&s.i1.value, &r.i1.value).max(rel(&s.i2.value, &r.i2.value));
                println!(
                    "{mr:>10} {:>8} {:>12.2e} {:>12}",
                    s.work,
                    err,
                    s.i1.error.max(s.i2.error)
                );
            }
            Err(e) => println!("{mr:>10}   refused: {e}"),
        }
    }
    Ok(())
}

pub fn main() -> Result<()> {
    study::<f64>("f64", ())?;
    study::<Mp>("MPFR 256 bits", MpPrec::new(256)?)?;
    Ok(())
}
