//! The command line's conventions (issue 20, "What to build" 6): `--help` on every command states
//! each option's domain and units, `--version` prints the package version, `completions SHELL`
//! prints a script that knows the commands and their options, and a mistyped command or option
//! gets clap's suggestion — on one line.

use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .args(args)
        .output()
        .expect("the moving-hertz binary runs")
}

/// Standard output of a run that must succeed.
fn stdout(args: &[&str]) -> String {
    let out = run(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8")
}

/// Each command's help names every option with its domain and units (one phrase each, as the
/// help states it).
#[test]
fn every_command_has_help_with_domains_and_units() {
    let speed = [
        "--nu <NU>",
        "-1 < NU <= 1/2",
        "--speed <M_R>",
        "0 <= M_R < 1",
        "--gap <G>",
        "0 < G <= 1",
        "dimensionless",
    ];
    let precision = ["--precision <P>", "f64, dd", "24 to 32768"];
    let output = ["--json", "--digits <N>", "1 <= N"];
    let methods = "auto, series, adaptive, adaptive-subtracted, fixed";
    // The ellipse solve's Newton steps need dI/dk: series and adaptive-subtracted not offered.
    let solving = "[possible values: auto, adaptive, fixed]";
    let cases: Vec<(&str, Vec<&str>)> = vec![
        (
            "ellipse",
            [
                &speed[..],
                &precision,
                &output,
                &[
                    "--ratio <A1/B1>",
                    "A1/B1 = R2/R1 > 0",
                    "--method <METHOD>",
                    solving,
                    "--repeat <N>",
                    "1 <= N <= 1000",
                    "nanoseconds",
                ],
            ]
            .concat(),
        ),
        (
            "contact",
            [
                &speed[..],
                &precision,
                &output,
                &[
                    "--r-along <R1>",
                    "--r-across <R2>",
                    "(length",
                    "--load <P>",
                    "(force",
                    "--approach <D0>",
                    "--shear-modulus <MU>",
                    "(pressure",
                    "--method <METHOD>",
                    solving,
                ],
            ]
            .concat(),
        ),
        (
            "integrals",
            [
                &speed[..],
                &precision,
                &output,
                &[
                    "--k <K>",
                    "k = b/a > 0",
                    "--tol <TOL>",
                    "0 < TOL",
                    "1e-10000",
                    "--method <METHOD>",
                    methods,
                    "--derivatives",
                    "--j0",
                ],
            ]
            .concat(),
        ),
        (
            "rayleigh",
            [
                &speed[..2],
                &["--precision <P>", "f64, dd", "24 to 1048576"][..],
                &output,
            ]
            .concat(),
        ),
        (
            "fig2",
            [
                &speed[..2],
                &precision,
                &["--out <DIR>", "parent must exist"],
            ]
            .concat(),
        ),
        (
            "study",
            vec![
                "<NAME>",
                "rayleigh",
                "series",
                "recursion",
                "integrals",
                "poisson",
                "pareto",
                "stability",
                "--out <DIR>",
                "parent must exist",
            ],
        ),
        (
            "symbolic",
            vec![
                "<KIND>",
                "coefficients",
                "moments",
                "condition",
                "--n <N>",
                "1 <= N <= 120",
                "--format <FORMAT>",
                "sympy",
            ],
        ),
        (
            "completions",
            vec!["<SHELL>", "bash", "elvish", "fish", "powershell", "zsh"],
        ),
    ];
    let top = stdout(&["--help"]);
    for (cmd, wants) in cases {
        assert!(top.contains(cmd), "{cmd} missing from the top-level help");
        let help = stdout(&[cmd, "--help"]);
        // The help wraps nothing: a phrase stands on one line.
        for want in wants {
            assert!(
                help.contains(want),
                "`{cmd} --help` lacks {want:?}:\n{help}"
            );
        }
        assert_eq!(help, stdout(&["help", cmd]), "`help {cmd}`");
    }
}

#[test]
fn version_is_the_package_version() {
    let want = format!("moving-hertz {}\n", env!("CARGO_PKG_VERSION"));
    assert_eq!(stdout(&["--version"]), want);
    let sub = format!("moving-hertz-ellipse {}\n", env!("CARGO_PKG_VERSION"));
    assert_eq!(stdout(&["ellipse", "--version"]), sub);
}

/// Each shell's script names the commands and their options (bash, zsh and fish list the
/// long options literally).
#[test]
fn completions_for_every_shell() {
    for shell in ["bash", "elvish", "fish", "powershell", "zsh"] {
        let script = stdout(&["completions", shell]);
        for want in [
            "ellipse",
            "integrals",
            "contact",
            "study",
            "--gap",
            "--precision",
        ] {
            assert!(script.contains(want), "{shell}: {want} missing");
        }
    }
    let bash = stdout(&["completions", "bash"]);
    assert!(bash.contains("complete -F _moving-hertz"), "{bash}");
}

/// A mistyped command or option: one line naming what was typed and what exists, exit 2.
#[test]
fn typos_get_suggestions_on_one_line() {
    for (args, wants) in [
        (vec!["elipse"], vec!["'elipse'", "'ellipse'"]),
        (
            vec!["ellipse", "--nu", "0.2", "--speed", "0.5", "--rati", "2"],
            vec!["'--rati'", "'--ratio'"],
        ),
        (
            vec!["study", "rayleig"],
            vec!["'rayleig'", "rayleigh, series"],
        ),
    ] {
        let out = run(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        for want in wants {
            assert!(err.contains(want), "{args:?}: {err:?} lacks {want:?}");
        }
    }
}
