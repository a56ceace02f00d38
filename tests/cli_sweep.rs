//! `moving-hertz sweep`: one row a point in input order (ratio fastest), each k within its
//! bound of the `ellipse` command's for the same inputs, JSON lines with the same values,
//! ranges that hold their ends, domains refused before any work naming the option and the text,
//! and points refused by the solver carrying their errors in their rows across batches.

use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .args(args)
        .output()
        .expect("the moving-hertz binary runs")
}

fn stdout_of(args: &[&str]) -> String {
    let out = run(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// The CSV rows as maps from the header's names.
fn rows(csv: &str) -> Vec<std::collections::HashMap<String, String>> {
    let mut lines = csv.lines();
    let header: Vec<String> = lines
        .next()
        .expect("header")
        .split(',')
        .map(String::from)
        .collect();
    lines
        .map(|l| {
            header
                .iter()
                .cloned()
                .zip(l.split(',').map(String::from))
                .collect()
        })
        .collect()
}

/// k of the `ellipse` command and its bound.
fn ellipse_k(nu: &str, speed: (&str, &str), ratio: &str, precision: &str) -> (f64, f64) {
    let out = stdout_of(&[
        "ellipse",
        "--nu",
        nu,
        speed.0,
        speed.1,
        "--ratio",
        ratio,
        "--precision",
        precision,
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let num = |key: &str| v[key].as_str().expect(key).parse::<f64>().expect(key);
    (num("k"), num("k_error"))
}

#[test]
fn rows_in_input_order_as_the_ellipse_command() {
    let csv = stdout_of(&[
        "sweep",
        "--nu",
        "0.2,-0.5",
        "--speed",
        "0.5,0.9999999999",
        "--ratio",
        "0.01,1/4,30",
    ]);
    let rows = rows(&csv);
    assert_eq!(rows.len(), 12);
    let mut i = 0;
    for nu in ["0.2", "-0.5"] {
        for speed in ["0.5", "0.9999999999"] {
            for ratio in ["0.01", "1/4", "30"] {
                let r = &rows[i];
                assert_eq!(
                    (r["nu"].as_str(), r["speed"].as_str(), r["ratio"].as_str()),
                    (nu, speed, ratio)
                );
                let (k, bound) = (
                    r["k"].parse::<f64>().unwrap(),
                    r["k_error"].parse::<f64>().unwrap(),
                );
                let (want, want_bound) = ellipse_k(nu, ("--speed", speed), ratio, "f64");
                assert!(
                    (k / want - 1.0).abs() <= bound + want_bound,
                    "{r:?}: k {k} vs {want}"
                );
                assert!(r["error"].is_empty());
                i += 1;
            }
        }
    }
}

#[test]
fn json_lines_and_log_ranges_of_the_gap_at_256_bits() {
    let out = stdout_of(&[
        "sweep",
        "--nu",
        "0.25",
        "--gap",
        "log:1e-2:1e-10:3",
        "--ratio",
        "0.5",
        "--precision",
        "256",
        "--format",
        "jsonl",
    ]);
    let lines: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).expect("one JSON object a line"))
        .collect();
    assert_eq!(lines.len(), 3);
    for (v, gap) in lines.iter().zip(["1e-2", "1e-6", "1e-10"]) {
        let got: f64 = v["gap"].as_str().unwrap().parse().unwrap();
        let want: f64 = gap.parse().unwrap();
        assert!((got / want - 1.0).abs() < 1e-15, "gap {got} for {gap}");
        let k = rug::Float::with_val(300, rug::Float::parse(v["k"].as_str().unwrap()).unwrap());
        let out = stdout_of(&[
            "ellipse",
            "--nu",
            "0.25",
            "--gap",
            v["gap"].as_str().unwrap(),
            "--ratio",
            "0.5",
            "--precision",
            "256",
            "--json",
        ]);
        let e: serde_json::Value = serde_json::from_str(&out).unwrap();
        let want = rug::Float::with_val(300, rug::Float::parse(e["k"].as_str().unwrap()).unwrap());
        let rel = ((k - &want) / want).abs().to_f64();
        let bound: f64 = v["k_error"].as_str().unwrap().parse::<f64>().unwrap()
            + e["k_error"].as_str().unwrap().parse::<f64>().unwrap();
        assert!(rel <= bound, "{v}: relative difference {rel:e} > {bound:e}");
    }
}

#[test]
fn linear_ranges_hold_their_ends() {
    let csv = stdout_of(&[
        "sweep",
        "--nu",
        "lin:-0.5:0.5:5",
        "--speed",
        "0",
        "--ratio",
        "1",
    ]);
    let nus: Vec<f64> = rows(&csv)
        .iter()
        .map(|r| r["nu"].parse().unwrap())
        .collect();
    assert_eq!(nus, vec![-0.5, -0.25, 0.0, 0.25, 0.5]);
}

/// A refused run: exit code 2, nothing on standard output, one line naming `option` and `text`.
fn refused(args: &[&str], option: &str, text: &str) {
    let out = run(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains(option) && err.contains(text),
        "{args:?}: {err}"
    );
}

#[test]
fn domains_refused_before_any_work() {
    let base = ["sweep", "--speed", "0.5", "--ratio", "1"];
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        base.iter().copied().chain(extra.iter().copied()).collect()
    };
    refused(&with(&["--nu", "0.2,0.7"]), "--nu", "0.7");
    refused(&with(&["--nu", "lin:-1:0.5:4"]), "--nu", "-1");
    refused(
        &with(&["--nu", "0.5000000000000000001"]),
        "--nu",
        "0.5000000000000000001",
    );
    // Inside (-1, 1/2] exactly, but -1 at f64: refused with the text and what it rounds to
    // (double-double holds it, and solves it).
    refused(
        &with(&["--nu", "-0.99999999999999999,0.2"]),
        "--nu",
        "-0.99999999999999999 (rounds to -1 at f64)",
    );
    let dd = run(&with(&[
        "--nu",
        "-0.99999999999999999",
        "--precision",
        "dd",
    ]));
    assert_eq!(dd.status.code(), Some(0));
    refused(
        &["sweep", "--nu", "0.2", "--speed", "1", "--ratio", "1"],
        "--speed",
        "1",
    );
    refused(
        &["sweep", "--nu", "0.2", "--gap", "0,0.1", "--ratio", "1"],
        "--gap",
        "0",
    );
    refused(
        &[
            "sweep",
            "--nu",
            "0.2",
            "--speed",
            "0.5",
            "--ratio",
            "log:0:1:3",
        ],
        "--ratio",
        "log:0:1:3",
    );
    refused(
        &[
            "sweep", "--nu", "0.2", "--speed", "0.5", "--ratio", "1e-400",
        ],
        "--ratio",
        "1e-400",
    );
    refused(
        &[
            "sweep",
            "--nu",
            "0.2",
            "--speed",
            "0.5",
            "--ratio",
            "lin:1:2:1",
        ],
        "--ratio",
        "lin:1:2:1",
    );
    refused(
        &[
            "sweep",
            "--nu",
            "lin:0:0.5:10000",
            "--speed",
            "lin:0:0.9:10000",
            "--ratio",
            "1",
        ],
        "10000000",
        "points",
    );
}

/// A value the working precision cannot hold as a normal number is refused naming the option
/// and the text as typed — a range by its whole text and the point: a range's end of 1e-4000 at
/// `f64` is neither solved as a gap of 0 nor refused quoting its rounded value
/// '0.0000000000000000e0'.
#[test]
fn values_beyond_the_precision_name_the_text_as_typed() {
    let sweep = |nu: &'static str, speed: [&'static str; 2], ratio: &'static str| {
        vec!["sweep", "--nu", nu, speed[0], speed[1], "--ratio", ratio]
    };
    for (args, option, text) in [
        (
            sweep("0.2", ["--gap", "log:1e-4000:1:3"], "2"),
            "--gap",
            "'log:1e-4000:1:3'",
        ),
        (sweep("0.2", ["--gap", "1e-320"], "2"), "--gap", "'1e-320'"),
        (
            sweep("0.2", ["--speed", "0.5"], "log:1e-4000:1e4000:3"),
            "--ratio",
            "'log:1e-4000:1e4000:3'",
        ),
        (
            sweep("0.2", ["--speed", "0.5"], "lin:1e-4000:1:2"),
            "--ratio",
            "point 1 of 2",
        ),
        (sweep("1e-400", ["--speed", "0.5"], "2"), "--nu", "'1e-400'"),
    ] {
        refused(&args, option, text);
    }
    // Zero itself is a value, at any precision.
    let out = run(&sweep("lin:0:0.5:2", ["--speed", "lin:0:0.5:2"], "2"));
    assert_eq!(out.status.code(), Some(0));
}

