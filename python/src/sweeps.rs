//! Vectorised sweeps: `moving_hertz::sweep::{ellipses, contacts, integrals}` over columns of
//! points that the Python layer has broadcast and flattened, with the GIL released.
//!
//! The points run in chunks of [`CHUNK`] (a multiple of the library's block, so that every
//! point's result is bit for bit the one of the whole sweep in one call: a point's result
//! depends only on its block, `moving_hertz::sweep`); between chunks the GIL is taken back to
//! call the progress callback and to let Ctrl-C through. A chunk's results are copied into
//! the output columns while the next chunk is solved, so that the memory beyond the output
//! arrays is about three chunks'.
//! A point whose input the binding refuses (text that does not parse, a ratio that is not
//! positive) is handed to the library as a point it refuses too (ν = NaN), so that the blocks
//! are the same whatever the inputs, and carries the binding's message.

use crate::fail::{guard, to_py, Fail};
use crate::input::{self, Num, SpeedKind};
use crate::single::{method, ContactGiven, Given};
use moving_hertz::scalar::{decimal_to_rational, Precision, Real};
use moving_hertz::sweep::{self, EllipsePoint, SpeedGiven, BLOCK};
use moving_hertz::{
    with_precision, ContactProblem, Estimated, IntegralOptions, Loading, Material, Options,
    RelError, Route, Speed,
};
use numpy::{IntoPyArray, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::ops::Range;
use std::sync::{Arc, Mutex};

/// Points per chunk: 64 blocks.
const CHUNK: usize = BLOCK * 64;

/// The route codes of the `route` column, in this order (−1: the point failed).
pub const ROUTES: [Route; 5] = [
    Route::Series,
    Route::Adaptive,
    Route::AdaptiveSubtracted,
    Route::FixedRule,
    Route::GradedRule,
];

/// One input column: float64 values or exact texts.
pub enum Col {
    F(Vec<f64>),
    T(Vec<String>),
}

impl Col {
    /// A 1-d float64 array or a list of str.
    fn from_py(x: &Bound<'_, PyAny>, argument: &'static str) -> Result<Col, Fail> {
        if let Ok(a) = x.extract::<PyReadonlyArray1<f64>>() {
            return Ok(Col::F(a.as_array().to_vec()));
        }
        x.extract::<Vec<String>>()
            .map(Col::T)
            .map_err(|_| Fail::Arg {
                argument,
                message: format!("{argument}: expected a float64 array or a list of decimal texts"),
            })
    }

    fn len(&self) -> usize {
        match self {
            Col::F(v) => v.len(),
            Col::T(v) => v.len(),
        }
    }

    /// The place of point `i`: `i`, or 0 in a column of one value (a scalar input, which
    /// the Python layer does not repeat).
    fn at(&self, i: usize) -> usize {
        if self.len() == 1 {
            0
        } else {
            i
        }
    }

    fn num(&self, i: usize) -> Num {
        match self {
            Col::F(v) => Num::F(v[self.at(i)]),
            Col::T(v) => Num::T(v[self.at(i)].clone()),
        }
    }
}

/// The output columns: per result field a value and a bound column, plus iterations (or the
/// work), the route code, the ok mask and the message of each failed point.
pub struct Columns {
    text: bool,
    f: Vec<Vec<f64>>,
    s: Vec<Vec<String>>,
    iterations: Vec<i64>,
    route: Vec<i8>,
    ok: Vec<bool>,
    /// The failed points: (index, message).
    failures: Vec<(usize, String)>,
}

impl Columns {
    fn new(fields: usize, n: usize, text: bool) -> Columns {
        let (nf, ns) = if text {
            (0, 2 * fields)
        } else {
            (2 * fields, 0)
        };
        Columns {
            text,
            f: (0..nf).map(|_| Vec::with_capacity(n)).collect(),
            s: (0..ns).map(|_| Vec::with_capacity(n)).collect(),
            iterations: Vec::with_capacity(n),
            route: Vec::with_capacity(n),
            ok: Vec::with_capacity(n),
            failures: Vec::new(),
        }
    }

    /// A solved point: its fields (absent ones as NaN or empty text).
    fn push<T: Real>(&mut self, fields: &[Option<&Estimated<T>>], iterations: usize, route: Route) {
        for (j, x) in fields.iter().enumerate() {
            if self.text {
                let (v, e) = x.map_or((String::new(), String::new()), |x| {
                    (x.value.to_decimal(), x.error.to_string())
                });
                self.s[2 * j].push(v);
                self.s[2 * j + 1].push(e);
            } else {
                let (v, e) = x.map_or((f64::NAN, f64::NAN), |x| {
                    (x.value.to_f64(), x.error.to_f64())
                });
                self.f[2 * j].push(v);
                self.f[2 * j + 1].push(e);
            }
        }
        self.iterations.push(iterations as i64);
        self.route.push(
            ROUTES
                .iter()
                .position(|r| *r == route)
                .map_or(-1, |i| i as i8),
        );
        self.ok.push(true);
    }

    /// A failed point with its message.
    fn fail(&mut self, message: String) {
        self.f.iter_mut().for_each(|c| c.push(f64::NAN));
        self.s.iter_mut().for_each(|c| c.push(String::new()));
        self.iterations.push(-1);
        self.route.push(-1);
        self.failures.push((self.ok.len(), message));
        self.ok.push(false);
    }

    /// `{"values": [...], "iterations", "route", "ok", "failures": [(index, message)]}` for the
    /// Python layer.
    fn into_py<'py>(self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        let values = PyList::empty(py);
        for c in self.f {
            values.append(c.into_pyarray(py))?;
        }
        for c in self.s {
            values.append(PyList::new(py, c)?)?;
        }
        d.set_item("values", values)?;
        d.set_item("iterations", self.iterations.into_pyarray(py))?;
        d.set_item("route", self.route.into_pyarray(py))?;
        d.set_item("ok", self.ok.into_pyarray(py))?;
        d.set_item("failures", PyList::new(py, self.failures)?)?;
        Ok(d)
    }
}

