//! Studies of the series route of section 5 (`moving-hertz study series`, `study recursion`;
//! findings in `docs/series.md`): the terms the series (37) needs against M_R and their cost
//! ([`terms_study`]), the error growth of the forward recursion (40) against the exact form
//! α_n K + β_n E ([`forward_study`]) and the bits any evaluation in the K, E basis loses
//! ([`condition_map`]). Inputs are dyadic (exact at every precision), so one reference serves
//! all precisions.

use super::median_ns;
use super::svg::{Chart, Heatmap, Series, Style, Style::*};
use moving_hertz::error::Result;
use moving_hertz::numerics::elliptic::ellipke_mc;
use moving_hertz::physics::{Material, Speed};
use moving_hertz::routes::moments::{ke_condition_bits, moments_with, KeForm, MomentMethod};
use moving_hertz::routes::series::{integrals, terms_estimate, SeriesOptions};
use moving_hertz::routes::AxisRatio;
use moving_hertz::scalar::{FieldOps, Mp, MpPrec, Precision, Real};
use rug::Float;

// ---------------------------------------------------------------------------------------------
// Terms needed and cost against M_R
// ---------------------------------------------------------------------------------------------

/// The speeds of the terms study: j/16 for j = 0 … 15 and 1 − 2^-k for k = 5 … 10 (dyadic).
/// The M_R of (35)–(37); exact dyadic values.
pub fn speed_grid() -> Vec<f64> {
    let mut v: Vec<f64> = (0..16).map(|j| j as f64 / 16.0).collect();
    v.extend((5..=10).map(|k| 1.0 - 2f64.powi(-k)));
    v
}

/// The targets of the terms study and the precision each is run at: the lowest precision whose
/// ε is below the target.
/// Tolerances for (37); exact.
pub fn targets() -> Vec<(f64, Precision)> {
    let mp = |b: u32| Precision::Mpfr(MpPrec::clamped(b));
    vec![
        (1e-8, Precision::F64),
        (1e-15, Precision::F64),
        (1e-30, Precision::DoubleDouble),
        (1e-30, mp(128)),
        (1e-70, mp(256)),
    ]
}

/// Poisson's ratio and axis ratio of the terms study (k = 1/2: e² = 3/4, forward moments).
pub const TERMS_NU: f64 = 0.25;
/// See [`TERMS_NU`].
pub const TERMS_K: f64 = 0.5;

/// One evaluation of the terms study.
#[derive(Clone, Debug)]
pub struct TermsRow {
    /// M_R.
    pub mr: f64,
    /// Target relative accuracy (the route's `rel_tol`).
    pub target: f64,
    /// Precision.
    pub precision: Precision,
    /// Terms summed (0 when the route refused: term cap).
    pub terms: usize,
    /// [`terms_estimate`] for the target.
    pub estimate: u64,
    /// Median time per evaluation of I1 and I2, ns.
    pub time_ns: f64,
    /// Larger relative error of I1, I2 against the reference.
    pub error: f64,
    /// The route's error estimate.
    pub error_estimate: f64,
}

/// I1, I2 by the series at 420 bits with tolerance 10⁻¹⁰⁰ (the reference of the terms study).
fn reference(mr: f64) -> Result<(Float, Float)> {
    let p = MpPrec::clamped(420);
    let (speed, axis) = terms_inputs::<Mp>(mr, p)?;
    let opts = SeriesOptions {
        rel_tol: Some(Mp::parse("1e-100", p)?),
        max_terms: 300_000,
    };
    let r = integrals(&speed, &axis, &opts)?;
    Ok((r.i1.to_float(420), r.i2.to_float(420)))
}

/// The speed M_R and the axis ratio [`TERMS_K`] at ν = [`TERMS_NU`], at precision `p`.
fn terms_inputs<T: Real>(mr: f64, p: T::Prec) -> Result<(Speed<T>, AxisRatio<T>)> {
    let mat = Material::new(T::from_f64(TERMS_NU, p))?;
    Ok((
        mat.speed(T::from_f64(mr, p))?,
        AxisRatio::new(T::from_f64(TERMS_K, p))?,
    ))
}

/// The error against a reference, at 440 bits.
fn rel_err<T: Real>(got: &T, want: &Float) -> f64 {
    super::rel_error(got, want, 440)
}

