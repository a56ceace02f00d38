//! The half-space in physical units ([`Solid`]): μ, c1, c2, c_R and the speed of a velocity
//! against independent mpmath values (tests/data/solid_mpmath.csv, made by
//! tools/gen_solid.py) at f64, double-double and 256 bits; refusals at and above c_R; and the
//! identities between the ways of giving a half-space (E or μ, the moduli or the wave speeds,
//! text or values).

mod common;

use common::{mp, read_csv, reference, rel_eps};
use moving_hertz::physics::{Material, Moduli, Solid};
use moving_hertz::scalar::{Dd, Field, Mp, Real};
use moving_hertz::Error;
use rug::Float;

/// The half-space of a CSV row, from its text.
fn solid_of<T: Real>(row: &[String], p: T::Prec) -> moving_hertz::Result<Solid<T>> {
    let (a, b, c) = (row[1].as_str(), row[2].as_str(), row[3].as_str());
    match row[0].as_str() {
        "youngs" => Solid::parse(
            b,
            Moduli::Youngs {
                youngs_modulus: a,
                density: c,
            },
            p,
        ),
        "shear" => Solid::parse(
            b,
            Moduli::Shear {
                shear_modulus: a,
                density: c,
            },
            p,
        ),
        _ => Solid::parse_wave_speeds(a, b, p),
    }
}

/// Every row: ν, μ, c1, c2 within 1 ε (μ correctly rounded: ½ ε), c_R within 2 ε, and M_R,
/// 1 − M_R of the velocity within 2 ε — also the gaps of 10⁻³¹ of the velocities 30 digits
/// from c_R — or refused, naming c_R, where the reference's gap is negative.
fn against_mpmath<T: Real>(p: T::Prec, label: &str) {
    let rows = read_csv("solid_mpmath.csv");
    let mut worst = 0.0f64;
    for row in &rows[1..] {
        let at = format!(
            "{label}: {} {} {} {} V = {}",
            row[0], row[1], row[2], row[3], row[4]
        );
        let s = solid_of::<T>(row, p).unwrap_or_else(|e| panic!("{at}: {e}"));
        let mut check = |what: &str, got: Option<&T>, col: usize, bound: f64| {
            if row[col].is_empty() {
                assert!(got.is_none(), "{at}: {what} should be absent");
                return;
            }
            let (got, want) = (got.expect(what), reference(&row[col]));
            if want.is_zero() {
                assert!(got.is_zero(), "{at}: {what} should be 0");
                return;
            }
            let e = rel_eps(got, &want);
            assert!(e <= bound, "{at}: {what} off by {e} eps");
            worst = worst.max(e);
        };
        check("nu", Some(s.nu()), 5, 0.5);
        check("mu", s.shear_modulus(), 6, 0.5);
        check("c1", s.c1(), 7, 1.0);
        check("c2", Some(s.c2()), 8, 1.0);
        check("c_R", Some(s.c_r()), 9, 2.0);
        if row[11].starts_with('-') {
            let e = s.parse_velocity(&row[4]).expect_err(&at);
            let msg = e.to_string();
            let c_r = &row[9][..6].replace('.', "");
            assert!(matches!(e, Error::Domain { .. }), "{at}: {e:?}");
            assert!(
                msg.contains(&row[4]) && msg.contains("c_R = "),
                "{at}: {msg}"
            );
            assert!(msg.replace('.', "").contains(c_r.as_str()), "{at}: {msg}");
            continue;
        }
        let v = s
            .parse_velocity(&row[4])
            .unwrap_or_else(|e| panic!("{at}: {e}"));
        check("M_R", Some(v.mr()), 10, 2.0);
        check("1 - M_R", Some(v.gap()), 11, 2.0);
    }
    eprintln!("{label}: worst {worst:.2} eps over {} rows", rows.len() - 1);
}

#[test]
fn speeds_against_mpmath() {
    against_mpmath::<f64>((), "f64");
    against_mpmath::<Dd>((), "dd");
    against_mpmath::<Mp>(mp(256), "mpfr256");
}

