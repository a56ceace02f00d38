//! One solve per call: the Rayleigh roots, the ellipse (33), the contact solution, I1 and I2 of
//! (34), and the symbolic coefficients of (36) and (40). Each entry reads its arguments with
//! the GIL, then parses, checks and solves without it (`py.detach`), inside [`guard`].

use crate::fail::{guard, to_py, Fail};
use crate::input::{self, Num, SpeedKind};
use crate::out::Fields;
use moving_hertz::scalar::{Precision, Real};
use moving_hertz::{
    integrals, integrals_to_tolerance, solve_ellipse, with_precision, ContactProblem, ExactInputs,
    IntegralOptions, Integrals, Loading, Method, Moduli, Mp, Options, RelError, Solid,
};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyTuple, PyType};

/// The options' method, refused naming `method`.
pub fn method(text: &str) -> Result<Method, Fail> {
    Method::parse(text).map_err(Fail::about("method"))
}

/// `(label, bits)` of a precision (`f64`, `dd`, `mpfr256`), refused naming `precision`.
#[pyfunction]
pub fn precision_info(py: Python<'_>, precision: &str) -> PyResult<(String, u32)> {
    let p = to_py(py, input::precision(precision))?;
    Ok((p.label(), p.bits()))
}

/// Runs `f` with the GIL released above double-double (an MPFR solve takes from tens of
/// microseconds to seconds); at `f64` and double-double, where a solve takes a few
/// microseconds, releasing and taking back the GIL would cost a sizeable share of the call.
fn detach_above_dd<R: Send>(py: Python<'_>, prec: Precision, f: impl FnOnce() -> R + Send) -> R {
    match prec {
        Precision::Mpfr(_) => py.detach(f),
        _ => f(),
    }
}

/// Whether numbers go back as text: above `f64`, or when asked for.
fn as_text(prec: Precision, text: bool) -> bool {
    text || prec != Precision::F64
}

/// `(precision, bits, m1, cR/c2, cR/c1, re1, im1, re2, im2, re3, im3)`: the Rayleigh root
/// m1 = (c_R/c2)² and the other two roots of the cubic (section 3).
#[pyfunction]
pub fn rayleigh<'py>(
    py: Python<'py>,
    precision: &str,
    nu: &Bound<'py, PyAny>,
    text: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let nu = to_py(py, Num::from_py(nu, "nu"))?;
    let prec = to_py(py, input::precision(precision))?;
    with_precision!(prec, T, p => {
        let mat = to_py(py, py.detach(|| guard(|| input::material::<T>(&nu, p))))?;
        let mut f = Fields::new(py, as_text(prec, text));
        f.label(&prec.label()).count(prec.bits() as usize);
        f.value(&mat.roots().m1).value(&mat.cr_over_c2()).value(&mat.cr_over_c1());
        for z in mat.roots().all() {
            f.value(&z.re).value(&z.im);
        }
        f.finish()
    })
}

/// `(precision, bits, route, k, k_error, e, e_error, major_axis, I1, I1_error, I2, I2_error,
/// iterations)`: the ellipse (33) by `solve_ellipse`.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn ellipse<'py>(
    py: Python<'py>,
    precision: &str,
    nu: &Bound<'py, PyAny>,
    speed: &Bound<'py, PyAny>,
    kind: &str,
    ratio: &Bound<'py, PyAny>,
    method: &str,
    text: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let kind = SpeedKind::parse(kind);
    let (nu, sp) = (Num::from_py(nu, "nu"), Num::from_py(speed, kind.argument()));
    let (nu, sp, ratio) = to_py(
        py,
        nu.and_then(|n| Ok((n, sp?, Num::from_py(ratio, "ratio")?))),
    )?;
    let prec = to_py(py, input::precision(precision))?;
    let method = to_py(py, self::method(method))?;
    with_precision!(prec, T, p => {
        let sol = detach_above_dd(py, prec, || guard(|| {
            let speed = input::cached_speed::<T>(&nu, &sp, kind, p)?;
            let ratio: T = input::positive(&ratio, "ratio", p)?;
            let opts = Options::<T> { method, ..Default::default() };
            Ok(solve_ellipse(&speed, &ratio, &opts)?)
        }));
        let sol = to_py(py, sol)?;
        let mut f = Fields::new(py, as_text(prec, text));
        ellipse_fields(&mut f, &sol);
        f.finish()
    })
}

