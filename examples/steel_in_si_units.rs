//! Tutorial, step 6: the half-space in physical units — steel (E = 210 GPa, ν = 0.3,
//! ρ = 7850 kg/m³) under a punch with R1 = 5 cm along the motion and R2 = 2 cm across it, 1 kN,
//! sliding at V = 2000 m/s — at f64 and at 256 bits; a velocity above c_R is refused.
//!
//! Run: `cargo run --release --example steel_in_si_units`

use moving_hertz::prelude::*;
use moving_hertz::ContactSolution;

/// Steel at 2000 m/s from decimal text (SI units), at precision `p`: the solid, then the
/// solution.
fn solve<T: Real>(p: T::Prec) -> Result<(Solid<T>, ContactSolution<T>)> {
    let num = |text: &str| T::parse(text, p);
    let moduli = Moduli::Youngs {
        youngs_modulus: "210e9", // E (Pa)
        density: "7850",         // ρ (kg/m³)
    };
    let steel = Solid::<T>::parse("0.3", moduli, p)?; // ν = 0.3
    let problem = ContactProblem {
        speed: steel.parse_velocity("2000")?, // V (m/s)
        radius_along: num("0.05")?,           // R1 (m)
        radius_across: num("0.02")?,          // R2 (m)
        loading: Loading::Load(num("1000")?), // P (N)
        shear_modulus: steel.shear_modulus().cloned().expect("given by E"), // μ = E/(2(1 + ν))
    };
    let solution = problem.solve(&Options::default())?;
    Ok((steel, solution))
}

pub fn main() -> Result<()> {
    let (steel, lo) = solve::<f64>(())?;
    let (_, hi) = solve::<Mp>(MpPrec::new(256)?)?;
    let c1 = steel.c1().expect("nu < 1/2");
    println!(
        "wave speeds  c1 = {c1}, c2 = {}, c_R = {} m/s",
        steel.c2(),
        steel.c_r()
    );
    println!("speed        M_R = V/c_R = {}", lo.problem().speed.mr());
    println!("semi-axes    a = {} m", lo.a());
    println!("             a = {} m", hi.a());
    println!("             b = {} m", lo.b());
    println!("pressure     p0 = {} Pa", lo.p0());
    println!("approach     d0 = {} m", lo.d0());
    // Above c_R: a typed error naming V and c_R.
    println!("{}", steel.parse_velocity("3000").unwrap_err());
    Ok(())
}
