//! `moving-hertz sweep`: the contact ellipse (33) over every (ν, speed, A1/B1) of three lists or
//! ranges, by the library's [`sweep::ellipses_at`] at speeds formed once a (ν, speed) pair
//! (parallel blocks, shared set-ups, continuation), written as CSV or JSON lines in input order as the blocks are solved
//! ([`pipeline::solve_in_order`]).

use super::args::{self, Decimal};
use super::output::{emit, emit_bytes};
use super::pipeline;
use super::progress::Progress;
use super::CliError;
use moving_hertz::scalar::{short, Precision, Real};
use moving_hertz::sweep::{self, AtSpeed, BLOCK};
use moving_hertz::{with_precision, Ellipse, Estimated, Material, Method, Options, Speed};
use rayon::prelude::*;
use rug::{Float, Rational};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock, PoisonError};

/// The most points one sweep solves (checked before any work).
pub const POINT_CAP: usize = 10_000_000;

/// `sweep` with the ellipse sweep's options, or `sweep contact` with its own
/// ([`super::sweep_contact`]): a subcommand and the options exclude each other.
#[derive(clap::Args, Debug)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct SweepCommand {
    #[command(subcommand)]
    pub of: Option<SweepOf>,
    #[command(flatten)]
    pub ellipse: SweepArgs,
}

/// What else `sweep` sweeps.
#[derive(clap::Subcommand, Debug)]
pub enum SweepOf {
    /// The full contact solution (a, b, k, e, p0, and d0 or the load, each with its bound) at
    /// every point of lists or ranges of nu, the speed (M_R, gap or velocity V), R1, R2 and the
    /// load or approach, for one modulus or a list, as CSV or JSON lines in input order (the
    /// load or approach fastest), on every core as `sweep` runs. Exit code 1 if a point failed
    /// (its row carries the error).
    Contact(Box<super::sweep_contact::ContactSweepArgs>),
}

/// Runs `sweep` or `sweep contact`.
pub fn run_command(c: &SweepCommand) -> Result<(), CliError> {
    match &c.of {
        Some(SweepOf::Contact(a)) => super::sweep_contact::run(a),
        None => run(&c.ellipse),
    }
}

#[derive(clap::Args, Debug)]
pub struct SweepArgs {
    /// Poisson's ratios, -1 < NU <= 1/2: a list `0.1,0.2,1/4`, a range `lin:START:STOP:N` (N
    /// points, evenly spaced) or `log:START:STOP:N` (N points, log-spaced; positive ends).
    #[arg(long, value_name = "LIST", value_parser = axis, allow_hyphen_values = true,
          required = true)]
    pub nu: Option<Axis>,
    #[command(flatten)]
    pub speed: SpeedAxis,
    /// Curvature ratios A1/B1 = R2/R1 > 0: a list, `lin:START:STOP:N` (N points, evenly
    /// spaced) or `log:START:STOP:N` (N points, log-spaced).
    #[arg(long, value_name = "LIST", value_parser = axis, required = true)]
    pub ratio: Option<Axis>,
    #[command(flatten)]
    pub run: RunArgs,
}

/// The options both sweeps end with.
#[derive(clap::Args, Debug)]
pub struct RunArgs {
    #[arg(long, value_name = "P", default_value = "f64", value_parser = args::precision,
          help = args::PRECISION_HELP)]
    pub precision: Precision,
    /// How the integrals are evaluated at each Newton iterate: auto, adaptive or fixed.
    #[arg(long, value_name = "METHOD", default_value = "auto", value_parser = args::solve_method())]
    pub method: Method,
    /// The output: csv (a header line, then one row a point) or jsonl (one JSON object a line).
    #[arg(long, value_name = "FORMAT", default_value = "csv")]
    pub format: Format,
}

