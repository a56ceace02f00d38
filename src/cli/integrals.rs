//! `moving-hertz integrals`: I1 and I2 of (34) (normalisation of (37)) by [`integrals`] at a
//! chosen precision, or by [`integrals_to_tolerance`] at the lowest precision that reaches
//! `--tol`.

use super::args::{self, Decimal, MaterialSpeed};
use super::output::{largest, print_json, ran, Obj, OutputArgs, Text};
use super::CliError;
use moving_hertz::scalar::{Precision, Real};
use moving_hertz::{
    integrals, integrals_to_tolerance, with_precision, ExactInputs, IntegralOptions, Integrals,
    Method, RelError,
};

#[derive(clap::Args, Debug)]
pub struct IntegralsArgs {
    #[command(flatten)]
    pub input: MaterialSpeed,
    /// The axis ratio k = b/a > 0 (dimensionless; a along the motion, b across).
    #[arg(long, value_name = "K", value_parser = args::decimal, allow_hyphen_values = true)]
    pub k: Decimal,
    /// The working precision: f64, dd (double-double, 106 bits) or a number of MPFR bits from
    /// 24 to 32768 (the largest precision the quadrature rules are built for; to 1048576 with
    /// --method series, which builds none), written 256 or mpfr256 as the output labels it.
    /// Default f64; without it, --tol chooses the precision.
    #[arg(long, value_name = "P", value_parser = args::precision_integrals)]
    pub precision: Option<Precision>,
    /// The relative tolerance for I1 and I2, 0 < TOL (dimensionless, any exponent: 1e-10000
    /// is fine). Alone: the lowest precision that reaches it is chosen (TOL < 1). With
    /// --precision: met at that precision or refused (a higher precision reaches it).
    #[arg(long, value_name = "TOL", value_parser = tol, allow_hyphen_values = true)]
    pub tol: Option<Tol>,
    /// The route: auto (the cheapest that meets the request), series, adaptive,
    /// adaptive-subtracted (k <= 1) or fixed (k <= 2^180). The route that ran is
    /// printed (fixed-rule for k <= 1, graded-rule for k > 1, ...).
    #[arg(long, value_name = "METHOD", default_value = "auto", value_parser = args::method())]
    pub method: Method,
    /// Also dI1/dk and dI2/dk (not by series or adaptive-subtracted; needs --precision when
    /// --tol is given).
    #[arg(long)]
    pub derivatives: bool,
    /// Also J0 of (32), the approach integral (with any method; needs --precision when --tol
    /// is given).
    #[arg(long)]
    pub j0: bool,
    #[command(flatten)]
    pub output: OutputArgs,
}

/// `--tol`: the text as typed and the bound it denotes.
#[derive(Clone, Debug)]
pub struct Tol {
    text: String,
    rel: RelError,
}

fn tol(s: &str) -> Result<Tol, String> {
    let rel = RelError::parse(s).map_err(|e| e.to_string())?;
    Ok(Tol {
        text: s.trim().to_string(),
        rel,
    })
}

pub fn run(a: &IntegralsArgs) -> Result<(), CliError> {
    // The quadrature routes' rules exist to MAX_RULE_BITS; only the series goes beyond.
    if let Some(p) = a.precision {
        let max = moving_hertz::numerics::quadrature::MAX_RULE_BITS;
        if p.bits() > max && a.method != Method::Series {
            let why = format!(
                "precision of {} bits is outside the supported range [24, {max}] bits of \
                 '--method {}' (--method series reaches 1048576)",
                p.bits(),
                a.method
            );
            return Err(CliError::value("--precision", &p.label(), why));
        }
    }
    match (&a.tol, a.precision) {
        (Some(tol), None) => to_tolerance(a, tol),
        (tol, precision) => {
            let prec = precision.unwrap_or(Precision::F64);
            with_precision!(prec, T, p => {
                let r = at_precision::<T>(a, tol.as_ref(), p)?;
                report(a, &r)
            })
        }
    }
}

/// The library errors of an evaluation: about the method, k or the tolerance, against the
/// option; an unreachable tolerance names `--tol` as typed (and the precision, if given).
fn run_error(a: &IntegralsArgs, e: moving_hertz::Error) -> CliError {
    let tol_text = a.tol.as_ref().map_or("", |t| t.text.as_str());
    if let (moving_hertz::Error::Unreachable { .. }, Some(t)) = (&e, &a.tol) {
        let at = a
            .precision
            .map(|p| format!(" at '--precision {p}'"))
            .unwrap_or_default();
        return CliError::Failed(format!("cannot meet '--tol {}'{at}: {e}", t.text));
    }
    let inputs = [
        ("method", "--method", a.method.label()),
        ("axis ratio k", "--k", a.k.text.as_str()),
        ("relative tolerance", "--tol", tol_text),
    ];
    CliError::from_run(e, &inputs, &format!("I1, I2 at k = {}", a.k.text))
}

