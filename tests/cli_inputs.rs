//! The command line's inputs and outputs at the edges (issue 15 item 4, issue 20 items 3, 5, 9):
//! values refused naming the option and quoting the text as typed, `--gap` the same speed as
//! `--speed`, inputs echoed as typed, `--digits`, the cap on `--repeat`, `--out` that creates
//! no directory tree, tolerances below the `f64` range, and a tolerance refused at a precision
//! that cannot meet it.

use rug::Float;
use std::path::PathBuf;
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .args(args)
        .output()
        .expect("the moving-hertz binary runs")
}

/// The JSON object of a run that must succeed.
fn json(args: &[&str]) -> serde_json::Value {
    let out = run(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

fn field<'a>(v: &'a serde_json::Value, key: &str) -> &'a str {
    v[key]
        .as_str()
        .unwrap_or_else(|| panic!("{key} missing or not a string in {v}"))
}

/// A refused run: exit code `code`, nothing on standard output, one line on standard error
/// holding every phrase of `wants`; returns that line.
fn refused(args: &[&str], code: i32, wants: &[&str]) -> String {
    let out = run(args);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(code), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?} printed to stdout");
    assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    for want in wants {
        assert!(err.contains(want), "{args:?}: {err:?} lacks {want:?}");
    }
    err
}

/// Issue 20 item 9: values as typed in every message, the option named, parse errors of
/// `integrals` included.
#[test]
fn refusals_name_the_option_and_quote_the_value_as_typed() {
    let e = |extra: &[&'static str]| {
        let mut v = vec!["ellipse", "--speed", "0.5", "--ratio", "0.5"];
        v.extend_from_slice(extra);
        v
    };
    // ν beyond the f64 range at 256 bits: quoted, not "inf".
    let msg = refused(
        &e(&["--nu", "1e400", "--precision", "256"]),
        2,
        &[
            "'--nu'",
            "'1e400'",
            "nu (Poisson's ratio) = 1e400",
            "(-1, 1/2]",
        ],
    );
    assert!(!msg.contains("inf"), "{msg}");
    // ν just above 1/2 at double-double: quoted in full, not rounded to 0.5.
    refused(
        &e(&["--nu", "0.5000000000000000001", "--precision", "dd"]),
        2,
        &["'--nu'", "= 0.5000000000000000001 is outside"],
    );
    // A ratio beyond the supported range: refused before any work, a short message, no page
    // of zeros — at 256 and 1024 bits (where the solve took minutes).
    for precision in ["256", "1024"] {
        refused(
            &[
                "ellipse",
                "--nu",
                "0.2",
                "--speed",
                "0.5",
                "--ratio",
                "1e-400",
                "--precision",
                precision,
            ],
            2,
            &["'--ratio'", "A1/B1 = R2/R1 = 1e-400", "[1e-100, 1e100]"],
        );
    }
    let msg = refused(
        &[
            "ellipse", "--nu", "0.2", "--speed", "0.5", "--ratio", "1e-300",
        ],
        2,
        &["A1/B1 = R2/R1 = 1e-300", "axis ratio k", "[1e-100, 1e100]"],
    );
    assert!(msg.len() < 300 && !msg.contains("0000000000"), "{msg}");
    // Values that do not fit the working precision are refused as such, not as inf or 0.
    refused(
        &[
            "ellipse", "--nu", "0.2", "--speed", "0.5", "--ratio", "1e400",
        ],
        2,
        &["'--ratio'", "'1e400'", "overflows f64"],
    );
    refused(
        &[
            "contact",
            "--nu",
            "0.3",
            "--speed",
            "0.5",
            "--r-along",
            "1e-400",
            "--r-across",
            "0.02",
            "--load",
            "1000",
            "--shear-modulus",
            "80e9",
        ],
        2,
        &["'--r-along'", "'1e-400'", "smallest normal number of f64"],
    );
    // Parse errors of every command name the option and quote the text.
    let int = |opt: &'static str, bad: &'static str| {
        let mut v = vec!["integrals"];
        for (o, good) in [("--nu", "0.2"), ("--speed", "0.5"), ("--k", "0.5")] {
            v.extend([o, if o == opt { bad } else { good }]);
        }
        if opt == "--tol" {
            v.extend(["--tol", bad]);
        }
        v
    };
    for (opt, bad) in [
        ("--nu", "0.2x"),
        ("--speed", "fast"),
        ("--k", "abc"),
        ("--tol", "1e-x"),
    ] {
        refused(&int(opt, bad), 2, &[opt, &format!("'{bad}'")]);
    }
    refused(
        &["integrals", "--nu", "0.2", "--gap", "0", "--k", "0.5"],
        2,
        &["'--gap'", "'0'", "(0, 1]"],
    );
    // A gap inside (0, 1] that rounds below the working precision's normal numbers: that bound,
    // not (0, 1].
    refused(
        &["integrals", "--nu", "0.2", "--gap", "1e-400", "--k", "0.5"],
        2,
        &[
            "'--gap'",
            "'1e-400'",
            "[the smallest normal number of the working precision, 1]",
        ],
    );
    // A method the ellipse solve cannot use: the library's refusal, against --method.
    refused(
        &e(&["--nu", "0.2", "--method", "series"]),
        2,
        &["'--method'", "'series'", "auto, adaptive or fixed"],
    );
    // A precision out of range names the bits as typed.
    refused(
        &e(&["--nu", "0.2", "--precision", "2000000"]),
        2,
        &["'--precision", "'2000000'", "2000000 bits"],
    );
}

