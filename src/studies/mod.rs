//! Studies: convergence, stability, cost and accuracy experiments whose data (CSV) and charts
//! (SVG) are committed under `docs/`. Each study is a library function returning its tables, run
//! by a `moving-hertz study …` command; only this layer writes files. No item of this module
//! implements a formula of the paper: they write, read and measure the studies' results.

pub mod fig2;
pub mod integrals;
pub mod pareto;
pub mod poisson;
pub mod rayleigh;
pub mod series;
pub mod stability;
pub mod svg;

use moving_hertz::scalar::{MpPrec, Precision};
use std::io::{IoSlice, Write};
use std::path::Path;
use std::time::Instant;

/// The error `e` met on the file `path`, with the file named first (`path: message`) and the
/// kind kept: a write that fails says which of a study's files it was.
pub fn naming(path: &Path) -> impl Fn(std::io::Error) -> std::io::Error + '_ {
    move |e| std::io::Error::new(e.kind(), format!("{}: {e}", path.display()))
}

/// The file `path`, created (or emptied) for writing, with its parent directories.
fn create(path: &Path) -> std::io::Result<std::fs::File> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    std::fs::File::create(path)
}

/// Writes `rows` under the header line `header` (the column names, comma-separated) as CSV to
/// `path`, creating parent directories; an error names the file.
pub fn write_csv(path: &Path, header: &str, rows: &[Vec<String>]) -> std::io::Result<()> {
    let body: String = rows.iter().map(|r| r.join(",") + "\n").collect();
    write_pieces(path, &[format!("{header}\n"), body])
}

/// Writes text (an SVG chart, a Markdown table) to `path`, creating parent directories. A
/// chart with a series that has no point to draw is refused (an error naming the file and the
/// series): a figure never silently omits a curve its legend promises. Every error names the
/// file.
pub fn write_text(path: &Path, text: &str) -> std::io::Result<()> {
    if let Some(i) = text.find(&format!("<!-- {}: ", svg::EMPTY_SERIES)) {
        let label = text[i..].split("-->").next().unwrap_or_default();
        let refused = std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!("{} --> refused", &label[5..]),
        );
        return Err(naming(path)(refused));
    }
    write_pieces(path, &[text])
}

/// Writes `pieces` one after the other to `path` (one `writev` call for all of them where the
/// system takes them at once), creating parent directories; an error names the file. For a
/// table formed in pieces on several cores: it is never joined in memory.
pub fn write_pieces(path: &Path, pieces: &[impl AsRef<str>]) -> std::io::Result<()> {
    let write = || {
        let mut f = create(path)?;
        let mut slices: Vec<IoSlice> = (pieces.iter())
            .map(|p| p.as_ref().as_bytes())
            .filter(|p| !p.is_empty())
            .map(IoSlice::new)
            .collect();
        let mut rest = &mut slices[..];
        while !rest.is_empty() {
            match f.write_vectored(rest) {
                Ok(0) => return Err(std::io::ErrorKind::WriteZero.into()),
                Ok(n) => IoSlice::advance_slices(&mut rest, n),
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                Err(e) => return Err(e),
            }
        }
        Ok(())
    };
    write().map_err(naming(path))
}

