//! The command line of issue 6, run as a user runs it (the built `moving-hertz` binary):
//! `ellipse` and `contact` print the library's results with every digit of the working precision
//! (JSON keys as specified, decimal strings; the route that ran under `route`, formerly
//! `method`), `--repeat` adds timings, decimal arguments are parsed at the working precision,
//! the summaries without `--json` name the axes and the units, and a bad argument prints one
//! line and exits non-zero.

use moving_hertz::prelude::*;
use moving_hertz::solve_ellipse;
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .args(args)
        .output()
        .expect("the moving-hertz binary runs")
}

/// The string fields at the top level of the CLI's JSON object (`inputs` and other nested
/// values left out).
fn fields(out: &Output) -> Vec<(String, String)> {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout.clone()).expect("utf-8");
    let body = text.trim();
    assert!(
        body.starts_with('{') && body.ends_with('}'),
        "not an object: {body}"
    );
    let value: serde_json::Value = serde_json::from_str(body).expect("valid JSON");
    value
        .as_object()
        .expect("an object")
        .iter()
        .filter_map(|(k, v)| Some((k.clone(), v.as_str()?.to_string())))
        .collect()
}

fn get<'a>(f: &'a [(String, String)], key: &str) -> &'a str {
    f.iter()
        .find(|(k, _)| k == key)
        .map(|(_, v)| v.as_str())
        .unwrap_or_else(|| panic!("key {key} missing from {f:?}"))
}

/// The inputs of the `contact` runs: ν, M_R, R1 (along), R2 (across), μ.
const CONTACT: [&str; 5] = ["0.3", "0.5", "0.05", "0.02", "80e9"];

/// `contact` with [`CONTACT`]'s inputs, `r_along` and `mu` replaced where given, the loading
/// flag and value, and `extra` arguments.
fn contact_args<'a>(
    r_along: Option<&'a str>,
    loading: Option<(&'a str, &'a str)>,
    mu: Option<&'a str>,
    extra: &[&'a str],
) -> Vec<&'a str> {
    let [nu, mr, r1, r2, mu0] = CONTACT;
    let mut v = vec!["contact", "--nu", nu, "--speed", mr, "--r-along"];
    v.extend([r_along.unwrap_or(r1), "--r-across", r2]);
    if let Some((flag, value)) = loading {
        v.extend([flag, value]);
    }
    v.extend(["--shear-modulus", mu.unwrap_or(mu0)]);
    v.extend_from_slice(extra);
    v
}

/// Significant digits of a decimal string such as "4.4305662497521886e-1".
fn digits(s: &str) -> usize {
    let mantissa = s.split(['e', 'E']).next().unwrap_or("");
    mantissa
        .chars()
        .filter(char::is_ascii_digit)
        .collect::<String>()
        .trim_start_matches('0')
        .len()
}

/// `ellipse --json` at one precision against the library's ladder on the same parsed inputs.
fn ellipse_matches<T: Real>(p: T::Prec, flag: &str, min_digits: usize) {
    let (nu, mr, ratio) = ("0.2", "0.9", "0.5");
    let out = run(&[
        "ellipse",
        "--nu",
        nu,
        "--speed",
        mr,
        "--ratio",
        ratio,
        "--precision",
        flag,
        "--json",
    ]);
    let f = fields(&out);
    let keys: Vec<&str> = f.iter().map(|(k, _)| k.as_str()).collect();
    for key in ["k", "e", "I1", "I2", "route", "precision", "error_estimate"] {
        assert!(keys.contains(&key), "{flag}: key {key} missing: {keys:?}");
    }
    let mat = Material::new(T::parse(nu, p).unwrap()).unwrap();
    let sp = mat.parse_speed(mr).unwrap();
    let lib = solve_ellipse(&sp, &T::parse(ratio, p).unwrap(), &Options::default()).unwrap();
    assert_eq!(get(&f, "k"), lib.k().to_decimal(), "{flag}: k");
    assert_eq!(get(&f, "e"), lib.e().to_decimal(), "{flag}: e");
    assert_eq!(get(&f, "I1"), lib.integrals().i1.to_decimal(), "{flag}: I1");
    assert_eq!(get(&f, "I2"), lib.integrals().i2.to_decimal(), "{flag}: I2");
    assert_eq!(get(&f, "route"), lib.integrals().route.label());
    for key in ["k", "e", "I1", "I2"] {
        let d = digits(get(&f, key));
        assert!(d >= min_digits, "{flag}: {key} has {d} digits");
    }
    let est: f64 = get(&f, "error_estimate").parse().expect("a number");
    let eps = T::epsilon(p).to_f64();
    assert!(est > 0.0 && est <= 100.0 * eps, "{flag}: estimate {est}");
}

