//! `moving-hertz contact`: the full moving-punch Hertz solution by [`ContactProblem::solve`].

use super::args::{self, Decimal, MaterialSpeed};
use super::output::{largest, print_json, ran, Obj, OutputArgs, Text};
use super::CliError;
use moving_hertz::scalar::{Precision, Real};
use moving_hertz::{
    with_precision, ContactProblem, ContactSolution, Loading, Method, Moduli, Options, Solid, Speed,
};

#[derive(clap::Args, Debug)]
#[command(group = clap::ArgGroup::new("loading").required(true).args(["load", "approach"]))]
#[command(group = clap::ArgGroup::new("modulus").required(true).args(["shear_modulus", "youngs_modulus"]))]
pub struct ContactArgs {
    #[command(flatten)]
    pub input: MaterialSpeed,
    /// R1: the punch's radius of curvature along the motion, > 0 (length, e.g. m).
    #[arg(long, value_name = "R1", value_parser = args::decimal, allow_hyphen_values = true)]
    pub r_along: Decimal,
    /// R2: the punch's radius of curvature across the motion, > 0 (length, same unit as R1).
    #[arg(long, value_name = "R2", value_parser = args::decimal, allow_hyphen_values = true)]
    pub r_across: Decimal,
    /// The load P > 0 (force, e.g. N). Exactly one of --load and --approach.
    #[arg(long, value_name = "P", value_parser = args::decimal, allow_hyphen_values = true)]
    pub load: Option<Decimal>,
    /// The approach (central displacement) d0 > 0 (length, same unit as R1).
    #[arg(long, value_name = "D0", value_parser = args::decimal, allow_hyphen_values = true)]
    pub approach: Option<Decimal>,
    /// The half-space's shear modulus mu > 0 (pressure, e.g. Pa: force/length^2 in the units
    /// of P and R1). Exactly one of --shear-modulus and --youngs-modulus.
    #[arg(long, value_name = "MU", value_parser = args::decimal, allow_hyphen_values = true)]
    pub shear_modulus: Option<Decimal>,
    /// The half-space's Young's modulus E > 0 (pressure, e.g. Pa); mu = E/(2(1 + nu)) is formed
    /// exactly.
    #[arg(long, value_name = "E", value_parser = args::decimal, allow_hyphen_values = true)]
    pub youngs_modulus: Option<Decimal>,
    /// The speed as the velocity V >= 0 (m/s with SI moduli and density), below the Rayleigh
    /// wave speed c_R of the half-space (E or mu, nu and --density give c_R): a third way to
    /// give the speed besides --speed and --gap. Needs --density.
    #[arg(long, value_name = "V", value_parser = args::decimal, allow_hyphen_values = true,
          group = "SpeedArg", requires = "density")]
    pub velocity: Option<Decimal>,
    /// The density rho > 0 of the half-space (kg/m^3 with SI moduli), for --velocity.
    #[arg(long, value_name = "RHO", value_parser = args::decimal, allow_hyphen_values = true,
          requires = "velocity")]
    pub density: Option<Decimal>,
    #[arg(long, value_name = "P", default_value = "f64", value_parser = args::precision,
          help = args::PRECISION_HELP)]
    pub precision: Precision,
    /// How the ellipse solve evaluates the integrals: auto, adaptive or fixed (as for
    /// `ellipse`; series and adaptive-subtracted are refused).
    #[arg(long, value_name = "METHOD", default_value = "auto", value_parser = args::solve_method())]
    pub method: Method,
    #[command(flatten)]
    pub output: OutputArgs,
}

pub fn run(a: &ContactArgs) -> Result<(), CliError> {
    with_precision!(a.precision, T, p => {
        let (speed, shear_modulus, solid) = half_space::<T>(a, p)?;
        let loading = match (&a.load, &a.approach) {
            (Some(l), None) => Loading::Load(args::positive::<T>(l, "--load", "load P", p)?),
            (None, Some(d)) => Loading::Approach(args::positive::<T>(d, "--approach", "approach d0", p)?),
            _ => return Err(CliError::Input("exactly one of --load P and --approach D0 is required".into())),
        };
        let problem = ContactProblem {
            speed,
            radius_along: args::positive(&a.r_along, "--r-along", "radius along the motion R1", p)?,
            radius_across: args::positive(&a.r_across, "--r-across", "radius across the motion R2", p)?,
            loading,
            shear_modulus,
        };
        ratio_fits::<T>(&a.r_across, &a.r_along, p)?;
        let opts = Options::<T> { method: a.method, ..Default::default() };
        // The ratio's range is checked by the solve before any work: a refusal (exit code 2).
        let inputs = [("method", "--method", a.method.label()), ("curvature ratio", "", "")];
        let context = format!("solving the contact at {}", a.precision);
        let sol = problem.solve(&opts).map_err(|e| CliError::from_run(e, &inputs, &context))?;
        match a.output.json {
            true => report_json(a, &sol, solid.as_ref()),
            false => report_text(a, &sol, solid.as_ref()),
        }
    })
}

