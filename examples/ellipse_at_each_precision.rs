//! One library call — the shape of the contact ellipse — at f64, double-double and MPFR 256 bits,
//! with the inputs parsed from decimal text at each precision.
//!
//! Run: `cargo run --release --example ellipse_at_each_precision`

use moving_hertz::contact::solve_ellipse_ladder;
use moving_hertz::physics::Material;
use moving_hertz::prelude::*;

/// ν = 0.2, M_R = 0.99, A1/B1 = 0.5 at precision `p` of backend `T`.
fn solve<T: Real>(label: &str, p: T::Prec) -> Result<()> {
    let mat = Material::new(T::parse("0.2", p)?)?;
    let speed = mat.speed(T::parse("0.99", p)?)?;
    let shape = solve_ellipse_ladder(&mat, &speed, &T::parse("0.5", p)?)?;
    println!("{label:>9}: k = {}", shape.k.to_decimal());
    println!(
        "{:>9}  e = {}  (error estimate {:.1e}, {} Newton steps)",
        "",
        shape.e.to_decimal(),
        shape.error_estimate.to_f64(),
        shape.iterations
    );
    Ok(())
}

fn main() -> Result<()> {
    println!("Contact ellipse for nu = 0.2, M_R = 0.99, A1/B1 = 0.5 (a along the motion, k = b/a)");
    solve::<f64>("f64", ())?;
    solve::<Dd>("dd", ())?;
    solve::<Mp>("mpfr256", MpPrec::new(256)?)?;
    Ok(())
}