#[test]
fn ellipse_json_is_the_library_result_with_every_digit() {
    ellipse_matches::<f64>((), "f64", 16);
    ellipse_matches::<Dd>((), "dd", 31);
    ellipse_matches::<Mp>(MpPrec::new(256).unwrap(), "256", 76);
}

#[test]
fn repeat_adds_the_median_and_the_minimum_time() {
    let out = run(&[
        "ellipse", "--nu", "0.2", "--speed", "0.9", "--ratio", "10", "--repeat", "5", "--json",
    ]);
    let f = fields(&out);
    let median: u64 = get(&f, "median_ns").parse().expect("an integer");
    let min: u64 = get(&f, "min_ns").parse().expect("an integer");
    assert!(min > 0 && min <= median, "min {min}, median {median}");
    let plain = fields(&run(&[
        "ellipse", "--nu", "0.2", "--speed", "0.9", "--ratio", "10", "--json",
    ]));
    assert!(plain.iter().all(|(k, _)| k != "median_ns" && k != "min_ns"));
    assert_eq!(get(&f, "k"), get(&plain, "k"));
}

/// `contact --json` with a load and with an approach against `ContactProblem::solve`.
fn contact_matches<T: Real>(p: T::Prec, flag: &str, loading: (&str, &str)) {
    let [nu, mr, r1, r2, mu] = CONTACT;
    let out = run(&contact_args(
        None,
        Some(loading),
        None,
        &["--precision", flag, "--json"],
    ));
    let f = fields(&out);
    let num = |t: &str| T::parse(t, p).unwrap();
    let mat = Material::new(num(nu)).unwrap();
    let sp = mat.parse_speed(mr).unwrap();
    let load = match loading.0 {
        "--load" => Loading::Load(num(loading.1)),
        _ => Loading::Approach(num(loading.1)),
    };
    let problem = ContactProblem {
        speed: sp,
        radius_along: num(r1),
        radius_across: num(r2),
        loading: load,
        shear_modulus: num(mu),
    };
    let lib = problem.solve(&Options::default()).unwrap();
    for (key, want) in [
        ("a", &lib.a().value),
        ("b", &lib.b().value),
        ("k", &lib.k().value),
        ("e", &lib.e().value),
        ("p0", &lib.p0().value),
        ("d0", &lib.d0().value),
        ("load", &lib.load().value),
    ] {
        assert_eq!(
            get(&f, key),
            want.to_decimal(),
            "{flag} {}: {key}",
            loading.0
        );
    }
    // a along the motion, b across: the punch is more curved across (R2 < R1), so b < a.
    assert!(lib.b().value < lib.a().value);
}

#[test]
fn contact_json_is_the_library_result() {
    contact_matches::<f64>((), "f64", ("--load", "1000"));
    contact_matches::<Dd>((), "dd", ("--approach", "7e-6"));
    contact_matches::<Mp>(MpPrec::new(256).unwrap(), "256", ("--load", "1000"));
}

