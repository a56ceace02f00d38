#!/usr/bin/env python3
"""Reference values for the half-space in physical units (`Solid`, tests/solid.rs).

Independent of the crate: mpmath at 120 digits, from the decimal inputs taken exactly
(mpmath.mpf of the decimal string at 120 digits).  mu = E/(2(1+nu)); c2 = sqrt(mu/rho);
c1 = c2*sqrt(2(1-nu)/(1-2nu)); from (c1, c2), nu = (c1^2 - 2 c2^2)/(2(c1^2 - c2^2)) (the usual
textbook form, not the crate's gamma form).  c_R is found as the root in (0, c2) of the Rayleigh
equation in speeds, unrationalised,
    (2 - V^2/c2^2)^2 - 4 sqrt(1 - V^2/c1^2) sqrt(1 - V^2/c2^2) = 0
(for nu = 1/2: c1 infinite, the first root factor is 1), by mpmath.findroot (Anderson's
bracketing method) in x = V/c2 on [1/2, 1), where the function changes sign.  M_R = V/c_R and 1 - M_R = (c_R - V)/c_R.

Columns: kind (youngs: a = E, b = nu, c = rho; shear: a = mu, b = nu, c = rho; speeds: a = c1,
b = c2), velocity (V, m/s; `near` rows take V = c_R rounded down to 30 significant digits), then
nu, mu, c1, c2, c_r, mr, gap to 100 significant digits (mu empty for speeds; c1 empty at nu = 1/2).

Usage: python3 tools/gen_solid.py > tests/data/solid_mpmath.csv
"""
import mpmath as mp

mp.mp.dps = 120
DIGITS = 100

CASES = [
    # (kind, a, b, c, velocities)
    ("youngs", "210e9", "0.3", "7850", ["0", "2000", "2974", "near"]),  # steel (issue 46)
    ("youngs", "70e9", "0.33", "2700", ["1000", "near"]),  # aluminium
    ("youngs", "63e9", "1/5", "2500", ["3000"]),  # glass
    ("youngs", "3e6", "0.5", "1100", ["20", "near"]),  # incompressible rubber
    ("youngs", "1e9", "-0.5", "1000", ["500"]),  # auxetic
    ("shear", "80e9", "0.3", "7850", ["2000", "near"]),
    ("shear", "1.5e-3", "0.25", "2.5e-9", ["100"]),  # small units
    ("speeds", "5900", "3200", "", ["2900", "near"]),
    ("speeds", "1", "0.5", "", ["0.25"]),
]


def dec(x):
    return mp.nstr(x, DIGITS, strip_zeros=False, min_fixed=1, max_fixed=0)


def num(s):
    if "/" in s:
        p, q = s.split("/")
        return mp.mpf(p) / mp.mpf(q)
    return mp.mpf(s)


def rayleigh_speed(c1, c2):
    def f(x):  # x = V/c2
        s1 = 1 if c1 is None else mp.sqrt(1 - (x * c2 / c1) ** 2)
        return (2 - x**2) ** 2 - 4 * s1 * mp.sqrt(1 - x**2)

    lo, hi = mp.mpf("0.5"), 1 - mp.mpf(10) ** -100
    assert f(lo) < 0 < f(hi)
    x = mp.findroot(f, (lo, hi), solver="anderson", tol=mp.mpf(10) ** -230)
    assert lo < x < hi and abs(f(x)) < mp.mpf(10) ** -105
    return c2 * x


def main():
    print("kind,a,b,c,velocity,nu,mu,c1,c2,c_r,mr,gap")
    for kind, a, b, c, velocities in CASES:
        if kind == "speeds":
            c1, c2 = num(a), num(b)
            nu = (c1**2 - 2 * c2**2) / (2 * (c1**2 - c2**2))
            mu = None
        else:
            nu = num(b)
            mu = num(a) / (2 * (1 + nu)) if kind == "youngs" else num(a)
            c2 = mp.sqrt(mu / num(c))
            c1 = None if nu == mp.mpf(1) / 2 else c2 * mp.sqrt(2 * (1 - nu) / (1 - 2 * nu))
        cr = rayleigh_speed(c1, c2)
        for v in velocities:
            if v == "near":
                v = mp.nstr(cr, 30, strip_zeros=False, min_fixed=1, max_fixed=0)
                while num(v) >= cr:  # rounded down
                    v = mp.nstr(num(v) - mp.mpf(10) ** (mp.floor(mp.log10(cr)) - 29), 30)
            vv = num(v)
            row = [kind, a, b, c, v, dec(nu), "" if mu is None else dec(mu),
                   "" if c1 is None else dec(c1), dec(c2), dec(cr), dec(vv / cr), dec((cr - vv) / cr)]
            print(",".join(row))


main()