/// The pools of `threads=`, one per size, built once.
static POOLS: Mutex<Vec<(usize, Arc<rayon::ThreadPool>)>> = Mutex::new(Vec::new());

/// The pool of `threads` threads (`None`: rayon's global pool, every core).
fn pool(threads: Option<usize>) -> Result<Option<Arc<rayon::ThreadPool>>, Fail> {
    let Some(n) = threads else { return Ok(None) };
    if n == 0 || n > 4096 {
        let message = format!("threads = {n} is outside 1 <= threads <= 4096");
        return Err(Fail::Arg {
            argument: "threads",
            message,
        });
    }
    let mut pools = POOLS.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, p)) = pools.iter().find(|(m, _)| *m == n) {
        return Ok(Some(p.clone()));
    }
    let built = rayon::ThreadPoolBuilder::new().num_threads(n).build();
    let p =
        Arc::new(built.map_err(|e| Fail::Panic(format!("building a pool of {n} threads: {e}")))?);
    pools.push((n, p.clone()));
    Ok(Some(p))
}

/// Builds and solves the points `0..n` chunk by chunk with the GIL released (on `pool`, if
/// any): `build` makes a chunk's points with the binding's message for each point it refuses,
/// `solve` runs the library's sweep, `collect` takes each result or message in order; calls
/// `progress(done, n)` between chunks. The calling thread's share overlaps the pool's: while
/// chunk k is solved, chunk k − 1's results are collected and chunk k + 1 is built (one
/// `rayon::join`). At most three chunks' points and results are held at once.
fn in_chunks<I: Send + Sync, R: Send>(
    py: Python<'_>,
    n: usize,
    threads: Option<usize>,
    progress: Option<&Bound<'_, PyAny>>,
    build: impl Fn(Range<usize>) -> Result<Built<I>, Fail> + Sync + Send,
    solve: impl Fn(&[I]) -> Vec<moving_hertz::Result<R>> + Sync + Send,
    mut collect: impl FnMut(Result<R, String>) + Send,
) -> PyResult<()> {
    let pool = to_py(py, pool(threads))?;
    let chunk = |start: usize| start.min(n)..(start + CHUNK).min(n);
    let mut built: Option<Built<I>> = None;
    let mut solved: Option<Solved<R>> = None;
    let (mut start, mut done) = (0, 0);
    while done < n {
        let (now, after) = (chunk(start), chunk(start + CHUNK));
        let r = py.detach(|| {
            guard(|| {
                let items = match built.take() {
                    Some(b) => b,
                    None => build(now.clone())?,
                };
                let (mut waiting, collect) = (solved.take(), &mut collect);
                let mut step = || {
                    rayon::join(
                        || solve(&items.0),
                        || {
                            let got = waiting.take().map_or(0, |w| w.collect_into(collect));
                            let next = (!after.is_empty()).then(|| build(after.clone()));
                            (got, next.transpose())
                        },
                    )
                };
                let (out, (got, next)) = match &pool {
                    Some(p) => p.install(step),
                    None => step(),
                };
                built = next?;
                solved = Some(Solved(out, items.1));
                Ok(got)
            })
        });
        done += to_py(py, r)?;
        start = now.end;
        py.check_signals()?;
        if let (Some(cb), true) = (progress, done > 0) {
            cb.call1((done, n))?;
        }
    }
    Ok(())
}