/// Issue 20 item 5: a tolerance that cannot be met at the precision given is refused (the
/// library's Unreachable, exit 1), not reported as a success with a larger estimate.
#[test]
fn a_tolerance_beyond_the_precision_given_is_refused() {
    refused(
        &[
            "integrals",
            "--nu",
            "0.2",
            "--speed",
            "0.5",
            "--k",
            "0.5",
            "--tol",
            "1e-40",
            "--precision",
            "f64",
        ],
        1,
        &[
            "'--tol 1e-40'",
            "'--precision f64'",
            "cannot reach relative tolerance",
        ],
    );
    // The same tolerance at a precision that reaches it: met.
    let v = json(&[
        "integrals",
        "--nu",
        "0.2",
        "--speed",
        "0.5",
        "--k",
        "0.5",
        "--tol",
        "1e-40",
        "--precision",
        "256",
        "--json",
    ]);
    for key in ["I1_error", "I2_error"] {
        let e = Float::with_val(64, Float::parse(field(&v, key)).expect("a decimal"));
        assert!(e <= 1e-40, "{key} = {e}");
    }
}

/// Issue 20 item 3 and issue 15: `--tol` alone at tolerances below the f64 range (5e-324, the
/// smallest subnormal; 1e-308; 1e-400): the precision comes from the exponent, each bound meets
/// its tolerance, and the three results agree within the sum of their bounds.
#[test]
fn tolerances_below_the_f64_range() {
    let mut results = Vec::new();
    for tol in ["5e-324", "1e-308", "1e-400"] {
        let v = json(&[
            "integrals",
            "--nu",
            "0.2",
            "--speed",
            "0.5",
            "--k",
            "0.5",
            "--tol",
            tol,
            "--json",
        ]);
        let num = |key: &str| Float::with_val(1500, Float::parse(field(&v, key)).expect("decimal"));
        let t = num("I1_error").max(&num("I2_error"));
        assert!(
            t <= Float::with_val(64, Float::parse(tol).unwrap()),
            "{tol}: {t}"
        );
        let bits = field(&v, "bits").parse::<u32>().expect("bits");
        assert!(bits > 1000, "{tol}: {bits} bits");
        assert_eq!(field(&v["inputs"], "tol"), tol);
        results.push((num("I1"), num("I2"), t));
    }
    for i in 0..results.len() {
        for j in 0..i {
            let (a, b) = (&results[i], &results[j]);
            let bound = Float::with_val(1500, &a.2 + &b.2);
            for (x, y) in [(&a.0, &b.0), (&a.1, &b.1)] {
                let d = Float::with_val(1500, x - y).abs() / y;
                assert!(d <= bound, "results {i}, {j} differ by {d:e}");
            }
        }
    }
}

/// `--gap G` is the speed `--speed 1-G` (the same exact decimal): the same digits in every
/// command and at every precision.
#[test]
fn gap_is_the_same_speed_as_speed() {
    let cases: [(&str, &[&str], &[&str]); 3] = [
        (
            "ellipse",
            &["--ratio", "0.5"],
            &["k", "e", "I1", "I2", "k_error"],
        ),
        (
            "integrals",
            &["--k", "0.01"],
            &["I1", "I2", "I1_error", "route"],
        ),
        (
            "contact",
            &[
                "--r-along",
                "0.05",
                "--r-across",
                "0.02",
                "--load",
                "1000",
                "--shear-modulus",
                "80e9",
            ],
            &["a", "b", "k", "p0", "d0", "load", "a_error"],
        ),
    ];
    for (cmd, rest, keys) in cases {
        for precision in ["f64", "dd", "256"] {
            let go = |speed: [&str; 2]| {
                let mut v = vec![cmd, "--nu", "0.25", speed[0], speed[1]];
                v.extend_from_slice(rest);
                v.extend(["--precision", precision, "--json"]);
                json(&v)
            };
            let by_speed = go(["--speed", "0.999999999999"]);
            let by_gap = go(["--gap", "1e-12"]);
            for key in keys {
                assert_eq!(
                    field(&by_speed, key),
                    field(&by_gap, key),
                    "{cmd} at {precision}: {key}"
                );
            }
            assert_eq!(field(&by_gap["inputs"], "gap"), "1e-12");
            assert!(by_gap["inputs"].get("speed").is_none());
        }
    }
}