/// The `Ellipse` of `moving_hertz._results` (a named tuple), looked up once.
static ELLIPSE: PyOnceLock<Py<PyType>> = PyOnceLock::new();

/// The `Ellipse` of [`ellipse`] for float ν, M_R and A1/B1 at `f64`, the result object made
/// here: the package's `solve_ellipse` for plain floats, where the solve takes about a
/// microsecond and what surrounds it in Python would cost as much (the target: a
/// Python call within twice the Rust warm solve, `tools/python_bench.py`). The same solve and
/// fields as [`ellipse`].
#[pyfunction]
pub fn ellipse_f64<'py>(
    py: Python<'py>,
    nu: f64,
    speed: f64,
    ratio: f64,
    method: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let method = to_py(py, self::method(method))?;
    let (nu, sp, ratio) = (Num::F(nu), Num::F(speed), Num::F(ratio));
    let sol = guard(|| {
        let speed = input::cached_speed::<f64>(&nu, &sp, SpeedKind::Mr, ())?;
        let ratio: f64 = input::positive(&ratio, "ratio", ())?;
        let opts = Options::<f64> {
            method,
            ..Default::default()
        };
        Ok(solve_ellipse(&speed, &ratio, &opts)?)
    });
    let sol = to_py(py, sol)?;
    let mut f = Fields::new(py, false);
    ellipse_fields(&mut f, &sol);
    f.instance(ELLIPSE.import(py, "moving_hertz._results", "Ellipse")?)
}

/// The fields of an `Ellipse` (`moving_hertz._results`) in order.
fn ellipse_fields<T: Real>(f: &mut Fields<'_>, sol: &moving_hertz::Ellipse<T>) {
    let ig = sol.integrals();
    f.precision(&ig.precision).label(ig.route.label());
    f.est(sol.k())
        .est(sol.e())
        .label(sol.major().label())
        .est(&ig.i1)
        .est(&ig.i2);
    f.count(sol.iterations());
}

/// How the half-space's stiffness and the speed are given.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Units {
    /// μ and M_R (or its gap).
    Shear,
    /// E (μ = E/(2(1 + ν)), `physics::solid::shear_from_youngs`) and M_R (or its gap).
    Youngs,
    /// μ or E with the density ρ and the velocity V in m/s ([`Solid`]).
    Velocity { youngs: bool },
}

/// How a contact problem is given, as the Python keywords name it (`solve_contact` and
/// `sweep_contacts`): the speed as `speed`, `gap` or `velocity` (V in m/s, with `density`),
/// the stiffness as `shear` or `youngs` modulus, the size as `load` or `approach`.
#[derive(Clone, Copy)]
pub struct ContactGiven {
    kind: SpeedKind,
    units: Units,
    by_load: bool,
}

/// ν, the speed, the modulus and the density (absent without a velocity), as given.
pub type Given = [Option<Num>; 4];

impl ContactGiven {
    /// From the keywords: `kind` `speed`, `gap` or `velocity`; `modulus_kind` `shear` or
    /// `youngs`; `loading` `load` or `approach`.
    pub fn parse(kind: &str, modulus_kind: &str, loading: &str) -> ContactGiven {
        let youngs = modulus_kind == "youngs";
        let (units, kind) = match (kind, youngs) {
            ("velocity", _) => (Units::Velocity { youngs }, SpeedKind::Mr),
            (_, true) => (Units::Youngs, SpeedKind::parse(kind)),
            _ => (Units::Shear, SpeedKind::parse(kind)),
        };
        ContactGiven {
            kind,
            units,
            by_load: loading == "load",
        }
    }