impl SweepArgs {
    /// `--nu`, `--speed` or `--gap`, and `--ratio`, each with its checks: clap requires them
    /// unless the subcommand is given, which leaves them out (hence their `Option`).
    fn axes(&self) -> Result<[(&Axis, &'static Checked); 3], CliError> {
        let speed = one_of([(&self.speed.speed, &SPEED), (&self.speed.gap, &GAP)]);
        match (&self.nu, speed, &self.ratio) {
            (Some(nu), Ok(speed), Some(ratio)) => Ok([(nu, &NU), speed, (ratio, &RATIO)]),
            _ => Err(CliError::Input(
                "sweep needs --nu LIST, --speed or --gap LIST and --ratio LIST (or the \
                 subcommand contact)"
                    .into(),
            )),
        }
    }
}

/// The axis of the option of `group` that was given, with its checks; none given is refused
/// (clap requires each group; this is the same check where the types ask for it).
pub(super) fn one_of<'a, const N: usize>(
    group: [(&'a Option<Axis>, &'static Checked); N],
) -> Result<(&'a Axis, &'static Checked), CliError> {
    if let Some((Some(axis), c)) = group.iter().find(|(axis, _)| axis.is_some()) {
        return Ok((axis, c));
    }
    let options = group.map(|(_, c)| c.option);
    let (last, rest) = options.split_last().unwrap_or((&"", &[]));
    let what = format!("one of {} and {last}", rest.join(", "));
    Err(CliError::Input(format!("{what} is required")))
}

/// `--speed LIST` or `--gap LIST`: exactly one.
#[derive(clap::Args, Debug)]
#[group(required = true, multiple = false)]
pub struct SpeedAxis {
    /// Speeds M_R = V/c_R, 0 <= M_R < 1: a list, `lin:START:STOP:N` (N points, evenly spaced)
    /// or `log:START:STOP:N` (N points, log-spaced; positive ends); each gap 1 - M_R formed
    /// exactly from the decimal.
    #[arg(long, value_name = "LIST", value_parser = axis)]
    pub speed: Option<Axis>,
    /// Speeds by their gap G = 1 - M_R, 0 < G <= 1: a list, `lin:START:STOP:N` (N points,
    /// evenly spaced) or `log:START:STOP:N` (N points, log-spaced; e.g. `log:1e-2:1e-12:11`
    /// walks M_R -> 1).
    #[arg(long, value_name = "LIST", value_parser = axis)]
    pub gap: Option<Axis>,
}

/// The output format.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Csv,
    Jsonl,
}

/// One option's values: decimals as typed, or a linear or logarithmic range.
#[derive(Clone, Debug)]
pub enum Axis {
    List(Vec<Decimal>),
    Range {
        log: bool,
        start: Decimal,
        stop: Decimal,
        n: usize,
    },
}

/// The value parser of a list or a range (`lin:START:STOP:N`, `log:START:STOP:N`, N ≥ 2, log
/// ranges of positive ends); each number as [`args::decimal`] reads it.
pub fn axis(s: &str) -> Result<Axis, String> {
    let s = s.trim();
    for (prefix, log) in [("lin:", false), ("log:", true)] {
        if let Some(rest) = s.strip_prefix(prefix) {
            let parts: Vec<&str> = rest.split(':').collect();
            let [a, b, n] = parts[..] else {
                return Err(format!("a range is {prefix}START:STOP:N"));
            };
            let n: usize = n
                .trim()
                .parse()
                .ok()
                .filter(|n| (2..=POINT_CAP).contains(n))
                .ok_or_else(|| format!("N = {n} is not a count from 2 to {POINT_CAP}"))?;
            let (start, stop) = (args::decimal(a)?, args::decimal(b)?);
            if log && (start.exact <= 0 || stop.exact <= 0) {
                return Err("a log range needs positive ends".into());
            }
            return Ok(Axis::Range {
                log,
                start,
                stop,
                n,
            });
        }
    }
    if let Some((prefix, _)) = s.split_once(':') {
        return Err(format!(
            "'{prefix}:' is not a range: a range is lin:START:STOP:N (evenly spaced) or \
             log:START:STOP:N (log-spaced), N points"
        ));
    }
    let items = s
        .split(',')
        .map(args::decimal)
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Axis::List(items))
}

impl Axis {
    pub(super) fn len(&self) -> usize {
        match self {
            Axis::List(v) => v.len(),
            Axis::Range { n, .. } => *n,
        }
    }

