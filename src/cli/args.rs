//! The options several commands share, their value parsers, and the conversion of decimal text
//! into the library's inputs at the working precision.
//!
//! Every number comes in as text and stays text until the working precision is known: ν and
//! the speed go to [`Material::parse`], [`Material::parse_speed`] and [`Material::parse_gap`]
//! (checked exactly, the gap 1 − M_R formed exactly), every other quantity to `T::parse`, so
//! that the library's messages quote the text as typed and nothing is rounded through an `f64`.

use super::output::Obj;
use super::CliError;
use moving_hertz::numerics::quadrature::MAX_RULE_BITS;
use moving_hertz::physics::solid::shear_from_youngs;
use moving_hertz::scalar::{decimal_to_rational, Precision, Real};
use moving_hertz::{Material, Method, MpPrec, Speed};
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
    if s.contains(':') {
        return Err(
            "one number here: ranges (lin:START:STOP:N, log:START:STOP:N) are taken by \
                    `sweep` only"
                .into(),
        );
    }
    let exact = decimal_to_rational(s).map_err(|e| e.to_string())?;
    Ok(Decimal {
        text: s.trim().to_string(),
        exact,
    })
}

/// The value parser of `--precision` for the commands that solve by quadrature (`ellipse`,
/// `contact`, `sweep`, `fig2`, and `integrals` but by the series): `f64`, `dd`, or a number of
/// MPFR bits as `256` or `mpfr256` ([`Precision::parse`]) from 24 to [`MAX_RULE_BITS`], the
/// largest precision the quadrature rules are built for.
pub fn precision(s: &str) -> Result<Precision, String> {
    precision_upto(s, MAX_RULE_BITS, "[24, 32768]")
}

/// The help of `--precision` of the commands that solve by quadrature ([`precision`]).
pub const PRECISION_HELP: &str = "The working precision: f64, dd (double-double, 106 bits) or a \
    number of MPFR bits from 24 to 32768 (the largest precision the quadrature rules are built \
    for), written 256 or mpfr256 as the output labels it";

/// The value parser of `--precision` of `rayleigh`, which needs no quadrature rule: bits up to
/// MPFR's limit here, [`MpPrec::MAX_BITS`].
pub fn precision_any(s: &str) -> Result<Precision, String> {
    precision_upto(s, MpPrec::MAX_BITS, "[24, 1048576]")
}

/// The value parser of `--precision` of `integrals`: bits up to [`MpPrec::MAX_BITS`], the
/// series' range; the quadrature routes' [`MAX_RULE_BITS`] is checked once the method is known.
pub fn precision_integrals(s: &str) -> Result<Precision, String> {
    let shown = "[24, 32768] ([24, 1048576] with --method series)";
    precision_upto(s, MpPrec::MAX_BITS, shown)
}

/// [`Precision::parse`], with a bit count outside [24, `max`] refused quoting the count as
/// typed and the range as `shown`.
fn precision_upto(s: &str, max: u32, shown: &str) -> Result<Precision, String> {
    let range = |bits: &str| {
        format!("precision of {bits} bits is outside the supported range {shown} bits")
    };
    match Precision::parse(s) {
        Ok(p) if p.bits() <= max => Ok(p),
        Ok(p) => Err(range(&p.bits().to_string())),
        Err(moving_hertz::Error::Precision { bits, .. }) => Err(range(&bits.to_string())),
        Err(e) => {
            let t = s.trim().to_ascii_lowercase();
            let digits = t.strip_prefix("mpfr").unwrap_or(&t);
            match !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()) {
                true => Err(range(digits)),
                false => Err(format!(
                    "{e}; the precisions are f64, dd, or a number of bits in {shown} (256 or \
                     mpfr256)"
                )),
            }
        }
    }
}

/// The value parser of `--method`: one of [`Method::label`]'s names.
pub fn method() -> impl clap::builder::TypedValueParser<Value = Method> {
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new(Method::ALL.map(|m| m.label()))
        .try_map(|s| Method::parse(&s))
}

