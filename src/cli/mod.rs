//! The command line: `clap` (derive) parses the arguments, builds the help of every command and
//! the shell completions; each command builds the library's inputs from the decimal text as
//! typed, runs, and prints a text summary or one JSON object. Reference: `docs/cli.md` (every
//! command, option, JSON key and exit code: 1 for a failure during the work or a closed or full
//! output, 2 for a command line refused before any work; one line on standard error). Nothing
//! in the library depends on this module.

mod args;
mod contact;
mod ellipse;
mod fig2;
mod integrals;
mod output;
mod pipeline;
mod progress;
mod rayleigh;
mod study;
mod sweep;
mod sweep_contact;
mod symbolic;

use clap::{CommandFactory, Parser, Subcommand};
use std::fmt;
use std::io::Write;

/// moving-hertz: the Hertz contact of a rigid punch sliding without friction at a constant
/// speed below the Rayleigh wave speed over an elastic half-space, at f64, double-double or any
/// MPFR precision.
#[derive(Parser, Debug)]
#[command(
    name = "moving-hertz",
    version,
    propagate_version = true,
    arg_required_else_help = true,
    after_help = "Numbers are read from their decimal text exactly and rounded once to the working \
precision; results are printed with every digit of it. Units are the caller's (SI in, SI out). \
Reference: docs/cli.md."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// The paper's Fig. 2: the eccentricity of the contact ellipse against A1/B1 for several
    /// speeds and against the speed for several A1/B1 (CSV in DIR/data, SVG in DIR/figures).
    Fig2(fig2::Fig2Args),
    /// The Rayleigh root m1 = (c_R/c2)^2, c_R/c2, c_R/c1 and the three roots of the Rayleigh
    /// cubic for one Poisson's ratio.
    Rayleigh(rayleigh::RayleighArgs),
    /// I1, I2 of (34) in the normalisation of (37) at one axis ratio k, each with its error
    /// bound, at a chosen precision or the lowest one that reaches --tol.
    Integrals(integrals::IntegralsArgs),
    /// The contact ellipse's axis ratio k = b/a (a along the motion) and eccentricity for a
    /// curvature ratio A1/B1 = R2/R1, solving (33) I2(k)/I1(k) = A1/B1.
    Ellipse(ellipse::EllipseArgs),
    /// The full moving-punch Hertz solution: a, b, k, e, p0, d0 and the load, each with its
    /// error bound.
    Contact(contact::ContactArgs),
    /// The contact ellipse over every (nu, speed, A1/B1) of three lists or ranges, in parallel
    /// on every core, as CSV or JSON lines written as they are solved (a progress bar on
    /// stderr past a second when it is a terminal). Exit code 1 if a point failed (its row
    /// carries the error). `sweep contact`: the full contact solution over lists or ranges.
    Sweep(sweep::SweepCommand),
    /// A study of the crate's docs: runs it and writes its CSV (DIR/data), SVG (DIR/figures)
    /// and summary tables.
    Study(study::StudyArgs),
    /// Prints a completion script for SHELL on standard output, e.g.
    /// `moving-hertz completions bash > /etc/bash_completion.d/moving-hertz`.
    Completions {
        /// The shell: bash, elvish, fish, powershell or zsh.
        #[arg(value_name = "SHELL")]
        shell: clap_complete::Shell,
    },
    /// Exact coefficients of (36) as rational functions of nu, and of the recursion (40) as
    /// rational functions of e2, derived by the crate's own recurrences; or the condition of
    /// the K, E basis from them.
    Symbolic(symbolic::SymbolicArgs),
}

/// A failure of a command, printed as one line; its kind fixes the exit code.
#[derive(Debug)]
pub enum CliError {
    /// The command line was refused (exit code 2).
    Input(String),
    /// The computation failed or cannot meet the request (exit code 1).
    Failed(String),
}

