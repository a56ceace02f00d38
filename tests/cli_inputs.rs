//! The command line's inputs and outputs at the edges (issue 15 item 4, issue 20 items 3, 5, 9):
//! values refused naming the option and quoting the text as typed, `--gap` the same speed as
//! `--speed`, inputs echoed as typed, `--digits`, the cap on `--repeat`, `--out` that creates
//! no directory tree, tolerances below the `f64` range, and a tolerance refused at a precision
//! that cannot meet it.

use rug::ops::Pow;
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
        &["'--method <METHOD>'", "'series'", "auto, adaptive, fixed"],
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
    // The same value in the text (scientific notation) and the JSON.
    let at = |s: &str| Float::with_val(1100, Float::parse(s).expect("a number"));
    assert_eq!(at(field(&v, "k")), at(k_line));
}

/// `--digits N` prints each result correctly rounded to N significant digits in scientific
/// notation (every digit when N is more than the precision has), and is refused with `--json`
/// and for N = 0.
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
            assert_rounded(s, &exact, n);
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

/// `s` is `d.ddd…e±x` with `n` significant digits (a nonzero first digit) and within half a
/// unit of its last digit of `exact`.
fn assert_rounded(s: &str, exact: &Float, n: usize) {
    let (mantissa, exp) = s
        .split_once('e')
        .unwrap_or_else(|| panic!("{s}: no exponent"));
    let digits = mantissa.trim_start_matches('-').replace('.', "");
    assert_eq!(digits.len(), n, "{s}: {n} digits");
    let point = mantissa.find('.').unwrap_or(mantissa.len());
    assert!(
        !digits.starts_with('0') && point == 1 + usize::from(mantissa.starts_with('-')),
        "{s}: one nonzero digit before the point"
    );
    let exp: i32 = exp.parse().unwrap_or_else(|_| panic!("{s}: exponent"));
    let printed = Float::with_val(600, Float::parse(s).expect("a number"));
    let ulp = Float::with_val(600, 10).pow(exp - n as i32 + 1);
    let off = Float::with_val(600, &printed - exact).abs();
    assert!(off <= ulp / 2u32, "{s} is not {exact} to {n} digits");
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

/// The commands, `help` and `--version`, each with arguments that succeed (`fig2` and `study`
/// write under `dir`).
fn every_command(dir: &str) -> Vec<Vec<String>> {
    let ell = "ellipse --nu 0.2 --speed 0.5 --ratio 0.5";
    let contact = "contact --nu 0.3 --speed 0.5 --r-along 0.05 --r-across 0.02 --load 1000 \
                   --shear-modulus 80e9";
    [
        "rayleigh --nu 0.25",
        "integrals --nu 0.2 --speed 0.5 --k 0.5",
        ell,
        contact,
        "sweep --nu 0.2 --speed 0.5 --ratio 0.5,2",
        "symbolic coefficients --n 5",
        "symbolic moments --n 5",
        "symbolic condition --n 5",
        "completions bash",
        "help",
        "help contact",
        "contact --help",
        "--version",
        &format!("fig2 --out {dir}"),
        &format!("study rayleigh --out {dir}"),
    ]
    .iter()
    .map(|c| c.split_whitespace().map(String::from).collect())
    .collect()
}

/// Issue 46 item 5: standard output closed by its reader (`| head -1`, here before the first
/// write) or full (`> /dev/full`) stops every command, `help` and `--version` with exit code 1
/// and one line, `writing to standard output: …`, on standard error; no panic.
#[test]
fn a_closed_or_full_output_is_one_line_and_exit_1() {
    let tmp = TempDir::new("closed-output");
    let d = tmp.0.to_str().expect("utf-8 path");
    for args in every_command(d) {
        for how in ["closed", "full"] {
            let stdout = match how {
                "closed" => {
                    let (reader, writer) = std::io::pipe().expect("a pipe");
                    drop(reader);
                    std::process::Stdio::from(writer)
                }
                _ => std::fs::OpenOptions::new()
                    .write(true)
                    .open("/dev/full")
                    .expect("/dev/full")
                    .into(),
            };
            let out = Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
                .args(&args)
                .stdout(stdout)
                .output()
                .expect("the binary runs");
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(1), "{args:?} {how}: {err}");
            assert!(!err.contains("panicked"), "{args:?} {how}: {err}");
            let last = err.trim_end().lines().last().unwrap_or("");
            assert!(
                last.starts_with("moving-hertz: error: writing to standard output: "),
                "{args:?} {how}: {err}"
            );
            // Only `study` prints notes of its progress before.
            if args[0] != "study" {
                assert_eq!(err.trim_end().lines().count(), 1, "{args:?} {how}: {err}");
            }
        }
    }
}

