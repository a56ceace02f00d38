//! `moving-hertz sweep contact`: the full moving-punch contact solution at every point of lists
//! or ranges of ν, the modulus, the speed, R1, R2 and the load (or approach), by the library's
//! [`sweep::try_contacts`] (parallel blocks, shared set-ups, continuation), written as CSV or
//! JSON lines in input order as the blocks are solved ([`pipeline::solve_in_order`]). Every
//! input is taken exactly from its text as `contact` takes it, so that a row carries the digits
//! of `contact --json` for the same inputs.

use super::args::{self, Decimal};
use super::contact::{ratio_fits, solid};
use super::sweep::{
    axis, check_and_bind, checked_nus, one_of, write_in_order, Axis, Checked, Column, Grid, Row,
    RunArgs, APPROACH, GAP, LOAD, NU, R_ACROSS, R_ALONG, SHEAR, SPEED, VELOCITY, YOUNGS,
};
use super::CliError;
use moving_hertz::scalar::{decimal_to_rational, Precision, Real};
use moving_hertz::sweep;
use moving_hertz::{
    with_precision, ContactProblem, ContactSolution, Loading, Material, Options, Solid,
};
use rayon::prelude::*;

#[derive(clap::Args, Debug)]
#[command(group = clap::ArgGroup::new("speed_given").required(true).args(["speed", "gap", "velocity"]))]
#[command(group = clap::ArgGroup::new("loading").required(true).args(["load", "approach"]))]
#[command(group = clap::ArgGroup::new("modulus").required(true).args(["shear_modulus", "youngs_modulus"]))]
pub struct ContactSweepArgs {
    /// Poisson's ratios, -1 < NU <= 1/2: a list `0.1,0.2,1/4`, a range `lin:START:STOP:N` (N
    /// points, evenly spaced) or `log:START:STOP:N` (N points, log-spaced; positive ends).
    #[arg(long, value_name = "LIST", value_parser = axis, allow_hyphen_values = true)]
    pub nu: Axis,
    /// Speeds M_R = V/c_R, 0 <= M_R < 1 (dimensionless): a list or range as for --nu, each gap
    /// 1 - M_R formed exactly. Exactly one of --speed, --gap and --velocity.
    #[arg(long, value_name = "LIST", value_parser = axis, allow_hyphen_values = true)]
    pub speed: Option<Axis>,
    /// Speeds by their gap G = 1 - M_R, 0 < G <= 1 (dimensionless): a list or range.
    #[arg(long, value_name = "LIST", value_parser = axis, allow_hyphen_values = true)]
    pub gap: Option<Axis>,
    /// Velocities V >= 0 (m/s with SI moduli and density): a list or range; a point with V at
    /// or above the Rayleigh wave speed c_R of its half-space is a row with its error (naming
    /// c_R and V). Needs --density.
    #[arg(long, value_name = "LIST", value_parser = axis, allow_hyphen_values = true,
          requires = "density")]
    pub velocity: Option<Axis>,
    /// The density rho > 0 of the half-space (kg/m^3 with SI moduli), one value, for
    /// --velocity.
    #[arg(long, value_name = "RHO", value_parser = args::decimal, allow_hyphen_values = true,
          requires = "velocity")]
    pub density: Option<Decimal>,
    /// R1: the punch's radii of curvature along the motion, > 0 (length, e.g. m): a list or
    /// range.
    #[arg(long, value_name = "LIST", value_parser = axis, allow_hyphen_values = true)]
    pub r_along: Axis,
    /// R2: the punch's radii of curvature across the motion, > 0 (length, same unit as R1): a
    /// list or range.
    #[arg(long, value_name = "LIST", value_parser = axis, allow_hyphen_values = true)]
    pub r_across: Axis,
    /// Loads P > 0 (force, e.g. N): a list or range. Exactly one of --load and --approach.
    #[arg(long, value_name = "LIST", value_parser = axis, allow_hyphen_values = true)]
    pub load: Option<Axis>,
    /// Approaches d0 > 0 (length, same unit as R1): a list or range.
    #[arg(long, value_name = "LIST", value_parser = axis, allow_hyphen_values = true)]
    pub approach: Option<Axis>,
    /// Shear moduli mu > 0 (pressure, e.g. Pa): one value, a list or a range. Exactly one of
    /// --shear-modulus and --youngs-modulus.
    #[arg(long, value_name = "LIST", value_parser = axis, allow_hyphen_values = true)]
    pub shear_modulus: Option<Axis>,
    /// Young's moduli E > 0 (pressure, e.g. Pa): one value, a list or a range; mu =
    /// E/(2(1 + nu)) is formed exactly at each nu.
    #[arg(long, value_name = "LIST", value_parser = axis, allow_hyphen_values = true)]
    pub youngs_modulus: Option<Axis>,
    #[command(flatten)]
    pub run: RunArgs,
}