/// A sweep of more points than one batch (1,024) and than one block (64), with points the
/// solver refuses in the middle (ratios beyond [1e-100, 1e100]): every row in input order, each
/// refused point's row with its error and no result, the exit code 1 with their count, and the
/// points on either side of a block's and of the batch's end as the `ellipse` command solves them.
#[test]
fn failed_points_across_batches_carry_their_errors() {
    let out = run(&[
        "sweep",
        "--nu",
        "0.2",
        "--speed",
        "0.5,0.9",
        "--ratio",
        "log:3e-151:3e149:601",
        "--format",
        "jsonl",
    ]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8(out.stdout).expect("UTF-8");
    let lines: Vec<serde_json::Value> = (stdout.lines())
        .map(|l| serde_json::from_str(l).expect("JSON"))
        .collect();
    assert_eq!(lines.len(), 1202);
    let mut failed = 0;
    for (i, v) in lines.iter().enumerate() {
        let (speed, j) = (["0.5", "0.9"][i / 601], i % 601);
        assert_eq!(
            (v["nu"].as_str(), v["speed"].as_str()),
            (Some("0.2"), Some(speed))
        );
        let ratio: f64 = v["ratio"].as_str().expect("ratio").parse().expect("number");
        let want = 3.0 * 10f64.powf(-151.0 + 0.5 * j as f64);
        assert!((ratio / want - 1.0).abs() < 1e-12, "row {i}: ratio {ratio}");
        if (1e-100..=1e100).contains(&ratio) {
            assert!(
                v.get("error").is_none() && v["k"].is_string(),
                "row {i}: {v}"
            );
        } else {
            failed += 1;
            assert!(v.get("k").is_none(), "row {i}: {v}");
            let error = v["error"].as_str().expect("an error");
            assert!(error.contains("outside its domain"), "row {i}: {error}");
        }
    }
    assert_eq!(failed, 2 * 201);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("402 of 1202 points failed"), "{stderr}");
    for i in [127, 128, 1023, 1024] {
        let v = &lines[i];
        let text = |key: &str| v[key].as_str().expect(key).to_string();
        let (k, bound): (f64, f64) = (
            text("k").parse().expect("k"),
            text("k_error").parse().expect("bound"),
        );
        let speed = text("speed");
        let (want, want_bound) = ellipse_k("0.2", ("--speed", &speed), &text("ratio"), "f64");
        assert!(
            (k / want - 1.0).abs() <= bound + want_bound,
            "row {i}: k {k} vs {want}"
        );
    }
}