/// At the precision given (default f64), with the tolerance, if any, checked there.
fn at_precision<T: Real>(
    a: &IntegralsArgs,
    tol: Option<&Tol>,
    p: T::Prec,
) -> Result<Integrals<T>, CliError> {
    let speed = a.input.at::<T>(p)?;
    let k: T = args::positive(&a.k, "--k", "axis ratio k = b/a", p)?;
    let opts = IntegralOptions {
        method: a.method,
        tolerance: tol.map(|t| t.rel),
        derivatives: a.derivatives,
        j0: a.j0,
    };
    integrals(&speed, &k, &opts).map_err(|e| run_error(a, e))
}

/// `--tol` alone: the inputs held exactly, the precision chosen from the tolerance's exponent,
/// the result printed at the precision that ran.
fn to_tolerance(a: &IntegralsArgs, tol: &Tol) -> Result<(), CliError> {
    if a.derivatives || a.j0 {
        return Err(CliError::Input(
            "--derivatives and --j0 need --precision: --tol alone chooses the precision for \
             I1 and I2 only"
                .into(),
        ));
    }
    let nu = &a.input.nu.text;
    let (kind, speed) = a.input.given();
    let parsed = match kind {
        "gap" => ExactInputs::parse_gap(nu, speed, &a.k.text),
        _ => ExactInputs::parse(nu, speed, &a.k.text),
    };
    let speed_option = if kind == "gap" { "--gap" } else { "--speed" };
    let inputs = parsed.map_err(|e| {
        CliError::from_run(
            e,
            &[
                ("nu", "--nu", nu.as_str()),
                ("speed", speed_option, speed),
                ("axis ratio k", "--k", a.k.text.as_str()),
            ],
            "the inputs",
        )
    })?;
    let r = integrals_to_tolerance(&inputs, tol.rel, a.method).map_err(|e| run_error(a, e))?;
    with_precision!(r.precision, T, p => report(a, &r.narrow::<T>(p)))
}

fn report<T: Real>(a: &IntegralsArgs, r: &Integrals<T>) -> Result<(), CliError> {
    let prec = r.precision;
    if a.output.json {
        let inputs = (a.input.json().put("k", a.k.text.as_str()))
            .put("method", a.method.label())
            .opt("precision", a.precision.map(|p| p.label()))
            .opt("tol", a.tol.as_ref().map(|t| t.text.as_str()))
            .put("derivatives", a.derivatives)
            .put("j0", a.j0);
        return print_json(
            &(Obj::head("integrals", inputs, prec).put("route", r.route.label()))
                .pairs(&[
                    ("I1", Some(&r.i1)),
                    ("I2", Some(&r.i2)),
                    ("dI1_dk", r.di1_dk.as_ref()),
                    ("dI2_dk", r.di2_dk.as_ref()),
                    ("J0", r.j0.as_ref()),
                ])
                .put("work", r.work.to_string())
                .put("error_estimate", largest(&[r.i1.error, r.i2.error])),
        );
    }
    let mut t = Text::new(a.output.digits);
    let tol = a
        .tol
        .as_ref()
        .map(|t| format!(", tolerance {}", t.text))
        .unwrap_or_default();
    t.line(format!(
        "I1, I2 of (34) in the normalisation of (37) (pi times the paper's) for k = {}, {}, \
         nu = {}{tol}",
        a.k.text,
        a.input.phrase(),
        a.input.nu.text
    ));
    t.line(format!(
        "{}, {} evaluations or terms; A1/B1 = I2/I1 for this k",
        ran(prec, a.method, r.route),
        r.work
    ));
    t.result("I1 (the cos^2 integral, (46))", &r.i1);
    t.result("I2 (the sin^2 integral, (47))", &r.i2);
    for (label, x) in [
        ("dI1/dk", &r.di1_dk),
        ("dI2/dk", &r.di2_dk),
        ("J0 of (32)", &r.j0),
    ] {
        if let Some(x) = x {
            t.result(label, x);
        }
    }
    t.print()
}
