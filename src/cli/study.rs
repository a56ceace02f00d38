//! `moving-hertz study <name>`: runs a study and writes its CSV data, SVG charts and summary
//! under `docs/` (or `--out DIR`).

use super::args::OutDir;
use super::progress::Progress;
use super::CliError;
use crate::studies::{self, integrals, pareto, poisson, rayleigh, series, stability, Timed};
use moving_hertz::{Method, Route};
use std::path::{Path, PathBuf};

/// `println!` through [`super::output::emit`]: a closed or full standard output stops the
/// study with exit code 1 and one line, as in every command (the studies print as they go).
macro_rules! say {
    ($($t:tt)*) => {
        super::output::emit(&format!("{}\n", format_args!($($t)*)))?
    };
}

/// `eprintln!` for the studies' notes of progress, ignoring a closed or full standard error.
macro_rules! note {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($t)*);
    }};
}

#[derive(clap::Args, Debug)]
pub struct StudyArgs {
    /// The study to run.
    #[arg(value_enum, value_name = "NAME")]
    pub name: Study,
    #[command(flatten)]
    pub out: OutDir,
    /// Draw the charts from the study's CSV data already under DIR/data, without measuring
    /// (the timing studies: integrals, pareto, series). The study itself draws its charts the same way,
    /// from the CSV it has just written.
    #[arg(long)]
    pub redraw: bool,
}

/// The studies behind the pages of docs/.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum Study {
    /// Stability of the closed-form Rayleigh roots against nu and precision (docs/rayleigh.md).
    Rayleigh,
    /// Terms and time of the series (37) against M_R per target accuracy (docs/series.md).
    Series,
    /// Error growth of the forward recursion (40), bits lost in the K, E basis (docs/series.md).
    Recursion,
    /// Accuracy against cost of every method x precision for I1, I2 as M_R -> 1
    /// (docs/integrals.md).
    Integrals,
    /// How much Poisson's ratio changes e, k and a (docs/results.md).
    Poisson,
    /// Accuracy against time of the ellipse solve for each method x precision.
    Pareto,
    /// Maps of the digits each method delivers at f64 and double-double (docs/stability.md).
    Stability,
}

pub fn run(a: &StudyArgs) -> Result<(), CliError> {
    if a.redraw && !matches!(a.name, Study::Integrals | Study::Pareto | Study::Series) {
        return Err(CliError::Input(format!(
            "--redraw draws the charts of the timing studies (integrals, pareto, series) from \
             their CSV; study {} draws its charts as it runs",
            format!("{:?}", a.name).to_lowercase()
        )));
    }
    let out = a.out.prepare()?;
    let out = out.as_path();
    // Studies time their work and run many precisions: every CPU.
    super::bind_global_pool(usize::MAX, &moving_hertz::Precision::F64);
    match a.name {
        Study::Integrals if a.redraw => draw_integrals(out),
        Study::Pareto if a.redraw => draw_pareto(out),
        Study::Series if a.redraw => draw_series(out),
        Study::Rayleigh => study_rayleigh(out),
        Study::Integrals => study_integrals(out),
        Study::Poisson => study_poisson(out),
        Study::Pareto => study_pareto(out),
        Study::Series => study_series(out),
        Study::Recursion => study_recursion(out),
        Study::Stability => study_stability(out),
    }
}

fn io(e: std::io::Error) -> CliError {
    CliError::Failed(format!("writing study output: {e}"))
}

/// Writes the row `row(item)` of each of `items` under `header` (comma-separated column names)
/// to `out/file`; returns the path.
fn csv<R>(
    out: &Path,
    file: &str,
    header: &str,
    items: &[R],
    row: impl Fn(&R) -> Vec<String>,
) -> Result<PathBuf, CliError> {
    let path = out.join(file);
    let rows: Vec<Vec<String>> = items.iter().map(row).collect();
    studies::write_csv(&path, header, &rows).map_err(io)?;
    Ok(path)
}

/// Writes `text` (a Markdown summary) to `out/file`.
fn text(out: &Path, file: &str, text: &str) -> Result<(), CliError> {
    studies::write_text(&out.join(file), text).map_err(io)
}