/// Issue 46 item 5: an input of 100,000 digits is quoted cut to its ends and length, in the
/// refusals of the command and of clap's parse, not echoed in full twice.
#[test]
fn long_inputs_are_cut_in_messages() {
    let long = format!("1{}", "2".repeat(99_999));
    let bad = format!("{long}x");
    for (args, length) in [
        (
            vec!["rayleigh", "--nu", long.as_str()],
            "(100000 characters)",
        ),
        (
            vec!["rayleigh", "--nu", bad.as_str()],
            "(100001 characters)",
        ),
        (
            vec!["ellipse", "--nu", "0.2", "--speed", "0.5", "--ratio", &long],
            "(100000 characters)",
        ),
    ] {
        let msg = refused(&args, 2, &["'--", "1222222222", length]);
        assert!(msg.len() < 600, "{} characters: {msg}", msg.len());
    }
}

/// Issue 46 item 5: counts too large for 64 bits are said in words (the series' terms at
/// 1 - M_R = 1e-300) or in full (a sweep of 10^21 points), never as 18446744073709551615.
#[test]
fn counts_that_do_not_fit_are_said_in_words() {
    let msg = refused(
        &[
            "integrals",
            "--nu",
            "0.5",
            "--gap",
            "1e-300",
            "--k",
            "2",
            "--method",
            "series",
        ],
        1,
        &["more terms than a 64-bit count holds", "100000"],
    );
    assert!(!msg.contains("18446744073709551615"), "{msg}");
    let msg = refused(
        &[
            "sweep",
            "--nu",
            "lin:0:0.5:10000000",
            "--speed",
            "lin:0:0.5:10000000",
            "--ratio",
            "lin:1:2:10000000",
        ],
        2,
        &["1000000000000000000000 points", "10000000"],
    );
    assert!(!msg.contains("18446744073709551615"), "{msg}");
}

/// Issue 46 item 5: radii whose ratio R2/R1 overflows or underflows the working precision are
/// refused before any work saying so, naming both options (not "A1/B1 = 0" or "inf is not
/// finite"); at 256 bits the same ratio is inside the exponent range and meets the solve's own
/// range, still a refusal (exit code 2).
#[test]
fn a_derived_ratio_that_overflows_is_named() {
    let contact = |r1: &'static str, r2: &'static str, p: &'static str| {
        vec![
            "contact",
            "--nu",
            "0.3",
            "--speed",
            "0.5",
            "--r-along",
            r1,
            "--r-across",
            r2,
            "--load",
            "1000",
            "--shear-modulus",
            "80e9",
            "--precision",
            p,
        ]
    };
    for (r1, r2, what) in [
        ("1e-300", "1e300", "overflows f64"),
        ("1e300", "1e-300", "underflows"),
    ] {
        let msg = refused(
            &contact(r1, r2, "f64"),
            2,
            &[
                "'--r-across'",
                "'--r-along'",
                "A1/B1 = R2/R1 = 1.00000e",
                what,
            ],
        );
        assert!(!msg.contains("inf") && !msg.contains("= 0 "), "{msg}");
    }
    refused(
        &contact("1e-300", "1e300", "256"),
        2,
        &["A1/B1 = R2/R1 = 1e600", "[1e-100, 1e100]"],
    );
}

/// Issue 46 item 5: a solve that fails once the work has started exits 1 (docs/cli.md), not 2:
/// here the approach d0 overflows f64 after the ellipse is solved.
#[test]
fn a_failure_during_the_work_exits_1() {
    refused(
        &[
            "contact",
            "--nu",
            "0.3",
            "--speed",
            "0.5",
            "--r-along",
            "1",
            "--r-across",
            "2",
            "--load",
            "1e300",
            "--shear-modulus",
            "1e-300",
        ],
        1,
        &["solving the contact at f64", "approach d0 = inf"],
    );
}

