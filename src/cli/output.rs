//! What the commands print: text summaries in which each result stands on its own line in
//! scientific notation, `d.ddd…e±x`, with every significant digit of the working precision (or
//! `--digits N` of them), each bound labelled by its kind; and one JSON object a command, every
//! number a decimal string with every digit.

use super::CliError;
use moving_hertz::scalar::{Precision, Real};
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
    /// Print each result of the text summary to N significant digits, in scientific notation
    /// like every number of the summary (1 <= N; N beyond the working precision's digits prints
    /// them all: 17 at f64, 32 at dd). Not with --json, which always carries every digit.
    #[arg(long, value_name = "N", conflicts_with = "json",
          value_parser = clap::value_parser!(u32).range(1..))]
    pub digits: Option<u32>,
}

/// The fields every command's JSON object opens with (docs/cli.md): the command, its inputs as
/// typed, and the precision that ran.
#[derive(serde::Serialize)]
pub struct Head<I> {
    command: &'static str,
    inputs: I,
    precision: String,
    bits: String,
}

impl<I> Head<I> {
    /// The opening of `command`'s object, for `inputs` and the precision `prec` that ran.
    pub fn new(command: &'static str, inputs: I, prec: Precision) -> Self {
        Head {
            command,
            inputs,
            precision: prec.label(),
            bits: prec.bits().to_string(),
        }
    }
}

/// `at P (B bits), method M: route R`: the text summaries' line on how a result was computed.
pub fn ran(
    prec: Precision,
    method: impl std::fmt::Display,
    route: impl std::fmt::Display,
) -> String {
    format!(
        "at {} ({} bits), method {method}: route {route}",
        prec.label(),
        prec.bits()
    )
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

    /// A result: `label, relative error <= bound:` (or `absolute error`, as the value's
    /// [`BoundKind`] says) on one line, the value on the next.
    pub fn result<T: Real>(&mut self, label: &str, x: &Estimated<T>) {
        let kind = x.kind.label();
        self.line(format!("{label}, {kind} error <= {}:", x.error));
        self.line(format!("  {}", self.value(&x.value)));
    }

    /// A value without a bound: the label line, then the value.
    pub fn plain<T: Real>(&mut self, label: &str, x: &T) {
        self.line(format!("{label}:"));
        self.line(format!("  {}", self.value(x)));
    }

    /// A value in scientific notation with every digit of the working precision, or
    /// `--digits` of them.
    pub fn value<T: Real>(&self, x: &T) -> String {
        scientific(x, self.digits)
    }

    /// Writes the summary to standard output.
    pub fn print(self) -> Result<(), CliError> {
        emit(&self.out)
    }
}

/// `x` as `d.ddd…e±x` with `n` significant digits, correctly rounded (every digit of the working
/// precision, as [`Real::to_decimal`] gives them, when `n` is `None` or more than that); 0 as
/// `0`, a non-finite value as [`Real::to_decimal`] prints it.
pub fn scientific<T: Real>(x: &T, n: Option<u32>) -> String {
    let full = x.to_decimal();
    let f = x.to_float(T::bits(x.prec()));
    if f.is_zero() {
        return "0".into();
    }
    if !f.is_finite() {
        return full;
    }
    let all = significant(&full);
    let n = n.map_or(all, |n| (n as usize).min(all)).max(1);
    let (neg, digits, exp) = f.to_sign_string_exp(10, Some(n));
    let exp = exp.unwrap_or(1) - 1;
    let (first, rest) = digits.split_at(1);
    let sign = if neg { "-" } else { "" };
    match rest.is_empty() {
        true => format!("{sign}{first}e{exp}"),
        false => format!("{sign}{first}.{rest}e{exp}"),
    }
}

/// The number of mantissa digits of a decimal string.
fn significant(s: &str) -> usize {
    let m = s.split(['e', 'E', '@']).next().unwrap_or("");
    m.chars().filter(char::is_ascii_digit).count()
}

/// Results as JSON keys `NAME` and `NAME_error`, in the order given: the value with every digit
/// of the working precision, the bound as `RelError` prints it (flattened into a command's
/// object).
pub struct Pairs(Vec<(&'static str, String, String)>);

impl Pairs {
    /// The pairs of the results in `list` that are present.
    pub fn of<T: Real>(list: &[(&'static str, Option<&Estimated<T>>)]) -> Pairs {
        let pair = |(name, x): &(&'static str, Option<&Estimated<T>>)| {
            x.map(|x| (*name, x.value.to_decimal(), x.error.to_string()))
        };
        Pairs(list.iter().filter_map(pair).collect())
    }
}

impl serde::Serialize for Pairs {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(2 * self.0.len()))?;
        for (name, value, error) in &self.0 {
            m.serialize_entry(name, value)?;
            m.serialize_entry(&format!("{name}_error"), error)?;
        }
        m.end()
    }
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

/// Writes `text` to standard output, the one way every command writes there: a reader that
/// closed the pipe (`| head -1`) or a full device (`> /dev/full`) is a failure (exit code 1,
/// `writing to standard output: …`), which stops the command.
pub fn emit(text: &str) -> Result<(), CliError> {
    emit_bytes(text.as_bytes())
}

/// [`emit`] of text already in bytes (the `sweep` command's rows).
pub fn emit_bytes(text: &[u8]) -> Result<(), CliError> {
    let mut out = std::io::stdout().lock();
    out.write_all(text)
        .and_then(|()| out.flush())
        .map_err(|e| CliError::Failed(format!("writing to standard output: {e}")))
}
