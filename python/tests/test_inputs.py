"""Numbers in and out: every accepted type gives the same bits as its exact text; bad inputs
raise the typed exception before any work; outputs are float, mpf or (without mpmath)
Decimal."""

import decimal
import fractions
import math

import mpmath
import numpy as np
import pytest

import moving_hertz as mh
from moving_hertz import _numbers


def _k(nu=0.25, speed=0.75, ratio=0.5, precision="f64", **kw):
    return mh.solve_ellipse(nu, speed=speed, ratio=ratio, precision=precision, **kw).k


@pytest.mark.parametrize("precision", ["f64", "dd", 256])
def test_every_type_gives_the_same_bits(precision):
    """0.25, 0.75, 0.5 are exact binary fractions: every type denotes the same numbers."""
    ref = _k(precision=precision, as_text=True)
    with mpmath.workprec(60):
        forms = [
            ("0.25", "0.75", "0.5"),
            ("1/4", "3/4", "1/2"),
            (fractions.Fraction(1, 4), fractions.Fraction(3, 4), fractions.Fraction(1, 2)),
            (decimal.Decimal("0.25"), decimal.Decimal("0.75"), decimal.Decimal("0.5")),
            (mpmath.mpf(0.25), mpmath.mpf(0.75), mpmath.mpf(0.5)),
            (np.float32(0.25), np.float64(0.75), np.float16(0.5)),
        ]
    for nu, speed, ratio in forms:
        assert _k(nu, speed, ratio, precision, as_text=True) == ref, (nu, speed, ratio)
    assert _k(0.25, 0.75, 1, precision, as_text=True) != ref  # the ratio matters
    assert _k("0.25", "0.75", 1, precision) == _k("0.25", "0.75", "1", precision)


def test_a_float_is_its_binary_value():
    """0.9 as a float is 0.90000000000000002220...: at 256 bits its k differs from that of
    the decimal text "0.9", and equals that of its exact expansion."""
    exact = str(decimal.Decimal(0.9))
    assert _k(speed=0.9, precision=256) == _k(speed=exact, precision=256)
    assert _k(speed=0.9, precision=256) != _k(speed="0.9", precision=256)


def test_text_speed_keeps_its_gap():
    """speed="0.9999999999" is exact: the same ellipse as gap="1e-10", and not the one of
    the float 0.9999999999 (whose gap is off in the 7th digit)."""
    a = mh.solve_ellipse(0.25, speed="0.9999999999", ratio=2.0)
    b = mh.solve_ellipse(0.25, gap="1e-10", ratio=2.0)
    c = mh.solve_ellipse(0.25, speed=0.9999999999, ratio=2.0)
    assert a.k == b.k
    assert abs(c.k / a.k - 1) > 1e-9


BAD = [float("nan"), float("inf"), -float("inf"), None, True, "abc", "1e1000000", [0.5],
       complex(1, 0), decimal.Decimal("NaN"), decimal.Decimal("Infinity"), mpmath.mpf("inf"),
       object()]


@pytest.mark.parametrize("bad", BAD, ids=repr)
@pytest.mark.parametrize("argument", ["nu", "speed", "ratio"])
def test_bad_inputs_raise_domain_error_naming_the_argument(bad, argument):
    kw = {"nu": 0.25, "speed": 0.5, "ratio": 1.0, argument: bad}
    with pytest.raises(mh.DomainError) as info:
        mh.solve_ellipse(kw.pop("nu"), **kw)
    assert info.value.argument == argument
    assert isinstance(info.value, ValueError)


def test_out_of_domain_values_name_the_argument_and_value():
    with pytest.raises(mh.DomainError, match=r"0\.5000000000000000001") as info:
        mh.solve_ellipse("0.5000000000000000001", speed=0.5, ratio=1.0)
    assert info.value.argument == "nu"
    for kw, arg in [(dict(speed=1.0), "speed"), (dict(gap=0.0), "gap"), (dict(gap=-0.0), "gap"),
                    (dict(speed=-1e-300), "speed")]:
        with pytest.raises(mh.DomainError) as info:
            mh.solve_ellipse(0.25, ratio=1.0, **kw)
        assert info.value.argument == arg
    with pytest.raises(mh.DomainError) as info:
        mh.solve_ellipse(0.25, speed=0.5, ratio=-0.0)
    assert info.value.argument == "ratio"
    with pytest.raises(mh.DomainError, match="overflow|not finite") as info:
        mh.solve_contact(0.25, speed=0.5, radius_along="1e400", radius_across=1.0, load=1.0,
                         shear_modulus=1.0)
    assert info.value.argument == "radius_along"