/// At and above c_R a velocity is refused with a typed error naming V as given and c_R in m/s
/// (rounded down, so that the c_R shown is never above the V refused); just below it, the gap
/// is formed at the precision its cancellation needs.
#[test]
fn velocities_at_and_above_rayleigh_are_refused() {
    let steel = || {
        let m = Moduli::Youngs {
            youngs_modulus: "210e9",
            density: "7850",
        };
        Solid::<f64>::parse("0.3", m, ()).unwrap()
    };
    let s = steel();
    // c_R = 2974.8233958335301755… m/s (tests/data/solid_mpmath.csv).
    for v in ["3000", "2974.823395833530176", "1e300", "2974.83"] {
        let e = s.parse_velocity(v).unwrap_err();
        let msg = e.to_string();
        assert!(matches!(e, Error::Domain { .. }), "{v}: {e:?}");
        assert!(msg.contains(&format!("velocity V (m/s) = {v} ")), "{msg}");
        assert!(msg.contains("c_R = 2974.82339583 m/s"), "{msg}");
    }
    // Just below c_R: the last digit of V decides, and the gap keeps its digits.
    let v = s.parse_velocity("2974.823395833530175").unwrap();
    let gap = v.gap() * s.c_r();
    assert!((gap - 5.262118437922e-16).abs() < 1e-27, "{gap:e}");
    // The same refusal for a value of the working type, and for V < 0.
    let c_r = reference("2974.82339583353017552621184379");
    for v in [s.c_r().next_down(), *s.c_r(), s.c_r().next_up()] {
        let below = Float::with_val(64, v) < c_r;
        assert_eq!(s.speed_from_velocity(v).is_ok(), below, "{v}");
    }
    let neg = s.speed_from_velocity(-1.0).unwrap_err().to_string();
    assert!(
        neg.contains("velocity V (m/s) = -1") && neg.contains("[0, c_R)"),
        "{neg}"
    );
    assert!(matches!(
        s.speed_from_velocity(f64::NAN),
        Err(Error::NotFinite { .. })
    ));
    // At 256 bits, V within 10^-63 of c_R is still told apart (c_R to 70 digits).
    let m = Moduli::Youngs {
        youngs_modulus: "210e9",
        density: "7850",
    };
    let s256 = Solid::<Mp>::parse("0.3", m, mp(256)).unwrap();
    let below = "2974.823395833530175526211843792205079489660973984677591756773649423";
    let sp = s256.parse_velocity(below).unwrap();
    // Its gap 2.1e-67 against the same velocity at 1024 bits (the reference file's 100 digits
    // of c_R do not resolve it).
    let s1024 = Solid::<Mp>::parse("0.3", m, mp(1024)).unwrap();
    let want = s1024.parse_velocity(below).unwrap().gap().to_float(1024);
    let e = rel_eps(sp.gap(), &want);
    assert!(e <= 2.0, "gap {} off by {e} eps", sp.gap().to_f64());
    assert!(s256
        .parse_velocity("2974.823395833530175526211843792205079489660973984677591756773649424")
        .is_err());
}

/// Moduli and wave speeds outside their domains are refused naming the input as given.
#[test]
fn bad_moduli_are_refused() {
    let refuse = |r: moving_hertz::Result<Solid<f64>>, name: &str, text: &str| {
        let msg = r.unwrap_err().to_string();
        assert!(msg.contains(name) && msg.contains(text), "{msg}");
    };
    let youngs = |e, rho| Moduli::Youngs {
        youngs_modulus: e,
        density: rho,
    };
    refuse(
        Solid::parse("0.3", youngs("-2e11", "7850"), ()),
        "Young's modulus E (Pa)",
        "-2e11",
    );
    refuse(
        Solid::parse("0.3", youngs("2e11", "0"), ()),
        "density rho (kg/m^3)",
        "= 0 ",
    );
    refuse(
        Solid::parse("0.7", youngs("2e11", "1"), ()),
        "nu (Poisson's ratio)",
        "0.7",
    );
    refuse(
        Solid::parse("0.3", youngs("1e400", "1"), ()),
        "shear modulus mu (Pa)",
        "overflows f64",
    );
    refuse(Solid::parse_wave_speeds("2", "1.8", ()), "c2/c1", "1.8/2");
    refuse(
        Solid::parse_wave_speeds("2", "-1", ()),
        "shear wave speed c2 (m/s)",
        "-1",
    );
    refuse(Solid::from_wave_speeds(f64::INFINITY, 1.0), "c1", "inf");
    let mat = Material::new(0.3).unwrap();
    let shear = Moduli::Shear {
        shear_modulus: 8e10,
        density: -1.0,
    };
    refuse(Solid::new(&mat, shear), "density rho (kg/m^3)", "-1");
}