/// Refuses, before any work, radii whose curvature ratio A1/B1 = R2/R1 (formed exactly from
/// the text) overflows or underflows the working precision, saying so (not "A1/B1 = 0" or
/// "inf is not finite" from the solve); `sweep contact` checks its lists' extremes.
pub(super) fn ratio_fits<T: Real>(
    r_across: &Decimal,
    r_along: &Decimal,
    p: T::Prec,
) -> Result<(), CliError> {
    let exact = r_across.exact.clone() / &r_along.exact;
    let ratio = T::from_float(&rug::Float::with_val(T::bits(p) + 64, &exact), p);
    let why = if !ratio.is_finite() {
        "overflows"
    } else if ratio < T::min_positive(p) {
        "underflows (is below the smallest normal number of)"
    } else {
        return Ok(());
    };
    let shown = rug::Float::with_val(64, &exact).to_string_radix(10, Some(6));
    Err(CliError::Input(format!(
        "invalid values '{}' for '--r-across' and '{}' for '--r-along': the curvature ratio \
         A1/B1 = R2/R1 = {shown} {why} {} (rescale, or use a wider precision)",
        r_across.text,
        r_along.text,
        Precision::of::<T>(p)
    )))
}

/// The speed and μ: by --velocity through the [`Solid`] of ν, E or μ and ρ (which gives c_R),
/// else by --speed or --gap with μ as given or μ = E/(2(1 + ν)) formed exactly. Refusals name
/// the option and quote the text.
fn half_space<T: Real>(a: &ContactArgs, p: T::Prec) -> Result<HalfSpace<T>, CliError> {
    let nu = &a.input.nu;
    if let (Some(v), Some(rho)) = (&a.velocity, &a.density) {
        // μ is named after the option that gave it (E gives μ = E/(2(1 + ν))).
        let (option, modulus) = match (&a.youngs_modulus, &a.shear_modulus) {
            (Some(e), _) => ("--youngs-modulus", e),
            (None, Some(mu)) => ("--shear-modulus", mu),
            (None, None) => return Err(CliError::Input(MODULUS_REQUIRED.into())),
        };
        let texts = [&nu.text, &modulus.text, &rho.text, &v.text].map(String::as_str);
        let solid = solid::<T>(texts, option, p)?;
        let speed =
            (solid.parse_velocity(&v.text)).map_err(|e| half_space_error(e, texts, option))?;
        let mu = solid
            .shear_modulus()
            .cloned()
            .ok_or_else(|| CliError::Input(MODULUS_REQUIRED.into()))?;
        return Ok((speed, mu, Some(solid)));
    }
    let speed = a.input.at::<T>(p)?;
    let mu = match (&a.shear_modulus, &a.youngs_modulus) {
        (Some(mu), _) => args::positive(mu, "--shear-modulus", "shear modulus mu", p)?,
        (None, Some(e)) => {
            if e.exact <= 0 {
                let why = format!(
                    "Young's modulus E = {} is outside its domain (0, inf)",
                    e.text
                );
                return Err(CliError::value("--youngs-modulus", &e.text, why));
            }
            args::mu_from_youngs(e, &nu.exact, p)?
        }
        (None, None) => return Err(CliError::Input(MODULUS_REQUIRED.into())),
    };
    Ok((speed, mu, None))
}

/// The half-space ([`Solid::parse`]) of the texts of ν, the modulus (of `option`: E or μ), ρ
/// (and the velocity, named in refusals); a refusal names the option and quotes the text.
pub(super) fn solid<T: Real>(
    texts: [&str; 4],
    option: &'static str,
    p: T::Prec,
) -> Result<Solid<T>, CliError> {
    let [nu, modulus, density, _] = texts;
    let moduli = match option {
        "--youngs-modulus" => Moduli::Youngs {
            youngs_modulus: modulus,
            density,
        },
        _ => Moduli::Shear {
            shear_modulus: modulus,
            density,
        },
    };
    Solid::parse(nu, moduli, p).map_err(|e| half_space_error(e, texts, option))
}