    /// The keyword of the speed.
    pub fn speed_name(self) -> &'static str {
        match self.units {
            Units::Velocity { .. } => "velocity",
            _ => self.kind.argument(),
        }
    }

    /// The keyword of the size (`load` or `approach`).
    pub fn size_name(self) -> &'static str {
        if self.by_load {
            "load"
        } else {
            "approach"
        }
    }

    /// The keyword of the modulus.
    pub fn modulus_name(self) -> &'static str {
        match self.units {
            Units::Youngs | Units::Velocity { youngs: true } => "youngs_modulus",
            _ => "shear_modulus",
        }
    }

    /// The speed and the shear modulus at precision `p`: from M_R (or its gap) with μ, or E
    /// and μ = E/(2(1 + ν)); from a velocity by the crate's [`Solid`] (c_R from ν, the
    /// modulus and ρ, every input exact), refused naming c_R unless 0 ≤ V < c_R.
    pub fn speed_and_modulus<T: Real>(
        self,
        [nu, sp, modulus, density]: &Given,
        p: T::Prec,
    ) -> Result<(moving_hertz::Speed<T>, T), Fail> {
        let (Some(nu), Some(sp), Some(modulus)) = (nu, sp, modulus) else {
            return Err(Fail::Arg {
                argument: "nu",
                message: "nu, the speed and a modulus are required".into(),
            });
        };
        let Units::Velocity { youngs } = self.units else {
            let speed = input::cached_speed::<T>(nu, sp, self.kind, p)?;
            let m: T = input::positive(modulus, self.modulus_name(), p)?;
            return Ok(if self.units == Units::Youngs {
                let mu = moving_hertz::physics::solid::shear_from_youngs(&m, speed.material().nu());
                (speed, mu)
            } else {
                (speed, m)
            });
        };
        let Some(density) = density else {
            return Err(Fail::Arg {
                argument: "density",
                message: "velocity= needs density= (kg/m^3)".into(),
            });
        };
        let [nu, modulus, density, v] = [nu, modulus, density, sp].map(exact_text);
        let moduli = if youngs {
            Moduli::Youngs {
                youngs_modulus: modulus.as_str(),
                density: density.as_str(),
            }
        } else {
            Moduli::Shear {
                shear_modulus: modulus.as_str(),
                density: density.as_str(),
            }
        };
        let solid = Solid::<T>::parse(&nu, moduli, p)?;
        let speed = solid.parse_velocity(&v).map_err(Fail::about("velocity"))?;
        let mu = solid.shear_modulus().cloned().ok_or_else(|| {
            Fail::Panic("a solid of given moduli without its shear modulus".into())
        })?;
        Ok((speed, mu))
    }

    /// The problem of this speed and shear modulus with the radii R1, R2 and the load or
    /// approach `[r1, r2, size]` as given (each checked positive).
    pub fn problem<T: Real>(
        self,
        speed: moving_hertz::Speed<T>,
        shear_modulus: T,
        [r1, r2, size]: &[Num; 3],
        p: T::Prec,
    ) -> Result<ContactProblem<T>, Fail> {
        let size: T = input::positive(size, self.size_name(), p)?;
        Ok(ContactProblem {
            speed,
            radius_along: input::positive(r1, "radius_along", p)?,
            radius_across: input::positive(r2, "radius_across", p)?,
            loading: if self.by_load {
                Loading::Load(size)
            } else {
                Loading::Approach(size)
            },
            shear_modulus,
        })
    }
}

