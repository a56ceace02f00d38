//! num-traits / num-complex interoperability of the Copy backends: `num_complex::Complex<Dd>`
//! multiplies and divides like the crate's `Complex<Dd>`; conversions round-trip.

use moving_hertz::prelude::*;
use num_traits::{FromPrimitive, Num, One, ToPrimitive, Zero};

#[test]
fn dd_satisfies_num_traits() {
    assert!(Zero::is_zero(&<Dd as Zero>::zero()) && <Dd as One>::one() == Dd::from_parts(1.0, 0.0));
    let a = <Dd as Num>::from_str_radix("0.2", 10).unwrap();
    assert_eq!(a, Dd::parse("0.2", ()).unwrap());
    assert!(<Dd as Num>::from_str_radix("0.2", 16).is_err());
    assert_eq!(
        Dd::from_u64(u64::MAX).unwrap().to_float(128),
        rug::Float::with_val(128, u64::MAX)
    );
    assert_eq!(
        ToPrimitive::to_f64(&<Dd as FromPrimitive>::from_f64(0.5).unwrap()),
        Some(0.5)
    );
    let r = Dd::parse("7.5", ()).unwrap() % Dd::parse("2", ()).unwrap();
    assert_eq!(r, Dd::parse("1.5", ()).unwrap());
}

#[test]
fn num_complex_arithmetic_matches_ours() {
    let ours_a = Complex::new(
        Dd::parse("0.3", ()).unwrap(),
        Dd::parse("-1.7", ()).unwrap(),
    );
    let ours_b = Complex::new(
        Dd::parse("2.25", ()).unwrap(),
        Dd::parse("0.125", ()).unwrap(),
    );
    let a: num_complex::Complex<Dd> = ours_a.clone().into();
    let b: num_complex::Complex<Dd> = ours_b.clone().into();
    let prod: Complex<Dd> = (a * b).into();
    let ours = ours_a.clone() * &ours_b;
    assert!(
        (prod.re - ours.re).abs() <= Dd::epsilon(())
            && (prod.im - ours.im).abs() <= Dd::epsilon(())
    );
    let quo: Complex<Dd> = (a / b).into();
    let ours = ours_a / &ours_b;
    let tol = Dd::epsilon(()).mul_i64(8);
    assert!((quo.re - ours.re).abs() <= tol && (quo.im - ours.im).abs() <= tol);
    let z: num_complex::Complex64 = Complex::new(1.5f64, -2.0).into();
    let back: Complex<f64> = z.into();
    assert_eq!(back, Complex::new(1.5, -2.0));
}