/// A library error forming a half-space or its speed from the texts of ν, the modulus (of
/// `option`), ρ and V, against the option that gave it.
fn half_space_error(e: moving_hertz::Error, texts: [&str; 4], option: &str) -> CliError {
    let [nu, modulus, density, velocity] = texts;
    let names = [
        ("Young's modulus", option, modulus),
        ("shear modulus", option, modulus),
        ("density", "--density", density),
        ("nu", "--nu", nu),
        ("velocity", "--velocity", velocity),
    ];
    CliError::from_run(e, &names, "forming the half-space's wave speeds")
}

/// The speed, μ and (when the speed was given by --velocity) the half-space.
type HalfSpace<T> = (Speed<T>, T, Option<Solid<T>>);

const MODULUS_REQUIRED: &str =
    "exactly one of --shear-modulus MU and --youngs-modulus E is required";

/// The solution as one JSON object (docs/cli.md lists its keys).
fn report_json<T: Real>(
    a: &ContactArgs,
    sol: &ContactSolution<T>,
    solid: Option<&Solid<T>>,
) -> Result<(), CliError> {
    let ig = sol.ellipse().integrals();
    let text = args::text_of;
    let inputs = (a.input.json().opt("velocity", text(&a.velocity)))
        .put("r_along", a.r_along.text.as_str())
        .put("r_across", a.r_across.text.as_str())
        .opt("load", text(&a.load))
        .opt("approach", text(&a.approach))
        .opt("shear_modulus", text(&a.shear_modulus))
        .opt("youngs_modulus", text(&a.youngs_modulus))
        .opt("density", text(&a.density))
        .put("method", a.method.label())
        .put("precision", a.precision.label());
    let (shape, loading) = (
        [
            ("a", sol.a()),
            ("b", sol.b()),
            ("k", sol.k()),
            ("e", sol.e()),
        ],
        [("p0", sol.p0()), ("d0", sol.d0()), ("load", sol.load())],
    );
    let bounds: Vec<_> = shape.iter().chain(&loading).map(|(_, x)| x.error).collect();
    print_json(
        &(Obj::head("contact", inputs, ig.precision).put("route", ig.route.label()))
            .opt("c_r", solid.map(|s| s.c_r().to_decimal()))
            .opt("mr", solid.map(|_| sol.problem().speed.mr().to_decimal()))
            .pairs(&shape.map(|(n, x)| (n, Some(x))))
            .put("major_axis", sol.ellipse().major().label())
            .pairs(&loading.map(|(n, x)| (n, Some(x))))
            .put("error_estimate", largest(&bounds)),
    )
}

/// The solution as text: the inputs, then each value with its bound.
fn report_text<T: Real>(
    a: &ContactArgs,
    sol: &ContactSolution<T>,
    solid: Option<&Solid<T>>,
) -> Result<(), CliError> {
    let ig = sol.ellipse().integrals();
    let mut t = Text::new(a.output.digits);
    let given = match (&a.load, &a.approach) {
        (Some(l), _) => format!("load P = {}", l.text),
        (_, Some(d)) => format!("approach d0 = {}", d.text),
        _ => String::new(),
    };
    let modulus = match (&a.shear_modulus, &a.youngs_modulus) {
        (Some(mu), _) => format!("mu = {}", mu.text),
        (_, Some(e)) => format!("E = {}", e.text),
        _ => String::new(),
    };
    let speed = match (&a.velocity, &a.density) {
        (Some(v), Some(rho)) => format!("V = {} m/s, rho = {}", v.text, rho.text),
        _ => a.input.phrase(),
    };
    t.line(format!(
        "moving rigid punch on an elastic half-space: nu = {}, {speed}, R1 (along) = {}, \
         R2 (across) = {}, {given}, {modulus}",
        a.input.nu.text, a.r_along.text, a.r_across.text,
    ));
    t.line(format!(
        "{}; units as given (SI inputs give SI outputs: m, Pa, N)",
        ran(ig.precision, a.method, ig.route)
    ));
    if let Some(solid) = solid {
        t.plain("Rayleigh wave speed c_R (m/s)", solid.c_r());
        t.plain("speed M_R = V/c_R", sol.problem().speed.mr());
    }
    t.result("semi-axis along the motion a", sol.a());
    t.result("semi-axis across the motion b", sol.b());
    t.result("axis ratio k = b/a", sol.k());
    let major = format!(
        "eccentricity e (major axis {} the motion)",
        sol.ellipse().major().label()
    );
    t.result(&major, sol.e());
    t.result("central pressure p0", sol.p0());
    t.result("approach d0", sol.d0());
    t.result("load P", sol.load());
    t.print()
}
