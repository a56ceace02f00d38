//! Results handed back to the Python layer: a tuple of fields, each number a Python float (at
//! `f64`) or the decimal text the command-line tool's JSON prints (above `f64`, or on request),
//! which the Python layer turns into `mpmath.mpf` or `decimal.Decimal` at the working precision.

use moving_hertz::scalar::Real;
use moving_hertz::{Estimated, MajorAxis, Precision};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyFloat, PyString, PyTuple, PyType};
use pyo3::IntoPyObjectExt;

/// The labels a result carries at `f64` (the precision, the routes, the major axis), made
/// once as Python strings: a result of a few microseconds does not make them again.
static LABELS: PyOnceLock<Vec<(&'static str, Py<PyString>)>> = PyOnceLock::new();

/// The Python string of `s`: the one made once for a label of [`LABELS`], else a new one.
fn label_str<'py>(py: Python<'py>, s: &str) -> Bound<'py, PyString> {
    let labels = LABELS.get_or_init(py, || {
        let routes = crate::sweeps::ROUTES.iter().map(|r| r.label());
        let majors = [MajorAxis::Along, MajorAxis::Across].map(|m| m.label());
        std::iter::once("f64")
            .chain(routes)
            .chain(majors)
            .map(|l| (l, PyString::new(py, l).unbind()))
            .collect()
    });
    match labels.iter().find(|(l, _)| *l == s) {
        Some((_, made)) => made.bind(py).clone(),
        None => PyString::new(py, s),
    }
}

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
        self.items.push(label_str(self.py, s).into_any());
        self
    }

    /// The precision's label and its bits.
    pub fn precision(&mut self, p: &Precision) -> &mut Self {
        self.label(&p.label()).count(p.bits() as usize)
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

    /// An instance of the tuple subclass `cls` (a result class of `moving_hertz._results`,
    /// a named tuple without instance attributes) holding the fields, made as
    /// `tuple.__new__(cls, fields)` makes it — the class's allocator, then each item — without
    /// the tuple in between.
    pub fn instance(&mut self, cls: &Bound<'py, PyType>) -> PyResult<Bound<'py, PyAny>> {
        let items = std::mem::take(&mut self.items);
        let n = items.len() as pyo3::ffi::Py_ssize_t;
        // SAFETY: `cls` is a subclass of tuple (checked), whose `tp_alloc` returns a new
        // reference to a zeroed instance of `n` items (NULL with an exception set on failure);
        // `PyTuple_SetItem` accepts an instance of a subclass holding its only reference and
        // steals the reference to each item, each slot set once.
        unsafe {
            let ty = cls.as_type_ptr();
            if pyo3::ffi::PyType_IsSubtype(ty, std::ptr::addr_of_mut!(pyo3::ffi::PyTuple_Type)) == 0
            {
                return Err(pyo3::exceptions::PyTypeError::new_err(
                    "not a tuple subclass",
                ));
            }
            let slot = pyo3::ffi::PyType_GetSlot(ty, pyo3::ffi::Py_tp_alloc);
            let slot: Option<pyo3::ffi::allocfunc> = std::mem::transmute(slot);
            let alloc = slot.unwrap_or(pyo3::ffi::PyType_GenericAlloc);
            let obj = Bound::from_owned_ptr_or_err(self.py, alloc(ty, n))?;
            for (i, item) in items.into_iter().enumerate() {
                let i = i as pyo3::ffi::Py_ssize_t;
                if pyo3::ffi::PyTuple_SetItem(obj.as_ptr(), i, item.into_ptr()) != 0 {
                    return Err(PyErr::fetch(self.py));
                }
            }
            Ok(obj)
        }
    }
}