/// The inputs are echoed as typed, whatever the precision: `--ratio 5` at 1024 bits is `5` in
/// the summary and in the JSON, not 300 digits.
#[test]
fn inputs_are_echoed_as_typed() {
    let args = [
        "ellipse",
        "--nu",
        "0.2",
        "--speed",
        "0.9",
        "--ratio",
        "5",
        "--precision",
        "1024",
    ];
    let out = run(&args);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    let head = text.lines().next().unwrap_or("");
    assert_eq!(
        head,
        "contact ellipse (33) for A1/B1 = R2/R1 = 5, M_R = 0.9, nu = 0.2"
    );
    // Each result on its own line, in full: 1024 bits are 310 significant digits.
    let k_line = text.lines().nth(3).unwrap_or("").trim();
    assert!(k_line.len() > 310 && !k_line.contains(' '), "{k_line}");
    let v = json(&[&args[..], &["--json"]].concat());
    assert_eq!(v["inputs"]["ratio"], "5");
    assert_eq!(v["inputs"]["nu"], "0.2");
    assert_eq!(v["inputs"]["precision"], "mpfr1024");
    assert_eq!(field(&v, "k"), k_line);
}

/// `--digits N` prints each result correctly rounded to N significant digits (the full value
/// when N is more than the precision has), and is refused with `--json` and for N = 0.
#[test]
fn digits_shorten_the_printed_results() {
    let base = ["ellipse", "--nu", "0.2", "--speed", "0.9", "--ratio", "0.5"];
    let full = json(&[&base[..], &["--precision", "dd", "--json"]].concat());
    let values = |extra: &[&str]| -> Vec<String> {
        let out = run(&[&base[..], &["--precision", "dd"], extra].concat());
        assert!(out.status.success());
        String::from_utf8_lossy(&out.stdout)
            .lines()
            .filter(|l| l.starts_with("  "))
            .map(|l| l.trim().to_string())
            .collect()
    };
    let keys = ["k", "e", "I1", "I2"];
    for n in [1usize, 5, 12] {
        let short = values(&["--digits", &n.to_string()]);
        assert_eq!(short.len(), keys.len());
        for (key, s) in keys.iter().zip(&short) {
            let exact = Float::with_val(200, Float::parse(field(&full, key)).unwrap());
            let want = exact.to_string_radix(10, Some(n));
            assert_eq!(s, &want, "{key} to {n} digits");
        }
    }
    // More digits than double-double has: every digit, as without --digits.
    assert_eq!(values(&["--digits", "100"]), values(&[]));
    refused(
        &[&base[..], &["--digits", "5", "--json"]].concat(),
        2,
        &["'--digits <N>'", "'--json'"],
    );
    refused(
        &[&base[..], &["--digits", "0"]].concat(),
        2,
        &["'0'", "--digits"],
    );
}

/// Issue 20 item 9: `--repeat` is capped at 1000 (stated in the help) and a larger count is
/// refused before any work.
#[test]
fn repeat_is_capped() {
    let base = ["ellipse", "--nu", "0.2", "--speed", "0.9", "--ratio", "10"];
    for n in ["1001", "1000000000"] {
        refused(
            &[&base[..], &["--repeat", n]].concat(),
            2,
            &["'--repeat <N>'", &format!("'{n}'"), "1..=1000"],
        );
    }
    let v = json(&[&base[..], &["--repeat", "3", "--json"]].concat());
    assert_eq!(field(&v, "repeat"), "3");
}

/// A fresh directory under the system's temporary directory, removed when dropped.
struct TempDir(PathBuf);