/// A sweep whose reader goes away (`| head -1`) stops at its next write with exit code 1 and
/// the one-line message of a closed output, instead of solving every point: here 10⁷ points at
/// double-double, minutes of work, of which the reader takes the header and one row. A sweep
/// that went on would trip the watchdog (a minute).
#[test]
fn a_sweep_stops_when_its_reader_goes_away() {
    use std::io::{BufRead, BufReader};
    use std::process::{Command, Stdio};
    let mut child = Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .args(["sweep", "--nu", "0.25", "--gap", "log:1e-1:1e-8:1000"])
        .args(["--ratio", "log:1e-2:1e2:10000", "--precision", "dd"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let mut reader = BufReader::new(child.stdout.take().expect("stdout"));
    let (mut header, mut row) = (String::new(), String::new());
    reader.read_line(&mut header).expect("the header");
    reader.read_line(&mut row).expect("a row");
    assert!(header.starts_with("nu,gap,ratio,k,"), "{header}");
    assert!(row.starts_with("0.25,"), "{row}");
    drop(reader);
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait") {
            break status;
        }
        if start.elapsed() > std::time::Duration::from_secs(60) {
            let _ = child.kill();
            panic!("the sweep went on after its reader closed the pipe");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    let mut err = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().expect("stderr"), &mut err)
        .expect("stderr");
    assert_eq!(status.code(), Some(1), "{err}");
    let last = err.trim_end().lines().last().unwrap_or("");
    assert!(
        last.starts_with("moving-hertz: error: writing to standard output: "),
        "{err}"
    );
}

// `sweep contact`: the full contact solution over lists or ranges (issue 46 item 2).

/// The JSON lines of a `sweep contact` run, with its exit code and standard error.
fn contact_sweep(args: &[&str]) -> (Vec<serde_json::Value>, Option<i32>, String) {
    let out = run(&[&["sweep", "contact", "--format", "jsonl"][..], args].concat());
    let rows = String::from_utf8(out.stdout)
        .expect("UTF-8")
        .lines()
        .map(|l| serde_json::from_str(l).expect("one JSON object a line"))
        .collect();
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    (rows, out.status.code(), err)
}

/// The `contact` command's JSON for the inputs of a `sweep contact` row (its input keys, as
/// typed), with `extra` options (the density, the precision).
fn contact_of(row: &serde_json::Value, extra: &[&str]) -> serde_json::Value {
    let mut args = vec!["contact".to_string(), "--json".to_string()];
    for key in [
        "nu",
        "shear_modulus",
        "youngs_modulus",
        "speed",
        "gap",
        "velocity",
        "r_along",
        "r_across",
        "load",
        "approach",
    ] {
        // With --approach given, the row's `load` is a result, not an input.
        let given_load = key == "load" && row.get("approach").is_some();
        if let (Some(v), false) = (row.get(key), given_load) {
            args.push(format!("--{}", key.replace('_', "-")));
            args.push(v.as_str().expect("text").to_string());
        }
    }
    args.extend(extra.iter().map(|s| s.to_string()));
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    serde_json::from_str(&stdout_of(&args)).expect("JSON")
}

/// The result keys of a row: every key that is not an input.
const RESULT_KEYS: [&str; 19] = [
    "c_r",
    "mr",
    "a",
    "a_error",
    "b",
    "b_error",
    "k",
    "k_error",
    "e",
    "e_error",
    "major_axis",
    "p0",
    "p0_error",
    "d0",
    "d0_error",
    "load",
    "load_error",
    "route",
    "iterations",
];

/// One point swept alone is the `contact` command's solve of the same text: every result key
/// of its row carries the digits of `contact --json`, at f64, double-double and 256 bits, for
/// a speed given as M_R, as a gap and as a velocity (with E or μ), by load and by approach.
/// (The single solve is the independent path: it forms its inputs and solves on its own.)
#[test]
fn a_point_swept_alone_has_the_digits_of_the_contact_command() {
    let points: [&[&str]; 3] = [
        &[
            "--nu",
            "0.3",
            "--youngs-modulus",
            "210e9",
            "--density",
            "7850",
            "--velocity",
            "2000",
            "--r-along",
            "0.05",
            "--r-across",
            "0.02",
            "--load",
            "1000",
        ],
        &[
            "--nu",
            "1/3",
            "--shear-modulus",
            "26e9",
            "--gap",
            "1e-6",
            "--r-along",
            "0.01",
            "--r-across",
            "0.3",
            "--approach",
            "1e-5",
        ],
        &[
            "--nu",
            "0.25",
            "--youngs-modulus",
            "70.3e9",
            "--speed",
            "0.9",
            "--r-along",
            "2",
            "--r-across",
            "1",
            "--load",
            "50",
        ],
    ];
    for precision in ["f64", "dd", "256"] {
        for point in points {
            let args = [point, &["--precision", precision]].concat();
            let (rows, code, err) = contact_sweep(&args);
            assert_eq!(code, Some(0), "{args:?}: {err}");
            assert_eq!(rows.len(), 1);
            let row = &rows[0];
            let density = if point.contains(&"--density") {
                vec!["--density", "7850"]
            } else {
                vec![]
            };
            let want = contact_of(row, &[&density[..], &["--precision", precision]].concat());
            let mut compared = 0;
            for key in RESULT_KEYS {
                let given = |k: &str| row.get(k).is_some() && point.contains(&&*format!("--{k}"));
                if given(key) || (key == "iterations") {
                    continue;
                }
                match row.get(key) {
                    Some(v) => {
                        assert_eq!(v, &want[key], "{precision} {point:?}: {key}");
                        compared += 1;
                    }
                    None => assert!(
                        key.starts_with("c_r")
                            || key.starts_with("mr")
                            || key.starts_with("load")
                            || key.starts_with("d0"),
                        "{precision} {point:?}: {key} missing"
                    ),
                }
            }
            assert!(compared >= 14, "{precision} {point:?}: {compared} keys");
        }
    }
}

/// `x` of a row or of `contact`'s JSON.
fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key]
        .as_str()
        .unwrap_or_else(|| panic!("{key} in {v}"))
        .parse()
        .unwrap_or_else(|_| panic!("{key} in {v}"))
}