/// "0.1" at 256 bits is the 256-bit number nearest 1/10, not the f64 0.1: the CLI's k is the
/// library's from the parsed decimal and differs from the one from the f64.
#[test]
fn decimal_arguments_are_parsed_at_the_working_precision() {
    let p = MpPrec::new(256).unwrap();
    let out = run(&[
        "ellipse",
        "--nu",
        "0.2",
        "--speed",
        "0.9",
        "--ratio",
        "0.1",
        "--precision",
        "256",
        "--json",
    ]);
    let k = get(&fields(&out), "k").to_string();
    let mat = Material::new(Mp::parse("0.2", p).unwrap()).unwrap();
    let sp = mat.parse_speed("0.9").unwrap();
    let solve = |ratio: Mp| {
        solve_ellipse(&sp, &ratio, &Options::default())
            .unwrap()
            .k()
            .to_decimal()
    };
    assert_eq!(k, solve(Mp::parse("0.1", p).unwrap()));
    assert_ne!(k, solve(Mp::from_f64(0.1, p)));
}

#[test]
fn summaries_name_the_axes_and_the_units() {
    let out = run(&["ellipse", "--nu", "0.2", "--speed", "0.9", "--ratio", "0.5"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("across/along the motion"), "{text}");
    assert!(text.contains("major axis along the motion"), "{text}");
    let out = run(&contact_args(None, Some(("--load", "1000")), None, &[]));
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for want in [
        "semi-axis along the motion",
        "semi-axis across the motion",
        "central pressure p0",
        "m, Pa, N",
    ] {
        assert!(text.contains(want), "{want:?} missing from {text}");
    }
}

/// Each bad argument: a non-zero exit, nothing on standard output, one line on standard error
/// that names what is wrong (the given text where there is one).
#[test]
fn a_bad_argument_prints_one_line_and_fails() {
    let ell = |extra: &[&'static str]| -> Vec<&'static str> {
        let mut v = vec!["ellipse", "--nu", "0.2", "--speed", "0.9", "--ratio", "0.5"];
        v.extend_from_slice(extra);
        v
    };
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["ellipse", "--nu", "0.7", "--speed", "0.9", "--ratio", "0.5"],
            "0.7",
        ),
        (
            vec!["ellipse", "--nu", "0.2", "--speed", "1", "--ratio", "0.5"],
            "1",
        ),
        (
            vec!["ellipse", "--nu", "0.2", "--speed", "0.9", "--ratio", "-2"],
            "-2",
        ),
        (
            vec!["ellipse", "--nu", "0.2", "--speed", "0.9", "--ratio", "nan"],
            "ratio",
        ),
        (
            vec!["ellipse", "--nu", "0.2", "--speed", "0.9", "--ratio", "abc"],
            "abc",
        ),
        (vec!["ellipse", "--nu", "0.2", "--speed", "0.9"], "ratio"),
        (ell(&["--precision", "10"]), "10"),
        (ell(&["--method", "bogus"]), "bogus"),
        (ell(&["--repeat", "x"]), "x"),
        (ell(&["--frobnicate"]), "frobnicate"),
        (contact_args(None, None, None, &[]), "--load"),
        (
            contact_args(Some("0"), Some(("--load", "1")), None, &[]),
            "0",
        ),
        (
            contact_args(None, Some(("--load", "1")), Some("-1"), &[]),
            "-1",
        ),
        (vec!["no-such-command"], "no-such-command"),
    ];
    for (args, named) in cases {
        let out = run(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?} succeeded");
        assert!(out.stdout.is_empty(), "{args:?} printed {:?}", out.stdout);
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(
            err.contains(named),
            "{args:?}: {err:?} does not name {named:?}"
        );
    }
}