/// Writes each (name, SVG) chart under `out/figures`.
fn charts(out: &Path, charts: impl IntoIterator<Item = (String, String)>) -> Result<(), CliError> {
    for (name, svg) in charts {
        text(out, &format!("figures/{name}"), &svg)?;
    }
    Ok(())
}

/// A Markdown table: the header of the `|`-separated `columns`, its rule and a line per row of
/// cells (an empty cell is left blank).
fn md_table(columns: &str, rows: impl IntoIterator<Item = Vec<String>>) -> String {
    let line = |cells: &[&str]| {
        let cells = cells.iter().map(|c| {
            if c.is_empty() {
                " |".into()
            } else {
                format!(" {c} |")
            }
        });
        format!("|{}\n", cells.collect::<String>())
    };
    let header: Vec<&str> = columns.split('|').collect();
    let mut md = line(&header) + &format!("|{}\n", "---|".repeat(header.len()));
    for row in rows {
        md += &line(&row.iter().map(String::as_str).collect::<Vec<_>>());
    }
    md
}

fn study_rayleigh(out: &Path) -> Result<(), CliError> {
    let nus = rayleigh::nu_grid();
    note!(
        "rayleigh roots: {} values of nu at 4 precisions ...",
        nus.len()
    );
    let rows = rayleigh::run(&nus);
    let data = csv(
        out,
        "data/rayleigh_stability.csv",
        "nu,precision,method,err_m1_eps,err_m23_eps",
        &rows,
        |r| {
            vec![
                format!("{:.17e}", r.nu),
                r.precision.label(),
                r.method.to_string(),
                format!("{:.4e}", r.m1),
                format!("{:.4e}", r.m23),
            ]
        },
    )?;
    charts(
        out,
        rayleigh::charts(&rows)
            .into_iter()
            .chain(rayleigh::closeups(&rows)),
    )?;
    let regions = rayleigh::REGIONS.map(|(r, _)| format!("|{r}: m1 / m2,m3 (ε)"));
    let md = md_table(
        &format!("precision|method{}", regions.concat()),
        rayleigh::summary(&rows).into_iter().map(Vec::from),
    );
    summarise(out, "data/rayleigh_summary.md", &md, &data)
}

/// Writes the Markdown summary `md` to `out/file` and prints it, then where the data `data` and
/// the charts went.
fn summarise(out: &Path, file: &str, md: &str, data: &Path) -> Result<(), CliError> {
    text(out, file, md)?;
    say!("{md}");
    say!(
        "wrote {} and charts under {}",
        data.display(),
        out.join("figures").display()
    );
    Ok(())
}

fn study_integrals(out: &Path) -> Result<(), CliError> {
    let (nu, k) = ("0.2", "0.3");
    let rows = integrals::run(nu, k, 60.0, |mr| note!("integrals: M_R = {mr} ..."))
        .map_err(CliError::lib)?;
    let data = timed_outputs(out, INTEGRALS_CSV, &rows, Route::label, "µs")?;
    draw_integrals(out)?;
    say!(
        "wrote {} and charts under {} (nu = {nu}, k = {k})",
        data.display(),
        out.join("figures").display()
    );
    Ok(())
}

