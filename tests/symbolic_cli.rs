//! `moving-hertz symbolic coefficients|moments --n N --format text|sympy`, run as a
//! user runs it: every format prints the library's derivation (the same expressions, one per
//! function), and bad arguments print one line and exit non-zero before any work.

use moving_hertz::symbolic::{
    coefficient_items, expression, green_coefficients, moment_forms, moment_items, Style,
};
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .args(args)
        .output()
        .expect("the moving-hertz binary runs")
}

fn stdout(out: &Output) -> String {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout.clone()).expect("utf-8")
}

#[test]
fn sympy_format_prints_every_function_as_the_library_writes_it() {
    let text = stdout(&run(&[
        "symbolic",
        "coefficients",
        "--n",
        "30",
        "--format",
        "sympy",
    ]));
    let items = coefficient_items(&green_coefficients(30).unwrap());
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 31 + 3);
    for (line, it) in lines.iter().zip(&items) {
        let want = format!(
            "{} = {}",
            it.name,
            expression(&it.value, it.var, it.xpow, Style::Sympy)
        );
        assert_eq!(*line, want);
    }
    assert_eq!(lines[0], "f_0 = 1 - nu");
    assert_eq!(
        lines[33],
        "f_2_printed_minus_derived = -5*x**2/(8*(1 - nu))"
    );

    let text = stdout(&run(&[
        "symbolic", "moments", "--n", "50", "--format", "sympy",
    ]));
    let items = moment_items(&moment_forms(50).unwrap());
    assert_eq!(text.lines().count(), 4 * 51);
    for (line, it) in text.lines().zip(&items) {
        let e = expression(&it.value, it.var, 0, Style::Sympy);
        assert_eq!(line, format!("{} = {e}", it.name));
    }
}

#[test]
fn text_format() {
    let text = stdout(&run(&["symbolic", "coefficients", "--n", "3"]));
    assert!(text.starts_with("# (35)-(36) corrected"));
    assert!(
        text.contains("\nf_2 = x^2 (67 - 220 nu + 312 nu^2 - 224 nu^3 + 64 nu^4)/(64 (1 - nu))\n")
    );
    assert!(text.contains(
        "\nf_2_printed = x^2 (27 - 220 nu + 312 nu^2 - 224 nu^3 + 64 nu^4)/(64 (1 - nu))\n"
    ));
}

#[test]
fn bad_arguments_print_one_line_and_fail() {
    for (args, needle) in [
        (
            vec!["symbolic", "coefficients", "--n", "0"],
            "1 <= n <= 120",
        ),
        (
            vec!["symbolic", "coefficients", "--n", "121"],
            "1 <= n <= 120",
        ),
        (vec!["symbolic", "moments", "--n", "151"], "1 <= n <= 150"),
        (vec!["symbolic", "moments", "--n", "-3"], "-3"),
        (vec!["symbolic", "moments"], "--n"),
        (vec!["symbolic", "series", "--n", "3"], "coefficients"),
        (vec!["symbolic"], "<KIND>"),
        (
            vec!["symbolic", "moments", "--n", "3", "--format", "pdf"],
            "--format",
        ),
        (
            vec!["symbolic", "moments", "--n", "3", "--format", "latex"],
            "--format",
        ),
        (
            vec!["symbolic", "condition", "--n", "3", "--format", "sympy"],
            "prints text",
        ),
        (vec!["symbolic", "condition", "--n", "151"], "1 <= n <= 150"),
    ] {
        let out = run(&args);
        assert!(!out.status.success(), "{args:?}");
        assert!(out.stdout.is_empty(), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

#[test]
fn condition_prints_the_pole_and_the_bits_lost() {
    let text = stdout(&run(&["symbolic", "condition", "--n", "20"]));
    assert!(text.contains("\n5\t5\t128/35\t-128/35\n"), "{text}");
    let row = text
        .lines()
        .find(|l| l.starts_with("0.25\t"))
        .expect("row e2 = 0.25");
    let bits: Vec<f64> = row
        .split('\t')
        .skip(1)
        .map(|x| x.parse().unwrap())
        .collect();
    assert_eq!(bits.len(), 5); // n = 1, 2, 5, 10, 20
    assert!(bits.windows(2).all(|w| w[1] > w[0]), "{row}");
}