/// Issue 46 item 5: exact zero is zero whatever its exponent, where zero is in the domain (ν,
/// the speed M_R, a sweep's speeds); a nonzero number with such an exponent is refused.
#[test]
fn exact_zero_is_accepted_with_any_exponent() {
    let zero = "0e-99999999999999999999";
    let ell = |nu: &str, speed: &str| {
        json(&[
            "ellipse", "--nu", nu, "--speed", speed, "--ratio", "0.5", "--json",
        ])
    };
    let (a, b) = (ell(zero, zero), ell("0", "0"));
    assert_eq!(field(&a, "k"), field(&b, "k"));
    let sweep = |speed: &str| {
        let out = run(&["sweep", "--nu", "0.2", "--speed", speed, "--ratio", "0.5"]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8(out.stdout).expect("UTF-8");
        text.lines()
            .nth(1)
            .expect("a row")
            .split(',')
            .nth(3)
            .expect("k")
            .to_string()
    };
    assert_eq!(sweep(&format!("{zero},0.5")), sweep("0,0.5"));
    refused(
        &["rayleigh", "--nu", "1e-99999999999999999999"],
        2,
        &[
            "'1e-99999999999999999999' for '--nu",
            "exponent out of range",
        ],
    );
}

/// Issue 46 item 5: `--out` and the names of the files are checked before any work: a parent
/// that is a file, and a 300-digit `--nu` whose file names pass 255 bytes (refused naming
/// `--nu`, nothing created).
#[test]
fn output_paths_are_checked_before_any_work() {
    refused(
        &["fig2", "--out", "/dev/null/x"],
        2,
        &["'--out'", "'/dev/null/x'", "/dev/null is not a directory"],
    );
    let tmp = TempDir::new("long-name");
    let out = tmp.0.join("out");
    let nu = format!("0.{}", "1".repeat(300));
    refused(
        &[
            "fig2",
            "--nu",
            &nu,
            "--out",
            out.to_str().expect("utf-8 path"),
        ],
        2,
        &["'--nu'", "more than the 255", "bytes"],
    );
    assert!(!out.exists(), "{} was created", out.display());
}

/// Issue 46 item 5: `fig2` without `--out` writes under docs/ only in the checkout (its
/// Cargo.toml and docs/ where it runs), and prints the path of each file it wrote (all five
/// exist); elsewhere it is refused and creates no ./docs.
#[test]
fn fig2_writes_docs_only_in_the_checkout() {
    let tmp = TempDir::new("outside");
    let out = Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .arg("fig2")
        .current_dir(&tmp.0)
        .output()
        .expect("the binary runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("--out DIR is required"), "{err}");
    assert!(!tmp.0.join("docs").exists(), "./docs was created");
    std::fs::write(
        tmp.0.join("Cargo.toml"),
        "[package]\nname = \"moving-hertz\"\n",
    )
    .expect("a manifest");
    std::fs::create_dir(tmp.0.join("docs")).expect("docs/");
    let out = Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .arg("fig2")
        .current_dir(&tmp.0)
        .output()
        .expect("the binary runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    let wrote = text
        .lines()
        .find_map(|l| l.strip_prefix("wrote "))
        .expect("a line of the files written");
    let paths: Vec<&str> = wrote.split(", ").collect();
    assert_eq!(paths.len(), 5, "{wrote}");
    for p in paths {
        assert!(p.starts_with("docs/"), "{p}");
        assert!(tmp.0.join(p).is_file(), "{p} was not written");
    }
}

/// Issue 46 item 5: the progress bar is drawn only when standard error is a terminal: a sweep
/// of several seconds with standard error a pipe leaves it empty.
#[test]
fn no_progress_bar_off_a_terminal() {
    let out = run(&[
        "sweep",
        "--nu",
        "0.25",
        "--speed",
        "lin:0:0.9:40",
        "--ratio",
        "log:0.1:10:150",
        "--precision",
        "128",
    ]);
    assert!(out.status.success());
    assert!(
        out.stderr.is_empty(),
        "{:?}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Issue 46 item 3: one precision vocabulary: `f64`, `dd`, bits as `256` or `mpfr256` (the
/// output's spelling, any case) read back to the same precision; `53` is MPFR; `double`
/// refused listing f64 and dd; every command quoting its own range ([24, 32768], or
/// [24, 1048576] where no quadrature rule is built).
#[test]
fn one_precision_vocabulary() {
    let ell = |p: &str| {
        json(&[
            "ellipse",
            "--nu",
            "0.2",
            "--speed",
            "0.5",
            "--ratio",
            "0.5",
            "--precision",
            p,
            "--json",
        ])
    };
    for (typed, label) in [
        ("f64", "f64"),
        ("dd", "dd"),
        ("256", "mpfr256"),
        ("53", "mpfr53"),
    ] {
        let v = ell(typed);
        assert_eq!(field(&v, "precision"), label);
        let back = ell(label);
        assert_eq!(field(&back, "k"), field(&v, "k"), "{typed} and {label}");
    }
    assert_eq!(field(&ell("MPFR256"), "precision"), "mpfr256");
    let base = ["ellipse", "--nu", "0.2", "--speed", "0.5", "--ratio", "0.5"];
    refused(
        &[&base[..], &["--precision", "double"]].concat(),
        2,
        &["'double'", "ambiguous", "f64", "dd"],
    );
    let contact = [
        "contact",
        "--nu",
        "0.3",
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
    ];
    let sweep = ["sweep", "--nu", "0.2", "--speed", "0.5", "--ratio", "0.5"];
    let integrals = ["integrals", "--nu", "0.2", "--speed", "0.5", "--k", "0.5"];
    for cmd in [
        &base[..],
        &contact,
        &sweep,
        &integrals,
        &["fig2", "--out", "/tmp"],
    ] {
        for p in ["20", "40000", "mpfr99999999999999999999999"] {
            refused(
                &[cmd, &["--precision", p]].concat(),
                2,
                &["--precision", "[24, 32768]"],
            );
        }
    }
    refused(
        &["rayleigh", "--nu", "0.2", "--precision", "20"],
        2,
        &["[24, 1048576]"],
    );
    refused(
        &["rayleigh", "--nu", "0.2", "--precision", "2000000"],
        2,
        &["[24, 1048576]"],
    );
    // The series builds no rule: 40000 bits pass to the next check (here of the speed).
    let series = [
        "integrals",
        "--nu",
        "0.2",
        "--speed",
        "2",
        "--k",
        "0.5",
        "--method",
        "series",
    ];
    refused(
        &[&series[..], &["--precision", "40000"]].concat(),
        2,
        &["'--speed'", "'2'"],
    );
    refused(
        &[&series[..], &["--precision", "20"]].concat(),
        2,
        &["[24, 32768] ([24, 1048576] with --method series)"],
    );
}

/// Issue 46 item 3: options a command cannot honour are refused before any work with exit code
/// 2 and nothing on standard output (`sweep --method series`); a range where one value is
/// taken, or a range of an unknown kind, says what is accepted.
#[test]
fn options_a_command_cannot_honour_are_refused() {
    let sweep = ["sweep", "--nu", "0.2", "--ratio", "0.5"];
    for m in ["series", "adaptive-subtracted"] {
        refused(
            &[&sweep[..], &["--speed", "0.5", "--method", m]].concat(),
            2,
            &["'--method <METHOD>'", "auto, adaptive, fixed"],
        );
    }
    refused(
        &[&sweep[..], &["--speed", "linspace:0:0.5:3"]].concat(),
        2,
        &["'linspace:'", "lin:START:STOP:N", "log:START:STOP:N"],
    );
    refused(
        &[
            "ellipse",
            "--nu",
            "0.2",
            "--speed",
            "lin:0:0.5:3",
            "--ratio",
            "0.5",
        ],
        2,
        &["'--speed <M_R>'", "`sweep` only"],
    );
    // log: is a range of --speed and --nu too (their help says so).
    let out = run(&[
        "sweep",
        "--nu",
        "log:0.1:0.4:2",
        "--speed",
        "log:0.1:0.5:2",
        "--ratio",
        "1",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Issue 46 item 4: every number of the text summaries in scientific notation with every digit
/// of the working precision (17 at f64, ⌈256·log10 2⌉ + 1 = 79 at 256 bits), the large central pressure as the
/// small semi-axes; each bound labelled by its kind.
#[test]
fn numbers_are_printed_one_way() {
    let contact = |p: &str| {
        let args = [
            "contact",
            "--nu",
            "0.3",
            "--speed",
            "0.5",
            "--r-along",
            "0.05",
            "--r-across",
            "0.02",
            "--load",
            "1000",
            "--shear-modulus",
            "80e9",
            "--precision",
            p,
        ];
        let out = run(&args);
        assert!(out.status.success());
        (
            String::from_utf8(out.stdout).expect("UTF-8"),
            json(&[&args[..], &["--json"]].concat()),
        )
    };
    for (p, n) in [("f64", 17), ("256", 79)] {
        let (text, v) = contact(p);
        let values: Vec<&str> = text
            .lines()
            .filter(|l| l.starts_with("  "))
            .map(str::trim)
            .collect();
        assert_eq!(values.len(), 7, "{text}");
        for (s, key) in values.iter().zip(["a", "b", "k", "e", "p0", "d0", "load"]) {
            let exact = Float::with_val(400, Float::parse(field(&v, key)).unwrap());
            assert_rounded(s, &exact, n);
        }
        assert!(text.contains("eccentricity e (major axis along the motion), absolute error <="));
        assert!(text.contains("central pressure p0, relative error <="));
    }
}

/// Issue 46 item 2: `sweep contact` refuses a command line it cannot honour before any work
/// (exit code 2, nothing on standard output, one line naming the option and quoting the text):
/// options missing or combined wrongly, a value outside its domain in any list, a modulus, a
/// density or a μ = E/(2(1 + ν)) that the working precision does not hold, radii whose ratio
/// overflows, a method or precision it cannot use, more points than one run solves, and the
/// ellipse sweep's options with the subcommand.
#[test]
fn sweep_contact_refusals_before_any_work() {
    let with = |swap: &[(&'static str, &'static str)], drop: &[&str]| {
        let mut base = vec![
            ("--nu", "0.2,0.3"),
            ("--shear-modulus", "80e9"),
            ("--speed", "0,0.5"),
            ("--r-along", "0.05"),
            ("--r-across", "0.02"),
            ("--load", "10,1000"),
        ];
        base.retain(|(k, _)| !drop.contains(k));
        for (k, v) in swap {
            match base.iter_mut().find(|(b, _)| b == k) {
                Some(slot) => slot.1 = v,
                None => base.push((k, v)),
            }
        }
        let mut args = vec!["sweep", "contact"];
        for (k, v) in base {
            args.extend([k, v]);
        }
        args
    };
    let cases: Vec<(Vec<&str>, Vec<&str>)> = vec![
        (
            with(&[], &["--shear-modulus"]),
            vec!["--shear-modulus", "--youngs-modulus"],
        ),
        (with(&[], &["--load"]), vec!["--load", "--approach"]),
        (
            with(&[("--velocity", "100")], &["--speed"]),
            vec!["--density"],
        ),
        (
            with(&[("--velocity", "100"), ("--density", "7850")], &[]),
            vec!["--speed", "--velocity"],
        ),
        (
            with(&[("--approach", "1e-6")], &[]),
            vec!["--load", "--approach"],
        ),
        (
            with(&[("--nu", "0.2,0.7")], &[]),
            vec!["'--nu'", "'0.7'", "(-1, 1/2]"],
        ),
        (
            with(&[("--load", "10,-1")], &[]),
            vec!["'--load'", "'-1'", "(0, inf)"],
        ),
        (
            with(&[("--r-across", "lin:0:1:3")], &[]),
            vec!["'--r-across'", "'0'"],
        ),
        (
            with(&[("--speed", "0.5,1")], &[]),
            vec!["'--speed'", "'1'", "[0, 1)"],
        ),
        (
            with(&[("--gap", "0")], &["--speed"]),
            vec!["'--gap'", "'0'", "(0, 1]"],
        ),
        (
            with(&[("--velocity", "-1"), ("--density", "7850")], &["--speed"]),
            vec!["'--velocity'", "'-1'", "[0, inf)"],
        ),
        (
            with(&[("--velocity", "100"), ("--density", "0")], &["--speed"]),
            vec!["'--density'", "'0'"],
        ),
        (
            with(&[("--shear-modulus", "1e-400")], &[]),
            vec!["'--shear-modulus'", "'1e-400'", "f64"],
        ),
        (
            with(&[("--r-along", "1e-200"), ("--r-across", "1e200")], &[]),
            vec!["'--r-across'", "'--r-along'", "overflows"],
        ),
        (
            with(
                &[("--nu", "-0.99999999999"), ("--youngs-modulus", "1e308")],
                &["--shear-modulus"],
            ),
            vec!["'--youngs-modulus'", "'1e308'", "overflows"],
        ),
        (
            with(
                &[
                    ("--nu", "-0.99999999999"),
                    ("--youngs-modulus", "1e308"),
                    ("--velocity", "1"),
                    ("--density", "1"),
                ],
                &["--shear-modulus", "--speed"],
            ),
            vec!["'--youngs-modulus'", "'1e308'"],
        ),
        (
            with(&[("--method", "series")], &[]),
            vec!["'--method <METHOD>'", "auto, adaptive, fixed"],
        ),
        (
            with(&[("--precision", "20")], &[]),
            vec!["'20'", "[24, 32768]"],
        ),
        (
            with(
                &[("--load", "lin:1:2:5000000"), ("--r-along", "1,2,3")],
                &[],
            ),
            vec!["60000000 points", "more than the 10000000"],
        ),
    ];
    for (args, wants) in &cases {
        refused(args, 2, wants);
    }
    refused(
        &[
            "sweep", "--nu", "0.2", "--speed", "0.5", "--ratio", "1", "contact",
        ],
        2,
        &["contact", "cannot be used with"],
    );
}