fn terms_at<T: Real>(
    p: T::Prec,
    prec: Precision,
    target: f64,
    mr: f64,
    refs: &(Float, Float),
    budget_ms: f64,
) -> Result<TermsRow> {
    let (speed, axis) = terms_inputs::<T>(mr, p)?;
    let opts = SeriesOptions {
        rel_tol: Some(T::parse(&format!("{target:e}"), p)?),
        max_terms: moving_hertz::routes::series::DEFAULT_MAX_TERMS,
    };
    let estimate = terms_estimate(mr * mr, target);
    let mut row = TermsRow {
        mr,
        target,
        precision: prec,
        terms: 0,
        estimate,
        time_ns: f64::NAN,
        error: f64::NAN,
        error_estimate: f64::NAN,
    };
    match integrals(&speed, &axis, &opts) {
        Ok(r) => {
            row.terms = r.work;
            row.error = rel_err(&r.i1, &refs.0).max(rel_err(&r.i2, &refs.1));
            row.error_estimate = r.error_estimate.to_f64();
            row.time_ns = median_ns(budget_ms, || integrals(&speed, &axis, &opts));
        }
        Err(moving_hertz::Error::TermCap { .. }) => {}
        Err(e) => return Err(e),
    }
    Ok(row)
}

/// Runs the terms study over `speeds` (see [`speed_grid`]) for every target of [`targets`],
/// timing each evaluation for about `budget_ms` ms.
/// Measures the terms of (37) each tolerance needs, and their cost.
pub fn terms_study(speeds: &[f64], budget_ms: f64) -> Result<Vec<TermsRow>> {
    let mut out = Vec::new();
    for &mr in speeds {
        let refs = reference(mr)?;
        for (target, prec) in targets() {
            let row = moving_hertz::with_precision!(prec, T, p => terms_at::<T>(p, prec, target, mr, &refs, budget_ms))?;
            out.push(row);
        }
    }
    Ok(out)
}

/// The rows of the terms study's CSV table (as `moving-hertz study series` writes it, header
/// `M_R,target,precision,terms,terms_estimate,time_ns,error,error_estimate`): the data its
/// charts are drawn from. An error names the line that does not read.
/// Reads the terms of (37) back; no arithmetic.
pub fn rows_from_csv(table: &super::Table) -> std::result::Result<Vec<TermsRow>, String> {
    table.each(|i| {
        Ok(TermsRow {
            mr: table.number(i, "M_R")?,
            target: table.number(i, "target")?,
            precision: table.precision(i, "precision")?,
            terms: table.number(i, "terms")?,
            estimate: table.number(i, "terms_estimate")?,
            time_ns: table.number(i, "time_ns")?,
            error: table.number(i, "error")?,
            error_estimate: table.number(i, "error_estimate")?,
        })
    })
}

/// Charts of the terms study: terms needed and time per evaluation against 1 − M_R (log-log).
/// Draws the terms of (37); no arithmetic beyond plotting.
pub fn terms_charts(rows: &[TermsRow]) -> Vec<(String, String)> {
    let mut terms = Chart::new(
        "Series (37): terms needed for I1, I2 (ν = 1/4, k = 1/2)",
        "1 − M_R (M_R = V/c_R; log scale)",
        "terms summed (log scale)",
    )
    .log(true, true);
    let mut time = Chart::new(
        "Series (37): time per evaluation of I1 and I2 (ν = 1/4, k = 1/2)",
        "1 − M_R (M_R = V/c_R; log scale)",
        "median time per evaluation, µs (log scale)",
    )
    .log(true, true);
    let mut seen_tol: Vec<u64> = Vec::new();
    for (target, prec) in targets() {
        let sel: Vec<&TermsRow> = rows
            .iter()
            .filter(|r| r.target == target && r.precision == prec && r.terms > 0)
            .collect();
        let pts = |f: fn(&TermsRow) -> f64| sel.iter().map(|r| (1.0 - r.mr, f(r))).collect();
        let label = format!("{target:.0e} at {}", prec.label());
        terms.push(Series::new(&label, pts(|r| r.terms as f64), LineMarkers));
        if !seen_tol.contains(&target.to_bits()) {
            seen_tol.push(target.to_bits());
            let estimate = pts(|r| r.estimate as f64);
            terms.push(Series::new(
                format!("estimate, {target:.0e}"),
                estimate,
                Dashed,
            ));
        }
        time.push(Series::new(label, pts(|r| r.time_ns / 1e3), LineMarkers));
    }
    vec![
        ("series_terms.svg".into(), terms.to_svg()),
        ("series_time.svg".into(), time.to_svg()),
    ]
}

// ---------------------------------------------------------------------------------------------
// The forward recursion against the exact form
// ---------------------------------------------------------------------------------------------