/// `(precision, bits, route, a, a_error, b, b_error, k, k_error, e, e_error, major_axis, p0,
/// p0_error, d0, d0_error, load, load_error)`: the contact solution of section 4. `kind` is
/// `speed`, `gap` or `velocity` (V in m/s, with `density`); `modulus_kind` `shear` or
/// `youngs` ([`ContactGiven`]).
#[pyfunction]
#[pyo3(signature = (precision, nu, speed, kind, radius_along, radius_across, loading, size, modulus, modulus_kind, density, method, text))]
#[allow(clippy::too_many_arguments)]
pub fn contact<'py>(
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
    text: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let how = ContactGiven::parse(kind, modulus_kind, loading);
    let nums = (|| {
        Ok::<_, Fail>((
            [
                Some(Num::from_py(nu, "nu")?),
                Some(Num::from_py(speed, how.speed_name())?),
                Some(Num::from_py(modulus, how.modulus_name())?),
                density.map(|d| Num::from_py(d, "density")).transpose()?,
            ],
            [
                Num::from_py(radius_along, "radius_along")?,
                Num::from_py(radius_across, "radius_across")?,
                Num::from_py(size, how.size_name())?,
            ],
        ))
    })();
    let (given, sizes) = to_py(py, nums)?;
    let prec = to_py(py, input::precision(precision))?;
    let method = to_py(py, self::method(method))?;
    with_precision!(prec, T, p => {
        let sol = detach_above_dd(py, prec, || guard(|| {
            let (speed, shear_modulus) = how.speed_and_modulus::<T>(&given, p)?;
            let problem = how.problem(speed, shear_modulus, &sizes, p)?;
            Ok(problem.solve(&Options::<T> { method, ..Default::default() })?)
        }));
        let sol = to_py(py, sol)?;
        let ig = sol.ellipse().integrals();
        let mut f = Fields::new(py, as_text(prec, text));
        f.label(&ig.precision.label()).count(ig.precision.bits() as usize).label(ig.route.label());
        f.est(sol.a()).est(sol.b()).est(sol.k()).est(sol.e()).label(sol.ellipse().major().label());
        f.est(sol.p0()).est(sol.d0()).est(sol.load()).finish()
    })
}

/// What `integrals` is asked for besides the inputs.
struct Request {
    method: Method,
    tol: Option<RelError>,
    derivatives: bool,
    j0: bool,
}

/// `(precision, bits, route, I1, I1_error, I2, I2_error, dI1_dk, dI1_dk_error, dI2_dk,
/// dI2_dk_error, J0, J0_error, work)`: I1, I2 of (34) at a precision (and `tol` checked there),
/// or with `tol` alone at the lowest precision that reaches it.
#[pyfunction]
#[pyo3(signature = (precision, nu, speed, kind, k, method, tol, derivatives, j0, text))]
#[allow(clippy::too_many_arguments)]
pub fn integrals_of<'py>(
    py: Python<'py>,
    precision: Option<&str>,
    nu: &Bound<'py, PyAny>,
    speed: &Bound<'py, PyAny>,
    kind: &str,
    k: &Bound<'py, PyAny>,
    method: &str,
    tol: Option<&str>,
    derivatives: bool,
    j0: bool,
    text: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let kind = SpeedKind::parse(kind);
    let nums = (|| {
        Ok::<_, Fail>([
            Num::from_py(nu, "nu")?,
            Num::from_py(speed, kind.argument())?,
            Num::from_py(k, "k")?,
        ])
    })();
    let [nu, sp, k] = to_py(py, nums)?;
    let tol = tol.map(|t| RelError::parse(t).map_err(Fail::about("tol")));
    let req = Request {
        method: to_py(py, self::method(method))?,
        tol: to_py(py, tol.transpose())?,
        derivatives,
        j0,
    };
    let prec = match precision {
        Some(t) => Some(to_py(py, input::precision(t))?),
        None if req.tol.is_none() => Some(Precision::F64),
        None => None,
    };
    let Some(prec) = prec else {
        if derivatives || j0 {
            let message = "derivatives and j0 need a precision: tol alone chooses the precision for I1 and I2 only".into();
            return Err(Fail::Arg {
                argument: "tol",
                message,
            }
            .into_py(py));
        }
        let r = py.detach(|| guard(|| to_tolerance(&nu, &sp, kind, &k, &req)));
        let r = to_py(py, r)?;
        let text = text || r.precision != Precision::F64;
        return with_precision!(r.precision, T, p => report(py, &r.narrow::<T>(p), text));
    };
    with_precision!(prec, T, p => {
        let r = detach_above_dd(py, prec, || guard(|| {
            let speed = input::cached_speed::<T>(&nu, &sp, kind, p)?;
            let k: T = input::positive(&k, "k", p)?;
            let opts = IntegralOptions { method: req.method, tolerance: req.tol, derivatives: req.derivatives, j0: req.j0 };
            Ok(integrals(&speed, &k, &opts)?)
        }));
        report(py, &to_py(py, r)?, as_text(prec, text))
    })
}