    /// The smallest and largest exact value (a range's ends, which bound it).
    pub(super) fn extremes(&self) -> Vec<&Decimal> {
        match self {
            Axis::List(v) => v.iter().collect(),
            Axis::Range { start, stop, .. } => vec![start, stop],
        }
    }

    /// The values at precision `p` with their text: a list's as typed, a range's as the value
    /// at the working precision prints (a linear range's points exact before their one
    /// rounding, a log range's formed 64 bits above the working precision), formed on the
    /// pool's threads.
    pub(super) fn values<T: Real + Send>(&self, p: T::Prec) -> Vec<(String, T)> {
        match self {
            Axis::List(v) => v
                .iter()
                .map(|d| (d.text.clone(), exact::<T>(&d.exact, p)))
                .collect(),
            Axis::Range { n, .. } => {
                let point = self.points(T::bits(p) + 64);
                (0..*n)
                    .into_par_iter()
                    .map(|j| {
                        let x = T::from_float(&point(j).0, p);
                        (x.to_decimal(), x)
                    })
                    .collect()
            }
        }
    }
}

impl Axis {
    /// Point `j` at `bits` as a function of `j` (MPFR's exponent range holds any typed value; a
    /// linear range's point is exact before this one rounding) and whether it is exactly 0; a log
    /// range's logarithms of its ends formed once.
    fn points(&self, bits: u32) -> impl Fn(usize) -> (Float, bool) + '_ {
        let logs = match self {
            Axis::Range {
                log: true,
                start,
                stop,
                ..
            } => Some((
                Float::with_val(bits, &start.exact).ln(),
                Float::with_val(bits, &stop.exact).ln(),
            )),
            _ => None,
        };
        move |j| {
            let q = match (self, &logs) {
                (Axis::List(v), _) => v[j].exact.clone(),
                (Axis::Range { n, .. }, Some((la, lb))) => {
                    let t = Float::with_val(bits, Rational::from((j as u64, *n as u64 - 1)));
                    return ((la.clone() + (lb.clone() - la) * t).exp(), false);
                }
                (Axis::Range { start, stop, n, .. }, None) => {
                    let t = Rational::from((j as u64, *n as u64 - 1));
                    start.exact.clone() + (stop.exact.clone() - &start.exact) * t
                }
            };
            (Float::with_val(bits, &q), q == 0)
        }
    }
}

/// An exact value rounded once to precision `p`.
fn exact<T: Real>(q: &Rational, p: T::Prec) -> T {
    T::from_float(&Float::with_val(T::bits(p) + 64, q), p)
}

/// An option a sweep checks before any work: its flag, what messages call it, and its domain
/// as messages write it (`(-1, 1/2]`: the brackets say whether an end is included, `inf` is no
/// bound), from which the check reads its ends.
pub(super) struct Checked {
    pub option: &'static str,
    pub what: &'static str,
    domain: &'static str,
}

const fn checked(option: &'static str, what: &'static str, domain: &'static str) -> Checked {
    Checked {
        option,
        what,
        domain,
    }
}

pub(super) const NU: Checked = checked("--nu", "nu (Poisson's ratio)", "(-1, 1/2]");
pub(super) const SPEED: Checked = checked("--speed", "speed M_R", "[0, 1)");
pub(super) const GAP: Checked = checked("--gap", "gap 1 - M_R", "(0, 1]");
pub(super) const VELOCITY: Checked = checked("--velocity", "velocity V", "[0, inf)");
const RATIO: Checked = checked("--ratio", "curvature ratio A1/B1", "(0, inf)");
pub(super) const R_ALONG: Checked = checked("--r-along", "radius along the motion R1", "(0, inf)");
pub(super) const R_ACROSS: Checked =
    checked("--r-across", "radius across the motion R2", "(0, inf)");
pub(super) const LOAD: Checked = checked("--load", "load P", "(0, inf)");
pub(super) const APPROACH: Checked = checked("--approach", "approach d0", "(0, inf)");
pub(super) const SHEAR: Checked = checked("--shear-modulus", "shear modulus mu", "(0, inf)");
pub(super) const YOUNGS: Checked = checked("--youngs-modulus", "Young's modulus E", "(0, inf)");