/// The ways of giving one half-space agree: E and μ = E/(2(1 + ν)) (as an exact fraction)
/// give the same bits; values of the working type give the bits their text gives when the
/// text is exact in it; the wave speeds (c1, c2) of a half-space give back its ν and c_R;
/// M_R = V/c_R for V = M·c_R.
fn identities<T: Real>(p: T::Prec, label: &str) {
    let num = |s: &str| T::parse(s, p).unwrap();
    for (e, nu, rho, mu_fraction) in [
        ("210e9", "0.3", "7850", "1050000000000/13"),
        ("70e9", "1/3", "2700", "26250000000"),
        ("1e9", "-0.5", "1000", "1000000000"),
        ("3e6", "0.5", "1100", "1000000"),
    ] {
        let at = format!("{label}: E = {e}, nu = {nu}, rho = {rho}");
        let by_e = Solid::<T>::parse(
            nu,
            Moduli::Youngs {
                youngs_modulus: e,
                density: rho,
            },
            p,
        )
        .unwrap();
        let by_mu = Solid::<T>::parse(
            nu,
            Moduli::Shear {
                shear_modulus: mu_fraction,
                density: rho,
            },
            p,
        )
        .unwrap();
        assert_eq!(by_e.shear_modulus(), by_mu.shear_modulus(), "{at}");
        assert_eq!(by_e.c2(), by_mu.c2(), "{at}");
        assert_eq!(by_e.c1(), by_mu.c1(), "{at}");
        assert_eq!(by_e.c_r(), by_mu.c_r(), "{at}");
        // Values of the working type: E and ρ are exact in every backend here.
        let mat = Material::<T>::parse(nu, p).unwrap();
        let by_value = Solid::new(
            &mat,
            Moduli::Youngs {
                youngs_modulus: num(e),
                density: num(rho),
            },
        )
        .unwrap();
        if !nu.contains('/') && nu != "0.3" {
            assert_eq!(by_value.c_r(), by_e.c_r(), "{at}");
        }
        // c_R/c2 is the material's √m1, and c2²·ρ = μ, to a few ε.
        let ratio = by_e.c_r().clone() / by_e.c2();
        assert!(
            common::rel_err_eps(&ratio, &by_e.material().cr_over_c2()) <= 4.0,
            "{at}"
        );
        let mu = by_e.c2().clone().square() * &num(rho);
        assert!(
            common::rel_err_eps(&mu, by_e.shear_modulus().unwrap()) <= 4.0,
            "{at}"
        );
        // Back from the wave speeds: ν and c_R.
        if let Some(c1) = by_e.c1() {
            let back = Solid::from_wave_speeds(c1.clone(), by_e.c2().clone()).unwrap();
            assert!(common::rel_err_eps(back.c_r(), by_e.c_r()) <= 8.0, "{at}");
            let dnu = (back.nu().clone() - by_e.nu()).abs() / &T::epsilon(p);
            assert!(
                dnu.to_f64() <= 16.0,
                "{at}: nu back off by {} eps",
                dnu.to_f64()
            );
        }
        // M_R = V/c_R.
        for m in ["0", "0.5", "0.99"] {
            let v = by_e.c_r().clone() * &num(m);
            let sp = by_e.speed_from_velocity(v).unwrap();
            let want = by_e.material().parse_speed(m).unwrap();
            assert!(
                common::rel_err_eps(sp.mr(), want.mr()) <= 2.0,
                "{at}: M_R = {m}"
            );
            assert!(
                common::rel_err_eps(sp.gap(), want.gap()) <= 200.0,
                "{at}: M_R = {m}"
            );
        }
    }
}

#[test]
fn ways_of_giving_a_half_space_agree() {
    identities::<f64>((), "f64");
    identities::<Dd>((), "dd");
    identities::<Mp>(mp(256), "mpfr256");
}
