"""Sweeps beyond one machine: ``dask.array`` grids whose blocks are the crate's sweeps.

``pip install "./python[dask]"`` installs dask and distributed. The functions here take the
arguments of :func:`moving_hertz.sweep_ellipses` (scalars, numpy or dask arrays, broadcast
together) and return a lazy ``dask.array`` of the broadcast shape with a structured dtype:
one field per value and bound (``k``, ``k_error``, ...), ``iterations``, ``route`` (codes of
:data:`moving_hertz.ROUTES`), ``ok`` and ``message`` (the error of a failed point, else
``None``). Values are float64 at ``precision="f64"``; above it they are the decimal text of
every digit (as ``as_text=True`` gives them), because a pickled ``mpmath.mpf`` is rebuilt at
the receiving process's precision (53 bits by default) on its way from a worker:
:func:`numbers` turns a computed block into ``mpmath.mpf`` (or ``Decimal``) at the working
precision.

The grid is flattened in C order and cut into chunks of a multiple of the crate's block (64
points), each solved by one in-process sweep (``map_blocks``): every point's result is bit
for bit the one of :func:`moving_hertz.sweep_ellipses` over the whole grid, whatever the
scheduler, the workers and their number. The chunk size follows the precision's cost
(:func:`chunk_points`, about 0.1 s of work a chunk), or ``chunk=``.

It runs on dask's default local scheduler with no set-up, and on any ``dask.distributed``
cluster once a client is made (``Client(address)``, or ``Client(LocalCluster(...))``): the
workers need moving_hertz installed, nothing else.
"""

import numpy as np

import dask.array as da

import moving_hertz as _mh
from . import _native, _numbers

__all__ = ["sweep_ellipses", "sweep_contacts", "chunk_points", "numbers"]

#: Approximate cost of one ellipse solve, in microseconds, at f64 and double-double; above,
#: MPFR's cost grows about as bits^1.6 from DD_US at 106 bits (docs/precision.md).
F64_US, DD_US = 2.0, 25.0
#: Work per chunk, in microseconds.
CHUNK_US = 100_000.0