impl TempDir {
    fn new(name: &str) -> TempDir {
        let dir = std::env::temp_dir().join(format!("moving-hertz-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir(&dir).expect("a temporary directory");
        TempDir(dir)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Issue 20 item 9: `fig2 --out` with a missing parent is refused before any work and creates
/// nothing; `study` the same.
#[test]
fn out_refuses_a_missing_parent() {
    let tmp = TempDir::new("out-refused");
    let missing = tmp.0.join("missing");
    let dir = missing.join("dir");
    let d = dir.to_str().expect("utf-8 path");
    refused(
        &["fig2", "--out", d],
        2,
        &["'--out'", &format!("'{d}'"), "does not exist"],
    );
    refused(
        &["study", "rayleigh", "--out", d],
        2,
        &["'--out'", "does not exist"],
    );
    assert!(!missing.exists(), "{} was created", missing.display());
}

/// Issue 20 item 9: `fig2 --nu " 0.3"` names its files after the trimmed text; a missing DIR
/// whose parent exists is created, with data/ and figures/ inside.
#[test]
fn fig2_names_files_after_the_trimmed_nu() {
    let tmp = TempDir::new("fig2");
    let out = tmp.0.join("out");
    let o = out.to_str().expect("utf-8 path");
    let run = run(&["fig2", "--nu", " 0.3", "--out", o]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let names = |sub: &str| -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(out.join(sub))
            .expect("the directory exists")
            .map(|e| e.expect("an entry").file_name().to_string_lossy().into())
            .collect();
        v.sort();
        v
    };
    assert_eq!(
        names("data"),
        [
            "fig2_e_vs_ratio_nu0.3_f64.csv",
            "fig2_e_vs_speed_nu0.3_f64.csv"
        ]
    );
    let figures = names("figures");
    assert!(!figures.is_empty());
    assert!(
        figures
            .iter()
            .all(|n| n.ends_with("_nu0.3_f64.svg") && !n.contains(' ')),
        "{figures:?}"
    );
}

/// A file of `fig2` that cannot be written (here a directory stands where the file goes) fails
/// the command with exit code 1 and one line naming that file, for a table and for a chart.
#[test]
fn a_file_that_cannot_be_written_is_named() {
    for file in ["data/fig2_e_vs_speed.csv", "figures/fig2_near_rayleigh.svg"] {
        let tmp = TempDir::new("unwritable");
        let blocked = tmp.0.join(file);
        std::fs::create_dir_all(&blocked).expect("a directory where the file goes");
        let o = tmp.0.to_str().expect("utf-8 path");
        let b = blocked.to_str().expect("utf-8 path");
        refused(&["fig2", "--out", o], 1, &["writing fig2 output", b]);
    }
}

/// Issue 20 item 4: a Poisson's ratio valid at the working precision but −1 when rounded to the
/// ladder's `f64` stage is solved, at 256 bits and at double-double, by `ellipse` and `contact`;
/// the 256-bit k agrees with the 512-bit solve of the same typed ν within its bound.
#[test]
fn a_nu_that_rounds_to_minus_one_at_f64_is_solved() {
    let nu = "-0.99999999999999999999999";
    let ell = |p: &str| {
        json(&[
            "ellipse",
            "--nu",
            nu,
            "--speed",
            "0.5",
            "--ratio",
            "0.5",
            "--precision",
            p,
            "--json",
        ])
    };
    let (lo, hi) = (ell("256"), ell("512"));
    let k = |v: &serde_json::Value| Float::with_val(600, Float::parse(field(v, "k")).unwrap());
    let err = ((k(&lo) - k(&hi)) / k(&hi)).abs().to_f64();
    let bound: f64 = field(&lo, "k_error").parse().unwrap();
    assert!(err <= bound, "k at 256 bits off by {err:e} > {bound:e}");
    assert_eq!(field(&ell("dd"), "precision"), "dd");
    let c = json(&[
        "contact",
        "--nu",
        nu,
        "--speed",
        "0.5",
        "--r-along",
        "1",
        "--r-across",
        "2",
        "--load",
        "1",
        "--shear-modulus",
        "1",
        "--precision",
        "256",
        "--json",
    ]);
    assert!(c.get("a").is_some(), "{c}");
}

/// Issue 20 item 8: a method's range of k is checked before any work — the adaptive subtracted
/// route at k = 8335 is refused as a usage error naming `--k` and the range.
#[test]
fn a_methods_range_of_k_is_checked_first() {
    refused(
        &[
            "integrals",
            "--nu",
            "0.2",
            "--speed",
            "0.5",
            "--k",
            "8335",
            "--tol",
            "1e-290",
            "--method",
            "adaptive-subtracted",
        ],
        2,
        &["'--k'", "8335", "(0, 1]", "adaptive-subtracted"],
    );
}