def test_negative_zero_is_zero():
    assert _k(nu=-0.0) == _k(nu=0.0)
    assert _k(speed=-0.0) == _k(speed=0.0)


@pytest.mark.parametrize("precision", ["f32", 23, 32769, 2.5, None, True, "0"])
def test_bad_precision(precision):
    with pytest.raises(mh.DomainError) as info:
        _k(precision=precision)
    assert info.value.argument == "precision"


def test_speed_and_gap_exclusive_and_required():
    with pytest.raises(mh.DomainError):
        mh.solve_ellipse(0.25, speed=0.5, gap=0.5, ratio=1.0)
    with pytest.raises(mh.DomainError):
        mh.solve_ellipse(0.25, ratio=1.0)
    with pytest.raises(mh.DomainError):
        mh.solve_ellipse(0.25, speed=0.5)
    with pytest.raises(mh.DomainError) as info:
        mh.solve_ellipse(0.25, speed=0.5, ratio=1.0, method="series")
    assert info.value.argument == "method"


def test_outputs_float_mpf_decimal(monkeypatch):
    e = mh.solve_ellipse(0.25, speed=0.5, ratio=2.0)
    assert all(type(getattr(e, f)) is float for f in ("k", "k_error", "e", "I1", "I2"))
    e = mh.solve_ellipse(0.25, speed=0.5, ratio=2.0, precision=300)
    assert type(e.k) is mpmath.mpf and e.bits == 300
    monkeypatch.setattr(_numbers, "_mpmath", None)
    d = mh.solve_ellipse(0.25, speed=0.5, ratio=2.0, precision=300)
    assert type(d.k) is decimal.Decimal
    t = mh.solve_ellipse(0.25, speed=0.5, ratio=2.0, precision=300, as_text=True)
    assert str(d.k) == t.k and len(t.k.split("e")[0]) > 90
    with mpmath.workprec(300):
        assert mpmath.mpf(str(d.k)) == e.k


def test_results_are_immutable_with_repr_and_dict():
    e = mh.solve_ellipse(0.25, speed=0.5, ratio=2.0)
    with pytest.raises(AttributeError):
        e.k = 1.0
    d = e.to_dict()
    assert list(d)[:4] == ["precision", "bits", "route", "k"] and d["k"] == e.k
    assert "k=" in repr(e) and "error <=" in repr(e)
    assert math.isfinite(e.k_error) and 0 < e.k_error < 1e-13
    c = mh.solve_contact(0.3, speed=0.9, radius_along=0.05, radius_across=0.02, load=1000.0,
                         shear_modulus=80e9)
    assert c.to_dict()["load"] == c.load
    assert abs(c.load - 1000.0) <= 1000.0 * c.load_error


def test_plain_floats_give_the_result_of_the_general_path():
    # Plain floats take the native fast path (the result object made in Rust); numpy float64
    # scalars, the same binary values, take the general one: the same result, field by field.
    for nu, speed, ratio, method in ((0.25, 0.9990234375, 2.0, "auto"),
                                     (0.3, 0.5, 1e-3, "adaptive"), (-0.5, 0.0, 7.0, "fixed")):
        fast = mh.solve_ellipse(nu, speed=speed, ratio=ratio, method=method)
        general = mh.solve_ellipse(np.float64(nu), speed=np.float64(speed),
                                   ratio=np.float64(ratio), method=method)
        assert type(fast) is mh.Ellipse and isinstance(fast, tuple)
        assert fast.to_dict() == general.to_dict() and repr(fast) == repr(general)
        assert fast._fields == general._fields and fast == general
        assert all(type(a) is type(b) for a, b in zip(fast, general))
    assert mh.solve_ellipse(0.3, speed=0.5, ratio=1e-3, method="adaptive").route == "adaptive"
    with pytest.raises(AttributeError):
        fast.k = 1.0
    with pytest.raises(mh.DomainError, match="ratio") as e:
        mh.solve_ellipse(0.25, speed=0.5, ratio=-1.0)
    assert e.value.argument == "ratio"
    with pytest.raises(mh.DomainError, match="nope") as e:
        mh.solve_ellipse(0.25, speed=0.5, ratio=1.0, method="nope")
    assert e.value.argument == "method"
    with pytest.raises(mh.DomainError):
        mh.solve_ellipse(0.25, speed=math.nan, ratio=1.0)
