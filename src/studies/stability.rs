//! Stability maps: for each method, the decimal digits it delivers at f64 and double-double over
//! its parameters, against references at 256 bits or more (`moving-hertz study stability`;
//! findings in `docs/stability.md`): the series (37) and the quadrature of (46)–(47) over
//! (1 − M_R, k), by a fixed 64-point Gauss–Legendre rule in α (what one would write first) and
//! by the crate; the paper's forward recursion (40) for L_n over (n, e²).

use super::svg::Heatmap;
use moving_hertz::numerics::quadrature::GaussLegendre;
use moving_hertz::physics::GreenFunction;
use moving_hertz::routes::moments::{moments, moments_with, MomentMethod};
use moving_hertz::scalar::{Dd, Mp, MpPrec, Precision, Real};
use moving_hertz::{integrals, ExactInputs, IntegralOptions, Integrals, Method};
use rug::Float;
use std::collections::HashMap;

/// A map: digits on a grid, for one method and precision.
#[derive(Clone, Debug)]
pub struct DigitMap {
    /// File stem, e.g. `stability_series_f64`.
    pub name: String,
    /// The digits as a heat map: `z[j][i]` at `(xs[i], ys[j])`, NaN where the method refused
    /// (a typed error), coloured from 0 to the precision's full digit count.
    pub map: Heatmap,
}

impl DigitMap {
    /// The map `stability_{kind}_{precision}` of the digits `z` over the grid `xs`, `ys` (log
    /// axes where `log` says), titled `title` with the axis labels `labels`, coloured from 0 to
    /// the precision's full digit count.
    fn new(
        (kind, label): (&str, Precision),
        title: String,
        labels: [&str; 2],
        (xs, ys): (Vec<f64>, Vec<f64>),
        log: (bool, bool),
        z: Vec<Vec<f64>>,
    ) -> DigitMap {
        let map = Heatmap {
            title,
            x_label: labels[0].into(),
            y_label: labels[1].into(),
            z_label: "correct decimal digits".into(),
            xs,
            ys,
            z,
            x_log: log.0,
            y_log: log.1,
            z_range: (0.0, super::full_digits(label.bits())),
            missing: "refused".into(),
        };
        let name = format!("stability_{kind}_{}", label.label());
        DigitMap { name, map }
    }

    /// The precision's full digit count (the colour scale's top).
    pub fn full(&self) -> f64 {
        self.map.z_range.1
    }

    /// CSV rows (x, y, digits; `refused` where the method refused).
    /// The digits each method of (6), (37), (40) delivers, as measured.
    pub fn rows(&self) -> Vec<Vec<String>> {
        let mut out = Vec::new();
        let m = &self.map;
        for (j, y) in m.ys.iter().enumerate() {
            for (i, x) in m.xs.iter().enumerate() {
                out.push(vec![
                    format!("{x:e}"),
                    format!("{y:e}"),
                    if m.z[j][i].is_nan() {
                        "refused".to_string()
                    } else {
                        format!("{:.2}", m.z[j][i])
                    },
                ]);
            }
        }
        out
    }
}

/// The digits a relative error `err` leaves, at most `full`; NaN (a refused cell) for NaN.
fn digits(err: f64, full: f64) -> f64 {
    if err.is_nan() {
        f64::NAN
    } else {
        super::correct_digits(err, full).min(full)
    }
}

/// The grid 1 − M_R from 10^-6 up to 1 and k from 10^-3 to 10^3.
fn speed_k_grid() -> (Vec<f64>, Vec<f64>) {
    let xs = (0..=12)
        .map(|j| 10f64.powf(-6.0 + 0.5 * j as f64))
        .collect();
    let ys = (0..=12)
        .map(|j| 10f64.powf(-3.0 + 0.5 * j as f64))
        .collect();
    (xs, ys)
}