impl Checked {
    /// The option's key in the sweeps' rows: `gap` for `--gap`, `r_along` for `--r-along`.
    pub(super) fn key(&self) -> &'static str {
        match self.option {
            "--shear-modulus" => "shear_modulus",
            "--youngs-modulus" => "youngs_modulus",
            "--r-along" => "r_along",
            "--r-across" => "r_across",
            option => &option[2..],
        }
    }

    /// Whether `x` lies in the domain, exactly.
    fn holds(&self, x: &Rational) -> bool {
        let d = self.domain;
        let (low, high) = d[1..d.len() - 1].split_once(", ").unwrap_or(("inf", "inf"));
        let end = |t: &str| t.parse::<Rational>().ok();
        let low_ok = end(low).is_none_or(|b| if d.starts_with('[') { *x >= b } else { *x > b });
        let high_ok = end(high).is_none_or(|b| if d.ends_with(']') { *x <= b } else { *x < b });
        low_ok && high_ok
    }

    /// Checks every value of `axis` against the domain, exactly (a range by its ends); a
    /// refusal names the option and quotes the text.
    pub(super) fn check(&self, axis: &Axis) -> Result<(), CliError> {
        match axis.extremes().into_iter().find(|d| !self.holds(&d.exact)) {
            Some(d) => {
                let why = format!(
                    "{} = {} is outside its domain {}",
                    self.what, d.text, self.domain
                );
                Err(CliError::value(self.option, &d.text, why))
            }
            None => Ok(()),
        }
    }

    /// The values of `axis` at precision `p` ([`Axis::values`]), refused, naming the option and
    /// its text as typed, unless each is a normal number of the working precision: one that
    /// overflows, or a nonzero one that rounds to a subnormal or to 0 (a range's end of 1e-4000
    /// at `f64`, which would have been solved as 0).
    pub(super) fn values<T: Real + Send>(
        &self,
        axis: &Axis,
        precision: &Precision,
        p: T::Prec,
    ) -> Result<Vec<(String, T)>, CliError> {
        let values = axis.values::<T>(p);
        let point = axis.points(64);
        for (j, (_, x)) in values.iter().enumerate() {
            let normal = x.is_finite() && x.clone().abs() >= T::min_positive(p);
            if normal || (x.is_zero() && point(j).1) {
                continue;
            }
            let what = self.what;
            let (text, why) = match axis {
                Axis::List(v) => (v[j].text.clone(), format!("{what} = {} is", v[j].text)),
                Axis::Range {
                    log,
                    start,
                    stop,
                    n,
                } => (
                    format!(
                        "{}:{}:{}:{n}",
                        if *log { "log" } else { "lin" },
                        start.text,
                        stop.text
                    ),
                    format!(
                        "{what}: its point {} of {n}, {}, is",
                        j + 1,
                        point(j).0.to_string_radix(10, Some(6))
                    ),
                ),
            };
            let why = format!(
                "{why} not a normal number of {precision} (rescale, or use a wider precision)"
            );
            return Err(CliError::value(self.option, &text, why));
        }
        Ok(values)
    }
}

/// The sweep commands' preamble, before any work: each axis's domain checked exactly (in the
/// order given: the first refusal is reported), the point count against [`POINT_CAP`], then
/// the global pool bound for that many points. Returns the count.
pub(super) fn check_and_bind(
    axes: &[(&Axis, &Checked)],
    precision: &Precision,
) -> Result<usize, CliError> {
    for (axis, checked) in axes {
        checked.check(axis)?;
    }
    // Saturating: six axes of up to POINT_CAP values each overflow a u128.
    let total = (axes.iter()).fold(1u128, |n, (axis, _)| n.saturating_mul(axis.len() as u128));
    if total > POINT_CAP as u128 {
        let total = match total {
            u128::MAX => "more than 10^38".to_string(),
            n => n.to_string(),
        };
        return Err(CliError::Input(format!(
            "the sweep has {total} points, more than the {POINT_CAP} one run solves"
        )));
    }
    super::bind_global_pool(total as usize, precision);
    Ok(total as usize)
}