/// A timing study's CSV data (`file`; integrals' with the work, pareto's with the bits) and
/// its Markdown table on standard output (the time in `unit`, µs or ms; a failed run's
/// failure in place of its numbers).
fn timed_outputs<M: Copy>(
    out: &Path,
    file: &str,
    rows: &[Timed<M>],
    label: fn(&M) -> &'static str,
    unit: &str,
) -> Result<PathBuf, CliError> {
    let ms = unit == "ms";
    let header = if ms {
        "mr,method,precision,bits,k_rel_error,error_estimate,time_ns,failure"
    } else {
        "mr,method,precision,rel_error,error_estimate,time_ns,work,failure"
    };
    let data = csv(out, file, header, rows, |r| {
        let (bits, work) = (r.precision.bits().to_string(), r.work.to_string());
        let mut row = vec![
            r.mr.to_string(),
            label(&r.method).into(),
            r.precision.label(),
        ];
        row.extend(ms.then_some(bits));
        row.extend([r.error, r.estimate].map(|x| format!("{x:.3e}")));
        row.push(format!("{:.1}", r.time_ns));
        row.extend((!ms).then_some(work));
        row.push(r.failure.clone().unwrap_or_default().replace(',', ";"));
        row
    })?;
    let columns = if ms {
        "M_R|method|precision|error of k|estimate|time per solve"
    } else {
        "M_R|method|precision|rel. error|estimate|time|work"
    };
    let table = rows.iter().map(|r| {
        let mut row = vec![
            r.mr.to_string(),
            label(&r.method).into(),
            r.precision.label(),
        ];
        let width = if ms { 6 } else { 7 };
        if let Some(f) = &r.failure {
            row.push(format!("failed: {f}"));
        } else {
            row.extend([r.error, r.estimate].map(|x| format!("{x:.1e}")));
            let scale = if ms { 1e6 } else { 1e3 };
            row.push(format!("{:.3} {unit}", r.time_ns / scale));
            row.extend((!ms).then(|| r.work.to_string()));
        }
        row.resize(width, String::new());
        row
    });
    super::output::emit(&md_table(columns, table))?;
    Ok(data)
}

/// A timing study's charts, drawn by `draw` from the rows `read` takes from its CSV data
/// `out/file` (the study draws them so from the CSV it has just written; `--redraw` alone).
fn redraw<R>(
    out: &Path,
    file: &str,
    read: fn(&studies::Table) -> Result<Vec<R>, String>,
    draw: impl Fn(&[R]) -> Vec<(String, String)>,
) -> Result<(), CliError> {
    let table = studies::Table::read(&out.join(file)).map_err(io)?;
    charts(out, draw(&read(&table).map_err(CliError::Failed)?))
}

fn draw_integrals(out: &Path) -> Result<(), CliError> {
    redraw(
        out,
        INTEGRALS_CSV,
        integrals::rows_from_csv,
        integrals::charts,
    )
}

fn draw_pareto(out: &Path) -> Result<(), CliError> {
    let draw = |rows: &[pareto::Row]| pareto::charts(rows, &PARETO_METHODS);
    redraw(out, PARETO_CSV, pareto::rows_from_csv, draw)
}

fn draw_series(out: &Path) -> Result<(), CliError> {
    redraw(out, SERIES_CSV, series::rows_from_csv, series::terms_charts)
}

/// The timing studies' data, which their charts are drawn from.
const INTEGRALS_CSV: &str = "data/integrals_study.csv";
const PARETO_CSV: &str = "data/pareto_ellipse.csv";
const SERIES_CSV: &str = "data/series_terms.csv";

/// The methods the pareto study compares.
const PARETO_METHODS: [Method; 2] = [Method::Fixed, Method::Adaptive];

fn study_poisson(out: &Path) -> Result<(), CliError> {
    let total = poisson::nu_grid().len() * poisson::SPEEDS.len() * poisson::ratio_grid().len();
    let bar = Progress::new("poisson", total);
    let pts = poisson::run(|| bar.advance(1)).map_err(CliError::lib)?;
    bar.finish();
    let data = csv(
        out,
        "data/poisson_study.csv",
        "nu,M_R,A1_over_B1,e,k,a_for_P_mu_R1_1,a_over_static_a",
        &pts,
        |q| {
            vec![
                format!("{}", q.nu),
                format!("{}", q.mr),
                format!("{:.6}", q.ratio),
                format!("{:.16e}", q.e),
                format!("{:.16e}", q.k),
                format!("{:.16e}", q.a),
                format!("{:.16e}", q.a_rel),
            ]
        },
    )?;
    charts(out, poisson::charts(&pts))?;
    say!("Largest deviation from nu = 0.2 (max over A1/B1 in [0.01, 1]), in %: e absolute (x100),");
    say!("k and a(M_R)/a(0) relative:");
    use poisson::Deviation::{Absolute, Relative};
    type Metric = (poisson::Deviation, fn(&poisson::Point) -> f64);
    let fs: [Metric; 3] = [
        (Absolute, |q| q.e),
        (Relative, |q| q.k),
        (Relative, |q| q.a_rel),
    ];
    // Each column's spreads over the whole grid once, then a row per speed.
    let spreads: Vec<_> = fs
        .iter()
        .flat_map(|&(how, f)| {
            [(0.0, 0.5), (-0.99, 0.5)].map(|range| poisson::spread(&pts, range, how, f))
        })
        .collect();
    let rows = poisson::SPEEDS.map(|mr| {
        let widest = |col: &Vec<_>| {
            let w = (col.iter().filter(|(m, _, _)| *m == mr))
                .map(|(_, _, w)| *w)
                .fold(0.0f64, f64::max);
            format!("{:.3}", 100.0 * w)
        };
        [mr.to_string()]
            .into_iter()
            .chain(spreads.iter().map(widest))
            .collect()
    });
    let columns = "M_R|e, 0<=nu<=1/2|e, all nu|k, 0<=nu<=1/2|k, all nu|a/a0, 0<=nu<=1/2|a/a0, \
                   all nu";
    super::output::emit(&md_table(columns, rows))?;
    say!("wrote {} and figures/poisson_*.svg", data.display());
    Ok(())
}

