//! `moving-hertz sweep contact`: the full moving-punch contact solution at every point of lists
//! or ranges of ν, the modulus, the speed, R1, R2 and the load (or approach), by the library's
//! [`sweep::try_contacts`] (parallel blocks, shared set-ups, continuation), written as CSV or
//! JSON lines in input order as the blocks are solved ([`pipeline::solve_in_order`]). Every
//! input is taken exactly from its text as `contact` takes it, so that a row carries the digits
//! of `contact --json` for the same inputs.

use super::args::{self, Decimal};
use super::contact::ratio_fits;
use super::sweep::{
    axis, check_and_bind, checked_nus, one_of, write_in_order, Axis, Checked, Row, RunArgs,
    APPROACH, GAP, LOAD, NU, R_ACROSS, R_ALONG, SHEAR, SPEED, VELOCITY, YOUNGS,
};
use super::CliError;
use moving_hertz::scalar::{decimal_to_rational, Precision, Real};
use moving_hertz::sweep;
use moving_hertz::{
    with_precision, ContactProblem, ContactSolution, Loading, Material, Moduli, Options, Solid,
    Speed,
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

/// The grid: each axis's values (ν and the speeds as text, the rest rounded), μ (per modulus,
/// or per (ν, E) when E is given without a velocity), in the order of the rows.
struct Grid<T> {
    nus: Vec<String>,
    moduli: Vec<String>,
    speeds: Vec<String>,
    along: Vec<(String, T)>,
    across: Vec<(String, T)>,
    sizes: Vec<(String, T)>,
    /// μ by modulus, or by (ν, E) (index ν·|E| + E) when `mu_by_nu`; empty with --velocity.
    mu: Vec<T>,
    mu_by_nu: bool,
    /// With --velocity, c_R of each (ν, modulus) (index ν·|moduli| + modulus).
    c_r: Vec<T>,
    /// The speed's, the modulus's and the size's options as given (`--gap`, `--youngs-modulus`,
    /// `--load`, …).
    given: [&'static Checked; 3],
    density: String,
}

impl<T> Grid<T> {
    fn velocity(&self) -> bool {
        self.given[0].option == "--velocity"
    }

    fn youngs(&self) -> bool {
        self.given[1].option == "--youngs-modulus"
    }

    fn by_load(&self) -> bool {
        self.given[2].option == "--load"
    }
}

impl<T: Real + Send + Sync> Grid<T> {
    /// The grid of the command line at precision `p`; every refusal before any work.
    fn new(a: &ContactSweepArgs, p: T::Prec) -> Result<Self, CliError> {
        let precision = &a.run.precision;
        let nus = checked_nus::<T>(&a.nu, precision, p)?;
        let [(speed_axis, speed), (modulus_axis, modulus), (size_axis, size)] = a.groups()?;
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
        let texts = |values: Vec<(String, T)>| values.into_iter().map(|(t, _)| t).collect();
        let mut grid = Grid {
            nus: texts(nus),
            moduli: Vec::new(),
            speeds: texts(speeds),
            along,
            across,
            sizes,
            mu: Vec::new(),
            mu_by_nu: false,
            c_r: Vec::new(),
            given: [speed, modulus, size],
            density: String::new(),
        };
        let moduli = positive_values::<T>(modulus_axis, modulus, precision, p)?;
        grid.moduli = moduli.iter().map(|(t, _)| t.clone()).collect();
        grid.half_spaces(a, moduli, modulus.option, p)?;
        Ok(grid)
    }

    /// Forms μ (and, with --velocity, checks every half-space) before any work: a refusal
    /// names the option and quotes the text.
    fn half_spaces(
        &mut self,
        a: &ContactSweepArgs,
        moduli: Vec<(String, T)>,
        option: &'static str,
        p: T::Prec,
    ) -> Result<(), CliError> {
        if let Some(rho) = &a.density {
            args::positive::<T>(rho, "--density", "density rho", p)?;
            self.density = rho.text.clone();
            let context = "forming the half-space's wave speeds";
            self.c_r = self.per_pair(|nu, m| {
                let names = [
                    ("Young's modulus", option, m),
                    ("shear modulus", option, m),
                    ("density", "--density", rho.text.as_str()),
                    ("nu", "--nu", nu),
                ];
                self.solid(nu, m, p)
                    .map(|s| s.c_r().clone())
                    .map_err(|e| CliError::from_run(e, &names, context))
            })?;
            return Ok(());
        }
        if !self.youngs() {
            self.mu = moduli.into_iter().map(|(_, mu)| mu).collect();
            return Ok(());
        }
        // μ = E/(2(1 + ν)) exactly at each (ν, E), rounded once, as `contact` forms it.
        self.mu = self.per_pair(|nu, e| {
            let exact =
                |t: &str| decimal_to_rational(t).map_err(|err| CliError::value(option, t, err));
            let e = Decimal {
                text: e.to_string(),
                exact: exact(e)?,
            };
            args::mu_from_youngs::<T>(&e, &exact(nu)?, p)
        })?;
        self.mu_by_nu = true;
        Ok(())
    }

    /// `f` of the texts of every (ν, modulus) (index ν·|moduli| + modulus), formed on the pool;
    /// the first refusal in that order.
    fn per_pair(
        &self,
        f: impl Fn(&str, &str) -> Result<T, CliError> + Sync,
    ) -> Result<Vec<T>, CliError> {
        let n = self.moduli.len();
        let all: Vec<_> = (0..self.nus.len() * n)
            .into_par_iter()
            .map(|j| f(&self.nus[j / n], &self.moduli[j % n]))
            .collect();
        all.into_iter().collect()
    }

    /// The half-space of ν and modulus text with the density ([`Solid::parse`], as `contact`).
    fn solid(&self, nu: &str, modulus: &str, p: T::Prec) -> moving_hertz::Result<Solid<T>> {
        let density = self.density.as_str();
        let moduli = match self.youngs() {
            true => Moduli::Youngs {
                youngs_modulus: modulus,
                density,
            },
            false => Moduli::Shear {
                shear_modulus: modulus,
                density,
            },
        };
        Solid::parse(nu, moduli, p)
    }

    /// The indices of point `j` on the six axes, in the order of the rows (the last fastest).
    fn indices(&self, mut j: usize) -> [usize; 6] {
        let lens = [
            self.nus.len(),
            self.moduli.len(),
            self.speeds.len(),
            self.along.len(),
            self.across.len(),
            self.sizes.len(),
        ];
        let mut at = [0; 6];
        for (i, n) in lens.iter().enumerate().rev() {
            at[i] = j % n;
            j /= n;
        }
        at
    }
}

/// The half-space of a point: a [`Solid`] (with --velocity) or the material with μ.
enum Half<T: Real> {
    Solid(Solid<T>),
    Material(Material<T>, T),
}

impl<T: Real> Half<T> {
    fn shear_modulus(&self) -> Option<T> {
        match self {
            Half::Solid(s) => s.shear_modulus().cloned(),
            Half::Material(_, mu) => Some(mu.clone()),
        }
    }
}

/// What a block formed last, at its indices: kept while consecutive points share it.
type Cached<K, V> = Option<(K, moving_hertz::Result<V>)>;

impl<T: Real + Send + Sync> Grid<T> {
    /// The half-space of ν `iv` and modulus `im` (checked before any work).
    fn half(&self, iv: usize, im: usize, p: T::Prec) -> moving_hertz::Result<Half<T>> {
        let nu = &self.nus[iv];
        if self.velocity() {
            return self.solid(nu, &self.moduli[im], p).map(Half::Solid);
        }
        let mu = match self.mu_by_nu {
            true => &self.mu[iv * self.moduli.len() + im],
            false => &self.mu[im],
        };
        Ok(Half::Material(Material::parse(nu, p)?, mu.clone()))
    }

    /// The speed `is` in `half`, from its text exactly (as `contact` forms it).
    fn speed(&self, half: &Half<T>, is: usize) -> moving_hertz::Result<Speed<T>> {
        let text = &self.speeds[is];
        match (half, self.given[0].option) {
            (Half::Solid(s), _) => s.parse_velocity(text),
            (Half::Material(m, _), "--gap") => m.parse_gap(text),
            (Half::Material(m, _), _) => m.parse_speed(text),
        }
    }

    /// The problems of the points `range`, each half-space and speed formed once for the
    /// consecutive points that share it.
    fn problems(
        &self,
        range: std::ops::Range<usize>,
        p: T::Prec,
    ) -> Vec<moving_hertz::Result<ContactProblem<T>>> {
        let mut half: Cached<(usize, usize), Half<T>> = None;
        let mut speed: Cached<(usize, usize, usize), Speed<T>> = None;
        let mut out = Vec::with_capacity(range.len());
        for j in range {
            let [iv, im, is, i1, i2, il] = self.indices(j);
            let h = match &mut half {
                Some((at, h)) if *at == (iv, im) => &*h,
                slot => &slot.insert(((iv, im), self.half(iv, im, p))).1,
            };
            let sp = match &mut speed {
                Some((at, sp)) if *at == (iv, im, is) => &*sp,
                slot => {
                    let sp = h
                        .as_ref()
                        .map_err(Clone::clone)
                        .and_then(|h| self.speed(h, is));
                    &slot.insert(((iv, im, is), sp)).1
                }
            };
            let size = self.sizes[il].1.clone();
            let problem = sp.clone().and_then(|speed| {
                let h = h.as_ref().map_err(Clone::clone)?;
                Ok(ContactProblem {
                    speed,
                    radius_along: self.along[i1].1.clone(),
                    radius_across: self.across[i2].1.clone(),
                    loading: if self.by_load() {
                        Loading::Load(size)
                    } else {
                        Loading::Approach(size)
                    },
                    // A half-space of moduli always has μ; none would be refused as 0.
                    shear_modulus: h.shear_modulus().unwrap_or_else(|| T::zero(p)),
                })
            });
            out.push(problem);
        }
        out
    }

    /// c_R of point `j`'s half-space (with --velocity).
    fn c_r(&self, j: usize) -> Option<&T> {
        if self.c_r.is_empty() {
            return None;
        }
        let [iv, im, ..] = self.indices(j);
        self.c_r.get(iv * self.moduli.len() + im)
    }

    /// The texts of point `j`'s inputs, in the order of the columns.
    fn texts(&self, j: usize) -> [&str; 6] {
        let [iv, im, is, i1, i2, il] = self.indices(j);
        [
            &self.nus[iv],
            &self.moduli[im],
            &self.speeds[is],
            &self.along[i1].0,
            &self.across[i2].0,
            &self.sizes[il].0,
        ]
    }

    /// The columns: the inputs, c_R and M_R with --velocity, the results, the error.
    fn keys(&self) -> Vec<&'static str> {
        let [speed, modulus, size] = self.given.map(Checked::key);
        let mut keys = vec!["nu", modulus, speed, "r_along", "r_across", size];
        if self.velocity() {
            keys.extend(["c_r", "mr"]);
        }
        keys.extend("a,a_error,b,b_error,k,k_error,e,e_error,major_axis,p0,p0_error".split(','));
        let other = match self.by_load() {
            true => ["d0", "d0_error"],
            false => ["load", "load_error"],
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
        if self.velocity() {
            match c_r {
                Some(c_r) => row.value(key(), c_r),
                None => row.text(key(), ""),
            }
            row.value(key(), s.problem().speed.mr());
        }
        let other = if self.by_load() { s.d0() } else { s.load() };
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
/// solved; exit code 1 when a point failed (its row carries the error).
fn solve_and_write<T: Real + Send + Sync>(
    a: &ContactSweepArgs,
    total: usize,
    p: T::Prec,
) -> Result<(), CliError> {
    let grid = Grid::<T>::new(a, p)?;
    let opts = Options::<T> {
        method: a.run.method,
        ..Default::default()
    };
    let keys = grid.keys();
    let solve = |range| sweep::try_contacts(&grid.problems(range, p), &opts);
    let row = |row: &mut Row, j: usize, r: &moving_hertz::Result<ContactSolution<T>>| {
        for (key, text) in keys.iter().zip(grid.texts(j)) {
            row.text(key, text);
        }
        grid.push_results(row, &keys[6..], r, grid.c_r(j));
    };
    write_in_order("sweep contact", &keys, &a.run, total, solve, row)
}