pub fn run(a: &SweepArgs) -> Result<(), CliError> {
    let total = check_and_bind(&a.axes()?, &a.run.precision)?;
    with_precision!(a.run.precision, T, p => solve_and_write::<T>(a, total, p))
}

/// An axis's values at the working precision: each value's output cell in the sweep's format
/// (quoted where CSV or JSON needs it, once a value rather than once a row), the value, and
/// where asked its text (as typed for a list, as the value prints for a range).
pub(super) struct Column<T> {
    pub texts: Vec<String>,
    pub values: Vec<T>,
    cells: Vec<String>,
}

impl<T> Column<T> {
    pub(super) fn new(values: Vec<(String, T)>, format: Format, keep_texts: bool) -> Self {
        let n = values.len();
        let mut col = Column {
            texts: Vec::with_capacity(if keep_texts { n } else { 0 }),
            values: Vec::with_capacity(n),
            cells: Vec::with_capacity(n),
        };
        for (text, x) in values {
            let mut cell = Vec::new();
            push_cell(&mut cell, format == Format::Jsonl, &text);
            col.cells.push(String::from_utf8_lossy(&cell).into_owned());
            col.values.push(x);
            if keep_texts {
                col.texts.push(text);
            }
        }
        col
    }
}

/// A sweep's grid: its axes in the order of the rows (the last fastest), ν first, the speed's
/// axis at `speed`. Its points are formed a block at a time, so that a sweep holds one batch of
/// points and rows, not all of them; the material of each ν and each speed (the axes up to the
/// speed's) are formed once, when the first block with a point of them is solved, and shared
/// by every block of their points ([`sweep::ellipses_at`]: a speed's set-ups and solve cache
/// built once a speed, not once a block), until their last point is taken.
pub(super) struct Grid<T: Real, const N: usize> {
    pub cols: [Column<T>; N],
    speed: usize,
    materials: Live<moving_hertz::Result<Material<T>>>,
    speeds: Live<moving_hertz::Result<Speed<T>>>,
}

/// A speed shared by the points of a block, formed on first use.
pub(super) type Shared<T> = Arc<OnceLock<moving_hertz::Result<Speed<T>>>>;

impl<T: Real, const N: usize> Grid<T, N> {
    pub(super) fn new(cols: [Column<T>; N], speed: usize) -> Self {
        Grid {
            cols,
            speed,
            materials: Live::default(),
            speeds: Live::default(),
        }
    }

    /// How many consecutive points share the value of axis `i` (and of every axis before it).
    pub(super) fn stride(&self, i: usize) -> usize {
        self.cols[i + 1..].iter().map(|c| c.values.len()).product()
    }

    /// The indices of point `j` on the axes.
    pub(super) fn indices(&self, mut j: usize) -> [usize; N] {
        let mut at = [0; N];
        for (i, c) in self.cols.iter().enumerate().rev() {
            at[i] = j % c.values.len();
            j /= c.values.len();
        }
        at
    }

    /// The speeds of the points `range`, one for each run of points that share one (from the
    /// run of `range.start`), each formed once by `form` from its first point's indices and the
    /// material of its ν (formed once by `material` from ν's index, when `form` first asks).
    pub(super) fn speeds(
        &self,
        range: std::ops::Range<usize>,
        material: impl Fn(usize) -> moving_hertz::Result<Material<T>>,
        form: impl for<'m> Fn([usize; N], Materials<'m, T>) -> moving_hertz::Result<Speed<T>>,
    ) -> Vec<Shared<T>> {
        let (per, per_nu) = (self.stride(self.speed), self.stride(0));
        let Some(last) = range.end.checked_sub(1) else {
            return Vec::new();
        };
        (range.start / per..=last / per)
            .map(|run| {
                let n = range.end.min((run + 1) * per) - range.start.max(run * per);
                let speed = self.speeds.take(run, per, n);
                speed.get_or_init(|| {
                    let at = self.indices(run * per);
                    let m = self.materials.take(at[0], per_nu / per, 1);
                    form(at, &|| {
                        let m = m.get_or_init(|| material(at[0]));
                        m.as_ref().map_err(Clone::clone)
                    })
                });
                speed
            })
            .collect()
    }

    /// Point `j`'s speed among the `speeds` of a block that begins at `start`.
    pub(super) fn speed_of<'s>(
        &self,
        speeds: &'s [Shared<T>],
        start: usize,
        j: usize,
    ) -> &'s moving_hertz::Result<Speed<T>> {
        let per = self.stride(self.speed);
        let s = &speeds[j / per - start / per];
        s.get_or_init(|| unreachable!("every speed of a block is formed before its points"))
    }
}

