//! What a speed keeps for its ellipse solves (the k = 1 probe's evaluation, its `f64` and
//! double-double copies for the precision ladder) changes no result: a solve at a speed that
//! has served other ratios returns the same k, e, I1, I2, bounds and evaluation count, bit for
//! bit, as the same solve at a speed made anew, at `f64`, double-double and 256 bits.

use moving_hertz::prelude::*;
use moving_hertz::solve_ellipse;

/// The solve's results as text, every digit (hex) of every value and bound.
fn fingerprint<T: Real>(speed: &Speed<T>, ratio: &T) -> String {
    let e = solve_ellipse(speed, ratio, &Options::default()).unwrap();
    let bits = T::bits(ratio.prec());
    let hex = |x: &T| x.to_float(bits).to_string_radix(16, None);
    let i = e.integrals();
    format!(
        "k {} ({}) e {} ({}) I1 {} ({}) I2 {} ({}) after {}",
        hex(&e.k().value),
        e.k().error,
        hex(&e.e().value),
        e.e().error,
        hex(&i.i1.value),
        i.i1.error,
        hex(&i.i2.value),
        i.i2.error,
        e.iterations()
    )
}

/// At each speed (the A1/B1 = 2 cells take the k = 1 probe; roots on both sides of k = 1),
/// each ratio solved at a fresh speed and at one speed that solved the others first.
fn cold_and_warm_agree<T: Real>(p: T::Prec) {
    let mat = Material::<T>::parse("0.25", p).unwrap();
    let ratios = ["2", "0.5", "0.01", "3", "20"];
    for mr in ["0.5", "0.99", "0.9999"] {
        let warm = mat.parse_speed(mr).unwrap();
        for r in ratios {
            fingerprint(&warm, &T::parse(r, p).unwrap());
        }
        for r in ratios {
            let ratio = T::parse(r, p).unwrap();
            let cold = fingerprint(&mat.parse_speed(mr).unwrap(), &ratio);
            let again = fingerprint(&warm, &ratio);
            assert_eq!(cold, again, "M_R = {mr}, A1/B1 = {r}, {} bits", T::bits(p));
        }
    }
}

#[test]
fn a_speed_that_kept_its_set_ups_gives_the_same_bits() {
    cold_and_warm_agree::<f64>(());
    cold_and_warm_agree::<Dd>(());
    cold_and_warm_agree::<Mp>(MpPrec::new(256).unwrap());
}