/// A chunk's results and the binding's messages, waiting to be collected.
struct Solved<R>(Vec<moving_hertz::Result<R>>, Vec<Option<String>>);

impl<R> Solved<R> {
    /// Hands each result (or the binding's message, else the library's) to `collect`, in order;
    /// returns how many.
    fn collect_into(self, collect: &mut impl FnMut(Result<R, String>)) -> usize {
        let count = self.0.len();
        for (r, pre) in self.0.into_iter().zip(self.1) {
            collect(r.map_err(|e| pre.unwrap_or_else(|| e.to_string())));
        }
        count
    }
}

/// A chunk's points and the binding's message for each point it refused (`None`: valid).
type Built<I> = (Vec<I>, Vec<Option<String>>);

/// What a sweep over `cols` asks for: the points' count ([`common_len`]), the precision, the
/// method, and whether values come as text (asked for, or any precision above `f64`).
fn request(
    cols: &[Col],
    precision: &str,
    method: &str,
    text: bool,
) -> Result<(usize, Precision, moving_hertz::Method, bool), Fail> {
    let n = common_len(&cols.iter().collect::<Vec<_>>())?;
    let prec = input::precision(precision)?;
    Ok((
        n,
        prec,
        self::method(method)?,
        text || prec != Precision::F64,
    ))
}

/// The columns' common length (a column of one value stands for every point), or a refusal.
fn common_len(cols: &[&Col]) -> Result<usize, Fail> {
    let n = cols.iter().map(|c| c.len()).find(|&l| l != 1).unwrap_or(1);
    if cols.iter().any(|c| c.len() != n && c.len() != 1) {
        let message =
            "the input columns differ in length (the Python layer broadcasts them)".into();
        return Err(Fail::Arg {
            argument: "nu",
            message,
        });
    }
    Ok(n)
}

/// The ellipse points at precision `p`, with the binding's message for each point it refuses.
fn ellipse_points<T: Real>(
    [nu, sp, ratio]: &[Col; 3],
    kind: SpeedKind,
    range: Range<usize>,
    p: T::Prec,
) -> Result<Built<EllipsePoint<T>>, Fail> {
    let mut points = Vec::with_capacity(range.len());
    let mut pre = vec![None; range.len()];
    for (i, slot) in range.zip(pre.iter_mut()) {
        let point = (|| -> Result<EllipsePoint<T>, Fail> {
            let nu = match nu {
                Col::F(v) => T::from_f64(v[nu.at(i)], p),
                Col::T(_) => input::material::<T>(&nu.num(i), p)?.nu().clone(),
            };
            let speed = match (sp, kind) {
                (Col::F(v), SpeedKind::Mr) => SpeedGiven::Mr(T::from_f64(v[sp.at(i)], p)),
                (Col::F(v), SpeedKind::Gap) => SpeedGiven::Gap(T::from_f64(v[sp.at(i)], p)),
                (Col::T(v), SpeedKind::Mr) => SpeedGiven::Text(v[sp.at(i)].clone()),
                (Col::T(v), SpeedKind::Gap) => SpeedGiven::Text(mr_of_gap(&v[sp.at(i)])?),
            };
            let ratio = match ratio {
                Col::F(v) => T::from_f64(v[ratio.at(i)], p),
                Col::T(_) => input::positive(&ratio.num(i), "ratio", p)?,
            };
            Ok(EllipsePoint { nu, speed, ratio })
        })();
        points.push(point.unwrap_or_else(|f| {
            *slot = Some(f.message());
            let nan = T::from_f64(f64::NAN, p);
            EllipsePoint {
                nu: nan.clone(),
                speed: SpeedGiven::Mr(nan.clone()),
                ratio: nan,
            }
        }));
    }
    Ok((points, pre))
}

/// The exact M_R = 1 − gap as text `p/q`, for a gap given as text (checked exactly:
/// 0 < gap ≤ 1), so that the library forms the gap back exactly.
fn mr_of_gap(gap: &str) -> Result<String, Fail> {
    let g = decimal_to_rational(gap).map_err(Fail::about("gap"))?;
    if g <= 0 || g > 1 {
        let message = format!(
            "speed gap 1 - M_R = {} is outside its domain (0, 1]",
            gap.trim()
        );
        return Err(Fail::Arg {
            argument: "gap",
            message,
        });
    }
    Ok((-(g - 1u32)).to_string())
}

