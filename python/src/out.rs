//! Results handed back to the Python layer: a tuple of fields, each number a Python float (at
//! `f64`) or the decimal text the command-line tool's JSON prints (above `f64`, or on request),
//! which the Python layer turns into `mpmath.mpf` or `decimal.Decimal` at the working precision.

use moving_hertz::scalar::Real;
use moving_hertz::Estimated;
use pyo3::prelude::*;
use pyo3::types::{PyFloat, PyString, PyTuple};
use pyo3::IntoPyObjectExt;

/// The fields of one result, in order.
pub struct Fields<'py> {
    py: Python<'py>,
    text: bool,
    items: Vec<Bound<'py, PyAny>>,
}

impl<'py> Fields<'py> {
    /// Empty; numbers as text when `text`.
    pub fn new(py: Python<'py>, text: bool) -> Self {
        Fields {
            py,
            text,
            items: Vec::with_capacity(24),
        }
    }

    /// A plain value: a float, or every digit of the working precision as text.
    pub fn value<T: Real>(&mut self, x: &T) -> &mut Self {
        let v = if self.text {
            PyString::new(self.py, &x.to_decimal()).into_any()
        } else {
            PyFloat::new(self.py, x.to_f64()).into_any()
        };
        self.items.push(v);
        self
    }

    /// A value and its error bound (the bound as a float, or as `RelError` prints it: three
    /// significant digits rounded upwards).
    pub fn est<T: Real>(&mut self, x: &Estimated<T>) -> &mut Self {
        self.value(&x.value);
        let b = if self.text {
            PyString::new(self.py, &x.error.to_string()).into_any()
        } else {
            PyFloat::new(self.py, x.error.to_f64()).into_any()
        };
        self.items.push(b);
        self
    }

    /// An optional value and bound (`None, None` when absent).
    pub fn opt<T: Real>(&mut self, x: Option<&Estimated<T>>) -> &mut Self {
        match x {
            Some(x) => self.est(x),
            None => {
                self.items.push(self.py.None().into_bound(self.py));
                self.items.push(self.py.None().into_bound(self.py));
                self
            }
        }
    }

    /// A label.
    pub fn label(&mut self, s: &str) -> &mut Self {
        self.items.push(PyString::new(self.py, s).into_any());
        self
    }

    /// A count.
    pub fn count(&mut self, n: usize) -> &mut Self {
        let v = n
            .into_bound_py_any(self.py)
            .unwrap_or_else(|_| self.py.None().into_bound(self.py));
        self.items.push(v);
        self
    }

    /// The tuple.
    pub fn finish(&mut self) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(self.py, std::mem::take(&mut self.items))
    }
}