/// Rounds a binary input to the nearest dyadic with 40 fractional bits (exact at every
/// precision used here).
fn dyadic(x: f64) -> f64 {
    if x == 0.0 {
        return 0.0;
    }
    let e = x.abs().log2().floor();
    let q = 2f64.powf(40.0 - e);
    (x * q).round() / q
}

/// I1, I2 by `method` at precision `p` and its floor.
fn run_at<T: Real>(inputs: &ExactInputs, p: T::Prec, method: Method) -> Option<Integrals<T>> {
    let (sp, k) = inputs.at::<T>(p).ok()?;
    let opts = IntegralOptions {
        method,
        ..Default::default()
    };
    integrals(&sp, &k, &opts).ok()
}

/// The 256-bit references (I1, I2), at 320 bits, by the bits of (M_R, k) at ν = 0.2: each is
/// formed once for the six maps that share it.
type References = HashMap<(u64, u64), Option<(Float, Float)>>;

/// The error against a reference, at 320 bits.
fn rel<T: Real>(got: &T, want: &Float) -> f64 {
    super::rel_error(got, want, 320)
}

/// I1, I2 by a fixed 64-point Gauss–Legendre rule on [0, π/2] in α (the naive quadrature of
/// (46)–(47)).
fn naive<T: Real>(inputs: &ExactInputs, p: T::Prec) -> Option<(T, T)> {
    let (sp, k) = inputs.at::<T>(p).ok()?;
    let k2 = k.square();
    let rule = GaussLegendre::<T>::get(64, p).ok()?;
    let g = GreenFunction::new(sp.material());
    let two_pi = T::pi(p).mul_pow2(1);
    let integrand = |a: &T, pick_cos: bool| {
        let (s, c) = a.clone().sin_cos();
        let (s2, c2) = (s.square(), c.square());
        let t = sp.mr2().clone() * &c2;
        let omt = sp.one_minus_mr2().clone() + sp.mr2().clone() * &s2;
        let d2 = c2.clone() + k2.clone() * &s2;
        let w = if pick_cos { c2 } else { s2 };
        two_pi.clone() * g.g_regular(&t) * w / (omt * d2.clone() * d2.sqrt())
    };
    let half_pi = T::pi(p).mul_pow2(-1);
    let zero = T::zero(p);
    let i1 = rule.integrate(|a: &T| integrand(a, false), &zero, &half_pi);
    let i2 = rule.integrate(|a: &T| integrand(a, true), &zero, &half_pi);
    Some((i1, i2))
}

fn integral_map(
    label: Precision,
    name: &str,
    what: &str,
    mut err: impl FnMut(f64, f64) -> f64,
    tick: &mut impl FnMut(),
) -> DigitMap {
    let (xs, ys) = speed_k_grid();
    let full = super::full_digits(label.bits());
    let z = ys
        .iter()
        .map(|&k| {
            xs.iter()
                .map(|&d| {
                    let v = digits(err(dyadic(1.0 - d), dyadic(k)), full);
                    tick();
                    v
                })
                .collect()
        })
        .collect();
    let title = format!("{what} at {label}: correct digits of I1, I2 (ν = 0.2)");
    let labels = ["1 − M_R", "axis ratio k"];
    DigitMap::new((name, label), title, labels, (xs, ys), (true, true), z)
}