fn study_pareto(out: &Path) -> Result<(), CliError> {
    let rows = pareto::run(&PARETO_METHODS, 200.0, |what| note!("pareto: {what} ..."))
        .map_err(CliError::lib)?;
    let data = timed_outputs(out, PARETO_CSV, &rows, Method::label, "ms")?;
    draw_pareto(out)?;
    say!("wrote {} and figures/pareto_*.svg", data.display());
    Ok(())
}

fn study_series(out: &Path) -> Result<(), CliError> {
    let speeds = series::speed_grid();
    note!(
        "series (37): terms and time at {} speeds x {} targets (about a minute) ...",
        speeds.len(),
        series::targets().len()
    );
    let rows = series::terms_study(&speeds, 20.0).map_err(CliError::lib)?;
    let data = csv(
        out,
        SERIES_CSV,
        "M_R,target,precision,terms,terms_estimate,time_ns,error,error_estimate",
        &rows,
        |r| {
            vec![
                format!("{}", r.mr),
                format!("{:e}", r.target),
                r.precision.label(),
                r.terms.to_string(),
                r.estimate.to_string(),
                format!("{:.0}", r.time_ns),
                format!("{:.3e}", r.error),
                format!("{:.3e}", r.error_estimate),
            ]
        },
    )?;
    draw_series(out)?;
    let columns = "M_R|target|precision|terms|estimate|time|error reached|error estimate";
    let md = md_table(
        columns,
        rows.iter().map(|r| {
            let time = if r.time_ns.is_nan() {
                "—".to_string()
            } else if r.time_ns < 1e6 {
                format!("{:.1} µs", r.time_ns / 1e3)
            } else {
                format!("{:.1} ms", r.time_ns / 1e6)
            };
            vec![
                r.mr.to_string(),
                format!("{:.0e}", r.target),
                r.precision.label(),
                r.terms.to_string(),
                r.estimate.to_string(),
                time,
                format!("{:.1e}", r.error),
                format!("{:.1e}", r.error_estimate),
            ]
        }),
    );
    summarise(out, "data/series_summary.md", &md, &data)
}

fn study_recursion(out: &Path) -> Result<(), CliError> {
    note!("forward recursion (40) against the exact form at 4 precisions ...");
    let (points, growth) = series::forward_study().map_err(CliError::lib)?;
    csv(
        out,
        "data/recursion_forward.csv",
        "k2,precision,n,rel_err_L,rel_err_M",
        &points,
        |p| {
            vec![
                format!("{}", p.mc),
                p.precision.label(),
                p.n.to_string(),
                format!("{:.3e}", p.err_l),
                format!("{:.3e}", p.err_m),
            ]
        },
    )?;
    let (md, gcsv) = growth_table(&growth);
    csv(out, "data/recursion_growth.csv", "k2,precision,predicted_bits_per_step,measured_L,measured_M,total_loss_n,predicted_total_loss_n,worst_err_eps,n_max", &gcsv, Vec::clone)?;
    charts(out, series::forward_charts(&points, &growth))?;
    write_condition_maps(out)?;
    summarise(out, "data/recursion_summary.md", &md, &out.join("data"))
}