def chunk_points(precision):
    """Points per chunk at ``precision``: about :data:`CHUNK_US` of work, a multiple of the
    crate's block (64), at least one block."""
    label, bits = _native.precision_info(_numbers.precision(precision))
    cost = F64_US if label == "f64" else DD_US * max(1.0, bits / 106) ** 1.6
    block = _native.BLOCK
    return max(block, int(CHUNK_US / cost) // block * block)


def numbers(computed, precision):
    """A computed array of :func:`sweep_ellipses` or :func:`sweep_contacts` above ``f64``
    (decimal text) with every value and bound as ``mpmath.mpf`` at the working precision
    (``decimal.Decimal`` without mpmath); an ``f64`` array is returned as it is."""
    label, bits = _native.precision_info(_numbers.precision(precision))
    if label == "f64":
        return computed
    out = computed.copy()
    for name in out.dtype.names:
        if out.dtype[name] == object and name != "message":
            flat = out[name].ravel()
            out[name] = np.array([_numbers.number(s, bits) for s in flat] + [None],
                                 dtype=object)[:-1].reshape(out.shape)
    return out


def _dtype(fields, counts, text):
    value = object if text else np.float64
    names = [(n, value) for f in fields for n in (f, f + "_error")]
    return np.dtype(names + [(counts, np.int64), ("route", np.int8), ("ok", np.bool_),
                             ("message", object)])


def _pack(r, dtype, counts):
    """A :class:`moving_hertz.SweepResult` as a structured array."""
    out = np.empty(r.shape, dtype=dtype)
    for f in r.fields:
        for n in (f, f + "_error"):
            out[n] = getattr(r, n).data
    out[counts] = getattr(r, counts)
    out["route"] = r.route
    out["ok"] = r.ok
    out["message"] = r.messages
    return out


def _grid(named, chunk):
    """The inputs broadcast, flattened in C order and cut into chunks of ``chunk`` points."""
    arrays = [a if isinstance(a, da.Array)
              else da.from_array(np.asarray(a, dtype=_kind(a)), chunks=-1) for a in named]
    arrays = da.broadcast_arrays(*arrays)
    shape = arrays[0].shape
    flat = [a.reshape(-1).rechunk(chunk) if a.ndim else a.reshape(1) for a in arrays]
    return shape, flat


def _kind(x):
    a = np.asarray(x)
    return np.float64 if a.dtype.kind in "fiu" and a.dtype.itemsize <= 8 else object


def _blocks(solve, named, fields, counts, precision, chunk):
    text = _native.precision_info(_numbers.precision(precision))[0] != "f64"
    dtype = _dtype(fields, counts, text)
    shape, flat = _grid(named, chunk)

    def block(*cols):
        return _pack(solve(text, *cols), dtype, counts)

    out = da.map_blocks(block, *flat, dtype=dtype, meta=np.empty(0, dtype=dtype))
    return out.reshape(shape) if shape != out.shape else out


def sweep_ellipses(nu, *, speed=None, gap=None, ratio=None, precision="f64", method="auto",
                   chunk=None, threads=1):
    """:func:`moving_hertz.sweep_ellipses` as a lazy ``dask.array`` (module docs): fields
    ``k``, ``e``, ``I1``, ``I2`` and their ``_error`` bounds, ``iterations``, ``route``,
    ``ok``, ``message``. ``chunk``: points per chunk (rounded down to a multiple of 64;
    default :func:`chunk_points`); ``threads``: threads of each chunk's sweep (1: the
    scheduler's workers make the parallelism)."""
    value, kind = _mh._speed(speed, gap)
    chunk = _chunk(chunk, precision)

    def solve(text, n, s, r):
        return _mh.sweep_ellipses(n, ratio=r, precision=precision, method=method,
                                  threads=threads, as_text=text, **{kind: s})

    return _blocks(solve, [nu, value, _mh._required(ratio, "ratio")],
                   ("k", "e", "I1", "I2"), "iterations", precision, chunk)


def sweep_contacts(nu, *, speed=None, gap=None, velocity=None, radius_along=None,
                   radius_across=None, load=None, approach=None, shear_modulus=None,
                   youngs_modulus=None, density=None, precision="f64", method="auto",
                   chunk=None, threads=1):
    """:func:`moving_hertz.sweep_contacts` as a lazy ``dask.array``: the same inputs (speed,
    gap or velocity with density; shear or Young's modulus; load or approach), fields ``a``,
    ``b``, ``k``, ``e``, ``p0``, ``d0``, ``load`` and their bounds, ``iterations``,
    ``route``, ``ok``, ``message`` (``chunk`` and ``threads`` as :func:`sweep_ellipses`)."""
    kind, value, loading, size, modulus_kind, modulus = _mh._contact_args(
        speed, gap, velocity, load, approach, shear_modulus, youngs_modulus, density)
    chunk = _chunk(chunk, precision)
    modulus_name = modulus_kind + "_modulus"

    def solve(text, n, s, r1, r2, p, m, *rho):
        extra = {"density": rho[0]} if rho else {}
        return _mh.sweep_contacts(n, radius_along=r1, radius_across=r2, precision=precision,
                                  method=method, threads=threads, as_text=text,
                                  **{kind: s, loading: p, modulus_name: m}, **extra)

    named = [nu, value, _mh._required(radius_along, "radius_along"),
             _mh._required(radius_across, "radius_across"), size, modulus]
    if density is not None:
        named.append(density)
    return _blocks(solve, named, ("a", "b", "k", "e", "p0", "d0", "load"), "iterations",
                   precision, chunk)


def _chunk(chunk, precision):
    if chunk is None:
        return chunk_points(precision)
    if isinstance(chunk, bool) or not isinstance(chunk, int) or chunk < 1:
        raise _mh.DomainError(f"chunk = {chunk!r} is not a positive int", "chunk")
    block = _native.BLOCK
    return max(block, chunk // block * block)