/// Digits of L_n by the paper's forward recursion over (n, e²), against the stable default at
/// 256 bits more than the working precision.
fn recursion_map<T: Real>(p: T::Prec, label: Precision, tick: &mut impl FnMut()) -> DigitMap {
    let ns: Vec<usize> = (0..=16)
        .map(|j| 10f64.powf(j as f64 / 4.0).round() as usize)
        .collect();
    // e² from −3 to 0.95: mc = k² = 1 − e² from 4 down to 0.05.
    let e2s: Vec<f64> = (0..=16).map(|j| -3.0 + 3.95 * j as f64 / 16.0).collect();
    let full = super::full_digits(label.bits());
    let n_max = *ns.last().unwrap_or(&1);
    let pr = MpPrec::clamped(T::bits(p) + 256);
    let z = e2s
        .iter()
        .map(|&e2| {
            let mc = dyadic(1.0 - e2);
            let fwd = moments_with(&T::from_f64(mc, p), n_max, MomentMethod::Forward, 0);
            let reference = moments(&Mp::from_f64(mc, pr), n_max);
            ns.iter()
                .map(|&n| {
                    tick();
                    match (&fwd, &reference) {
                        // A value the recursion overflowed to (not finite) has no correct
                        // digit; a recursion that refused (a typed error) is NaN.
                        (Ok(f), Ok(r)) => match rel(&f.l()[n], r.l()[n].as_float()) {
                            e if e.is_nan() => 0.0,
                            e => digits(e, full),
                        },
                        _ => f64::NAN,
                    }
                })
                .collect()
        })
        .collect();
    let title = format!("Forward recursion (40) for L_n at {label}: correct digits");
    let xs = ns.iter().map(|&n| n.max(1) as f64).collect();
    let labels = ["n", "e² = 1 − k²"];
    DigitMap::new(
        ("recursion", label),
        title,
        labels,
        (xs, e2s),
        (true, false),
        z,
    )
}

/// The relative error of (I1, I2) at `T` by `method`, or by the naive rule where `None`, at
/// ν = 0.2, against the 256-bit quadrature; NaN where refused.
fn cell_error<T: Real<Prec = ()>>(
    method: Option<Method>,
    mr: f64,
    k: f64,
    refs: &mut References,
) -> f64 {
    let Ok(inputs) = ExactInputs::from_f64(0.2, mr, k) else {
        return f64::NAN;
    };
    let reference = refs.entry((mr.to_bits(), k.to_bits())).or_insert_with(|| {
        let r = run_at::<Mp>(&inputs, MpPrec::clamped(256), Method::Adaptive)?;
        Some((r.i1.value.to_float(320), r.i2.value.to_float(320)))
    });
    let Some((r1, r2)) = reference else {
        return f64::NAN;
    };
    let got = match method {
        Some(m) => run_at::<T>(&inputs, (), m).map(|r| (r.i1.value, r.i2.value)),
        None => naive::<T>(&inputs, ()),
    };
    got.map_or(f64::NAN, |(i1, i2)| rel(&i1, r1).max(rel(&i2, r2)))
}

/// All maps at f64 and double-double; `tick` is called after each cell.
/// Measures the methods for (6), (37) and (40) against 256-bit references or more.
pub fn run(mut tick: impl FnMut()) -> Vec<DigitMap> {
    let kinds = [
        ("series", "Series (37)", Some(Method::Series)),
        ("naive_quadrature", "64-point Gauss–Legendre in α", None),
        (
            "quadrature",
            "Graded quadrature (crate)",
            Some(Method::Adaptive),
        ),
    ];
    let (mut out, mut refs) = (Vec::new(), References::new());
    for (name, what, method) in kinds {
        let f64_err = |mr, k| cell_error::<f64>(method, mr, k, &mut refs);
        out.push(integral_map(Precision::F64, name, what, f64_err, &mut tick));
        let dd_err = |mr, k| cell_error::<Dd>(method, mr, k, &mut refs);
        let dd = Precision::DoubleDouble;
        out.push(integral_map(dd, name, what, dd_err, &mut tick));
    }
    out.push(recursion_map::<f64>((), Precision::F64, &mut tick));
    out.push(recursion_map::<Dd>((), Precision::DoubleDouble, &mut tick));
    out
}

/// Cells [`run`] computes (for a progress bar).
/// Implements no equation; exact count.
pub fn cells() -> usize {
    let (xs, ys) = speed_k_grid();
    6 * xs.len() * ys.len() + 2 * 17 * 17
}
