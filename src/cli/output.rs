//! What the commands print: text summaries in which each result stands in full on its own line
//! (or with `--digits N` significant digits), and one JSON object a command, every number a
//! decimal string.

use super::CliError;
use moving_hertz::scalar::Real;
use moving_hertz::{Estimated, RelError};
use std::io::Write;

/// `--json` and `--digits N`: the output options of the commands that compute a result.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct OutputArgs {
    /// Print one JSON object instead of the text summary: every number a decimal string with
    /// every digit of the working precision, every error bound a decimal string (keys in
    /// docs/cli.md).
    #[arg(long)]
    pub json: bool,
    /// Print each result of the text summary to N significant digits (1 <= N; at most the
    /// working precision's digits). Not with --json, which always carries every digit.
    #[arg(long, value_name = "N", conflicts_with = "json",
          value_parser = clap::value_parser!(u32).range(1..))]
    pub digits: Option<u32>,
}

/// Builds a text summary: heading lines, and results as a label line followed by the value on
/// a line of its own.
pub struct Text {
    out: String,
    digits: Option<u32>,
}

impl Text {
    /// An empty summary printing results in full, or to `digits` significant digits.
    pub fn new(digits: Option<u32>) -> Text {
        Text {
            out: String::new(),
            digits,
        }
    }

    /// A line as given.
    pub fn line(&mut self, s: impl AsRef<str>) {
        self.out.push_str(s.as_ref());
        self.out.push('\n');
    }

    /// A result: `label, relative error <= bound` on one line, the value on the next.
    pub fn result<T: Real>(&mut self, label: &str, x: &Estimated<T>) {
        self.bounded(label, "relative", x);
    }

    /// A result whose bound is absolute (the eccentricity).
    pub fn result_abs<T: Real>(&mut self, label: &str, x: &Estimated<T>) {
        self.bounded(label, "absolute", x);
    }

    fn bounded<T: Real>(&mut self, label: &str, kind: &str, x: &Estimated<T>) {
        self.line(format!("{label}, {kind} error <= {}:", x.error));
        self.line(format!("  {}", self.value(&x.value)));
    }

    /// A value without a bound: the label line, then the value.
    pub fn plain<T: Real>(&mut self, label: &str, x: &T) {
        self.line(format!("{label}:"));
        self.line(format!("  {}", self.value(x)));
    }

    /// A value in full, or to `--digits` significant digits.
    pub fn value<T: Real>(&self, x: &T) -> String {
        match self.digits {
            Some(n) => shorten(x, n),
            None => x.to_decimal(),
        }
    }

    /// Writes the summary to standard output.
    pub fn print(self) -> Result<(), CliError> {
        emit(&self.out)
    }
}

/// `x` to `n` significant digits, correctly rounded (its full decimal when that is shorter).
pub fn shorten<T: Real>(x: &T, n: u32) -> String {
    let full = x.to_decimal();
    let f = x.to_float(T::bits(x.prec()));
    if f.is_zero() {
        return "0".into();
    }
    if !f.is_finite() {
        return full;
    }
    let short = f.to_string_radix(10, Some(n.max(1) as usize));
    if significant(&short) < significant(&full) {
        short
    } else {
        full
    }
}

/// The number of mantissa digits of a decimal string.
fn significant(s: &str) -> usize {
    let m = s.split(['e', 'E', '@']).next().unwrap_or("");
    m.chars().filter(char::is_ascii_digit).count()
}

/// A value and its bound as JSON strings: every digit of the working precision, the bound as
/// `RelError` prints it.
pub fn json_pair<T: Real>(x: &Estimated<T>) -> (String, String) {
    (x.value.to_decimal(), x.error.to_string())
}

/// The largest of several bounds (the JSON key `error_estimate`).
pub fn largest(bounds: &[RelError]) -> String {
    bounds
        .iter()
        .fold(RelError::ZERO, |a, b| a.max(*b))
        .to_string()
}

/// One JSON object on standard output, two-space indented.
pub fn print_json<S: serde::Serialize>(value: &S) -> Result<(), CliError> {
    let text = serde_json::to_string_pretty(value)
        .map_err(|e| CliError::Failed(format!("writing JSON: {e}")))?;
    emit(&(text + "\n"))
}

/// Writes `text` to standard output; a reader that closed the pipe early (`| head`) is not an
/// error.
pub fn emit(text: &str) -> Result<(), CliError> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(CliError::Failed(format!("writing to standard output: {e}"))),
    }
}