/// `sweep::ellipses` over the columns: per point k, e, I1, I2 with their bounds, iterations,
/// route.
#[pyfunction]
#[pyo3(signature = (precision, nu, speed, kind, ratio, method, threads, progress, text))]
#[allow(clippy::too_many_arguments)]
pub fn sweep_ellipses<'py>(
    py: Python<'py>,
    precision: &str,
    nu: &Bound<'py, PyAny>,
    speed: &Bound<'py, PyAny>,
    kind: &str,
    ratio: &Bound<'py, PyAny>,
    method: &str,
    threads: Option<usize>,
    progress: Option<&Bound<'py, PyAny>>,
    text: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let kind = SpeedKind::parse(kind);
    let cols = (|| {
        Ok::<_, Fail>([
            Col::from_py(nu, "nu")?,
            Col::from_py(speed, kind.argument())?,
            Col::from_py(ratio, "ratio")?,
        ])
    })();
    let cols = to_py(py, cols)?;
    let (n, prec, method, text) = to_py(py, request(&cols, precision, method, text))?;
    with_precision!(prec, T, p => {
        let opts = Options::<T> { method, ..Default::default() };
        let mut out = Columns::new(4, n, text);
        let build = |r| ellipse_points::<T>(&cols, kind, r, p);
        in_chunks(py, n, threads, progress, build, |c| sweep::ellipses(c, &opts), |r| match r {
            Ok(s) => out.push(&[Some(s.k()), Some(s.e()), Some(&s.integrals().i1), Some(&s.integrals().i2)], s.iterations(), s.integrals().route),
            Err(m) => out.fail(m),
        })?;
        out.into_py(py)
    })
}

/// A contact point's speed and shear modulus, or the message of its refusal.
type Made<T> = Result<(Speed<T>, T), String>;

/// The contact problems at precision `p`, with the binding's message for each it refuses:
/// each point's speed and shear modulus as `solve_contact` makes them
/// ([`ContactGiven::speed_and_modulus`]; made once for consecutive points of the same ν,
/// speed, modulus and density).
fn contact_problems<T: Real>(
    cols: &[Col],
    how: ContactGiven,
    range: Range<usize>,
    p: T::Prec,
) -> Result<Built<ContactProblem<T>>, Fail> {
    let zero = T::zero(p);
    let fallback = Material::new(zero.clone())?.speed(zero)?;
    let mut last: Option<(Given, Made<T>)> = None;
    let mut problems = Vec::with_capacity(range.len());
    let mut pre = vec![None; range.len()];
    for (i, slot) in range.zip(pre.iter_mut()) {
        let given: Given = [0, 1, 5, 6].map(|j| cols.get(j).map(|c| c.num(i)));
        let same = last.as_ref().is_some_and(|(g, _)| {
            g.iter().zip(&given).all(|(a, b)| match (a, b) {
                (Some(a), Some(b)) => input::same_num(a, b),
                (a, b) => a.is_none() && b.is_none(),
            })
        });
        if !same {
            let made = how.speed_and_modulus::<T>(&given, p);
            last = Some((given, made.map_err(|f| f.message())));
        }
        let problem = match last.as_ref().map(|(_, made)| made) {
            Some(Ok((speed, mu))) => {
                let sizes = [2, 3, 4].map(|j| cols[j].num(i));
                how.problem(speed.clone(), mu.clone(), &sizes, p)
                    .map_err(|f| f.message())
            }
            Some(Err(m)) => Err(m.clone()),
            None => Err("a contact point without its speed".into()),
        };
        problems.push(problem.unwrap_or_else(|m| {
            *slot = Some(m);
            let one = T::one(p);
            let loading = Loading::Load(one.clone());
            let nan = T::from_f64(f64::NAN, p);
            ContactProblem {
                speed: fallback.clone(),
                radius_along: nan,
                radius_across: one.clone(),
                loading,
                shear_modulus: one,
            }
        }));
    }
    Ok((problems, pre))
}

