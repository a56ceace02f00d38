//! `moving-hertz ellipse`: the contact ellipse's shape, (33) I2(k)/I1(k) = A1/B1, by
//! [`solve_ellipse`].

use super::args::{self, Decimal, MaterialSpeed, REPEAT_CAP};
use super::output::{largest, print_json, ran, Obj, OutputArgs, Text};
use super::CliError;
use moving_hertz::scalar::{Precision, Real};
use moving_hertz::{solve_ellipse, with_precision, Ellipse, Method, Options};
use std::time::Instant;

#[derive(clap::Args, Debug)]
pub struct EllipseArgs {
    #[command(flatten)]
    pub input: MaterialSpeed,
    /// The curvature ratio A1/B1 = R2/R1 > 0 (dimensionless; R1 the punch's radius of
    /// curvature along the motion, R2 across it).
    #[arg(long, value_name = "A1/B1", value_parser = args::decimal, allow_hyphen_values = true)]
    pub ratio: Decimal,
    #[arg(long, value_name = "P", default_value = "f64", value_parser = args::precision,
          help = args::PRECISION_HELP)]
    pub precision: Precision,
    /// How the integrals are evaluated at each Newton iterate: auto (the fixed rules where they
    /// apply, else adaptive quadrature), adaptive or fixed. series and adaptive-subtracted
    /// give no k-derivatives and are refused.
    #[arg(long, value_name = "METHOD", default_value = "auto", value_parser = args::solve_method())]
    pub method: Method,
    /// Also time N further solves (1 <= N <= 1000, checked before any work) and report the
    /// median and the minimum wall time per solve, in nanoseconds.
    #[arg(long, value_name = "N",
          value_parser = clap::value_parser!(u64).range(1..=REPEAT_CAP as u64))]
    pub repeat: Option<u64>,
    #[command(flatten)]
    pub output: OutputArgs,
}

pub fn run(a: &EllipseArgs) -> Result<(), CliError> {
    with_precision!(a.precision, T, p => {
        let speed = a.input.at::<T>(p)?;
        let ratio: T = args::positive(&a.ratio, "--ratio", "curvature ratio A1/B1", p)?;
        let opts = Options::<T> { method: a.method, ..Default::default() };
        let inputs = [("method", "--method", a.method.label()), ("curvature ratio", "--ratio", a.ratio.text.as_str())];
        let context = format!("solving (33) for A1/B1 = {} at {}", a.ratio.text, a.precision);
        let sol = solve_ellipse(&speed, &ratio, &opts).map_err(|e| CliError::from_run(e, &inputs, &context))?;
        let times = time(a.repeat.unwrap_or(0), || solve_ellipse(&speed, &ratio, &opts).is_ok());
        report(a, &sol, &times)
    })
}

/// Wall times of `n` calls of `f`, in nanoseconds, sorted.
pub fn time(n: u64, mut f: impl FnMut() -> bool) -> Vec<f64> {
    let mut t: Vec<f64> = (0..n)
        .map(|_| {
            let start = Instant::now();
            std::hint::black_box(f());
            start.elapsed().as_nanos() as f64
        })
        .collect();
    t.sort_by(|a, b| a.total_cmp(b));
    t
}

fn report<T: Real>(a: &EllipseArgs, sol: &Ellipse<T>, times: &[f64]) -> Result<(), CliError> {
    let ig = sol.integrals();
    let prec = ig.precision;
    let median = (!times.is_empty()).then(|| format!("{:.0}", times[times.len() / 2]));
    let min = times.first().map(|t| format!("{t:.0}"));
    if a.output.json {
        let inputs = (a.input.json().put("ratio", a.ratio.text.as_str()))
            .put("method", a.method.label())
            .put("precision", a.precision.label());
        let bound = largest(&[sol.k().error, sol.e().error, ig.i1.error, ig.i2.error]);
        return print_json(
            &(Obj::head("ellipse", inputs, prec).put("route", ig.route.label()))
                .pairs(&[("k", Some(sol.k())), ("e", Some(sol.e()))])
                .put("major_axis", sol.major().label())
                .pairs(&[("I1", Some(&ig.i1)), ("I2", Some(&ig.i2))])
                .put("iterations", sol.iterations().to_string())
                .put("error_estimate", bound)
                .opt(
                    "repeat",
                    (!times.is_empty()).then(|| times.len().to_string()),
                )
                .opt("median_ns", median)
                .opt("min_ns", min),
        );
    }
    let mut t = Text::new(a.output.digits);
    t.line(format!(
        "contact ellipse (33) for A1/B1 = R2/R1 = {}, {}, nu = {}",
        a.ratio.text,
        a.input.phrase(),
        a.input.nu.text
    ));
    t.line(format!(
        "{}, {} evaluations",
        ran(prec, a.method, ig.route),
        sol.iterations()
    ));
    t.result("k = b/a (across/along the motion)", sol.k());
    let major = format!(
        "eccentricity e (major axis {} the motion)",
        sol.major().label()
    );
    t.result(&major, sol.e());
    t.result("I1 (normalisation of (37))", &ig.i1);
    t.result("I2 (normalisation of (37))", &ig.i2);
    if let (Some(med), Some(min)) = (median, min) {
        t.line(format!(
            "time per solve over {} runs: median {med} ns, min {min} ns",
            times.len()
        ));
    }
    t.print()
}
