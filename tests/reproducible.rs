//! The committed outputs of the cheap commands — `fig2` at f64 (the README's main job),
//! `study poisson` and `study rayleigh` — are what the current code writes: each is regenerated
//! into a temporary directory and compared with `docs/data` field by field. Values agree to
//! 10⁻¹² relative (a change of route or rounding moves them by a few ulps, within their error
//! bounds), the eccentricity through e² to 10⁻¹² absolute (e² = 1 − k² carries k's error as an
//! absolute one); error-estimate columns to a factor 2; every other field exactly. Stale data fails here.

use std::path::{Path, PathBuf};
use std::process::Command;

fn regenerate(args: &[&str], dir: &Path) {
    let out = Command::new(env!("CARGO_BIN_EXE_moving-hertz"))
        .args(args)
        .arg("--out")
        .arg(dir)
        .output()
        .expect("the moving-hertz binary runs");
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Whether two fields of the column `name` agree (module docs).
fn agree(name: &str, a: &str, b: &str) -> bool {
    match (a.parse::<f64>(), b.parse::<f64>()) {
        (Ok(x), Ok(y)) if name.contains("estimate") || name.contains("error") => {
            (x == y) || (x > 0.0 && y > 0.0 && (x / y).max(y / x) <= 2.0)
        }
        // e² = (1 − k)(1 + k) carries k's error as an absolute one: near a circular contact
        // (k → 1) e itself moves by √δk.
        (Ok(x), Ok(y)) if name == "e" => (x * x - y * y).abs() <= 1e-12,
        (Ok(x), Ok(y)) => x == y || (x - y).abs() <= 1e-12 * x.abs().max(y.abs()),
        _ => a == b,
    }
}

fn compare(file: &str, fresh: &Path) {
    let committed = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("docs/data")
        .join(file);
    let want = std::fs::read_to_string(&committed).expect("committed file");
    let got = std::fs::read_to_string(fresh.join("data").join(file)).expect("regenerated file");
    let (want, got): (Vec<&str>, Vec<&str>) = (want.lines().collect(), got.lines().collect());
    assert_eq!(want.len(), got.len(), "{file}: number of lines");
    let header: Vec<&str> = want[0].split(',').collect();
    assert_eq!(want[0], got[0], "{file}: header");
    for (i, (w, g)) in want.iter().zip(&got).enumerate().skip(1) {
        let (w, g): (Vec<&str>, Vec<&str>) = (w.split(',').collect(), g.split(',').collect());
        assert_eq!(w.len(), g.len(), "{file}:{}", i + 1);
        for ((name, a), b) in header.iter().zip(&w).zip(&g) {
            assert!(
                agree(name, a, b),
                "{file}:{} column {name}: committed {a}, regenerated {b} — re-run the command \
                 and commit its output",
                i + 1
            );
        }
    }
}

#[test]
fn committed_data_is_what_the_code_writes() {
    let dir = std::env::temp_dir().join(format!("moving-hertz-repro-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temporary directory");
    regenerate(&["fig2"], &dir);
    regenerate(&["study", "poisson"], &dir);
    regenerate(&["study", "rayleigh"], &dir);
    for file in [
        "fig2_e_vs_ratio.csv",
        "fig2_e_vs_speed.csv",
        "poisson_study.csv",
        "rayleigh_stability.csv",
    ] {
        compare(file, &dir);
    }
    let _ = std::fs::remove_dir_all(&dir);
}
