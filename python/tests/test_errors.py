"""The exception hierarchy, the library's errors mapped onto it, panics caught, and a fuzz of
every entry over the domains tests/properties.rs fuzzes (and beyond them): each call returns
finite values with finite bounds or raises a MovingHertzError, nothing else."""

import math
import random

import mpmath
import numpy as np
import pytest

import moving_hertz as mh
from moving_hertz import _native


def test_hierarchy():
    assert issubclass(mh.DomainError, mh.MovingHertzError)
    assert issubclass(mh.DomainError, ValueError)
    assert issubclass(mh.ConvergenceError, mh.MovingHertzError)
    assert issubclass(mh.ConvergenceError, ArithmeticError)
    assert issubclass(mh.ToleranceError, mh.MovingHertzError)


def test_panic_becomes_moving_hertz_error():
    with pytest.raises(mh.MovingHertzError, match="internal error.*planted") as info:
        _native._panic_through_guard("planted")
    assert type(info.value) is mh.MovingHertzError


def test_unreachable_tolerance_is_tolerance_error():
    with pytest.raises(mh.ToleranceError) as info:
        mh.integrals(0.25, speed=0.5, k=0.5, precision="f64", tol="1e-30")
    assert info.value.argument == "tol"


def test_convergence_error_class():
    from moving_hertz._errors import ConvergenceError
    assert ConvergenceError("x").argument is None


def _finite(x):
    if x is None or isinstance(x, str):
        return True
    return math.isfinite(float(x)) if isinstance(x, float) else mpmath.isfinite(x)


def _check(result):
    for name, v in result.to_dict().items():
        if name not in ("precision", "route", "major_axis", "roots"):
            assert _finite(v), (name, v)
        if name.endswith("_error") and v is not None:
            assert v >= 0


def _draw(rng):
    """ν over (-1, 1/2] and beyond, M_R over [0, 1) and beyond, gaps down to 1e-300, ratios
    and k from 1e-120 to 1e120, radii, loads and moduli over 1e-300 .. 1e300, as floats or
    text."""
    nu = rng.choice([rng.uniform(-1.2, 0.6), -0.999999, 0.5, "-1", "0.5", "1/3"])
    gap = rng.choice([10 ** rng.uniform(-300, 0.2), rng.uniform(-0.1, 1.1), "1e-200"])
    mag = lambda lo, hi: 10 ** rng.uniform(lo, hi)
    return dict(nu=nu, gap=gap, ratio=mag(-120, 120), k=mag(-60, 60), r1=mag(-300, 300),
                r2=mag(-30, 30), load=mag(-300, 300), mu=mag(-300, 300))


@pytest.mark.parametrize("seed", range(6))
def test_fuzz_entries_never_escape_the_hierarchy(seed):
    rng = random.Random(seed)
    for _ in range(12):
        d = _draw(rng)
        prec = rng.choice(["f64", "dd", 64, 128])
        calls = [
            lambda: mh.rayleigh(d["nu"], precision=prec),
            lambda: mh.solve_ellipse(d["nu"], gap=d["gap"], ratio=d["ratio"], precision=prec),
            lambda: mh.integrals(d["nu"], gap=d["gap"], k=d["k"], precision=prec, j0=True),
            lambda: mh.solve_contact(d["nu"], gap=d["gap"], radius_along=d["r1"],
                                     radius_across=d["r2"], load=d["load"],
                                     shear_modulus=d["mu"], precision=prec),
        ]
        for call in calls:
            try:
                _check(call())
            except mh.MovingHertzError as e:
                assert type(e) is not mh.MovingHertzError, e  # a panic would be the base class
                assert str(e)


def test_fuzz_sweep_masks_every_bad_point():
    rng = np.random.default_rng(7)
    nu = rng.uniform(-1.2, 0.7, 3000)
    gap = 10 ** rng.uniform(-300, 0.3, 3000)
    ratio = 10 ** rng.uniform(-120, 120, 3000)
    r = mh.sweep_ellipses(nu, gap=gap, ratio=ratio)
    assert 0 < r.ok.sum() < 3000
    assert np.isfinite(r.k.compressed()).all() and np.isfinite(r.k_error.compressed()).all()
    assert all(isinstance(m, str) and m for m in r.messages[~r.ok])
    bad_nu = (nu <= -1) | (nu > 0.5)
    assert not r.ok[bad_nu].any()
