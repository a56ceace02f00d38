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
/// ν = 0.2 at f64, else `_nu<NU>_<precision>`.
fn suffix(nu: &str, prec: Precision) -> String {
    if nu == "0.2" && prec == Precision::F64 {
        return String::new();
    }
    format!("_nu{nu}_{}", prec.label())
}

/// The files `fig2` writes under DIR, before the suffix of ν and the precision (the charts'
/// names as `studies::fig2::charts` gives them): their names' length is checked before any
/// work.
const FILES: [&str; 5] = [
    "data/fig2_e_vs_ratio.csv",
    "data/fig2_e_vs_speed.csv",
    "figures/fig2_e_vs_ratio.svg",
    "figures/fig2_e_vs_speed.svg",
    "figures/fig2_near_rayleigh.svg",
];

pub fn run(a: &Fig2Args) -> Result<(), CliError> {
    let nu = a.nu.text.as_str();
    let prec = a.precision;
    // ν checked exactly at the working precision before any work or any directory is made; a
    // decimal, as it goes into the file names.
    if nu.contains('/') {
        return Err(CliError::value(
            "--nu",
            nu,
            "fig2 takes a decimal (it names the files)",
        ));
    }
    with_precision!(prec, T, p => {
        Material::<T>::parse(nu, p).map_err(|e| CliError::value("--nu", nu, e))?;
    });
    let suffix = suffix(nu, prec);
    let names = FILES.map(|f| f.replace('.', &format!("{suffix}.")));
    let base = |n: &str| n.rsplit('/').next().unwrap_or(n).to_string();
    if let Some(base) = names
        .iter()
        .map(|n| base(n))
        .find(|b| b.len() > args::NAME_MAX)
    {
        let why = format!(
            "the file names carry nu as typed: {base} would be {} bytes, more than the {} a \
             file name may have (give a shorter decimal)",
            base.len(),
            args::NAME_MAX
        );
        return Err(CliError::value("--nu", nu, why));
    }
    let out = a.out.prepare()?;
    let by_ratio_pairs: Vec<(f64, f64)> = fig2::SPEEDS
        .iter()
        .flat_map(|&mr| fig2::ratio_grid().into_iter().map(move |r| (mr, r)))
        .collect();
    let by_speed_pairs: Vec<(f64, f64)> = fig2::RATIOS
        .iter()
        .flat_map(|&r| fig2::speed_grid().into_iter().map(move |mr| (mr, r)))
        .collect();
    super::bind_global_pool(by_ratio_pairs.len() + by_speed_pairs.len(), &prec);
    let bar = Progress::new(
        format!("fig2 at {}", prec.label()),
        by_ratio_pairs.len() + by_speed_pairs.len(),
    );
    let tick = |n: usize| bar.advance(n);
    let decimals = fig2::grid_decimals();
    let curves = [&by_ratio_pairs[..], &by_speed_pairs[..]];
    let [a, b] = with_precision!(prec, T, p => {
        fig2::solve_all::<T, 2>(nu, curves, p, &decimals, &tick).map_err(CliError::lib)?
    });
    bar.finish();
    let (a_pts, b_pts) = (&a.points, &b.points);
    let d1 = out.join(&names[0]);
    let d2 = out.join(&names[1]);
    let mut files = vec![
        (d1, Written::Table(&a.table)),
        (d2, Written::Table(&b.table)),
    ];
    // The charts are formed on every core, and the five files written two at a time.
    for (name, svg) in fig2::charts(nu, a_pts, b_pts) {
        let name = name.replace(".svg", &format!("{suffix}.svg"));
        files.push((out.join("figures").join(name), Written::Chart(svg)));
    }
    files
        .par_iter()
        .try_for_each(|(path, body)| match body {
            Written::Chart(svg) => studies::write_text(path, svg),
            Written::Table(pieces) => studies::write_pieces(path, pieces),
        })
        .map_err(|e| CliError::Failed(format!("writing fig2 output: {e}")))?;
    let worst = a_pts
        .iter()
        .chain(b_pts.iter())
        .map(|q| q.error_estimate)
        .fold(0.0f64, f64::max);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "fig2: {} ellipse solves at {} (nu = {nu}); worst relative error estimate of k {:.1e}",
        a_pts.len() + b_pts.len(),
        prec.label(),
        worst
    );
    let written: Vec<String> = files.iter().map(|(p, _)| p.display().to_string()).collect();
    let _ = writeln!(s, "wrote {}", written.join(", "));
    // A few values for the terminal, as in the paper's figure.
    let _ = writeln!(s, "\n e at A1/B1 = 0.5:");
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