/// k² values of the forward study (dyadic): e² = 15/16, 3/4 (stable), 1/2 (neutral), 7/16, 1/4,
/// 1/16, 1/256 (|r| = k²/e² = 9/7 … 255) and k² = 2, 16, 256 (e² < 0, r = 2, 16/15, 256/255).
pub const FORWARD_MC: [f64; 10] = [
    0.0625, 0.25, 0.5, 0.5625, 0.75, 0.9375, 0.99609375, 2.0, 16.0, 256.0,
];

/// Largest n of the forward study.
pub const FORWARD_N: usize = 10_000;

/// |r| = |k²/e²|, the modulus of the parasitic characteristic root of (40).
pub fn parasitic_root(mc: f64) -> f64 {
    mc / (1.0 - mc).abs()
}

/// Predicted growth of the forward recursion's relative error: log₂ max(1, |k²/e²|) bits per step.
/// The growth rate of the forward recursion (40) (docs/series.md); an `f64` estimate.
pub fn predicted_bits_per_step(mc: f64) -> f64 {
    parasitic_root(mc).log2().max(0.0)
}

/// One sampled point of the forward study.
#[derive(Clone, Debug)]
pub struct ForwardPoint {
    /// k².
    pub mc: f64,
    /// Precision.
    pub precision: Precision,
    /// n.
    pub n: usize,
    /// Relative error of L_n.
    pub err_l: f64,
    /// Relative error of M_n.
    pub err_m: f64,
}

/// The growth summary of one (k², precision).
#[derive(Clone, Debug)]
pub struct Growth {
    /// k².
    pub mc: f64,
    /// Precision.
    pub precision: Precision,
    /// Predicted bits lost per step, log₂ max(1, |k²/e²|).
    pub predicted: f64,
    /// Measured bits per step of the L_n error (least-squares slope of log₂ error over the
    /// points with 2¹⁰ ε ≤ error ≤ 2⁻¹⁰), NaN when fewer than 3 such points.
    pub measured_l: f64,
    /// The same for M_n.
    pub measured_m: f64,
    /// First n with relative error ≥ 1 in L_n (total loss), if any.
    pub total_loss_n: Option<usize>,
    /// Predicted total-loss index (bits − 1)/predicted.
    pub predicted_loss_n: Option<f64>,
    /// Largest L_n error in ε over the whole range (for the stable cases).
    pub worst_eps: f64,
    /// Last n studied.
    pub n_max: usize,
}

/// The n range of the forward study for `mc`: up to 10⁴, or about 60 steps past where 256 bits
/// are predicted to be lost.
fn forward_n_max(mc: f64) -> usize {
    let lam = predicted_bits_per_step(mc);
    if lam <= 0.0 {
        FORWARD_N
    } else {
        ((300.0 / lam).ceil() as usize + 60).min(FORWARD_N)
    }
}

/// The sample of n: every n up to 64, then about 150 log-spaced values.
fn sample(n_max: usize) -> Vec<usize> {
    let mut v: Vec<usize> = (0..=n_max.min(64)).collect();
    let mut x = 64.0f64;
    while (x as usize) < n_max {
        x *= 1.04;
        v.push((x as usize).min(n_max));
    }
    v.dedup();
    v
}

/// Reference L_n, M_n (n ≤ n_max) from the exact form α_n K + β_n E with the coefficients run
/// at `bits` bits (≥ 256 + bits lost + 96, so its own rounding is far below 2⁻²⁵⁶).
fn exact_form_reference(mc: f64, n_max: usize, bits: u32) -> Result<Vec<(Float, Float)>> {
    let p = MpPrec::clamped(bits);
    let x = Mp::from_f64(mc, p);
    let (k, e) = ellipke_mc(&x)?;
    let mut form = KeForm::new(x)?;
    Ok((0..=n_max)
        .map(|_| {
            let t = form.next_term();
            let l = t.l.0 * &k + t.l.1 * &e;
            let m = t.m.0 * &k + t.m.1 * &e;
            (l.to_float(bits), m.to_float(bits))
        })
        .collect())
}

