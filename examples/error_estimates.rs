//! Tutorial, step 4: reading the error estimates. Every result carries a bound on its relative
//! error ([`RelError`]); this example checks the bounds of an f64 solve against a 256-bit one,
//! shows what "for the inputs as represented" means near the Rayleigh speed, asks for integrals
//! to a tolerance, and shows a request that cannot be met refused before any work.
//!
//! Run: `cargo run --release --example error_estimates`

use moving_hertz::prelude::*;
use moving_hertz::{integrals, integrals_to_tolerance, solve_ellipse, ExactInputs};

/// |x − reference|/|reference| as a bound-like number, x at any precision.
fn true_error<T: Real>(x: &T, reference: &Mp) -> RelError {
    let p = reference.prec();
    let x = Mp::from_float(&x.to_float(p.bits()), p);
    RelError::of(&((x - reference) / reference))
}

pub fn main() -> Result<()> {
    let p256 = MpPrec::new(256)?;
    let ratio = "0.5"; // A1/B1
    let k_of = |speed: Speed<Mp>| {
        solve_ellipse(&speed, &Mp::parse(ratio, p256)?, &Options::default()).map(|s| s.k().clone())
    };

    // 1. The speed typed as text: the gap 1 - M_R is formed exactly, so k is good to the decimal.
    let mat = Material::<f64>::parse("0.2", ())?;
    let solved = solve_ellipse(&mat.parse_speed("0.99999")?, &0.5, &Options::default())?;
    let k_text = solved.k();
    let k_ref = k_of(Material::<Mp>::parse("0.2", p256)?.parse_speed("0.99999")?)?;
    println!("M_R = 0.99999 from text: k = {}", k_text);
    println!(
        "   true error against 256 bits: {}",
        true_error(&k_text.value, &k_ref.value)
    );

    // 2. The speed as an f64 number: 0.99999 is not representable, and k's condition number in
    //    M_R is ~M_R/(4(1 - M_R)) = 25000 here. The bound is for the speed as represented.
    let solved_f64 = solve_ellipse(&mat.speed(0.99999)?, &0.5, &Options::default())?;
    let k_f64 = solved_f64.k();
    let exact_f64 = format!("{:.60}", rug::Float::with_val(53, 0.99999f64)); // exact
    let k_ref_f64 = k_of(Material::<Mp>::parse("0.2", p256)?.parse_speed(&exact_f64)?)?;
    println!("M_R = 0.99999 as an f64: k = {}", k_f64);
    println!(
        "   true error against the decimal 0.99999: {}",
        true_error(&k_f64.value, &k_ref.value)
    );
    println!(
        "   true error against the f64 {exact_f64}: {}",
        true_error(&k_f64.value, &k_ref_f64.value)
    );

    // 3. The integrals I1, I2 of (34) with their k-derivatives, each with its bound, and the
    //    route that ran (`j0: true` adds J0 of (32)).
    let speed = mat.parse_speed("0.9")?;
    let opts = IntegralOptions {
        derivatives: true,
        ..Default::default()
    };
    let r = integrals(&speed, &0.3, &opts)?;
    println!("I1 = {}\nI2 = {}\nroute: {}", r.i1, r.i2, r.route.label());
    if let Some(d1) = &r.di1_dk {
        println!("dI1/dk = {d1}");
    }

    // 4. A tolerance: the lowest precision whose bound meets it, from exact decimal inputs.
    let tol = RelError::parse("1e-40")?;
    let t = integrals_to_tolerance(&ExactInputs::parse("0.2", "0.9", "0.3")?, tol, Method::Auto)?;
    println!(
        "to 1e-40: {} bits, I1 bound {} (<= {tol})",
        t.precision.bits(),
        t.i1.error
    );

    // 5. A tolerance the working precision cannot meet is a typed error, before any work.
    let strict = IntegralOptions {
        tolerance: Some(RelError::parse("1e-20")?),
        ..Default::default()
    };
    match integrals(&speed, &0.3, &strict) {
        Ok(_) => println!("1e-20 at f64: unexpectedly met"),
        Err(e) => println!("1e-20 at f64: refused: {e}"),
    }
    Ok(())
}