/// The value parser of `--method` for the commands that solve the ellipse (`ellipse`,
/// `contact`, `sweep`): auto, adaptive or fixed, the methods that give the k-derivatives its
/// Newton steps need (series and adaptive-subtracted are refused by clap before any work,
/// listing these three).
pub fn solve_method() -> impl clap::builder::TypedValueParser<Value = Method> {
    use clap::builder::TypedValueParser;
    let solving = [Method::Auto, Method::Adaptive, Method::Fixed];
    clap::builder::PossibleValuesParser::new(solving.map(|m| m.label()))
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

    /// `("speed", text)` or `("gap", text)`: the speed as given.
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

    /// ν and the speed as typed: the JSON `inputs`' `nu`, and `speed` or `gap` (neither where
    /// the speed was given otherwise, as by `contact --velocity`).
    pub fn json(&self) -> Obj {
        (Obj::default().put("nu", self.nu.text.as_str()))
            .opt("speed", text_of(&self.speed.speed))
            .opt("gap", text_of(&self.speed.gap))
    }
}

/// The text of an optional decimal option, as typed.
pub fn text_of(d: &Option<Decimal>) -> Option<&str> {
    d.as_ref().map(|d| d.text.as_str())
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
    positive_by(arg, option, what, p, arg.text.contains('/'))
}

/// [`positive`] and [`mu_from_youngs`]: the domain check, the one rounding (from `arg.exact`
/// when `from_exact`, else by `T::parse` of the text) and the check that the rounded value is
/// a normal number of the working precision.
fn positive_by<T: Real>(
    arg: &Decimal,
    option: &str,
    what: &str,
    p: T::Prec,
    from_exact: bool,
) -> Result<T, CliError> {
    let refuse = |why: String| CliError::value(option, &arg.text, why);
    if arg.exact <= 0 {
        return Err(refuse(format!(
            "{what} = {} is outside its domain (0, inf)",
            arg.text
        )));
    }
    let x = if from_exact {
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
    /// The directory that receives data/ (CSV, Markdown tables) and figures/ (SVG). Default:
    /// docs, only when run from the root of the moving-hertz checkout (its Cargo.toml and
    /// docs/ there); anywhere else --out is required. DIR itself is created if missing, but its
    /// parent must exist as a directory (checked before any work, as are the names of the
    /// files): no directory tree is created silently.
    #[arg(long, value_name = "DIR")]
    pub out: Option<std::path::PathBuf>,
}

/// The longest file name most file systems allow, in bytes (`NAME_MAX`).
pub const NAME_MAX: usize = 255;

impl OutDir {
    /// DIR: `--out` as given, or `docs` in the moving-hertz checkout; elsewhere refused.
    fn dir(&self) -> Result<std::path::PathBuf, CliError> {
        if let Some(d) = &self.out {
            return Ok(d.clone());
        }
        let manifest = std::fs::read_to_string("Cargo.toml").unwrap_or_default();
        let checkout = manifest
            .lines()
            .any(|l| l.trim() == "name = \"moving-hertz\"")
            && std::path::Path::new("docs").is_dir();
        match checkout {
            true => Ok("docs".into()),
            false => Err(CliError::Input(
                "--out DIR is required here: its default, docs, is the docs/ of the \
                 moving-hertz checkout and applies only when run from the checkout's root"
                    .into(),
            )),
        }
    }

    /// Checks DIR before any work and creates DIR (if its parent is a directory), DIR/data and
    /// DIR/figures; a parent that is missing or not a directory, or a DIR or subdirectory that
    /// is a file, is refused naming `--out` and the path as typed.
    pub fn prepare(&self) -> Result<std::path::PathBuf, CliError> {
        let dir = self.dir()?;
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
                let why = match parent.exists() {
                    true => "is not a directory",
                    false => "does not exist (create it first)",
                };
                return Err(refuse(format!("its parent {} {why}", parent.display())));
            }
        }
        for d in [dir.clone(), dir.join("data"), dir.join("figures")] {
            if !d.is_dir() {
                std::fs::create_dir(&d).map_err(|e| {
                    CliError::value("--out", &text, format!("creating {}: {e}", d.display()))
                })?;
            }
        }
        Ok(dir)
    }
}

/// μ = E/(2(1 + ν)) formed exactly from Young's modulus `e` (of `--youngs-modulus`) and ν,
/// rounded once to precision `p`; refused as [`positive`] refuses, quoting E as typed.
pub fn mu_from_youngs<T: Real>(e: &Decimal, nu: &Rational, p: T::Prec) -> Result<T, CliError> {
    let exact = shear_from_youngs(&e.exact, nu);
    let mu = Decimal {
        text: e.text.clone(),
        exact,
    };
    let what = "shear modulus mu = E/(2(1 + nu)) from E";
    positive_by(&mu, "--youngs-modulus", what, p, true)
}