/// Every value of `row` within its bound plus `contact`'s of the `contact` command's (relative,
/// the eccentricity absolute), its route and axis the same.
fn within_bounds_of_contact(row: &serde_json::Value, want: &serde_json::Value) {
    for key in ["a", "b", "k", "e", "p0", "d0", "load"] {
        // The given load (or approach) is an input of the row, without a bound; every other
        // value must be there with its bound.
        let by_approach = row.get("approach").is_some();
        if (key == "load" && !by_approach) || (key == "d0" && by_approach) {
            continue;
        }
        let (g, w) = (num(row, key), num(want, key));
        let bound = num(row, &format!("{key}_error")) + num(want, &format!("{key}_error"));
        let d = if key == "e" {
            (g - w).abs()
        } else {
            (g / w - 1.0).abs()
        };
        assert!(d <= bound, "{key}: {g} vs {w} (bound {bound}) in {row}");
    }
    assert_eq!(row["major_axis"], want["major_axis"], "{row}");
}

/// A grid of 32 points over lists of every axis: the rows in input order (ν slowest, then the
/// modulus, the speed, R1, R2, the load fastest), each within its bounds of the `contact`
/// command's solve of the same text, at f64 and double-double.
#[test]
fn contact_rows_in_input_order_within_bounds_of_the_contact_command() {
    let axes: [(&str, &[&str]); 6] = [
        ("nu", &["0.25", "0.3"]),
        ("youngs_modulus", &["70e9", "210e9"]),
        ("speed", &["0", "0.9"]),
        ("r_along", &["0.05"]),
        ("r_across", &["0.02", "0.1"]),
        ("load", &["10", "1000"]),
    ];
    for precision in ["f64", "dd"] {
        let mut args = vec!["--precision".to_string(), precision.to_string()];
        for (key, values) in axes {
            args.push(format!("--{}", key.replace('_', "-")));
            args.push(values.join(","));
        }
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (rows, code, err) = contact_sweep(&args);
        assert_eq!(code, Some(0), "{err}");
        assert_eq!(rows.len(), 32);
        for (j, row) in rows.iter().enumerate() {
            let mut rest = j;
            for (key, values) in axes.iter().rev() {
                assert_eq!(row[*key], values[rest % values.len()], "row {j}: {key}");
                rest /= values.len();
            }
            let want = contact_of(row, &["--precision", precision]);
            within_bounds_of_contact(row, &want);
        }
    }
}

