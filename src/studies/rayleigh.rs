//! Stability study of the Rayleigh roots: the closed forms against the polished default, as a
//! function of ν, at f64, double-double and MPFR 128 and 256 bits.
//!
//! Every ν is a dyadic number, exact at every precision; the reference is the default method run
//! at 640 bits. Errors are in units of the working ε: relative for m1, relative to the modulus for
//! m2 and m3 (the worse of the two is reported).

use super::svg::{Chart, Series, Style};
use moving_hertz::physics::{ClosedForm, RayleighRoots};
use moving_hertz::scalar::{Mp, MpPrec, Precision, Real};
use rug::Float;

/// One measurement.
#[derive(Clone, Debug)]
pub struct RootError {
    /// Poisson's ratio (exact dyadic value).
    pub nu: f64,
    /// Precision label.
    pub precision: Precision,
    /// `complex-cardano`, `real-branches` or `default`.
    pub method: &'static str,
    /// Relative error of m1 in ε.
    pub m1: f64,
    /// Worst error of m2, m3 relative to their modulus, in ε.
    pub m23: f64,
}

/// The ν grid: uniform over (−1, 1/2] plus refinements near ν* ≈ 0.26308 (m2 = m3), ν = 2/5
/// (where p = 0 in the depressed cubic) and both ends; all dyadic with 40 fractional bits.
/// The ν of the Rayleigh cubic (6); exact dyadic values.
pub fn nu_grid() -> Vec<f64> {
    let mut v: Vec<f64> = (1..=300).map(|j| -1.0 + 1.5 * j as f64 / 300.0).collect();
    for k in 1..=40 {
        let d = 10f64.powf(-(k as f64) * 0.35);
        for c in [NU_STAR, 0.4] {
            v.push(c + d);
            v.push(c - d);
        }
        v.push(0.5 - d.min(0.4));
        v.push(-1.0 + d.min(0.4));
    }
    let q = (1u64 << 40) as f64;
    let mut v: Vec<f64> = v
        .into_iter()
        .map(|x| (x * q).round() / q)
        .filter(|&x| x > -1.0 && x <= 0.5)
        .collect();
    v.sort_by(|a, b| a.total_cmp(b));
    v.dedup();
    v
}

fn errors<T: Real>(roots: &RayleighRoots<T>, reference: &RayleighRoots<Mp>) -> (f64, f64) {
    let bits = 700;
    let eps = T::epsilon(roots.m1.prec()).to_f64();
    let e1 = super::rel_error(&roots.m1, &reference.m1.to_float(bits), bits);
    let mut e23: f64 = 0.0;
    for (got, want) in [(&roots.m2, &reference.m2), (&roots.m3, &reference.m3)] {
        let modulus = want.abs().to_float(bits);
        let dr = Float::with_val(bits, &got.re.to_float(bits) - &want.re.to_float(bits));
        let di = Float::with_val(bits, &got.im.to_float(bits) - &want.im.to_float(bits));
        let d = Float::with_val(bits, dr.hypot(&di)) / &modulus;
        e23 = e23.max(d.to_f64() / eps);
    }
    (e1 / eps, e23)
}

fn measure_at<T: Real>(p: T::Prec, label: Precision, nus: &[f64], out: &mut Vec<RootError>) {
    let pr = MpPrec::clamped(640);
    for &nu in nus {
        let Ok(reference) = RayleighRoots::<Mp>::new(&Mp::from_f64(nu, pr)) else {
            continue;
        };
        let nu_t = T::from_f64(nu, p);
        let closed = |form| Some(RayleighRoots::closed_form(&nu_t, form));
        for (method, roots) in [
            ("complex-cardano", closed(ClosedForm::ComplexCardano)),
            ("real-branches", closed(ClosedForm::RealBranches)),
            ("default", RayleighRoots::new(&nu_t).ok()),
        ] {
            let Some(r) = roots else { continue };
            let (m1, m23) = errors(&r, &reference);
            out.push(RootError {
                nu,
                precision: label,
                method,
                m1,
                m23,
            });
        }
    }
}

/// Runs the study over `nus` at f64, double-double, MPFR 128 and 256 bits.
/// Measures the roots of (6) by each method against the default at 640 bits; errors exact to a
/// few percent.
pub fn run(nus: &[f64]) -> Vec<RootError> {
    let mut out = Vec::new();
    for prec in precisions() {
        moving_hertz::with_precision!(prec, T, p => measure_at::<T>(p, prec, nus, &mut out));
    }
    out
}

/// The methods compared, in the order of the charts and the summary.
const METHODS: [&str; 3] = ["complex-cardano", "real-branches", "default"];

/// A root group: its name and its error in a row.
type Group = (&'static str, fn(&RootError) -> f64);

/// The root groups: m1 (relative error) and m2, m3 (relative to the modulus), in ε.
const GROUPS: [Group; 2] = [("m1", |r| r.m1), ("m2,m3", |r| r.m23)];

/// The rows of one precision and method.
fn of<'a>(
    rows: &'a [RootError],
    prec: Precision,
    method: &'a str,
) -> impl Iterator<Item = &'a RootError> {
    rows.iter()
        .filter(move |r| r.precision == prec && r.method == method)
}