/// A CSV table as [`write_csv`] writes it (fields without commas), read back to draw a study's
/// charts from its committed data.
#[derive(Clone, Debug)]
pub struct Table {
    /// The file, for messages.
    pub path: String,
    /// The column names.
    pub header: Vec<String>,
    /// The fields of each row.
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// The table in the file `path`; an error names the file (and the line whose field count
    /// differs from the header's).
    pub fn read(path: &Path) -> std::io::Result<Table> {
        let text = std::fs::read_to_string(path).map_err(naming(path))?;
        let mut lines = text.lines();
        let split = |l: &str| l.split(',').map(str::to_string).collect::<Vec<_>>();
        let header = lines.next().map(split).unwrap_or_default();
        let rows: Vec<Vec<String>> = lines.map(split).collect();
        if let Some(i) = rows.iter().position(|r| r.len() != header.len()) {
            let bad = std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!(
                    "line {}: {} fields, the header has {}",
                    i + 2,
                    rows[i].len(),
                    header.len()
                ),
            );
            return Err(naming(path)(bad));
        }
        let path = path.display().to_string();
        Ok(Table { path, header, rows })
    }
    /// Each row read by `row` (from its index); the first error.
    pub fn each<R>(&self, row: impl Fn(usize) -> Result<R, String>) -> Result<Vec<R>, String> {
        (0..self.rows.len()).map(row).collect()
    }
    /// The message `e` about row `i`, naming the file and the line.
    pub fn at(&self, i: usize, e: impl std::fmt::Display) -> String {
        format!("{}: line {}: {e}", self.path, i + 2)
    }
    /// The field of row `i` in column `name`.
    pub fn text(&self, i: usize, name: &str) -> Result<String, String> {
        let j = (self.header.iter().position(|h| h == name))
            .ok_or_else(|| format!("{}: no column {name}", self.path))?;
        Ok(self.rows[i][j].clone())
    }
    /// The number in row `i`, column `name` (a float, `NaN` reading as NaN, or a count).
    pub fn number<F: std::str::FromStr>(&self, i: usize, name: &str) -> Result<F, String> {
        let t = self.text(i, name)?;
        t.parse()
            .map_err(|_| self.at(i, format!("{name} = {t:?} is not a number")))
    }
    /// The precision labelled in row `i`, column `name` (`f64`, `dd`, `mpfr256`).
    pub fn precision(&self, i: usize, name: &str) -> Result<Precision, String> {
        let t = self.text(i, name)?;
        Precision::parse(t.strip_prefix("mpfr").unwrap_or(&t)).map_err(|e| self.at(i, e))
    }
}

/// One measurement of a timing study (`integrals`, `pareto`): a method at one precision and
/// speed, its error against the study's reference, its own estimate, its work and median time,
/// or why it failed (then the numbers are NaN). `M` names the method (a route, a method).
#[derive(Clone, Debug)]
pub struct Timed<M> {
    /// M_R.
    pub mr: f64,
    /// The method.
    pub method: M,
    /// The precision.
    pub precision: Precision,
    /// Relative error against the reference.
    pub error: f64,
    /// The method's own error estimate.
    pub estimate: f64,
    /// Median time per evaluation, ns.
    pub time_ns: f64,
    /// Terms or evaluations (0 where the study does not count them).
    pub work: usize,
    /// Why the method failed, if it did.
    pub failure: Option<String>,
}

impl<M: Copy> Timed<M> {
    /// The measurement of `method` at `precision`, M_R = `mr`, filled by `measure` (its error
    /// is the failure).
    pub fn measure(
        mr: f64,
        method: M,
        precision: Precision,
        measure: impl FnOnce(&mut Timed<M>) -> Result<(), String>,
    ) -> Timed<M> {
        let nan = f64::NAN;
        let mut t = Timed {
            mr,
            method,
            precision,
            error: nan,
            estimate: nan,
            time_ns: nan,
            work: 0,
            failure: None,
        };
        t.failure = measure(&mut t).err();
        t
    }

    /// The rows of a timing study's CSV table (columns `mr`, `method`, `precision`, `error`
    /// (the error's column), `error_estimate`, `time_ns`, `failure`, and `work` where the table
    /// has it), the method read by `method`: the data its charts are drawn from. An error names
    /// the line that does not read. Reads measurements back; no arithmetic.
    pub fn read(
        table: &Table,
        error: &str,
        method: impl Fn(&str) -> Option<M>,
    ) -> Result<Vec<Timed<M>>, String> {
        table.each(|i| {
            let (m, f) = (table.text(i, "method")?, table.text(i, "failure")?);
            Ok(Timed {
                mr: table.number(i, "mr")?,
                method: method(&m).ok_or_else(|| table.at(i, format!("no method {m:?}")))?,
                precision: table.precision(i, "precision")?,
                error: table.number(i, error)?,
                estimate: table.number(i, "error_estimate")?,
                time_ns: table.number(i, "time_ns")?,
                work: match table.header.iter().any(|h| h == "work") {
                    true => table.number(i, "work")?,
                    false => 0,
                },
                failure: (!f.is_empty()).then_some(f),
            })
        })
    }

    /// The correct digits (an exact result counts the digits of its precision).
    pub fn digits(&self) -> f64 {
        correct_digits(self.error, full_digits(self.precision.bits()))
    }
}

