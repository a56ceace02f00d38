//! The options several commands share, their value parsers, and the conversion of decimal text
//! into the library's inputs at the working precision.
//!
//! Every number comes in as text and stays text until the working precision is known: ν and
//! the speed go to [`Material::parse`], [`Material::parse_speed`] and [`Material::parse_gap`]
//! (checked exactly, the gap 1 − M_R formed exactly), every other quantity to `T::parse`, so
//! that the library's messages quote the text as typed and nothing is rounded through an `f64`.

use super::CliError;
use moving_hertz::scalar::{decimal_to_rational, Precision, Real};
use moving_hertz::{Material, Method, Speed};
use rug::Rational;

/// A number as typed (trimmed) with its exact value; the text is checked to be a decimal
/// (`0.25`, `-1.5e-3`) or a fraction (`1/4`) when the command line is parsed.
#[derive(Clone, Debug)]
pub struct Decimal {
    /// The text as typed, without surrounding white space.
    pub text: String,
    /// Its exact value.
    pub exact: Rational,
}

/// The value parser of every numeric option: [`Decimal`], or the library's parse error (which
/// clap prints after `invalid value 'TEXT' for '--OPTION'`).
pub fn decimal(s: &str) -> Result<Decimal, String> {
    let exact = decimal_to_rational(s).map_err(|e| e.to_string())?;
    Ok(Decimal {
        text: s.trim().to_string(),
        exact,
    })
}

/// The value parser of `--precision`: `f64`, `dd` or a number of MPFR bits, by
/// [`Precision::parse`] (an out-of-range count is refused naming the bits typed).
pub fn precision(s: &str) -> Result<Precision, String> {
    Precision::parse(s).map_err(|e| e.to_string())
}

/// The value parser of `--method`: one of [`Method::label`]'s names.
pub fn method() -> impl clap::builder::TypedValueParser<Value = Method> {
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new(Method::ALL.map(|m| m.label()))
        .try_map(|s| Method::parse(&s))
}

/// The cap on `--repeat`: the timed solves a command runs at most (stated in its help).
pub const REPEAT_CAP: usize = 1000;

/// Poisson's ratio and the speed, by M_R or by its gap: the inputs of every command that takes
/// a speed.
#[derive(clap::Args, Debug)]
pub struct MaterialSpeed {
    /// Poisson's ratio ν, -1 < NU <= 1/2 (dimensionless; decimal or p/q, checked exactly
    /// before it is rounded).
    #[arg(long, value_name = "NU", value_parser = decimal, allow_hyphen_values = true)]
    pub nu: Decimal,
    #[command(flatten)]
    pub speed: SpeedArg,
}

/// `--speed M_R` or `--gap G`: exactly one.
#[derive(clap::Args, Debug)]
#[group(required = true, multiple = false)]
pub struct SpeedArg {
    /// The speed as a Rayleigh Mach number M_R = V/c_R, 0 <= M_R < 1 (dimensionless; the gap
    /// 1 - M_R is formed exactly from the text). Exactly one of --speed and --gap.
    #[arg(long, value_name = "M_R", value_parser = decimal, allow_hyphen_values = true)]
    pub speed: Option<Decimal>,
    /// The speed by its gap to the Rayleigh speed, G = 1 - M_R, 0 < G <= 1 (dimensionless):
    /// the same speed as --speed 1-G, for speeds near c_R (e.g. --gap 1e-12).
    #[arg(long, value_name = "G", value_parser = decimal, allow_hyphen_values = true)]
    pub gap: Option<Decimal>,
}

impl MaterialSpeed {
    /// The speed (with its material) at precision `p`; a refusal names the option and quotes
    /// the text.
    pub fn at<T: Real>(&self, p: T::Prec) -> Result<Speed<T>, CliError> {
        let nu = &self.nu.text;
        let mat = Material::<T>::parse(nu, p).map_err(|e| CliError::value("--nu", nu, e))?;
        match (&self.speed.speed, &self.speed.gap) {
            (Some(s), _) => mat
                .parse_speed(&s.text)
                .map_err(|e| CliError::value("--speed", &s.text, e)),
            (None, Some(g)) => mat
                .parse_gap(&g.text)
                .map_err(|e| CliError::value("--gap", &g.text, e)),
            (None, None) => Err(CliError::Input(
                "one of --speed M_R and --gap G is required".into(),
            )),
        }
    }

    /// `("speed", text)` or `("gap", text)`: the speed as given, for the echo of the inputs.
    pub fn given(&self) -> (&'static str, &str) {
        match (&self.speed.speed, &self.speed.gap) {
            (Some(s), _) => ("speed", &s.text),
            (None, Some(g)) => ("gap", &g.text),
            (None, None) => ("speed", ""),
        }
    }