/// Charts: one per precision, error (ε, log scale) against ν, for each method and root group.
/// Draws the errors of the roots of (6); no arithmetic beyond plotting.
pub fn charts(rows: &[RootError]) -> Vec<(String, String)> {
    let chart = |prec: Precision| {
        let l = prec.label();
        let mut chart = Chart::new(
            format!("Rayleigh roots at {l}: error against ν (0 plotted as 0.01 ε)"),
            "Poisson's ratio ν",
            "error / ε (m1 relative; m2, m3 relative to |m|)",
        )
        .log(false, true);
        for method in METHODS {
            let style = if method == "default" {
                Style::Line
            } else {
                Style::Markers
            };
            for (which, err) in GROUPS {
                let pts = of(rows, prec, method).map(|r| (r.nu, err(r).max(1e-2)));
                chart.push(Series::new(
                    format!("{method} {which}"),
                    pts.collect(),
                    style,
                ));
            }
        }
        (format!("rayleigh_stability_{l}.svg"), chart.to_svg())
    };
    precisions().into_iter().map(chart).collect()
}

/// Two close-ups, log-log against the distance to the special point: m2, m3 near the merge ν*
/// (real-branch closed form against the default), and m1 near ν = 2/5 (complex Cardano).
/// Draws the errors of the roots of (6) near its special points; no arithmetic beyond plotting.
pub fn closeups(rows: &[RootError]) -> Vec<(String, String)> {
    let mut merge = Chart::new(
        "m2, m3 near the merge point ν* ≈ 0.26308 (real-branch closed form vs default)",
        "|ν − ν*|",
        "error of m2, m3 / ε (relative to |m|)",
    )
    .log(true, true);
    let mut p0 = Chart::new(
        "m1 near ν = 2/5, where the depressed cubic's p vanishes (complex Cardano vs default)",
        "|ν − 2/5|",
        "relative error of m1 / ε",
    )
    .log(true, true);
    // The errors `err` of one method near the point c, against |ν − c|, sorted.
    let near = |prec, c: f64, method, err: fn(&RootError) -> f64| {
        let near_c = of(rows, prec, method).filter(|r| (r.nu - c).abs() < 0.05);
        let mut v: Vec<(f64, f64)> = near_c
            .map(|r| ((r.nu - c).abs(), err(r).max(1e-2)))
            .collect();
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        v
    };
    // Each close-up's closed form at every precision, then the default's, dashed.
    for (m_merge, m_p0, style) in [
        ("real-branches", "complex-cardano", Style::LineMarkers),
        ("default", "default", Style::Dashed),
    ] {
        for prec in precisions() {
            let l = prec.label();
            let at_merge = near(prec, NU_STAR, m_merge, GROUPS[1].1);
            merge.push(Series::new(format!("{m_merge} {l}"), at_merge, style));
            let at_p0 = near(prec, 0.4, m_p0, GROUPS[0].1);
            p0.push(Series::new(format!("{m_p0} {l}"), at_p0, style));
        }
    }
    vec![
        ("rayleigh_near_merge.svg".to_string(), merge.to_svg()),
        ("rayleigh_near_p0.svg".to_string(), p0.to_svg()),
    ]
}

/// The worst error per (precision, method, root group, ν region), as Markdown table rows:
/// the precision, the method and a cell per region of [`REGIONS`].
/// Tabulates the errors of the roots of (6) as measured.
pub fn summary(rows: &[RootError]) -> Vec<[String; 6]> {
    let mut out = Vec::new();
    for prec in precisions() {
        for method in METHODS {
            let [a, b, c, d] = REGIONS.map(|(_, inside)| {
                let sel = of(rows, prec, method).filter(|r| inside(r.nu));
                let (w1, w23) = sel.fold((0.0f64, 0.0f64), |(a, b), r| (a.max(r.m1), b.max(r.m23)));
                format!("{} / {}", fmt_eps(w1), fmt_eps(w23))
            });
            out.push([prec.label(), method.to_string(), a, b, c, d]);
        }
    }
    out
}

/// The precisions of the study: f64, double-double, MPFR 128 and 256 bits.
fn precisions() -> Vec<Precision> {
    super::precisions(&[128, 256])
}

/// ν ≈ 0.26308, where the roots m2 and m3 of (6) merge.
const NU_STAR: f64 = 0.263_082_064_883_363_6;

/// A region of ν: its name and whether a ν lies in it.
pub type Region = (&'static str, fn(f64) -> bool);

/// The ν regions of [`summary`]'s columns 3–6.
pub const REGIONS: [Region; 4] = [
    ("whole range", |_| true),
    ("dist(ν, ν*) < 1e-3", |nu| (nu - NU_STAR).abs() < 1e-3),
    ("dist(ν, 0.4) < 1e-3", |nu| (nu - 0.4).abs() < 1e-3),
    ("ν < −0.99 or ν > 0.499", |nu| {
        !(-0.99..=0.499).contains(&nu)
    }),
];

fn fmt_eps(e: f64) -> String {
    if e < 10.0 {
        format!("{e:.1}")
    } else {
        format!("{e:.1e}")
    }
}
