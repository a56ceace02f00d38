//! Decimal speeds near the Rayleigh speed are taken as typed: `ellipse --precision f64` with
//! `--speed` and with `--gap` gives k within 8 ε of an independent mpmath solve on the exact
//! decimal inputs (tests/data/rayleigh_gap.csv, written by tools/gen_rayleigh_gap.py), for
//! speeds up to 1 − 10⁻¹² — although k's condition number in M_R is ~M_R/(4(1 − M_R)), so that
//! rounding the speed to f64 first would cost up to 10¹¹ ε.

use std::process::Command;

fn k_from_cli(args: &[&str]) -> f64 {
    let out = Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .args(args)
        .args(["--precision", "f64", "--json"])
        .output()
        .expect("the moving-hertz binary runs");
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    v["k"].as_str().expect("k").parse().expect("a number")
}

#[test]
fn decimal_speeds_near_the_rayleigh_speed_meet_8_eps() {
    let data = include_str!("data/rayleigh_gap.csv");
    let mut cases = 0;
    let mut worst: f64 = 0.0;
    for line in data
        .lines()
        .filter(|l| !l.starts_with('#') && !l.is_empty())
    {
        let f: Vec<&str> = line.split(',').collect();
        let (nu, speed, gap, ratio) = (f[0], f[1], f[2], f[3]);
        let want: f64 = f[4].parse().expect("k");
        let base = ["ellipse", "--nu", nu, "--ratio", ratio];
        for input in [["--speed", speed], ["--gap", gap]] {
            let k = k_from_cli(&[&base[..], &input[..]].concat());
            let err = ((k - want) / want).abs() / f64::EPSILON;
            assert!(err <= 8.0, "nu={nu} {input:?} ratio={ratio}: {err:.1} eps");
            worst = worst.max(err);
            cases += 1;
        }
    }
    assert!(cases >= 40, "{cases} cases");
    println!("{cases} cases, worst {worst:.2} eps");
}
