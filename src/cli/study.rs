//! `moving-hertz study <name>`: runs a study and writes its CSV data, SVG charts and summary
//! under `docs/` (or `--out DIR`).

use super::args::Args;
use moving_hertz::studies::{self, rayleigh};
use std::path::PathBuf;

pub fn run(name: &str, args: &Args) -> Result<(), String> {
    let out = PathBuf::from(args.optional("out").unwrap_or("docs"));
    match name {
        "rayleigh" => study_rayleigh(&out),
        other => Err(format!("unknown study `{other}` (available: rayleigh)")),
    }
}

fn io(e: std::io::Error) -> String {
    format!("writing study output: {e}")
}

fn study_rayleigh(out: &std::path::Path) -> Result<(), String> {
    let nus = rayleigh::nu_grid();
    eprintln!(
        "rayleigh roots: {} values of nu at 4 precisions ...",
        nus.len()
    );
    let rows = rayleigh::run(&nus);
    let csv: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            vec![
                format!("{:.17e}", r.nu),
                r.precision.label(),
                r.method.to_string(),
                format!("{:.4e}", r.m1),
                format!("{:.4e}", r.m23),
            ]
        })
        .collect();
    let data = out.join("data/rayleigh_stability.csv");
    studies::write_csv(
        &data,
        &["nu", "precision", "method", "err_m1_eps", "err_m23_eps"],
        &csv,
    )
    .map_err(io)?;
    for (name, svg) in rayleigh::charts(&rows)
        .into_iter()
        .chain(rayleigh::closeups(&rows))
    {
        studies::write_text(&out.join("figures").join(name), &svg).map_err(io)?;
    }
    let mut md = String::from("| precision | method |");
    for r in rayleigh::SUMMARY_REGIONS {
        md.push_str(&format!(" {r}: m1 / m2,m3 (ε) |"));
    }
    md.push_str("\n|---|---|---|---|---|---|\n");
    for row in rayleigh::summary(&rows) {
        md.push_str(&format!("| {} |\n", row.join(" | ")));
    }
    studies::write_text(&out.join("data/rayleigh_summary.md"), &md).map_err(io)?;
    println!("{md}");
    println!(
        "wrote {} and charts under {}",
        data.display(),
        out.join("figures").display()
    );
    Ok(())
}
