"""The package's numbers equal the command-line tool's --json digit for digit (as_text=True),
and its numeric results are those digits at the working precision (float at f64, mpmath.mpf
above), at f64, dd and 256 bits."""

import mpmath
import pytest

import moving_hertz as mh

PRECISIONS = ["f64", "dd", 256]
LABELS = {"f64": "f64", "dd": "dd", 256: "mpfr256"}


def _same(result, json, skip=("precision",)):
    """Every field of the result that the JSON has: equal as text, and the numeric result
    equal to the JSON digits read at the working precision."""
    d = result.to_dict()
    keys = [k for k in d if k in json and k not in skip]
    assert len(keys) >= 7
    for k in keys:
        assert str(d[k]) == str(json[k]), k
    return keys


def _numeric(result, json, keys, bits):
    for k in keys:
        v = getattr(result, k)
        if k in ("bits", "iterations", "work", "route", "major_axis"):
            assert str(v) == str(json[k]), k
        elif bits == 53 and k.endswith("_error"):
            # The float is the bound itself; the JSON prints it to 3 digits rounded upwards.
            assert type(v) is float and v <= float(json[k]) <= v * 1.01 + 1e-300, k
        elif bits == 53:
            assert type(v) is float and v == float(json[k]), k
        else:
            with mpmath.workprec(bits):
                assert isinstance(v, mpmath.mpf) and v == mpmath.mpf(json[k]), k


@pytest.mark.parametrize("precision", PRECISIONS)
@pytest.mark.parametrize("nu,speed,ratio", [("0.25", "0.9990234375", "2"),
                                            ("0.3", "0.9999999999", "0.05"),
                                            ("-0.5", "0.5", "30")])
def test_ellipse_equals_cli(cli, precision, nu, speed, ratio):
    json = cli("ellipse", "--nu", nu, "--speed", speed, "--ratio", ratio,
               "--precision", precision)
    text = mh.solve_ellipse(nu, speed=speed, ratio=ratio, precision=precision, as_text=True)
    assert text.precision == json["precision"] == LABELS[precision]
    keys = _same(text, json)
    value = mh.solve_ellipse(nu, speed=speed, ratio=ratio, precision=precision)
    _numeric(value, json, keys, int(json["bits"]))


@pytest.mark.parametrize("precision", PRECISIONS)
def test_ellipse_by_gap_equals_cli(cli, precision):
    json = cli("ellipse", "--nu", "0.2", "--gap", "1e-12", "--ratio", "0.5",
               "--precision", precision)
    _same(mh.solve_ellipse("0.2", gap="1e-12", ratio="0.5", precision=precision,
                           as_text=True), json)


@pytest.mark.parametrize("precision", PRECISIONS)
@pytest.mark.parametrize("size", [("--load", "1000"), ("--approach", "1e-5")])
def test_contact_equals_cli(cli, precision, size):
    json = cli("contact", "--nu", "0.3", "--speed", "0.9", "--r-along", "0.05", "--r-across",
               "0.02", *size, "--shear-modulus", "80e9", "--precision", precision)
    kw = {size[0][2:]: size[1]}
    text = mh.solve_contact("0.3", speed="0.9", radius_along="0.05", radius_across="0.02",
                            shear_modulus="80e9", precision=precision, as_text=True, **kw)
    keys = _same(text, json)
    value = mh.solve_contact("0.3", speed="0.9", radius_along="0.05", radius_across="0.02",
                             shear_modulus="80e9", precision=precision, **kw)
    _numeric(value, json, keys, int(json["bits"]))


@pytest.mark.parametrize("precision", PRECISIONS)
def test_integrals_equal_cli(cli, precision):
    json = cli("integrals", "--nu", "0.25", "--speed", "0.999", "--k", "0.5", "--precision",
               precision, "--derivatives", "--j0")
    text = mh.integrals("0.25", speed="0.999", k="0.5", precision=precision, derivatives=True,
                        j0=True, as_text=True)
    keys = _same(text, json)
    assert {"dI1_dk", "dI2_dk", "J0", "work"} <= set(keys)
    value = mh.integrals("0.25", speed="0.999", k="0.5", precision=precision,
                         derivatives=True, j0=True)
    _numeric(value, json, keys, int(json["bits"]))


def test_integrals_to_tolerance_equal_cli(cli):
    json = cli("integrals", "--nu", "0.25", "--gap", "1e-9", "--k", "2", "--tol", "1e-60")
    text = mh.integrals("0.25", gap="1e-9", k="2", tol="1e-60", as_text=True)
    assert text.precision == json["precision"] != "f64"
    _same(text, json)


@pytest.mark.parametrize("precision", PRECISIONS)
def test_rayleigh_equals_cli(cli, precision):
    json = cli("rayleigh", "--nu", "0.3", "--precision", precision)
    text = mh.rayleigh("0.3", precision=precision, as_text=True)
    for k in ("m1", "cR_over_c2", "cR_over_c1"):
        assert getattr(text, k) == json[k], k
    assert [list(r) for r in text.roots] == json["roots"]
