//! `moving-hertz fig2`: the paper's Fig. 2 reproduced and extended (the README's main job).

use super::args::{self, Decimal, OutDir};
use super::output::emit;
use super::progress::Progress;
use super::CliError;
use crate::studies::{self, fig2};
use moving_hertz::scalar::Precision;
use moving_hertz::{with_precision, Material};
use rayon::prelude::*;
use std::collections::HashMap;
use std::fmt::Write as _;

#[derive(clap::Args, Debug)]
pub struct Fig2Args {
    /// Poisson's ratio ν, -1 < NU <= 1/2 (dimensionless decimal; default 0.2 as in the paper).
    /// Other values, or another precision, add `_nu<NU>_<precision>` to the file names.
    #[arg(long, value_name = "NU", default_value = "0.2", value_parser = args::decimal,
          allow_hyphen_values = true)]
    pub nu: Decimal,
    /// The working precision: f64, dd (double-double, 106 bits) or a number of MPFR bits
    /// (24 to 32768, the largest precision the quadrature rules are built for).
    #[arg(long, value_name = "P", default_value = "f64", value_parser = args::precision)]
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
    let out = a.out.prepare()?;
    super::bind_global_pool();
    let by_ratio_pairs: Vec<(f64, f64)> = fig2::SPEEDS
        .iter()
        .flat_map(|&mr| fig2::ratio_grid().into_iter().map(move |r| (mr, r)))
        .collect();
    let by_speed_pairs: Vec<(f64, f64)> = fig2::RATIOS
        .iter()
        .flat_map(|&r| fig2::speed_grid().into_iter().map(move |mr| (mr, r)))
        .collect();
    let mut bar = Progress::new(
        format!("fig2 at {}", prec.label()),
        by_ratio_pairs.len() + by_speed_pairs.len(),
    );
    let (a_pts, b_pts) = with_precision!(prec, T, p => {
        let a = fig2::solve_all::<T>(nu, &by_ratio_pairs, p, || bar.tick()).map_err(CliError::lib)?;
        let b = fig2::solve_all::<T>(nu, &by_speed_pairs, p, || bar.tick()).map_err(CliError::lib)?;
        (a, b)
    });
    bar.finish();
    let io = |e: std::io::Error| CliError::Failed(format!("writing fig2 output: {e}"));
    // The grids' few hundred distinct M_R and A1/B1 written once, not once a row.
    let grids = [fig2::ratio_grid(), fig2::speed_grid()];
    let text: HashMap<u64, String> = (grids.iter().flatten())
        .chain(fig2::SPEEDS.iter().chain(&fig2::RATIOS))
        .map(|&v| (v.to_bits(), format!("{v}")))
        .collect();
    let csv = |pts: &[fig2::Point]| csv_text(pts, &text);
    let suffix = suffix(nu, prec);
    let d1 = out.join(format!("data/fig2_e_vs_ratio{suffix}.csv"));
    let d2 = out.join(format!("data/fig2_e_vs_speed{suffix}.csv"));
    // The tables and the charts are formed on every core (as long as the solves at f64), and
    // the five files written two at a time.
    let ((csv_a, csv_b), charts) = rayon::join(
        || rayon::join(|| csv(&a_pts), || csv(&b_pts)),
        || fig2::charts(nu, &a_pts, &b_pts),
    );
    let mut files = vec![(d1.clone(), csv_a, false), (d2.clone(), csv_b, false)];
    for (name, svg) in charts {
        let name = name.replace(".svg", &format!("{suffix}.svg"));
        files.push((out.join("figures").join(name), svg, true));
    }
    files
        .par_iter()
        .try_for_each(|(path, body, chart)| {
            if *chart {
                studies::write_text(path, body)
            } else {
                std::fs::write(path, body).map_err(studies::naming(path))
            }
        })
        .map_err(io)?;
    let worst = a_pts
        .iter()
        .chain(&b_pts)
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
    let _ = writeln!(
        s,
        "wrote {}, {} and figures/fig2_*{suffix}.svg under {}",
        d1.display(),
        d2.display(),
        out.display()
    );
    // A few values for the terminal, as in the paper's figure.
    let _ = writeln!(s, "\n e at A1/B1 = 0.5:");
    for mr in fig2::SPEEDS {
        if let Some(q) = a_pts.iter().find(|q| q.mr == mr && q.ratio == 0.5) {
            let _ = writeln!(
                s,
                "   M_R = {mr:<6} e = {:.10}  k = {:.10}",
                q.e_f64, q.k_f64
            );
        }
    }
    emit(&s)
}

/// The CSV table of `pts` (header and one row a point: M_R, A1/B1, k, e and k's relative error
/// estimate), formed in pieces on every core; `text` holds the decimals of every M_R and A1/B1.
fn csv_text(pts: &[fig2::Point], text: &HashMap<u64, String>) -> String {
    let push_decimal = |t: &mut String, v: f64| match text.get(&v.to_bits()) {
        Some(d) => t.push_str(d),
        None => {
            let _ = write!(t, "{v}");
        }
    };
    let pieces: Vec<String> = pts
        .par_chunks(256)
        .map(|chunk| {
            let mut t = String::with_capacity(96 * chunk.len());
            for q in chunk {
                push_decimal(&mut t, q.mr);
                t.push(',');
                push_decimal(&mut t, q.ratio);
                let _ = writeln!(t, ",{},{},{:.2e}", q.k, q.e, q.error_estimate);
            }
            t
        })
        .collect();
    let mut s = String::from("M_R,A1_over_B1,k,e,k_rel_error_estimate\n");
    s.extend(pieces);
    s
}
