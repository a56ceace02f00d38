//! Command-line front end: argument parsing, dispatch on precision, text and JSON output.
//! Nothing in the library depends on this module.

mod args;
mod json;
mod rayleigh;
mod study;

use args::Args;

const HELP: &str = "\
moving-hertz — Hertz contact of a rigid punch sliding at sub-Rayleigh speed

USAGE: moving-hertz <COMMAND> [OPTIONS]

COMMANDS:
  rayleigh --nu NU [--precision f64|dd|BITS] [--json]
        m1 = (c_R/c2)^2, c_R/c2 and the three roots of the Rayleigh cubic
  study rayleigh|series|recursion [--out DIR]
        rayleigh: stability of the closed-form Rayleigh roots against nu and precision;
        series: terms and time of the series (37) against M_R per target accuracy;
        recursion: error growth of the forward recursion (40), bits lost in the K, E basis
        (writes DIR/data/*.csv and DIR/figures/*.svg; DIR defaults to docs)
  help  this text

Numbers are parsed from their decimal text at the working precision and printed with every
digit of it. --precision takes f64, dd (double-double) or a number of MPFR bits (24 or more).";

/// Runs the command in `argv`; an `Err` is one line for the user.
pub fn run(argv: &[String]) -> Result<(), String> {
    let Some(cmd) = argv.first() else {
        println!("{HELP}");
        return Ok(());
    };
    let rest = &argv[1..];
    match cmd.as_str() {
        "help" | "--help" | "-h" => {
            println!("{HELP}");
            Ok(())
        }
        "rayleigh" => rayleigh::run(&Args::parse(cmd, rest, &["nu", "precision"], &["json"])?),
        "study" => {
            let Some(name) = rest.first() else {
                return Err("`study` needs a study name (rayleigh, series, recursion)".into());
            };
            study::run(name, &Args::parse(cmd, &rest[1..], &["out"], &[])?)
        }
        other => Err(format!(
            "unknown command `{other}` (try `moving-hertz help`)"
        )),
    }
}
