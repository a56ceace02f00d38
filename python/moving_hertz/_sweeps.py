"""Vectorised sweeps over numpy arrays (``moving_hertz.sweep_*``)."""

import numpy as np

from . import _native, _numbers
from ._errors import DomainError

#: Route names of the ``route`` code arrays (code -1: the point failed).
ROUTES = tuple(_native.ROUTES)


class SweepResult:
    """The result of a sweep: numpy arrays of the broadcast shape of the inputs.

    ``fields`` names the value arrays; each ``NAME`` comes with ``NAME_error`` (its bound),
    both ``numpy.ma.MaskedArray`` masked where the point failed (``~ok``); ``ok`` is the
    boolean mask of solved points, ``messages`` an object array holding each failed point's
    error message (``None`` where solved), ``route`` the codes of :data:`ROUTES` (-1 where
    failed) and ``iterations`` (or ``work``) an int64 array (-1 where failed). Values are
    float64 at ``precision="f64"``, else object arrays of ``mpmath.mpf`` (or ``Decimal``), or
    of ``str`` with ``as_text=True``. Immutable: attributes cannot be set.
    """

    __slots__ = ("_d",)

    def __init__(self, d):
        object.__setattr__(self, "_d", d)

    def __getattr__(self, name):
        try:
            return object.__getattribute__(self, "_d")[name]
        except KeyError:
            raise AttributeError(name) from None

    def __setattr__(self, name, value):
        raise AttributeError("a SweepResult is immutable")

    def __reduce__(self):
        return (SweepResult, (self._d,))

    def __dir__(self):
        return sorted(self._d)

    @property
    def shape(self):
        """The broadcast shape of the inputs."""
        return self._d["ok"].shape

    def to_dict(self):
        """Every array by name (a new dict; the arrays are shared)."""
        return dict(self._d)

    def __repr__(self):
        n = self._d["ok"].size
        bad = n - int(self._d["ok"].sum())
        return (f"SweepResult(shape={self.shape}, fields={self._d['fields']}, "
                f"precision={self._d['precision']!r}, failed={bad} of {n})")


def _array(x, name):
    """``x`` as a numpy array of float64 (floats, small ints) or of exact texts (object)."""
    if isinstance(x, np.ndarray):
        a = x
    elif isinstance(x, (list, tuple)):
        a = np.array(x, dtype=object)
        try:  # a list of floats or ints stays numeric
            a = np.array(x)
        except (ValueError, TypeError):
            pass
        if a.dtype.kind not in "fiu":
            a = np.array(x, dtype=object)
    else:
        a = np.array(_numbers.scalar(x, name) if not isinstance(x, (str, float)) else x,
                     dtype=float if type(x) is float else object)
    kind = a.dtype.kind
    if kind == "f" and a.dtype.itemsize <= 8:
        return a.astype(np.float64, copy=False)
    if kind in "iu" and (a.size == 0 or np.abs(a).max() <= 2**53):
        return a.astype(np.float64)
    if kind in "iufOUS":
        return a.astype(object) if kind != "O" else a
    raise DomainError(f"{name}: an array of dtype {a.dtype} is not an array of numbers", name)


def columns(named):
    """Broadcasts the inputs (numpy rules) and flattens them into the native columns:
    ``(shape, [column, ...])``, each column a contiguous float64 array or a list of texts, of
    the broadcast size or (an input of one value) of one."""
    arrays = {name: _array(x, name) for name, x in named.items()}
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays.values()))
    except ValueError as e:
        raise DomainError(f"the inputs do not broadcast together: {e}", None) from None
    size = int(np.prod(shape))
    cols = []
    for name, a in arrays.items():
        # A single value stays one value (the native sweep reads it for every point).
        flat = a.reshape(1) if a.size == 1 and size != 1 else np.broadcast_to(a, shape).ravel()
        if a.dtype == np.float64:
            cols.append(np.ascontiguousarray(flat))
        else:
            cols.append([_numbers.text(v, name) for v in flat])
    return shape, cols


def progress_callback(progress):
    """``progress``: ``None``, a callable ``(done, total)`` or ``True`` for a tqdm bar."""
    if progress is None or progress is False:
        return None, None
    if progress is True:
        try:
            from tqdm.auto import tqdm
        except ImportError:
            raise DomainError("progress=True needs tqdm (pip install tqdm); "
                              "pass a callable (done, total) instead", "progress") from None
        bar = tqdm(total=0, unit="pt")

        def update(done, total):
            bar.total = total
            bar.update(done - bar.n)

        return update, bar
    if not callable(progress):
        raise DomainError(f"progress = {progress!r} is not callable", "progress")
    return progress, None


def result(native, shape, fields, keep, counts, precision, as_text):
    """The :class:`SweepResult` of a native sweep of the given shape: of the native value
    columns (``fields``, each with its bound), those in ``keep``."""
    ok = native["ok"].reshape(shape)
    mask = ~ok
    out = {"fields": tuple(f for f in fields if f in keep), "ok": ok, "shape": shape}
    values = native["values"]
    names = [n for f in fields for n in (f, f + "_error")]
    prec_label, bits = precision
    for j, name in enumerate(names):
        if name.removesuffix("_error") not in keep:
            continue
        v = values[j]
        if isinstance(v, list):
            if as_text:
                arr = np.array(v, dtype=object)
            else:
                arr = np.array([_numbers.number(s, bits) for s in v] if v else [], dtype=object)
        else:
            arr = v
        out[name] = np.ma.masked_array(arr.reshape(shape), mask=mask)
    out[counts] = native["iterations"].reshape(shape)
    out["route"] = native["route"].reshape(shape)
    messages = np.full(ok.size, None, dtype=object)
    for i, m in native["failures"]:
        messages[i] = m
    out["messages"] = messages.reshape(shape)
    out["precision"] = prec_label
    out["bits"] = bits
    return SweepResult(out)
