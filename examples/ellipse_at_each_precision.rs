//! One library call — the shape of the contact ellipse — at f64, double-double and MPFR 256 bits,
//! with the inputs parsed from decimal text at each precision (the speed's gap 1 − M_R formed
//! exactly from its text).
//!
//! Run: `cargo run --release --example ellipse_at_each_precision`

use moving_hertz::prelude::*;
use moving_hertz::solve_ellipse;

/// ν = 0.2, M_R = 0.99, A1/B1 = 0.5 at precision `p` of backend `T`.
fn solve<T: Real>(label: &str, p: T::Prec) -> Result<()> {
    let speed = Material::<T>::parse("0.2", p)?.parse_speed("0.99")?;
    let shape = solve_ellipse(&speed, &T::parse("0.5", p)?, &Options::default())?;
    println!("{label:>9}: k = {}", shape.k().to_decimal());
    println!(
        "{:>9}  e = {}  (k's relative error <= {}, {} evaluations at this precision)",
        "",
        shape.e().to_decimal(),
        shape.k().error,
        shape.iterations()
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