/// `contact` in physical units (issue 46): steel from E, ν, ρ at V = 2000 m/s. c_R and M_R are
/// stated (JSON `c_r`, `mr`; text lines) against the mpmath values of tests/data/solid_mpmath.csv;
/// a, p0 and d0 are within their bounds of a 1024-bit library solve of the same inputs; E and
/// μ = E/(2(1 + ν)) typed as a fraction give the same bits; a velocity above c_R and a missing
/// density are refused (exit 2, one line naming the option and c_R).
#[test]
fn contact_in_physical_units() {
    let steel = |modulus: &[&str], speed: &[&str], extra: &[&str]| {
        let mut v = vec![
            "contact",
            "--nu",
            "0.3",
            "--r-along",
            "0.05",
            "--r-across",
            "0.02",
        ];
        v.extend_from_slice(&["--load", "1000"]);
        v.extend_from_slice(modulus);
        v.extend_from_slice(speed);
        v.extend_from_slice(extra);
        v.into_iter().map(String::from).collect::<Vec<_>>()
    };
    let strs = |v: &[String]| run(&v.iter().map(String::as_str).collect::<Vec<_>>());
    let by_velocity = ["--density", "7850", "--velocity", "2000"];
    let f = fields(&strs(&steel(
        &["--youngs-modulus", "210e9"],
        &by_velocity,
        &["--json"],
    )));
    let rel = |got: &str, want: &str| {
        let (g, w) = (got.parse::<f64>().unwrap(), want.parse::<f64>().unwrap());
        ((g - w) / w).abs()
    };
    // c_R = 2974.8233958335301755… m/s, M_R = 0.67230881765995063824… (mpmath).
    assert!(rel(get(&f, "c_r"), "2974.82339583353017552621184379") <= 2.0 * f64::EPSILON);
    assert!(rel(get(&f, "mr"), "0.672308817659950638248924148813") <= 2.0 * f64::EPSILON);
    // The same inputs at 1024 bits through the library.
    let p = MpPrec::new(1024).unwrap();
    let moduli = Moduli::Youngs {
        youngs_modulus: "210e9",
        density: "7850",
    };
    let solid = Solid::<Mp>::parse("0.3", moduli, p).unwrap();
    let num = |s: &str| Mp::parse(s, p).unwrap();
    let want = ContactProblem {
        speed: solid.parse_velocity("2000").unwrap(),
        radius_along: num("0.05"),
        radius_across: num("0.02"),
        loading: Loading::Load(num("1000")),
        shear_modulus: solid.shear_modulus().unwrap().clone(),
    }
    .solve(&Options::default())
    .unwrap();
    for (key, w) in [("a", want.a()), ("p0", want.p0()), ("d0", want.d0())] {
        let bound: f64 = get(&f, &format!("{key}_error")).parse().unwrap();
        let d = rel(get(&f, key), &w.value.to_decimal());
        assert!(d <= bound, "{key}: {d:e} > {bound:e}");
    }
    // μ = E/(2(1 + ν)) = 1050000000000/13 exactly, typed as μ: the same bits.
    let g = fields(&strs(&steel(
        &["--shear-modulus", "1050000000000/13"],
        &by_velocity,
        &["--json"],
    )));
    for key in ["c_r", "mr", "a", "b", "p0", "d0"] {
        assert_eq!(get(&f, key), get(&g, key), "{key}");
    }
    // The text summary states c_R and M_R.
    let out = strs(&steel(&["--youngs-modulus", "210e9"], &by_velocity, &[]));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("Rayleigh wave speed c_R (m/s):\n  2.97482339583353"),
        "{text}"
    );
    assert!(
        text.contains("speed M_R = V/c_R:\n  6.72308817659950"),
        "{text}"
    );
    // Refusals.
    for (args, named) in [
        (
            steel(
                &["--youngs-modulus", "210e9"],
                &["--density", "7850", "--velocity", "3000"],
                &[],
            ),
            vec!["'--velocity'", "3000", "c_R = 2974.82339583 m/s"],
        ),
        (
            steel(&["--youngs-modulus", "210e9"], &["--velocity", "2000"], &[]),
            vec!["--density"],
        ),
        (
            steel(
                &["--youngs-modulus", "210e9", "--shear-modulus", "8e10"],
                &["--speed", "0.5"],
                &[],
            ),
            vec!["--shear-modulus"],
        ),
        (
            steel(&["--youngs-modulus", "-1"], &["--speed", "0.5"], &[]),
            vec!["'--youngs-modulus'", "-1"],
        ),
        (
            steel(
                &["--shear-modulus", "8e10"],
                &["--density", "0", "--velocity", "1"],
                &[],
            ),
            vec!["'--density'", "0"],
        ),
    ] {
        let out = strs(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        for n in named {
            assert!(err.contains(n), "{args:?}: {err} does not name {n}");
        }
    }
}