fn forward_at<T: Real>(
    p: T::Prec,
    prec: Precision,
    mc: f64,
    refs: &[(Float, Float)],
    ns: &[usize],
    out: &mut Vec<ForwardPoint>,
) -> Result<Growth> {
    let n_max = refs.len() - 1;
    let tab = moments_with(&T::from_f64(mc, p), n_max, MomentMethod::Forward, 0)?;
    let eps = T::epsilon(p).to_f64();
    let bits = T::bits(p) as f64;
    let mut fit_l = Vec::new();
    let mut fit_m = Vec::new();
    let mut total_loss_n = None;
    let mut worst: f64 = 0.0;
    for (n, (rl, rm)) in refs.iter().enumerate() {
        let el = rel_err(&tab.l()[n], rl);
        let em = rel_err(&tab.m()[n], rm);
        worst = worst.max(el / eps);
        // NaN (a non-finite result) counts as total loss too.
        if total_loss_n.is_none() && (el >= 1.0 || el.is_nan()) {
            total_loss_n = Some(n);
        }
        let window = |x: f64| x >= eps * 1024.0 && x <= 1.0 / 1024.0;
        if window(el) {
            fit_l.push((n as f64, el.log2()));
        }
        if window(em) {
            fit_m.push((n as f64, em.log2()));
        }
        if ns.binary_search(&n).is_ok() {
            out.push(ForwardPoint {
                mc,
                precision: prec,
                n,
                err_l: el,
                err_m: em,
            });
        }
    }
    let lam = predicted_bits_per_step(mc);
    Ok(Growth {
        mc,
        precision: prec,
        predicted: lam,
        measured_l: slope(&fit_l),
        measured_m: slope(&fit_m),
        total_loss_n,
        predicted_loss_n: (lam > 0.0).then(|| (bits - 1.0) / lam),
        worst_eps: worst,
        n_max,
    })
}

/// Least-squares slope of the points (NaN for fewer than 3).
fn slope(pts: &[(f64, f64)]) -> f64 {
    if pts.len() < 3 {
        return f64::NAN;
    }
    let n = pts.len() as f64;
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / n;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / n;
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    sxy / sxx
}

/// The precisions of the recursion study: f64, double-double, MPFR 128 and 256 bits.
/// For the study of (40); exact.
pub fn recursion_precisions() -> Vec<Precision> {
    super::precisions(&[128, 256])
}

/// Runs the forward study for every k² of [`FORWARD_MC`] at every precision of
/// [`recursion_precisions`]: sampled errors and growth summaries.
/// Measures the forward recursion (40) against the exact form α_n K + β_n E of (42) run with
/// hundreds of guard bits; errors to a few percent.
pub fn forward_study() -> Result<(Vec<ForwardPoint>, Vec<Growth>)> {
    let mut points = Vec::new();
    let mut growth = Vec::new();
    for &mc in FORWARD_MC.iter() {
        let n_max = forward_n_max(mc);
        let lam = predicted_bits_per_step(mc);
        let bits = 256 + (lam * n_max as f64).ceil() as u32 + 96;
        let refs = exact_form_reference(mc, n_max, bits)?;
        let ns = sample(n_max);
        for prec in recursion_precisions() {
            let g = moving_hertz::with_precision!(prec, T, p => forward_at::<T>(p, prec, mc, &refs, &ns, &mut points))?;
            growth.push(g);
        }
    }
    Ok((points, growth))
}

fn mc_label(mc: f64) -> String {
    let e2 = 1.0 - mc;
    if mc <= 1.0 {
        format!("e²={e2}")
    } else {
        format!("k={:.3}", mc.sqrt())
    }
}

/// Charts of the forward study: one per precision, relative error of L_n against n (log-log,
/// errors clipped to [ε/1000, 1000]); and measured against predicted growth.
/// Draws the errors of (40); no arithmetic beyond plotting.
pub fn forward_charts(points: &[ForwardPoint], growth: &[Growth]) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for prec in recursion_precisions() {
        let eps = 2f64.powi(1 - prec.bits() as i32);
        let (lo, hi) = (eps / 1000.0, 1000.0);
        let mut chart = Chart::new(
            format!(
                "Forward recursion (40) at {}: relative error of L_n (vs exact form)",
                prec.label()
            ),
            "n (log scale)",
            "relative error of L_n (log scale, clipped)",
        )
        .log(true, true);
        for &mc in FORWARD_MC.iter() {
            let pts = points
                .iter()
                .filter(|p| p.precision == prec && p.mc == mc && p.n > 0)
                .map(|p| (p.n as f64, p.err_l.clamp(lo, hi)))
                .collect();
            chart.push(Series::new(
                format!("{}, |r|={:.3}", mc_label(mc), parasitic_root(mc)),
                pts,
                Style::Line,
            ));
        }
        out.push((
            format!("recursion_forward_{}.svg", prec.label()),
            chart.to_svg(),
        ));
    }
    let mut g = Chart::new(
        "Forward recursion: measured against predicted error growth",
        "predicted log₂|k²/e²|, bits per step (log scale)",
        "measured slope of log₂(error of L_n), bits per step (log scale)",
    )
    .log(true, true);
    for prec in recursion_precisions() {
        let pts = growth
            .iter()
            .filter(|r| r.precision == prec && r.predicted > 0.0)
            .map(|r| (r.predicted, r.measured_l))
            .collect();
        g.push(Series::new(prec.label(), pts, Style::Markers));
    }
    let lo = growth
        .iter()
        .filter(|r| r.predicted > 0.0)
        .map(|r| r.predicted)
        .fold(f64::INFINITY, f64::min);
    let hi = growth.iter().map(|r| r.predicted).fold(0.0, f64::max);
    g.push(Series::new(
        "measured = predicted",
        vec![(lo / 1.5, lo / 1.5), (hi * 1.5, hi * 1.5)],
        Style::Dashed,
    ));
    out.push(("recursion_growth.svg".into(), g.to_svg()));
    out
}