/// The recursion study's growth table: Markdown for the summary and CSV rows.
fn growth_table(growth: &[series::Growth]) -> (String, Vec<Vec<String>>) {
    let opt = |x: f64| {
        if x.is_nan() {
            "—".to_string()
        } else {
            format!("{x:.4}")
        }
    };
    let columns = "k²|e²|predicted bits/step|precision|measured bits/step (L)|(M)|total loss at n (L)|predicted n|worst error (ε)|n studied";
    let (mut md_rows, mut gcsv) = (Vec::new(), Vec::new());
    for g in growth {
        let loss = g.total_loss_n.map_or("—".to_string(), |n| n.to_string());
        let pred = g
            .predicted_loss_n
            .map_or("—".to_string(), |n| format!("{n:.0}"));
        // A measured growth rate is shown where growth is predicted.
        let measured = |x: f64| opt(if g.predicted > 0.0 { x } else { f64::NAN });
        md_rows.push(vec![
            g.mc.to_string(),
            (1.0 - g.mc).to_string(),
            format!("{:.4}", g.predicted),
            g.precision.label(),
            measured(g.measured_l),
            measured(g.measured_m),
            loss.clone(),
            pred.clone(),
            format!("{:.2e}", g.worst_eps),
            g.n_max.to_string(),
        ]);
        gcsv.push(vec![
            format!("{}", g.mc),
            g.precision.label(),
            format!("{:.6}", g.predicted),
            format!("{:.6}", g.measured_l),
            format!("{:.6}", g.measured_m),
            loss,
            pred,
            format!("{:.3e}", g.worst_eps),
            g.n_max.to_string(),
        ]);
    }
    (md_table(columns, md_rows), gcsv)
}

/// The bits lost in the K, E basis over (n, e) and (n, k): CSV and charts.
fn write_condition_maps(out: &Path) -> Result<(), CliError> {
    note!("bits lost in the K, E basis over (n, e) and (n, k) ...");
    for k_side in [false, true] {
        let map = series::condition_map(k_side).map_err(CliError::lib)?;
        let mut rows = Vec::new();
        for (i, x) in map.params.iter().enumerate() {
            for (j, n) in map.ns.iter().enumerate() {
                rows.push(vec![
                    format!("{x:.6}"),
                    n.to_string(),
                    format!("{:.3}", map.bits_l[i][j]),
                    format!("{:.3}", map.bits_m[i][j]),
                ]);
            }
        }
        let (param, file) = if k_side {
            ("k_minus_1", "data/recursion_bits_lost_k.csv")
        } else {
            ("e", "data/recursion_bits_lost_e.csv")
        };
        csv(
            out,
            file,
            &format!("{param},n,bits_L,bits_M"),
            &rows,
            Vec::clone,
        )?;
        charts(out, [series::condition_chart(&map, k_side)])?;
    }
    Ok(())
}

fn study_stability(out: &Path) -> Result<(), CliError> {
    let bar = Progress::new("stability maps", stability::cells());
    let maps = stability::run(|| bar.advance(1));
    bar.finish();
    for m in &maps {
        csv(
            out,
            &format!("data/{}.csv", m.name),
            "x,y,digits",
            &m.rows(),
            Vec::clone,
        )?;
        charts(out, [(format!("{}.svg", m.name), m.map.to_svg())])?;
        let all: Vec<f64> = m.map.z.iter().flatten().cloned().collect();
        let min = all.iter().cloned().fold(f64::INFINITY, f64::min);
        let full = all.iter().filter(|&&d| d >= m.full() - 1.0).count();
        let refused = all.iter().filter(|d| d.is_nan()).count();
        say!(
            "{}: min {:.1} digits, {} of {} cells within a digit of full ({:.1}), {refused} refused",
            m.name,
            min,
            full,
            all.len(),
            m.full()
        );
    }
    Ok(())
}
