//! `moving-hertz fig2`: the paper's Fig. 2 reproduced and extended (the README's main job).

use super::args::{self, Decimal, OutDir};
use super::output::emit;
use super::progress::Progress;
use super::CliError;
use crate::studies::{self, fig2};
use moving_hertz::scalar::Precision;
use moving_hertz::{with_precision, Material};
use rayon::prelude::*;
use std::fmt::Write as _;

#[derive(clap::Args, Debug)]
pub struct Fig2Args {
    /// Poisson's ratio ν, -1 < NU <= 1/2 (dimensionless decimal; default 0.2 as in the paper).
    /// Other values, or another precision, add `_nu<NU>_<precision>` to the file names.
    #[arg(long, value_name = "NU", default_value = "0.2", value_parser = args::decimal,
          allow_hyphen_values = true)]
    pub nu: Decimal,
    #[arg(long, value_name = "P", default_value = "f64", value_parser = args::precision,
          help = args::PRECISION_HELP)]
    pub precision: Precision,
    #[command(flatten)]
    pub out: OutDir,
}

/// The file-name suffix for ν (as typed, trimmed) and the precision: empty for the paper's
/// ν = 0.2 at f64, else `_nu<NU>_<precision>`; ν checked exactly at the working precision, a
/// decimal (it goes into the file names), and the names' length checked against
/// [`args::NAME_MAX`] ([`FILES`]), before any work or any directory is made.
fn suffix(nu: &str, prec: Precision) -> Result<String, CliError> {
    if nu.contains('/') {
        let why = "fig2 takes a decimal (it names the files)";
        return Err(CliError::value("--nu", nu, why));
    }
    with_precision!(prec, T, p => {
        Material::<T>::parse(nu, p).map_err(|e| CliError::value("--nu", nu, e))?;
    });
    if nu == "0.2" && prec == Precision::F64 {
        return Ok(String::new());
    }
    let suffix = format!("_nu{nu}_{}", prec.label());
    let base = |f: &str| {
        f.rsplit('/')
            .next()
            .unwrap_or(f)
            .replace('.', &format!("{suffix}."))
    };
    match FILES
        .map(base)
        .into_iter()
        .find(|b| b.len() > args::NAME_MAX)
    {
        None => Ok(suffix),
        Some(base) => Err(CliError::value(
            "--nu",
            nu,
            format!(
                "the file names carry nu as typed: {base} would be {} bytes, more than the {} \
                 a file name may have (give a shorter decimal)",
                base.len(),
                args::NAME_MAX
            ),
        )),
    }
}

/// The files `fig2` writes under DIR, before the suffix of ν and the precision (the charts'
/// names as `studies::fig2::charts` gives them).
const FILES: [&str; 5] = [
    "data/fig2_e_vs_ratio.csv",
    "data/fig2_e_vs_speed.csv",
    "figures/fig2_e_vs_ratio.svg",
    "figures/fig2_e_vs_speed.svg",
    "figures/fig2_near_rayleigh.svg",
];

pub fn run(a: &Fig2Args) -> Result<(), CliError> {
    let (nu, prec) = (a.nu.text.as_str(), a.precision);
    let suffix = suffix(nu, prec)?;
    let out = a.out.prepare()?;
    let pairs = |outer: &[f64], inner: Vec<f64>, speed_outer: bool| -> Vec<(f64, f64)> {
        let pair = |o: f64, i: f64| if speed_outer { (o, i) } else { (i, o) };
        (outer.iter())
            .flat_map(|&o| inner.iter().map(move |&i| pair(o, i)))
            .collect()
    };
    let by_ratio = pairs(&fig2::SPEEDS, fig2::ratio_grid(), true);
    let by_speed = pairs(&fig2::RATIOS, fig2::speed_grid(), false);
    let total = by_ratio.len() + by_speed.len();
    super::bind_global_pool(total, &prec);
    let bar = Progress::new(format!("fig2 at {}", prec.label()), total);
    let (tick, decimals) = (|n: usize| bar.advance(n), fig2::grid_decimals());
    let [a, b] = with_precision!(prec, T, p => {
        fig2::solve_all::<T, 2>(nu, [&by_ratio, &by_speed], p, &decimals, &tick)
            .map_err(CliError::lib)?
    });
    bar.finish();
    let (a_pts, b_pts) = (&a.points, &b.points);
    let named = |f: &str| out.join(f.replace('.', &format!("{suffix}.")));
    let mut files = vec![
        (named(FILES[0]), Written::Table(&a.table)),
        (named(FILES[1]), Written::Table(&b.table)),
    ];
    // The charts are formed on every core, and the five files written two at a time.
    for (name, svg) in fig2::charts(nu, a_pts, b_pts) {
        files.push((named(&format!("figures/{name}")), Written::Chart(svg)));
    }
    files
        .par_iter()
        .try_for_each(|(path, body)| match body {
            Written::Chart(svg) => studies::write_text(path, svg),
            Written::Table(pieces) => studies::write_pieces(path, pieces),
        })
        .map_err(|e| CliError::Failed(format!("writing fig2 output: {e}")))?;
    let worst = (a_pts.iter().chain(b_pts)).fold(0.0f64, |w, q| w.max(q.error_estimate));
    let written: Vec<String> = files.iter().map(|(p, _)| p.display().to_string()).collect();
    let mut s = format!(
        "fig2: {} ellipse solves at {} (nu = {nu}); worst relative error estimate of k {:.1e}\n\
         wrote {}\n\n e at A1/B1 = 0.5:\n",
        a_pts.len() + b_pts.len(),
        prec.label(),
        worst,
        written.join(", ")
    );
    // A few values for the terminal, as in the paper's figure.
    for mr in fig2::SPEEDS {
        if let Some(q) = a_pts.iter().find(|q| q.mr == mr && q.ratio == 0.5) {
            let _ = writeln!(
                s,
                "   M_R = {mr:<6} e = {:.10e}  k = {:.10e}",
                q.e_f64, q.k_f64
            );
        }
    }
    emit(&s)
}

/// What `fig2` writes to a file: a chart, or a table in pieces.
enum Written<'a> {
    Chart(String),
    Table(&'a [String]),
}
