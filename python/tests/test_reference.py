"""Values against the committed reference data of tests/data (mpmath at 50 to 120 digits):
each value within its own error bound (plus the reference's last digit), and the bound itself
a few units of the working precision, at f64, dd and 256 bits."""

import mpmath
import pytest

import moving_hertz as mh
from conftest import read_csv

# The largest bound accepted at each precision (relative): a few hundred units of the last
# place, so that a wrong bound (or a solve at a lower precision) fails.
LIMIT = {"f64": "1e-12", "dd": "1e-27", 256: "1e-72"}
BITS = {"f64": 53, "dd": 106, 256: 256}


def _check(value, bound, ref, precision, ref_digits):
    with mpmath.workprec(400):
        v, b, r = mpmath.mpf(value), mpmath.mpf(bound), mpmath.mpf(ref)
        assert b <= mpmath.mpf(LIMIT[precision])
        assert abs(v - r) <= (b + mpmath.mpf(10) ** -ref_digits) * abs(r)


INTEGRAL_ROWS = [r for r in read_csv("integrals_mpmath.csv") if r[0] == "I"]


@pytest.mark.parametrize("precision", ["f64", "dd", 256])
@pytest.mark.parametrize("row", INTEGRAL_ROWS, ids=lambda r: f"nu{r[1]}-mr{r[2]}-k{r[3]}")
def test_integrals_against_mpmath(row, precision):
    _, nu, mr, k, i1, i2 = row
    r = mh.integrals(nu, speed=mr, k=k, precision=precision, as_text=True)
    _check(r.I1, r.I1_error, i1, precision, 38)
    _check(r.I2, r.I2_error, i2, precision, 38)
    assert r.bits == BITS[precision]


J0_ROWS = read_csv("j0_mpmath.csv")


@pytest.mark.parametrize("precision", ["f64", "dd", 256])
@pytest.mark.parametrize("row", J0_ROWS, ids=lambda r: f"nu{r[0]}-gap{r[1]}-k{r[2]}")
def test_j0_against_mpmath(row, precision):
    nu, gap, k, j0 = row
    r = mh.integrals(nu, gap=gap, k=k, precision=precision, j0=True, as_text=True)
    _check(r.J0, r.J0_error, j0, precision, 38)


RAYLEIGH_ROWS = [r for r in read_csv("rayleigh_mpmath.csv") if r[0] == "root1"][::40]


@pytest.mark.parametrize("precision", ["f64", "dd", 256])
@pytest.mark.parametrize("row", RAYLEIGH_ROWS, ids=lambda r: f"nu{r[1][:12]}")
def test_rayleigh_root_against_mpmath(row, precision):
    """m1 = (c_R/c2)^2 within 4 units of the last place of the working precision (numeric
    results: float at f64, mpf above)."""
    _, nu, _, m1, _ = row
    r = mh.rayleigh(nu, precision=precision)
    assert type(r.m1) is (float if precision == "f64" else mpmath.mpf)
    with mpmath.workprec(400):
        rel = abs(mpmath.mpf(r.m1) / mpmath.mpf(m1) - 1)
        assert rel <= 4 * mpmath.mpf(2) ** (1 - BITS[precision])


def test_ellipse_root_satisfies_33_at_256_bits():
    """The ellipse's k is the root of (33): I2(k)/I1(k) = A1/B1, checked by an independent
    evaluation of the integrals at 400 bits at the returned k."""
    e = mh.solve_ellipse("0.25", speed="0.9990234375", ratio="2", precision=256)
    r = mh.integrals("0.25", speed="0.9990234375", k=e.k, precision=400)
    with mpmath.workprec(400):
        assert abs(r.I2 / r.I1 / 2 - 1) < mpmath.mpf("1e-70")
        assert e.k_error < mpmath.mpf("1e-72")