/// The material of a speed's ν (formed once for every speed of it), or its error.
pub(super) type Materials<'m, T> = &'m dyn Fn() -> moving_hertz::Result<&'m Material<T>>;

/// Values that many points share, each formed on first use and kept while points of it are
/// still to be taken (a count of points given with the first take): the sweep holds those of
/// the points being solved only, whatever its size, and forms each once whatever the order in
/// which the threads take its points.
struct Live<V>(Mutex<HashMap<usize, Taken<V>>>);

/// A value of [`Live`] and the count of its points not yet taken.
type Taken<V> = (Arc<OnceLock<V>>, usize);

impl<V> Default for Live<V> {
    fn default() -> Self {
        Live(Mutex::new(HashMap::new()))
    }
}

impl<V> Live<V> {
    /// The value of `key`, of `total` points in all, taken for `n` of them: dropped from here
    /// once all are taken (the takers' handles keep it while they use it).
    fn take(&self, key: usize, total: usize, n: usize) -> Arc<OnceLock<V>> {
        let mut live = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        let (value, left) = live
            .entry(key)
            .or_insert_with(|| (Arc::new(OnceLock::new()), total));
        *left = left.saturating_sub(n);
        let value = value.clone();
        if *left == 0 {
            live.remove(&key);
        }
        value
    }
}

/// The values of `--nu` at `p`, refused before any work, naming the text,
/// where one is not a normal number of the working precision or rounds onto −1.
pub(super) fn checked_nus<T: Real + Send>(
    axis: &Axis,
    precision: &Precision,
    p: T::Prec,
) -> Result<Vec<(String, T)>, CliError> {
    let nus = NU.values::<T>(axis, precision, p)?;
    // ν > −1 exactly (checked before) may round onto −1 at the working precision, where the
    // material is not defined: refused here by the single commands' own check, with the text.
    if let Some((text, nu)) = nus.iter().find(|(_, nu)| *nu <= -T::one(p)) {
        let why = Material::<T>::parse(text, p).err().map_or_else(
            || format!("nu (Poisson's ratio) = {text} rounds to {}", short(nu)),
            |e| e.to_string(),
        );
        return Err(CliError::value("--nu", text, why));
    }
    Ok(nus)
}