/// `tol` alone: the inputs held exactly ([`ExactInputs`]), the precision chosen by
/// [`integrals_to_tolerance`].
fn to_tolerance(
    nu: &Num,
    sp: &Num,
    kind: SpeedKind,
    k: &Num,
    req: &Request,
) -> Result<Integrals<Mp>, Fail> {
    let [nu, sp, k] = [nu, sp, k].map(exact_text);
    let inputs = match kind {
        SpeedKind::Gap => ExactInputs::parse_gap(&nu, &sp, &k),
        SpeedKind::Mr => ExactInputs::parse(&nu, &sp, &k),
    }?;
    let tol = req.tol.unwrap_or(RelError::ZERO);
    integrals_to_tolerance(&inputs, tol, req.method).map_err(Fail::about("tol"))
}

/// The exact text of a number: a float as the fraction p/q it is (NaN and ∞ as `NaN`, `inf`,
/// refused by the parser naming them).
fn exact_text(x: &Num) -> String {
    match x {
        Num::T(s) => s.clone(),
        Num::F(f) if f.is_finite() => rug::Float::with_val(53, *f)
            .to_rational()
            .map_or_else(|| format!("{f:?}"), |r| r.to_string()),
        Num::F(f) => format!("{f:?}"),
    }
}

fn report<'py, T: Real>(
    py: Python<'py>,
    r: &Integrals<T>,
    text: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let mut f = Fields::new(py, text);
    f.label(&r.precision.label())
        .count(r.precision.bits() as usize)
        .label(r.route.label());
    f.est(&r.i1)
        .est(&r.i2)
        .opt(r.di1_dk.as_ref())
        .opt(r.di2_dk.as_ref())
        .opt(r.j0.as_ref());
    f.count(r.work).finish()
}

/// The coefficients of (36) (`coefficients`: f_n = F_n(ν) xⁿ, n ≤ N, then the paper's printed
/// f1, f2) or of (40) (`moments`: α_n … δ_n(e²)), exact, rendered as `text` or `sympy` (as
/// `moving-hertz symbolic KIND --n N --format FORMAT` prints them).
#[pyfunction]
pub fn symbolic(py: Python<'_>, kind: &str, n: usize, format: &str) -> PyResult<String> {
    use moving_hertz::symbolic::{
        coefficient_items, green_coefficients, moment_forms, moment_items, render, Style,
    };
    let style = match format {
        "text" => Style::Text,
        "sympy" => Style::Sympy,
        _ => {
            let message = format!("format = {format:?} is not one of 'text', 'sympy'");
            return Err(Fail::Arg {
                argument: "format",
                message,
            }
            .into_py(py));
        }
    };
    let r = py.detach(|| {
        guard(|| {
            let about = Fail::about("n");
            Ok(match kind {
                "coefficients" => {
                    let title = format!("(35)-(36): f_n = F_n(nu) x^n, x = M2^2, n <= {n}");
                    render(&title, &coefficient_items(&green_coefficients(n).map_err(about)?), style)
                }
                _ => {
                    let title = format!("(40), (42): L_n = alpha_n K + beta_n E, M_n = gamma_n K + delta_n E, e2 = 1 - k^2, n <= {n}");
                    render(&title, &moment_items(&moment_forms(n).map_err(about)?), style)
                }
            })
        })
    });
    to_py(py, r)
}