impl CliError {
    /// A value refused, naming the option and quoting the text as typed:
    /// `invalid value '0.7' for '--nu': nu (Poisson's ratio) = 0.7 is outside …` (the form of
    /// clap's own messages).
    pub fn value(option: &str, text: &str, why: impl fmt::Display) -> CliError {
        CliError::Input(format!("invalid value '{text}' for '{option}': {why}"))
    }

    /// A library error met during the work (a study's or `fig2`'s solves, whose inputs were
    /// checked before): exit code 1, whatever its kind.
    pub fn lib(e: moving_hertz::Error) -> CliError {
        CliError::Failed(e.to_string())
    }

    /// A library error from a run whose inputs are `inputs` (the library's name of a quantity,
    /// or its prefix; the option; the text as typed). An error about one of them is a refusal
    /// of that input before any work (exit code 2), naming the option and quoting the text (an
    /// empty option: the quantity is derived from several options, and the message is the
    /// library's after `context`); so is a precision out of range or text that does not parse.
    /// Any other error is a failure during the work (exit code 1), printed after `context`
    /// (what was being computed, from which inputs).
    pub fn from_run(
        e: moving_hertz::Error,
        inputs: &[(&str, &str, &str)],
        context: &str,
    ) -> CliError {
        use moving_hertz::Error as E;
        let name = match &e {
            E::Domain { name, .. } | E::NotFinite { name, .. } => Some(*name),
            E::Unsupported { .. } => Some("method"),
            _ => None,
        };
        let hit = name.and_then(|n| inputs.iter().find(|(lib, _, _)| n.starts_with(lib)));
        match (hit, &e) {
            (Some((_, "", _)), _) | (None, E::Precision { .. } | E::Parse { .. }) => {
                CliError::Input(format!("{context}: {e}"))
            }
            (Some((_, option, text)), _) => CliError::value(option, text, &e),
            (None, _) => CliError::Failed(format!("{context}: {e}")),
        }
    }

    fn code(&self) -> i32 {
        match self {
            CliError::Input(_) => 2,
            CliError::Failed(_) => 1,
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Input(m) | CliError::Failed(m) => f.write_str(m),
        }
    }
}

/// Runs the command line; returns the process's exit code.
pub fn main() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_failure(e),
    };
    match run(cli.command) {
        Ok(()) => 0,
        Err(e) => {
            say_error(&format!("moving-hertz: error: {e}"));
            e.code()
        }
    }
}

/// Prints one line on standard error, its long words cut ([`cut_long_words`]); a closed or full
/// standard error is ignored (the exit code still tells).
fn say_error(line: &str) {
    let _ = writeln!(std::io::stderr(), "{}", cut_long_words(line));
}

/// The longest word (a run between spaces and quotes) an error line echoes in full.
const LONGEST_WORD: usize = 80;

/// `line` with every word longer than [`LONGEST_WORD`] characters (an input echoed as typed,
/// which may be 100,000 digits) cut to its first 40 and last 12 characters around
/// `…(N characters)…`, so that a message stays readable whatever was typed.
pub fn cut_long_words(line: &str) -> String {
    let mut out = String::with_capacity(line.len().min(4096));
    let mut word = String::new();
    let flush = |word: &mut String, out: &mut String| {
        let n = word.chars().count();
        if n > LONGEST_WORD {
            let head: String = word.chars().take(40).collect();
            let tail: String = word.chars().skip(n - 12).collect();
            out.push_str(&format!("{head}…({n} characters)…{tail}"));
        } else {
            out.push_str(word);
        }
        word.clear();
    };
    for c in line.chars() {
        if c.is_whitespace() || c == '\'' || c == '"' {
            flush(&mut word, &mut out);
            out.push(c);
        } else {
            word.push(c);
        }
    }
    flush(&mut word, &mut out);
    out
}