impl ContactSweepArgs {
    /// The speed, modulus and load (or approach) axes, each with its checks.
    fn groups(&self) -> Result<[(&Axis, &'static Checked); 3], CliError> {
        Ok([
            one_of([
                (&self.speed, &SPEED),
                (&self.gap, &GAP),
                (&self.velocity, &VELOCITY),
            ])?,
            one_of([
                (&self.shear_modulus, &SHEAR),
                (&self.youngs_modulus, &YOUNGS),
            ])?,
            one_of([(&self.load, &LOAD), (&self.approach, &APPROACH)])?,
        ])
    }
}

pub fn run(a: &ContactSweepArgs) -> Result<(), CliError> {
    let [speeds, moduli, sizes] = a.groups()?;
    let checks = [
        (&a.nu, &NU),
        speeds,
        (&a.r_along, &R_ALONG),
        (&a.r_across, &R_ACROSS),
        sizes,
        moduli,
    ];
    let total = check_and_bind(&checks, &a.run.precision)?;
    with_precision!(a.run.precision, T, p => solve_and_write::<T>(a, total, p))
}

/// A positive axis's values with their text, each rounded once as `contact` rounds it
/// ([`args::positive`] of its text) and refused, naming the option, unless a normal number of
/// the working precision.
fn positive_values<T: Real + Send>(
    axis: &Axis,
    checked: &Checked,
    precision: &Precision,
    p: T::Prec,
) -> Result<Vec<(String, T)>, CliError> {
    let (option, what) = (checked.option, checked.what);
    (checked.values::<T>(axis, precision, p)?.into_par_iter())
        .map(|(text, _)| {
            let exact =
                decimal_to_rational(&text).map_err(|e| CliError::value(option, &text, e))?;
            let d = Decimal { text, exact };
            args::positive::<T>(&d, option, what, p).map(|x| (d.text, x))
        })
        .collect()
}

/// What the sweep forms of its half-spaces before any work: μ (per modulus, or per (ν, E)
/// when E is given), and with --velocity the [`Solid`] of every (ν, modulus) (index
/// ν·|moduli| + modulus), which gives c_R and μ.
struct HalfSpaces<T: Real> {
    mu: Vec<T>,
    mu_by_nu: bool,
    solids: Vec<Solid<T>>,
    /// The speed's, the modulus's and the size's options as given (`--gap`,
    /// `--youngs-modulus`, `--load`, …).
    given: [&'static Checked; 3],
}

/// The grid of the command line at precision `p` (ν, modulus, speed, R1, R2, load or
/// approach), and its half-spaces; every refusal before any work.
fn grid<T: Real + Send + Sync>(
    a: &ContactSweepArgs,
    p: T::Prec,
) -> Result<(Grid<T, 6>, HalfSpaces<T>), CliError> {
    let (precision, format) = (&a.run.precision, a.run.format);
    let [(speed_axis, speed), (modulus_axis, modulus), (size_axis, size)] = a.groups()?;
    let nus = checked_nus::<T>(&a.nu, precision, p)?;
    let speeds = match speed.option {
        "--velocity" => speed_axis.values::<T>(p),
        _ => speed.values::<T>(speed_axis, precision, p)?,
    };
    let along = positive_values::<T>(&a.r_along, &R_ALONG, precision, p)?;
    let across = positive_values::<T>(&a.r_across, &R_ACROSS, precision, p)?;
    for r2 in a.r_across.extremes() {
        for r1 in a.r_along.extremes() {
            ratio_fits::<T>(r2, r1, p)?;
        }
    }
    let sizes = positive_values::<T>(size_axis, size, precision, p)?;
    let moduli = positive_values::<T>(modulus_axis, modulus, precision, p)?;
    let grid = Grid::new(
        [nus, moduli, speeds, along, across, sizes].map(|c| Column::new(c, format, true)),
        2,
    );
    let half = half_spaces(a, &grid, [speed, modulus, size], p)?;
    Ok((grid, half))
}

/// Forms μ (and, with --velocity, every half-space) before any work: a refusal names the
/// option and quotes the text.
fn half_spaces<T: Real + Send + Sync>(
    a: &ContactSweepArgs,
    grid: &Grid<T, 6>,
    given: [&'static Checked; 3],
    p: T::Prec,
) -> Result<HalfSpaces<T>, CliError> {
    let [nus, moduli, ..] = &grid.cols;
    let option = given[1].option;
    let youngs = option == "--youngs-modulus";
    let mut half = HalfSpaces {
        mu: Vec::new(),
        mu_by_nu: youngs,
        solids: Vec::new(),
        given,
    };
    if let Some(rho) = &a.density {
        args::positive::<T>(rho, "--density", "density rho", p)?;
        let density = rho.text.as_str();
        half.solids = per_pair(nus, moduli, |nu, m| solid([nu, m, density, ""], option, p))?;
        // A half-space of moduli always has μ; none would be refused as 0.
        let mu = |s: &Solid<T>| s.shear_modulus().cloned().unwrap_or_else(|| T::zero(p));
        (half.mu, half.mu_by_nu) = (half.solids.iter().map(mu).collect(), true);
    } else if youngs {
        // μ = E/(2(1 + ν)) exactly at each (ν, E), rounded once, as `contact` forms it.
        half.mu = per_pair(nus, moduli, |nu, e| {
            let exact =
                |t: &str| decimal_to_rational(t).map_err(|err| CliError::value(option, t, err));
            let e = Decimal {
                text: e.to_string(),
                exact: exact(e)?,
            };
            args::mu_from_youngs::<T>(&e, &exact(nu)?, p)
        })?;
    } else {
        half.mu = moduli.values.clone();
    }
    Ok(half)
}

/// `f` of the texts of every (ν, modulus) (index ν·|moduli| + modulus), formed on the pool;
/// the first refusal in that order.
fn per_pair<T: Sync, V: Send>(
    nus: &Column<T>,
    moduli: &Column<T>,
    f: impl Fn(&str, &str) -> Result<V, CliError> + Sync,
) -> Result<Vec<V>, CliError> {
    let n = moduli.texts.len();
    let all: Vec<_> = (0..nus.texts.len() * n)
        .into_par_iter()
        .map(|j| f(&nus.texts[j / n], &moduli.texts[j % n]))
        .collect();
    all.into_iter().collect()
}

impl<T: Real> HalfSpaces<T> {
    /// μ of ν `iv` and modulus `im`.
    fn mu(&self, iv: usize, im: usize, moduli: usize) -> &T {
        match self.mu_by_nu {
            true => &self.mu[iv * moduli + im],
            false => &self.mu[im],
        }
    }

    /// The columns: the inputs, c_R and M_R with --velocity, the results, the error.
    fn keys(&self) -> Vec<&'static str> {
        let [speed, modulus, size] = self.given.map(Checked::key);
        let mut keys = vec!["nu", modulus, speed, "r_along", "r_across", size];
        if !self.solids.is_empty() {
            keys.extend(["c_r", "mr"]);
        }
        keys.extend("a,a_error,b,b_error,k,k_error,e,e_error,major_axis,p0,p0_error".split(','));
        let other = match self.given[2].option {
            "--load" => ["d0", "d0_error"],
            _ => ["load", "load_error"],
        };
        keys.extend(other.into_iter().chain(["route", "iterations", "error"]));
        keys
    }

    /// The result cells of one point (after its inputs, under `keys`, the columns after the
    /// six inputs): c_R and M_R with --velocity, the values and bounds, or empty cells and the
    /// error.
    fn push_results(
        &self,
        row: &mut Row,
        keys: &[&str],
        r: &moving_hertz::Result<ContactSolution<T>>,
        c_r: Option<&T>,
    ) {
        let s = match r {
            Ok(s) => s,
            // Every result column empty, then the error.
            Err(e) => return row.failed(&keys[..keys.len() - 1], e),
        };
        let mut keys = keys.iter();
        let mut key = || keys.next().copied().unwrap_or_default();
        if let Some(c_r) = c_r {
            row.value(key(), c_r);
            row.value(key(), s.problem().speed.mr());
        }
        let other = match self.given[2].option {
            "--load" => s.d0(),
            _ => s.load(),
        };
        for x in [s.a(), s.b(), s.k(), s.e()] {
            row.estimated([key(), key()], x);
        }
        row.label(key(), s.ellipse().major().label());
        for x in [s.p0(), other] {
            row.estimated([key(), key()], x);
        }
        row.label(key(), s.ellipse().integrals().route.label());
        row.count(key(), s.ellipse().iterations());
        row.text(key(), "");
    }
}

/// Solves the sweep block by block on the pool, writing the rows in input order as they are
/// solved; exit code 1 when a point failed (its row carries the error). Each point's
/// half-space and speed are formed from their text exactly, as `contact` forms them.
fn solve_and_write<T: Real + Send + Sync>(
    a: &ContactSweepArgs,
    total: usize,
    p: T::Prec,
) -> Result<(), CliError> {
    let (grid, half) = grid::<T>(a, p)?;
    let opts = Options::<T> {
        method: a.run.method,
        ..Default::default()
    };
    let keys = half.keys();
    let [nus, moduli, speeds, along, across, sizes] = &grid.cols;
    let nm = moduli.texts.len();
    let solve = |range: std::ops::Range<usize>| {
        let material = |iv: usize| Material::parse(&nus.texts[iv], p);
        let shared = grid.speeds(range.clone(), material, |[iv, im, is, ..], material| {
            let text = &speeds.texts[is];
            match half.given[0].option {
                "--velocity" => half.solids[iv * nm + im].parse_velocity(text),
                "--gap" => material()?.parse_gap(text),
                _ => material()?.parse_speed(text),
            }
        });
        let problems: Vec<_> = (range.clone())
            .map(|j| {
                let [iv, im, _, i1, i2, il] = grid.indices(j);
                let size = sizes.values[il].clone();
                let speed = grid.speed_of(&shared, range.start, j).clone()?;
                Ok(ContactProblem {
                    speed,
                    radius_along: along.values[i1].clone(),
                    radius_across: across.values[i2].clone(),
                    loading: match half.given[2].option {
                        "--load" => Loading::Load(size),
                        _ => Loading::Approach(size),
                    },
                    shear_modulus: half.mu(iv, im, nm).clone(),
                })
            })
            .collect();
        sweep::try_contacts(&problems, &opts)
    };
    let row = |row: &mut Row, j: usize, r: &moving_hertz::Result<ContactSolution<T>>| {
        let [iv, im, ..] = grid.indices(j);
        let c_r = half.solids.get(iv * nm + im).map(Solid::c_r);
        half.push_results(row, &keys[6..], r, c_r);
    };
    write_in_order("sweep contact", &keys, &a.run, &grid, total, solve, row)
}
