//! `moving-hertz fig2`: the paper's Fig. 2 reproduced and extended (the README's main job).

use super::args::Args;
use super::progress::Progress;
use crate::studies::{self, fig2};
use moving_hertz::with_precision;
use std::path::PathBuf;

pub fn run(args: &Args) -> Result<(), String> {
    let nu = args.optional("nu").unwrap_or("0.2").to_string();
    let prec = args.precision()?;
    let out = PathBuf::from(args.optional("out").unwrap_or("docs"));
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
    let (a, b) = with_precision!(prec, T, p => {
        let a = fig2::solve_all::<T>(&nu, &by_ratio_pairs, p, || bar.tick()).map_err(|e| e.to_string())?;
        let b = fig2::solve_all::<T>(&nu, &by_speed_pairs, p, || bar.tick()).map_err(|e| e.to_string())?;
        (a, b)
    });
    bar.finish();
    let io = |e: std::io::Error| format!("writing fig2 output: {e}");
    let rows = |pts: &[fig2::Point]| -> Vec<Vec<String>> {
        pts.iter()
            .map(|q| {
                vec![
                    format!("{}", q.mr),
                    format!("{}", q.ratio),
                    q.k.clone(),
                    q.e.clone(),
                    format!("{:.2e}", q.error_estimate),
                ]
            })
            .collect()
    };
    let suffix = if nu == "0.2" && prec == moving_hertz::scalar::Precision::F64 {
        String::new()
    } else {
        format!("_nu{}_{}", nu, prec.label())
    };
    let header = ["M_R", "A1_over_B1", "k", "e", "k_rel_error_estimate"];
    let d1 = out.join(format!("data/fig2_e_vs_ratio{suffix}.csv"));
    let d2 = out.join(format!("data/fig2_e_vs_speed{suffix}.csv"));
    studies::write_csv(&d1, &header, &rows(&a)).map_err(io)?;
    studies::write_csv(&d2, &header, &rows(&b)).map_err(io)?;
    for (name, svg) in fig2::charts(&nu, &a, &b) {
        let name = name.replace(".svg", &format!("{suffix}.svg"));
        studies::write_text(&out.join("figures").join(name), &svg).map_err(io)?;
    }
    let worst = a
        .iter()
        .chain(&b)
        .map(|q| q.error_estimate)
        .fold(0.0f64, f64::max);
    println!(
        "fig2: {} ellipse solves at {} (nu = {nu}); worst relative error estimate of k {:.1e}",
        a.len() + b.len(),
        prec.label(),
        worst
    );
    println!(
        "wrote {}, {} and figures/fig2_*{suffix}.svg under {}",
        d1.display(),
        d2.display(),
        out.display()
    );
    // A few values for the terminal, as in the paper's figure.
    println!("\n e at A1/B1 = 0.5:");
    for mr in fig2::SPEEDS {
        if let Some(q) = a.iter().find(|q| q.mr == mr && q.ratio == 0.5) {
            println!("   M_R = {mr:<6} e = {:.10}  k = {:.10}", q.e_f64, q.k_f64);
        }
    }
    Ok(())
}
