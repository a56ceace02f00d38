//! Tutorial, step 1: one contact solution — a rigid punch (R1 = 5 cm along the motion, R2 = 2 cm
//! across it) pressed with 1 kN into a half-space with ν = 0.3, μ = 80 GPa, sliding at 0.9 times
//! the Rayleigh speed — at f64 and at 256 bits, every quantity with a bound on its relative error.
//!
//! Run: `cargo run --release --example contact_solution`

use moving_hertz::prelude::*;
use moving_hertz::ContactSolution;

/// The problem from decimal text, parsed at precision `p` of the scalar type `T`.
fn solve<T: Real>(p: T::Prec) -> Result<ContactSolution<T>> {
    let num = |text: &str| T::parse(text, p);
    let speed = Material::<T>::parse("0.3", p)?.parse_speed("0.9")?; // ν, then M_R = V/c_R
    let problem = ContactProblem {
        speed,
        radius_along: num("0.05")?,           // R1 (m), along the motion
        radius_across: num("0.02")?,          // R2 (m), across it
        loading: Loading::Load(num("1000")?), // P (N)
        shear_modulus: num("80e9")?,          // μ (Pa)
    };
    problem.solve(&Options::default())
}

pub fn main() -> Result<()> {
    let lo = solve::<f64>(())?;
    let hi = solve::<Mp>(MpPrec::new(256)?)?;
    println!("semi-axis along the motion  a  = {} m", lo.a());
    println!("                            a  = {} m", hi.a());
    println!("semi-axis across it         b  = {} m", lo.b());
    println!("axis ratio              k = b/a = {}", lo.k());
    // The eccentricity's bound is absolute (e vanishes for a circle): `BoundKind::Absolute`.
    println!("eccentricity                e  = {}", lo.e());
    println!("major axis {} the motion", lo.ellipse().major().label());
    println!("central pressure            p0 = {} Pa", lo.p0());
    println!("approach                    d0 = {} m", lo.d0());
    // The pressure field (9) at a point of the contact, (x along the motion, y across it); its
    // bound is relative to p0 (the pressure vanishes on the edge of the contact).
    let (x, y) = (0.2 * lo.a().value, 0.1 * lo.b().value);
    let p = lo.pressure(&x, &y)?;
    println!(
        "pressure at ({x:.3e}, {y:.3e}) = {} (error <= {} relative to p0) Pa",
        p.to_decimal(),
        p.error
    );
    Ok(())
}
