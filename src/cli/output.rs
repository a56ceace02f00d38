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

/// A JSON object with its members in the order they are put (docs/cli.md lists every
/// command's keys): `command`, `inputs` (as typed), `precision` and `bits` first ([`Obj::head`]),
/// then the results; every number a decimal string.
#[derive(serde::Serialize, Default)]
pub struct Obj(#[serde(serialize_with = "members")] Vec<(String, Member)>);

/// A member's value: a JSON value, or an object of its own.
#[derive(serde::Serialize)]
#[serde(untagged)]
enum Member {
    Value(serde_json::Value),
    Obj(Obj),
}

fn members<S: serde::Serializer>(m: &[(String, Member)], s: S) -> Result<S::Ok, S::Error> {
    s.collect_map(m.iter().map(|(k, v)| (k, v)))
}

impl Obj {
    /// The opening of `command`'s object: its `inputs` as typed and the precision `prec` that ran.
    pub fn head(command: &'static str, inputs: Obj, prec: Precision) -> Obj {
        let mut o = Obj::default().put("command", command);
        o.0.push(("inputs".into(), Member::Obj(inputs)));
        o.put("precision", prec.label())
            .put("bits", prec.bits().to_string())
    }

    /// The member `key`.
    pub fn put(mut self, key: &str, value: impl Into<serde_json::Value>) -> Obj {
        self.0.push((key.into(), Member::Value(value.into())));
        self
    }

    /// The member `key` when `value` is present.
    pub fn opt(self, key: &str, value: Option<impl Into<serde_json::Value>>) -> Obj {
        match value {
            Some(v) => self.put(key, v),
            None => self,
        }
    }

    /// The results of `list` that are present as `NAME` and `NAME_error`: the value with every
    /// digit of the working precision, the bound as `RelError` prints it.
    pub fn pairs<T: Real>(self, list: &[(&str, Option<&Estimated<T>>)]) -> Obj {
        list.iter().fold(self, |o, (name, x)| match x {
            Some(x) => (o.put(name, x.value.to_decimal()))
                .put(&format!("{name}_error"), x.error.to_string()),
            None => o,
        })
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

#[cfg(test)]
#[path = "../../tests/unit/cli_output.rs"]
mod tests;