/// `sweep::contacts` over the columns: per point a, b, k, e, p0, d0, load with their bounds,
/// iterations, route. The columns are given as `solve_contact` takes its arguments
/// ([`ContactGiven`]: `kind` `speed`, `gap` or `velocity`, `modulus_kind` `shear` or
/// `youngs`, `density` with a velocity only).
#[pyfunction]
#[pyo3(signature = (precision, nu, speed, kind, radius_along, radius_across, loading, size, modulus, modulus_kind, density, method, threads, progress, text))]
#[allow(clippy::too_many_arguments)]
pub fn sweep_contacts<'py>(
    py: Python<'py>,
    precision: &str,
    nu: &Bound<'py, PyAny>,
    speed: &Bound<'py, PyAny>,
    kind: &str,
    radius_along: &Bound<'py, PyAny>,
    radius_across: &Bound<'py, PyAny>,
    loading: &str,
    size: &Bound<'py, PyAny>,
    modulus: &Bound<'py, PyAny>,
    modulus_kind: &str,
    density: Option<&Bound<'py, PyAny>>,
    method: &str,
    threads: Option<usize>,
    progress: Option<&Bound<'py, PyAny>>,
    text: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let how = ContactGiven::parse(kind, modulus_kind, loading);
    let cols = (|| {
        let mut cols = vec![
            Col::from_py(nu, "nu")?,
            Col::from_py(speed, how.speed_name())?,
            Col::from_py(radius_along, "radius_along")?,
            Col::from_py(radius_across, "radius_across")?,
            Col::from_py(size, how.size_name())?,
            Col::from_py(modulus, how.modulus_name())?,
        ];
        if let Some(d) = density {
            cols.push(Col::from_py(d, "density")?);
        }
        Ok::<_, Fail>(cols)
    })();
    let cols = to_py(py, cols)?;
    let (n, prec, method, text) = to_py(py, request(&cols, precision, method, text))?;
    with_precision!(prec, T, p => {
        let opts = Options::<T> { method, ..Default::default() };
        let mut out = Columns::new(7, n, text);
        let build = |r| contact_problems::<T>(&cols, how, r, p);
        in_chunks(py, n, threads, progress, build, |c| sweep::contacts(c, &opts), |r| match r {
            Ok(s) => out.push(&[Some(s.a()), Some(s.b()), Some(s.k()), Some(s.e()), Some(s.p0()), Some(s.d0()), Some(s.load())], s.ellipse().iterations(), s.ellipse().integrals().route),
            Err(m) => out.fail(m),
        })?;
        out.into_py(py)
    })
}

/// `sweep::integrals` at one speed over the column of k: per point I1, I2, dI1/dk, dI2/dk, J0
/// (the last three when asked for) with their bounds, the work, the route.
#[pyfunction]
#[pyo3(signature = (precision, nu, speed, kind, k, method, tol, derivatives, j0, threads, progress, text))]
#[allow(clippy::too_many_arguments)]
pub fn sweep_integrals<'py>(
    py: Python<'py>,
    precision: &str,
    nu: &Bound<'py, PyAny>,
    speed: &Bound<'py, PyAny>,
    kind: &str,
    k: &Bound<'py, PyAny>,
    method: &str,
    tol: Option<&str>,
    derivatives: bool,
    j0: bool,
    threads: Option<usize>,
    progress: Option<&Bound<'py, PyAny>>,
    text: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let kind = SpeedKind::parse(kind);
    let nums = (|| {
        Ok::<_, Fail>((
            Num::from_py(nu, "nu")?,
            Num::from_py(speed, kind.argument())?,
            Col::from_py(k, "k")?,
        ))
    })();
    let (nu, sp, ks) = to_py(py, nums)?;
    let prec = to_py(py, input::precision(precision))?;
    let tol = to_py(
        py,
        tol.map(|t| RelError::parse(t).map_err(Fail::about("tol")))
            .transpose(),
    )?;
    let opts = IntegralOptions {
        method: to_py(py, self::method(method))?,
        tolerance: tol,
        derivatives,
        j0,
    };
    let text = text || prec != Precision::F64;
    with_precision!(prec, T, p => {
        let speed = py.detach(|| guard(|| input::speed(&input::material::<T>(&nu, p)?, &sp, kind)));
        let speed = to_py(py, speed)?;
        let mut out = Columns::new(5, ks.len(), text);
        let build = |r: Range<usize>| {
            let mut pre = vec![None; r.len()];
            let ks: Vec<T> = r.zip(pre.iter_mut()).map(|(i, slot)| input::positive(&ks.num(i), "k", p).unwrap_or_else(|f| {
                *slot = Some(f.message());
                T::from_f64(f64::NAN, p)
            })).collect();
            Ok((ks, pre))
        };
        in_chunks(py, ks.len(), threads, progress, build, |c| sweep::integrals(&speed, c, &opts), |r| match r {
            Ok(s) => out.push(&[Some(&s.i1), Some(&s.i2), s.di1_dk.as_ref(), s.di2_dk.as_ref(), s.j0.as_ref()], s.work, s.route),
            Err(m) => out.fail(m),
        })?;
        out.into_py(py)
    })
}