/// Solves the sweep block by block on the pool, writing the rows in input order as they are
/// solved; exit code 1 when a point failed (its row carries the error). The axes' values that
/// overflow or underflow the working precision are refused before any work.
fn solve_and_write<T: Real + Send + Sync>(
    a: &SweepArgs,
    total: usize,
    p: T::Prec,
) -> Result<(), CliError> {
    let [(nu, _), (speed, given), (ratio, _)] = a.axes()?;
    let (precision, format) = (&a.run.precision, a.run.format);
    let grid = Grid::new(
        [
            Column::new(checked_nus(nu, precision, p)?, format, false),
            Column::new(given.values::<T>(speed, precision, p)?, format, true),
            Column::new(RATIO.values::<T>(ratio, precision, p)?, format, false),
        ],
        1,
    );
    let opts = Options::<T> {
        method: a.run.method,
        ..Default::default()
    };
    let [nus, speeds, ratios] = &grid.cols;
    let results = "k,k_error,e,e_error,major_axis,route,iterations,error".split(',');
    let keys: Vec<_> = ["nu", given.key(), "ratio"]
        .into_iter()
        .chain(results)
        .collect();
    let solve = |range: std::ops::Range<usize>| {
        let shared = grid.speeds(
            range.clone(),
            |iv| Material::new(nus.values[iv].clone()),
            |[_, is, _], material| match given.key() {
                "gap" => material()?.speed_from_gap(speeds.values[is].clone()),
                _ => material()?.parse_speed(&speeds.texts[is]),
            },
        );
        let points: Vec<_> = (range.clone())
            .map(|j| AtSpeed {
                speed: grid.speed_of(&shared, range.start, j),
                ratio: &ratios.values[j % ratios.values.len()],
            })
            .collect();
        sweep::ellipses_at(&points, &opts)
    };
    let row = |row: &mut Row, r: &moving_hertz::Result<Ellipse<T>>| match r {
        Ok(e) => {
            row.estimated(["k", "k_error"], e.k());
            row.estimated(["e", "e_error"], e.e());
            row.label("major_axis", e.major().label());
            row.label("route", e.integrals().route.label());
            row.count("iterations", e.iterations());
            row.text("error", "");
        }
        Err(err) => row.failed(&keys[3..10], err),
    };
    write_in_order("sweep", &keys, &a.run, &grid, total, solve, |r, _, x| {
        row(r, x)
    })
}

/// Writes the CSV header of `keys` (in CSV), then solves the points of `0..total` block by block
/// on every thread (`solve` gives a block's results in order) and writes their lines (the
/// point's input cells from `grid`, then what `row` appends: its results or its error) in input
/// order ([`pipeline::solve_in_order`]), the lines formed where their block is solved, under a
/// progress bar `label`; then [`CliError::Failed`] counting the points that failed.
pub(super) fn write_in_order<T: Real + Sync, R, const N: usize>(
    label: &str,
    keys: &[&str],
    run: &RunArgs,
    grid: &Grid<T, N>,
    total: usize,
    solve: impl Fn(std::ops::Range<usize>) -> Vec<moving_hertz::Result<R>> + Sync,
    row: impl Fn(&mut Row, usize, &moving_hertz::Result<R>) + Sync,
) -> Result<(), CliError> {
    if run.format == Format::Csv {
        emit(&(keys.join(",") + "\n"))?;
    }
    let bar = Progress::new(label, total);
    let solve = |range: std::ops::Range<usize>, out: &mut Vec<u8>| {
        let (n, mut failed) = (range.len(), 0);
        // Read in place (a result is a few hundred bytes: not moved out).
        for (j, r) in range.clone().zip(&solve(range)) {
            failed += usize::from(r.is_err());
            // Room for the whole line first, so that its cells never reallocate.
            out.reserve(ROW_BYTES);
            let mut line = Row::new(out, run.format);
            for ((key, col), i) in keys.iter().zip(&grid.cols).zip(grid.indices(j)) {
                line.open(key);
                line.out.extend_from_slice(col.cells[i].as_bytes());
            }
            row(&mut line, j, r);
            line.end();
        }
        bar.advance(n);
        failed
    };
    let failed = pipeline::solve_in_order(total, BLOCK, solve, emit_bytes)?;
    bar.finish();
    if failed > 0 {
        let precision = &run.precision;
        return Err(CliError::Failed(format!(
            "{failed} of {total} points failed at {precision}; their rows carry the error"
        )));
    }
    Ok(())
}

/// Room for a row of `sweep` at `f64` (its longest: three inputs of up to 24 bytes, two
/// decimals of 24, two bounds of 10, the labels and count, in JSON their keys and quotes).
const ROW_BYTES: usize = 256;

/// One line of the output being written: CSV cells, or a JSON object's members (an empty cell
/// is left out of the object). The one writer of the `sweep` commands' cells: numbers with
/// every digit of the working precision ([`Real::push_decimal`]), bounds with three
/// ([`moving_hertz::RelError::push_text`]), counts, labels and quoted text.
pub(super) struct Row<'a> {
    out: &'a mut Vec<u8>,
    json: bool,
    first: bool,
}