    /// The speed as a phrase for the text summaries: `M_R = 0.9` or `1 - M_R = 1e-12`.
    pub fn phrase(&self) -> String {
        match self.given() {
            ("gap", g) => format!("1 - M_R = {g}"),
            (_, s) => format!("M_R = {s}"),
        }
    }
}

/// A positive quantity (a ratio, a radius, a load, a modulus) rounded once to precision `p`
/// by `T::parse` (a fraction p/q from its exact value). Refused, naming `option` and quoting
/// the text, unless it is positive and its rounded value a normal number of the working
/// precision (a value that would overflow to ∞ or underflow to 0 there is refused as such,
/// not reported as `inf` or `0`).
pub fn positive<T: Real>(
    arg: &Decimal,
    option: &str,
    what: &str,
    p: T::Prec,
) -> Result<T, CliError> {
    let refuse = |why: String| CliError::value(option, &arg.text, why);
    if arg.exact <= 0 {
        return Err(refuse(format!(
            "{what} = {} is outside its domain (0, inf)",
            arg.text
        )));
    }
    let x = if arg.text.contains('/') {
        let bits = T::bits(p) + 64;
        T::from_float(&rug::Float::with_val(bits, &arg.exact), p)
    } else {
        T::parse(&arg.text, p).map_err(|e| refuse(e.to_string()))?
    };
    let prec = Precision::of::<T>(p);
    if !x.is_finite() {
        return Err(refuse(format!(
            "{what} = {} overflows {prec} (rescale, or use a wider precision)",
            arg.text
        )));
    }
    if x < T::min_positive(p) {
        return Err(refuse(format!(
            "{what} = {} is below the smallest normal number of {prec} (rescale, or use a \
             wider precision)",
            arg.text
        )));
    }
    Ok(x)
}

/// `--out DIR` of `fig2` and `study`: where the data (DIR/data) and figures (DIR/figures) go.
#[derive(clap::Args, Debug)]
pub struct OutDir {
    /// The directory that receives data/ (CSV, Markdown tables) and figures/ (SVG); default
    /// docs. DIR itself is created if missing, but its parent must exist (checked before any
    /// work): no directory tree is created silently.
    #[arg(long, value_name = "DIR", default_value = "docs")]
    pub out: std::path::PathBuf,
}

impl OutDir {
    /// Checks DIR before any work and creates DIR (if its parent exists), DIR/data and
    /// DIR/figures; a missing parent, or a DIR or subdirectory that is a file, is refused
    /// naming `--out` and the path as typed.
    pub fn prepare(&self) -> Result<&std::path::Path, CliError> {
        let dir = self.out.as_path();
        let text = dir.display().to_string();
        let refuse = |why: String| CliError::value("--out", &text, why);
        if !dir.is_dir() {
            if dir.exists() {
                return Err(refuse("it exists and is not a directory".into()));
            }
            let parent = match dir.parent() {
                Some(p) if p.as_os_str().is_empty() => std::path::Path::new("."),
                Some(p) => p,
                None => std::path::Path::new("."),
            };
            if !parent.is_dir() {
                return Err(refuse(format!(
                    "its parent directory {} does not exist (create it first)",
                    parent.display()
                )));
            }
        }
        for d in [dir.to_path_buf(), dir.join("data"), dir.join("figures")] {
            if !d.is_dir() {
                std::fs::create_dir(&d).map_err(|e| {
                    CliError::value("--out", &text, format!("creating {}: {e}", d.display()))
                })?;
            }
        }
        Ok(dir)
    }
}

/// A positive quantity formed exactly from the inputs (μ = E/(2(1 + ν)) of `contact
/// --youngs-modulus`), rounded once from `arg.exact` to precision `p`; refused as
/// [`positive`] refuses, naming `option` and quoting `arg.text` (the input it came from).
pub fn positive_exact<T: Real>(
    arg: &Decimal,
    option: &str,
    what: &str,
    p: T::Prec,
) -> Result<T, CliError> {
    let refuse = |why: String| CliError::value(option, &arg.text, why);
    let prec = Precision::of::<T>(p);
    let x = T::from_float(&rug::Float::with_val(T::bits(p) + 64, &arg.exact), p);
    if arg.exact <= 0 {
        return Err(refuse(format!(
            "{what} = {} is outside its domain (0, inf)",
            arg.text
        )));
    }
    if !x.is_finite() {
        return Err(refuse(format!(
            "{what} = {} overflows {prec} (rescale, or use a wider precision)",
            arg.text
        )));
    }
    if x < T::min_positive(p) {
        return Err(refuse(format!(
            "{what} = {} is below the smallest normal number of {prec} (rescale, or use a \
             wider precision)",
            arg.text
        )));
    }
    Ok(x)
}