/// A CSV line's cells, a quoted cell (one with a comma or a quote) unquoted.
fn csv_cells(line: &str) -> Vec<String> {
    let (mut cells, mut cell, mut quoted) = (Vec::new(), String::new(), false);
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                cell.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => cells.push(std::mem::take(&mut cell)),
            _ => cell.push(c),
        }
    }
    cells.push(cell);
    cells
}

/// The steel of issue 46 (E = 210 GPa, ν = 0.3, ρ = 7850 kg/m³, R1 = 0.05 m, R2 = 0.02 m,
/// 1 kN) over velocities in m/s up to one above c_R = 2974.82 m/s, as CSV: c_R and M_R as the
/// `contact` command forms them (digit for digit), M_R·c_R = V, the other values within their
/// bounds of `contact`'s; the row of V = 3000 m/s carries an error naming c_R and V in m/s,
/// and the run exits 1 saying how many points failed.
#[test]
fn steel_over_velocities_up_to_one_above_the_rayleigh_speed() {
    let out = run(&[
        "sweep",
        "contact",
        "--nu",
        "0.3",
        "--youngs-modulus",
        "210e9",
        "--density",
        "7850",
        "--velocity",
        "0,1000,2000,2974.8,3000",
        "--r-along",
        "0.05",
        "--r-across",
        "0.02",
        "--load",
        "1000",
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("1 of 5 points failed"), "{err}");
    let csv = String::from_utf8(out.stdout).expect("UTF-8");
    let mut lines = csv.lines();
    let header = csv_cells(lines.next().expect("header"));
    let rows: Vec<serde_json::Value> = lines
        .map(|l| {
            let cells = csv_cells(l);
            assert_eq!(cells.len(), header.len(), "{l}");
            let pairs = header.iter().zip(cells).filter(|(_, v)| !v.is_empty());
            serde_json::Value::Object(pairs.map(|(k, v)| (k.clone(), v.into())).collect())
        })
        .collect();
    assert_eq!(rows.len(), 5);
    for (row, v) in rows.iter().zip([0.0, 1000.0, 2000.0, 2974.8, 3000.0]) {
        if v == 3000.0 {
            let e = row["error"].as_str().expect("an error");
            assert!(
                e.contains("V (m/s) = 3000") && e.contains("c_R = 2974.82339583 m/s"),
                "{e}"
            );
            assert!(row.get("a").is_none() && row.get("c_r").is_none(), "{row}");
            continue;
        }
        assert!(row.get("error").is_none(), "{row}");
        let want = contact_of(row, &["--density", "7850"]);
        assert_eq!(
            (&row["c_r"], &row["mr"]),
            (&want["c_r"], &want["mr"]),
            "V = {v}"
        );
        assert!(
            (num(row, "mr") * num(row, "c_r") - v).abs() <= 4e-16 * v,
            "{row}"
        );
        within_bounds_of_contact(row, &want);
    }
}

/// A list of shear moduli at one load: the sizes scale as the closed forms say (a, b ∝ μ^(-1/3),
/// p0 ∝ μ^(2/3), d0 ∝ μ^(-2/3); the shape k, e does not change), each within the rows' bounds;
/// μ doubling from row to row.
#[test]
fn a_list_of_moduli_scales_the_sizes_as_the_closed_forms() {
    let (rows, code, err) = contact_sweep(&[
        "--nu",
        "0.3",
        "--shear-modulus",
        "20e9,40e9,80e9,160e9",
        "--gap",
        "1e-3",
        "--r-along",
        "0.05",
        "--r-across",
        "0.02",
        "--load",
        "1000",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(rows.len(), 4);
    for (j, row) in rows.iter().enumerate().skip(1) {
        let first = &rows[0];
        for (key, power) in [
            ("a", -1.0),
            ("b", -1.0),
            ("p0", 2.0),
            ("d0", -2.0),
            ("k", 0.0),
        ] {
            let want = 2f64.powf(power * j as f64 / 3.0);
            let got = num(row, key) / num(first, key);
            let bound = num(row, &format!("{key}_error")) + num(first, &format!("{key}_error"));
            assert!(
                (got / want - 1.0).abs() <= bound + 4e-16,
                "{key} at mu = {}: {got} vs {want}",
                row["shear_modulus"]
            );
        }
    }
}

/// `sweep contact` whose reader goes away stops at its next write with exit code 1 and the
/// one-line message of a closed output: 10⁷ points at double-double, of which the reader takes
/// the header and one row.
#[test]
fn a_contact_sweep_stops_when_its_reader_goes_away() {
    use std::io::{BufRead, BufReader};
    use std::process::{Command, Stdio};
    let mut child = Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .args([
            "sweep",
            "contact",
            "--nu",
            "0.25",
            "--shear-modulus",
            "80e9",
        ])
        .args(["--gap", "log:1e-1:1e-8:1000", "--r-along", "1"])
        .args([
            "--r-across",
            "log:1e-2:1e2:10000",
            "--load",
            "1",
            "--precision",
            "dd",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let mut reader = BufReader::new(child.stdout.take().expect("stdout"));
    let (mut header, mut row) = (String::new(), String::new());
    reader.read_line(&mut header).expect("the header");
    reader.read_line(&mut row).expect("a row");
    assert!(
        header.starts_with("nu,shear_modulus,gap,r_along,r_across,load,a,"),
        "{header}"
    );
    assert!(row.starts_with("0.25,80e9,"), "{row}");
    drop(reader);
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait") {
            break status;
        }
        if start.elapsed() > std::time::Duration::from_secs(60) {
            let _ = child.kill();
            panic!("the sweep went on after its reader closed the pipe");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    let mut err = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().expect("stderr"), &mut err)
        .expect("stderr");
    assert_eq!(status.code(), Some(1), "{err}");
    let last = err.trim_end().lines().last().unwrap_or("");
    assert!(
        last.starts_with("moving-hertz: error: writing to standard output: "),
        "{err}"
    );
}
