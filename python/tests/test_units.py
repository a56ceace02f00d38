"""Physical units in solve_contact: Young's modulus for the shear modulus, and a velocity in
m/s with the density, through the crate's Solid; checked against mu = E/(2(1 + nu)) in exact
fractions and c_R = c2 sqrt(m1) formed with mpmath from the crate's Rayleigh root at 320
bits."""

import fractions

import mpmath
import pytest

import moving_hertz as mh

COMMON = dict(radius_along="0.05", radius_across="0.02", load="1000")


@pytest.mark.parametrize("precision", ["f64", "dd", 256])
def test_youngs_modulus_is_the_shear_modulus_of_nu(precision):
    e = mh.solve_contact("0.3", speed="0.9", youngs_modulus="210e9", precision=precision,
                         **COMMON)
    mu = fractions.Fraction(210 * 10**9) / (2 * (1 + fractions.Fraction(3, 10)))
    m = mh.solve_contact("0.3", speed="0.9", shear_modulus=mu, precision=precision, **COMMON)
    with mpmath.workprec(400):
        for f in ("a", "b", "p0", "d0"):
            x, y = mpmath.mpf(getattr(e, f)), mpmath.mpf(getattr(m, f))
            bound = mpmath.mpf(getattr(e, f + "_error")) + mpmath.mpf(getattr(m, f + "_error"))
            assert abs(x / y - 1) <= bound + 8 * mpmath.mpf(2) ** -e.bits, f


@pytest.mark.parametrize("modulus", ["youngs_modulus", "shear_modulus"])
def test_velocity_in_metres_per_second(modulus):
    """V = 1500 m/s over steel (E = 210 GPa or mu = 80 GPa, rho = 7850 kg/m^3, nu = 0.3)
    gives the contact of M_R = V/c_R."""
    value = "210e9" if modulus == "youngs_modulus" else "80e9"
    v = mh.solve_contact("0.3", velocity="1500", density="7850", precision="dd",
                         **{modulus: value}, **COMMON)
    with mpmath.workprec(320):
        nu = mpmath.mpf(3) / 10
        mu = mpmath.mpf(value) / (2 * (1 + nu)) if modulus == "youngs_modulus" else mpmath.mpf(value)
        m1 = mh.rayleigh("0.3", precision=320).m1
        c_r = mpmath.sqrt(mu / 7850) * mpmath.sqrt(m1)
        mr = 1500 / c_r
        s = mh.solve_contact("0.3", speed=mr, shear_modulus=mu, precision="dd", **COMMON)
        assert 0.4 < mr < 0.6
        for f in ("a", "b", "k", "p0"):
            x, y = getattr(v, f), getattr(s, f)
            assert abs(x / y - 1) <= getattr(v, f + "_error") + getattr(s, f + "_error") \
                + mpmath.mpf("1e-29"), f


def test_velocity_at_or_above_rayleigh_speed_is_refused():
    with pytest.raises(mh.DomainError, match="c_R") as info:
        mh.solve_contact("0.3", velocity="4000", youngs_modulus="210e9", density="7850",
                         **COMMON)
    assert info.value.argument == "velocity"


def test_unit_arguments_go_together():
    with pytest.raises(mh.DomainError) as info:
        mh.solve_contact(0.3, speed=0.5, shear_modulus=80e9, density=7850.0, **COMMON)
    assert info.value.argument == "density"
    with pytest.raises(mh.DomainError):
        mh.solve_contact(0.3, velocity=1000.0, shear_modulus=80e9, **COMMON)
    with pytest.raises(mh.DomainError):
        mh.solve_contact(0.3, speed=0.5, shear_modulus=80e9, youngs_modulus=210e9, **COMMON)
    with pytest.raises(mh.DomainError) as info:
        mh.solve_contact(0.3, velocity=1000.0, youngs_modulus=210e9, density=-1.0, **COMMON)
    assert "density" in str(info.value) or info.value.argument == "density"
