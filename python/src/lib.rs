//! `moving_hertz._native`: the native module of the Python package `moving_hertz` (PyO3).
//!
//! The pure-Python package (`python/moving_hertz/`) is the public interface: it converts the
//! numbers it accepts into floats or exact text, calls these entries, and builds the result
//! objects and exceptions (but for `ellipse_f64`, the f64 ellipse of plain floats, whose
//! result object is made here: `single::ellipse_f64`). Each entry parses and solves with the GIL released and never lets a
//! panic unwind into the interpreter (`fail::guard`): a panic becomes `MovingHertzError`.
//! Implements no formula of its own: every number comes from the `moving-hertz` crate.

mod fail;
mod input;
mod out;
mod single;
mod sweeps;

use pyo3::prelude::*;

/// Runs a panic inside [`fail::guard`], as every entry runs its work: the check (by the
/// package's tests) that a panic reaches Python as `MovingHertzError`, never as an abort or a
/// `PanicException`.
#[pyfunction]
fn _panic_through_guard(py: Python<'_>, message: &str) -> PyResult<()> {
    let r = py.detach(|| fail::guard(|| -> Result<(), fail::Fail> { panic!("{message}") }));
    fail::to_py(py, r)
}

/// The native entries of `moving_hertz` (use the package's functions, which document them).
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(single::precision_info, m)?)?;
    m.add_function(wrap_pyfunction!(single::rayleigh, m)?)?;
    m.add_function(wrap_pyfunction!(single::ellipse, m)?)?;
    m.add_function(wrap_pyfunction!(single::ellipse_f64, m)?)?;
    m.add_function(wrap_pyfunction!(single::contact, m)?)?;
    m.add_function(wrap_pyfunction!(single::integrals_of, m)?)?;
    m.add_function(wrap_pyfunction!(single::symbolic, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::sweep_ellipses, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::sweep_contacts, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::sweep_integrals, m)?)?;
    m.add_function(wrap_pyfunction!(_panic_through_guard, m)?)?;
    let routes: Vec<&str> = sweeps::ROUTES.iter().map(|r| r.label()).collect();
    m.add("ROUTES", routes)?;
    m.add("BLOCK", moving_hertz::sweep::BLOCK)?;
    Ok(())
}