/// Builds `rayon`'s global pool once a job's inputs are checked (a refused command line starts
/// no threads): one thread per CPU, each bound to its own (`moving_hertz::sweep::bind_to_cpu`),
/// or `RAYON_NUM_THREADS` of them unbound, capped at the CPUs (with a note on standard error)
/// and at what the job's `points` at `precision` keep busy (`moving_hertz::sweep::threads_worth`).
/// Why: docs/design.md, "Many cores".
fn bind_global_pool(points: usize, precision: &moving_hertz::Precision) {
    let cpus = std::thread::available_parallelism().map_or(1, |n| n.get());
    let asked = std::env::var("RAYON_NUM_THREADS").ok();
    let asked = asked.and_then(|v| v.trim().parse::<usize>().ok().filter(|&n| n > 0));
    if let Some(n) = asked.filter(|&n| n > cpus) {
        let _ = writeln!(
            std::io::stderr(),
            "moving-hertz: note: RAYON_NUM_THREADS = {n} is more than the {cpus} CPUs this \
             process may run on; running {cpus} threads"
        );
    }
    let threads = asked
        .unwrap_or(cpus)
        .min(cpus)
        .min(moving_hertz::sweep::threads_worth(points, precision));
    let builder = rayon::ThreadPoolBuilder::new().num_threads(threads);
    // An error means the pool exists already, or that its threads cannot be started (rayon
    // then tries again, unbound, on first use).
    let _ = match asked {
        Some(_) => builder.build_global(),
        None => builder
            .start_handler(|i| {
                moving_hertz::sweep::bind_to_cpu(i);
            })
            .build_global(),
    };
}

fn run(command: Command) -> Result<(), CliError> {
    match command {
        Command::Fig2(a) => fig2::run(&a),
        Command::Rayleigh(a) => rayleigh::run(&a),
        Command::Integrals(a) => integrals::run(&a),
        Command::Ellipse(a) => ellipse::run(&a),
        Command::Contact(a) => contact::run(&a),
        Command::Study(a) => study::run(&a),
        Command::Sweep(a) => sweep::run_command(&a),
        Command::Symbolic(a) => symbolic::run(a.kind, a.n, a.format),
        Command::Completions { shell } => {
            let mut script = Vec::new();
            clap_complete::generate(shell, &mut Cli::command(), "moving-hertz", &mut script);
            output::emit(&String::from_utf8_lossy(&script))
        }
    }
}

/// Help and version go to standard output with exit code 0; a refused command line prints one
/// line on standard error (clap's message, its tips, and where the help is) and exits 2.
fn clap_failure(e: clap::Error) -> i32 {
    use clap::error::ErrorKind;
    match e.kind() {
        ErrorKind::DisplayHelp
        | ErrorKind::DisplayVersion
        | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            // Written as every command writes: a closed or full output is an error (exit 1).
            match output::emit(&e.render().to_string()) {
                Ok(()) => e.exit_code(),
                Err(err) => {
                    say_error(&format!("moving-hertz: error: {err}"));
                    err.code()
                }
            }
        }
        _ => {
            say_error(&format!(
                "moving-hertz: {}",
                one_line(&e.render().to_string())
            ));
            2
        }
    }
}

/// clap's rendered error on one line: `error: …` first, then its tips and the pointer to the
/// help, separated by semicolons (the usage block is left out: `--help` shows it).
fn one_line(rendered: &str) -> String {
    let mut out = String::new();
    let mut in_usage = false;
    for line in rendered.lines() {
        let t = line.trim();
        if t.is_empty() {
            in_usage = false;
            continue;
        }
        if t.starts_with("Usage:") {
            in_usage = true;
        }
        if in_usage {
            continue;
        }
        let t = t.replace("For more information, try", "for more information, try");
        let sep = if out.is_empty() {
            ""
        } else if out.ends_with(':') {
            " "
        } else {
            "; "
        };
        out.push_str(sep);
        out.push_str(t.trim_end_matches('.'));
    }
    out
}