// ---------------------------------------------------------------------------------------------
// Bits lost in the K, E basis
// ---------------------------------------------------------------------------------------------

/// The condition map: bits lost in L_n and M_n over a grid.
#[derive(Clone, Debug)]
pub struct ConditionMap {
    /// The parameter of each row (e, or k − 1).
    pub params: Vec<f64>,
    /// The n of each column.
    pub ns: Vec<usize>,
    /// log₂ κ of L_n: `bits_l[row][col]`.
    pub bits_l: Vec<Vec<f64>>,
    /// log₂ κ of M_n.
    pub bits_m: Vec<Vec<f64>>,
}

/// The n columns of the maps: 1 … 10⁴, 33 log-spaced values.
/// The n of (38)–(41); exact.
pub fn map_columns() -> Vec<usize> {
    let mut v: Vec<usize> = (0..=32)
        .map(|j| 10f64.powf(j as f64 / 8.0).round() as usize)
        .collect();
    v.dedup();
    v
}

/// Rows: e = 0.02 … 0.98 (step 0.024) for `k_side = false`; k − 1 = 10^(j/6) for
/// j = −18 … 18 (k from 1.001 to 1001) for `k_side = true`.
/// The e, k of (41); `f64` values.
pub fn map_rows(k_side: bool) -> Vec<f64> {
    if k_side {
        (-18..=18).map(|j| 10f64.powf(j as f64 / 6.0)).collect()
    } else {
        (0..=40).map(|j| 0.02 + 0.024 * j as f64).collect()
    }
}

/// Computes the map over `map_rows(k_side)` × [`map_columns`] at 64-bit MPFR.
/// The condition of (40)–(42) in the K, E basis ([`crate::routes::moments::ke_condition_bits`]).
pub fn condition_map(k_side: bool) -> Result<ConditionMap> {
    let p = MpPrec::clamped(64);
    let params = map_rows(k_side);
    let ns = map_columns();
    let n_max = *ns.last().unwrap_or(&1);
    let mut bits_l = Vec::new();
    let mut bits_m = Vec::new();
    for &x in &params {
        let mc = if k_side {
            (Mp::from_f64(x, p) + Mp::one(p)).square()
        } else {
            let e = Mp::from_f64(x, p);
            Mp::one(p) - e.square()
        };
        let b = ke_condition_bits(&mc, n_max)?;
        bits_l.push(ns.iter().map(|&n| b[n].0.max(0.0)).collect());
        bits_m.push(ns.iter().map(|&n| b[n].1.max(0.0)).collect());
    }
    Ok(ConditionMap {
        params,
        ns,
        bits_l,
        bits_m,
    })
}

/// The heat map of bits lost in L_n (colour capped at 256 bits).
/// Draws the condition of (40)–(42); no arithmetic beyond plotting.
pub fn condition_chart(map: &ConditionMap, k_side: bool) -> (String, String) {
    let (range, y_label, side) = if k_side {
        (
            "k > 1",
            "k − 1, k = b/a > 1 (log scale; e² = 1 − k² < 0)",
            "k",
        )
    } else {
        ("0 < e < 1", "eccentricity e = √(1 − k²)", "e")
    };
    let h = Heatmap {
        title: format!("Bits lost in the K, E basis: log₂((|α_n|K + |β_n|E)/L_n), {range}"),
        x_label: "n (log scale)".into(),
        y_label: y_label.into(),
        z_label: "bits lost (colour capped at 256)".into(),
        xs: map.ns.iter().map(|&n| n as f64).collect(),
        ys: map.params.clone(),
        z: (map.bits_l.iter())
            .map(|r| r.iter().map(|v| v.min(256.0)).collect())
            .collect(),
        x_log: true,
        y_log: k_side,
        z_range: (0.0, 256.0),
        missing: "no value".into(),
    };
    (format!("recursion_bits_lost_{side}.svg"), h.to_svg())
}