/// A timing study's Pareto chart at one speed: correct digits (linear) against time (log), a
/// line per method of `methods` (label, method) through its precisions in order of time, in the
/// colour and marker of its place; a method's failures named in the legend, not drawn.
pub fn pareto_chart<M: Copy + PartialEq>(
    mut chart: svg::Chart,
    rows: &[Timed<M>],
    mr: f64,
    methods: &[(&str, M)],
) -> svg::Chart {
    chart = chart.log(true, false);
    for (look, &(label, m)) in methods.iter().enumerate() {
        let sel: Vec<&Timed<M>> = (rows.iter())
            .filter(|r| r.mr == mr && r.method == m)
            .collect();
        let mut pts: Vec<(f64, f64)> = (sel.iter())
            .filter(|r| r.failure.is_none())
            .map(|r| (r.time_ns, r.digits()))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        if !pts.is_empty() {
            chart.push(svg::Series::new(label, pts, svg::Style::LineMarkers).look(look));
        }
        let failed: Vec<&&Timed<M>> = sel.iter().filter(|r| r.failure.is_some()).collect();
        if let Some(first) = failed.first() {
            let precs: Vec<String> = failed.iter().map(|r| r.precision.label()).collect();
            let why = first.failure.as_deref().unwrap_or_default();
            (chart.notes).push(format!(
                "{label} failed at {} (not drawn): {why}",
                precs.join(", ")
            ));
        }
    }
    chart
}

/// |got − want|/|want|, the difference formed and divided at `bits` bits (enough above both
/// precisions that it is exact or rounded once), to `f64`: the error of a study's result
/// against its MPFR reference.
pub fn rel_error<T: moving_hertz::scalar::Real>(got: &T, want: &rug::Float, bits: u32) -> f64 {
    let d = rug::Float::with_val(bits, &got.to_float(bits) - want) / want;
    d.abs().to_f64()
}

/// The correct decimal digits of a result with relative error `err`: −log₁₀ err, 0 for an
/// error of 1 or more, and `exact` (the digits of the working precision) for an error of 0.
/// The accuracy axis of the studies' charts (a linear axis of digits, on which an exact result
/// has a place).
pub fn correct_digits(err: f64, exact: f64) -> f64 {
    if err == 0.0 {
        exact
    } else {
        (-err.log10()).max(0.0)
    }
}

/// The decimal digits of a precision of `bits` significand bits, (bits − 1)·log₁₀ 2 (the
/// digits of its unit roundoff).
pub fn full_digits(bits: u32) -> f64 {
    (bits as f64 - 1.0) * std::f64::consts::LOG10_2
}

/// f64, double-double and MPFR at each of `mpfr_bits`, in that order: the precisions a study
/// runs at.
pub fn precisions(mpfr_bits: &[u32]) -> Vec<Precision> {
    let mpfr = mpfr_bits
        .iter()
        .map(|&b| Precision::Mpfr(MpPrec::clamped(b)));
    [Precision::F64, Precision::DoubleDouble]
        .into_iter()
        .chain(mpfr)
        .collect()
}

/// Median wall time of `f` in nanoseconds, over enough repetitions to fill about `budget_ms`
/// milliseconds (at least 3 runs). For the studies' cost axes only; the benches use criterion.
/// A median of wall times (noisy on a shared machine).
pub fn median_ns<R>(budget_ms: f64, mut f: impl FnMut() -> R) -> f64 {
    let t0 = Instant::now();
    std::hint::black_box(f());
    let first = t0.elapsed().as_nanos() as f64;
    let reps = ((budget_ms * 1e6 / first.max(1.0)) as usize).clamp(3, 2001);
    // Group very fast calls so that one timing spans at least ~2 µs.
    let inner = ((2000.0 / first.max(1.0)).ceil() as usize).clamp(1, 10_000);
    let mut samples: Vec<f64> = (0..reps.div_ceil(inner).max(3))
        .map(|_| {
            let t = Instant::now();
            for _ in 0..inner {
                std::hint::black_box(f());
            }
            t.elapsed().as_nanos() as f64 / inner as f64
        })
        .collect();
    samples.sort_by(|a, b| a.total_cmp(b));
    samples[samples.len() / 2]
}

#[cfg(test)]
#[path = "../../tests/unit/studies.rs"]
mod tests;