impl<'a> Row<'a> {
    /// A line begun in `out` (in JSON its brace); [`Row::end`] ends it.
    #[inline(always)]
    pub(super) fn new(out: &'a mut Vec<u8>, format: Format) -> Self {
        let json = format == Format::Jsonl;
        if json {
            out.push(b'{');
        }
        Row {
            out,
            json,
            first: true,
        }
    }

    /// Ends the line (in JSON the closing brace).
    #[inline(always)]
    pub(super) fn end(self) {
        if self.json {
            self.out.push(b'}');
        }
        self.out.push(b'\n');
    }

    /// The separator before every cell but the first, and in JSON the key.
    #[inline(always)]
    fn open(&mut self, key: &str) {
        if !self.first {
            self.out.push(b',');
        }
        self.first = false;
        if self.json {
            push_json(self.out, key);
            self.out.push(b':');
        }
    }

    /// A cell that needs no quoting or escaping in either format (a number, a label), written
    /// by `write` (in JSON as a string).
    #[inline(always)]
    fn number(&mut self, key: &str, write: impl FnOnce(&mut Vec<u8>)) {
        self.open(key);
        if self.json {
            self.out.push(b'"');
        }
        write(self.out);
        if self.json {
            self.out.push(b'"');
        }
    }

    /// A value with every digit of the working precision.
    #[inline(always)]
    pub(super) fn value<T: Real>(&mut self, key: &str, x: &T) {
        self.number(key, |o| x.push_decimal(o));
    }

    /// A value and its bound under the two `keys`.
    #[inline(always)]
    pub(super) fn estimated<T: Real>(&mut self, keys: [&str; 2], x: &Estimated<T>) {
        self.value(keys[0], &x.value);
        self.number(keys[1], |o| x.error.push_text(o));
    }

    /// A label (ASCII, no comma or quote: an axis, a route).
    #[inline(always)]
    pub(super) fn label(&mut self, key: &str, label: &str) {
        self.number(key, |o| o.extend_from_slice(label.as_bytes()));
    }

    /// A count, in decimal digits.
    #[inline(always)]
    pub(super) fn count(&mut self, key: &str, n: usize) {
        self.number(key, |o| push_count(o, n));
    }

    /// A cell of any text: quoted where CSV or JSON needs it; an empty one is left out of JSON.
    #[inline(always)]
    pub(super) fn text(&mut self, key: &str, v: &str) {
        if self.json && v.is_empty() {
            return;
        }
        self.open(key);
        push_cell(self.out, self.json, v);
    }

    /// The cells of a point that failed: empty under `empty` (the result's columns), and the
    /// error under `error`.
    #[inline(always)]
    pub(super) fn failed(&mut self, empty: &[&str], err: &moving_hertz::Error) {
        for key in empty {
            self.text(key, "");
        }
        self.text("error", &err.to_string());
    }
}

/// Appends the text `v` as a JSON string, or as a CSV cell (quoted where it holds a comma or
/// a quote).
fn push_cell(out: &mut Vec<u8>, json: bool, v: &str) {
    if json {
        push_json(out, v);
    } else if v.bytes().any(|b| b == b',' || b == b'"') {
        out.push(b'"');
        out.extend_from_slice(v.replace('"', "\"\"").as_bytes());
        out.push(b'"');
    } else {
        out.extend_from_slice(v.as_bytes());
    }
}

/// Appends the decimal digits of `n`.
fn push_count(out: &mut Vec<u8>, mut n: usize) {
    let mut digits = [0u8; 20];
    let mut at = digits.len();
    loop {
        at -= 1;
        digits[at] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    out.extend_from_slice(&digits[at..]);
}

/// Appends `s` as a JSON string, escaped as `serde_json` escapes it.
fn push_json(out: &mut Vec<u8>, s: &str) {
    if s.bytes().any(|b| b == b'"' || b == b'\\' || b < b' ') {
        out.extend_from_slice(serde_json::Value::from(s).to_string().as_bytes());
    } else {
        out.push(b'"');
        out.extend_from_slice(s.as_bytes());
        out.push(b'"');
    }
}

#[cfg(test)]
#[path = "../../tests/unit/cli_sweep.rs"]
mod tests;
