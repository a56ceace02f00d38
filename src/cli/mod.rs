//! Command-line front end: argument parsing, dispatch on precision, text and JSON output.
//! Nothing in the library depends on this module.

mod args;
mod contact;
mod fig2;
mod integrals;
mod json;
mod progress;
mod rayleigh;
mod study;
mod symbolic;

use args::Args;

const HELP: &str = "\
moving-hertz — Hertz contact of a rigid punch sliding at sub-Rayleigh speed

USAGE: moving-hertz <COMMAND> [OPTIONS]

COMMANDS:
  fig2 [--nu NU] [--precision f64|dd|BITS] [--out DIR]
        the paper's Fig. 2: eccentricity of the contact ellipse against A1/B1 for several
        speeds, and against the speed for several A1/B1 (CSV in DIR/data, SVG in DIR/figures)
  rayleigh --nu NU [--precision f64|dd|BITS] [--json]
        m1 = (c_R/c2)^2, c_R/c2 and the three roots of the Rayleigh cubic
  integrals --nu NU --speed MR --k K [--precision f64|dd|BITS | --tol TOL]
            [--method auto|series|quadrature|subtracted] [--json]
        I1, I2 of (34) in the normalisation of (37), with an error estimate; with --tol
        (and no --precision) the lowest precision reaching TOL is chosen
  ellipse --nu NU --speed MR --ratio A1_OVER_B1 [--precision ...] [--method auto|quadrature|fast]
          [--repeat N] [--json]
        the contact ellipse's axis ratio k = b/a (a along the motion) and eccentricity for
        the curvature ratio A1/B1 = R2/R1 (R1 along the motion, R2 across)
  contact --nu NU --speed MR --r-along R1 --r-across R2 (--load P | --approach D0)
          --shear-modulus MU [--precision ...] [--json]
        the full moving-punch Hertz solution: a, b, k, e, p0, d0, load
  study rayleigh|series|recursion [--out DIR]
        rayleigh: stability of the closed-form Rayleigh roots against nu and precision;
        series: terms and time of the series (37) against M_R per target accuracy;
        recursion: error growth of the forward recursion (40), bits lost in the K, E basis
  study poisson [--out DIR]
        how much Poisson's ratio changes e, k and a (the paper's 'about 2%' claim)
  study stability [--out DIR]
        maps of the digits each method delivers at f64 and double-double
  study pareto [--out DIR]
        accuracy against time of the ellipse solve for each method x precision
  study integrals [--out DIR]
        accuracy against cost of every method x precision for I1, I2 as M_R -> 1
        (writes DIR/data/*.csv and DIR/figures/*.svg; DIR defaults to docs)
  symbolic coefficients|moments|condition --n N [--format text|latex|sympy|json]
        f_n(nu) of (36) and alpha_n, beta_n(e2) of (40) as exact rational functions;
        condition: their pole at e2 = 0 and the bits the K, E basis loses (text, json)
  help  this text

Numbers are parsed from their decimal text at the working precision and printed with every
digit of it. --precision takes f64, dd (double-double) or a number of MPFR bits (24 or more).";

/// Runs the command line; returns the process's exit code.
pub fn main() -> i32 {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => 0,
        Err(msg) => {
            eprintln!("moving-hertz: {msg}");
            2
        }
    }
}

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
        "integrals" => integrals::run(&Args::parse(
            cmd,
            rest,
            &["nu", "speed", "k", "precision", "method", "tol"],
            &["json"],
        )?),
        "fig2" => fig2::run(&Args::parse(cmd, rest, &["nu", "precision", "out"], &[])?),
        "ellipse" => contact::ellipse(&Args::parse(
            cmd,
            rest,
            &["nu", "speed", "ratio", "precision", "method", "repeat"],
            &["json"],
        )?),
        "contact" => contact::contact(&Args::parse(
            cmd,
            rest,
            &[
                "nu",
                "speed",
                "r-along",
                "r-across",
                "load",
                "approach",
                "shear-modulus",
                "precision",
            ],
            &["json"],
        )?),
        "rayleigh" => rayleigh::run(&Args::parse(cmd, rest, &["nu", "precision"], &["json"])?),
        "study" => {
            let Some(name) = rest.first() else {
                return Err("`study` needs a study name (rayleigh, series, recursion)".into());
            };
            study::run(name, &Args::parse(cmd, &rest[1..], &["out"], &[])?)
        }
        "symbolic" => {
            let a = Args::parse(cmd, rest.get(1..).unwrap_or(&[]), &["n", "format"], &[])?;
            symbolic::run(
                symbolic::SymbolicKind::parse(rest.first().map_or("", |s| s.as_str()))?,
                symbolic::parse_n(a.required("n")?)?,
                symbolic::SymbolicFormat::parse(a.optional("format").unwrap_or("text"))?,
            )
        }
        other => Err(format!(
            "unknown command `{other}` (try `moving-hertz help`)"
        )),
    }
}
