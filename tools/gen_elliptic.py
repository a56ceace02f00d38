#!/usr/bin/env python3
"""Reference values for src/numerics/elliptic.rs, from mpmath (an independent engine).

Writes tests/data/elliptic_mpmath.csv   (function,arg,phi,value: K, E, B, D by m or mc, and
                                        heuman_lambda_c_mc = 1 - Heuman's Lambda)
   and tests/data/elliptic_mpmath_8192.csv (K, E, D at 8192 bits)

Every input is a dyadic rational with at most 53 significant bits, so it is exactly
representable at every precision the tests use (f64, double-double, MPFR); it is written as its
exact decimal expansion. Values carry DIGITS significant digits, enough to check 1024-bit results
(1024 bits ~ 308 digits). Each value is computed at two working precisions (DPS + 40
and DPS + 100 digits, plus extra digits where a formula cancels) and the script stops if they disagree.

Usage:  python3 tools/gen_elliptic.py      (needs mpmath; made with mpmath 1.3.0)
"""

from fractions import Fraction as Fr
import os
import sys

import mpmath as mp

DIGITS = DIGITS_MAIN = 330
DPS = DPS_MAIN = 340


def exact(x):
    """Exact decimal expansion of a dyadic rational (Fraction or float)."""
    fr = Fr(x)
    den = fr.denominator
    k = 0
    while den % 2 == 0:
        den //= 2
        k += 1
    assert den == 1, f"{x} is not dyadic"
    num = fr.numerator * 5**k  # value = num / 10^k
    sign = "-" if num < 0 else ""
    s = str(abs(num)).rjust(k + 1, "0")
    if k == 0:
        return sign + s
    return sign + s[:-k] + "." + s[-k:]


def dyadic(x):
    """Asserts that x has at most 53 significant bits (exact in f64), returns it as Fraction."""
    fr = Fr(x)
    assert Fr(float(fr)) == fr, f"{x} is not exact in f64"
    return fr


def mpf(fr):
    return mp.mpf(fr.numerator) / fr.denominator


# --- reference formulas, each valid at any working precision --------------------------------
def extra_digits(fr):
    """Digits lost to cancellation in (E - mc K)/m, (K - E)/m when m is small."""
    return 0 if fr == 0 else max(0, int(-mp.log10(abs(mpf(fr)))) + 5)


def f_ellipk(m):
    return mp.ellipk(mpf(m))


def f_ellipe(m):
    return mp.ellipe(mpf(m))


def f_ellipb(m):  # (E - mc K)/m
    with mp.extradps(extra_digits(m)):
        mm = mpf(m)
        if mm == 0:
            return mp.pi / 4
        return (mp.ellipe(mm) - (1 - mm) * mp.ellipk(mm)) / mm


def f_ellipd(m):  # (K - E)/m
    with mp.extradps(extra_digits(m)):
        mm = mpf(m)
        if mm == 0:
            return mp.pi / 4
        return (mp.ellipk(mm) - mp.ellipe(mm)) / mm


def heuman(phi, m):
    """Heuman's Lambda_0(phi|m) = (2/pi)[E(m)F(phi|mc) + K(m)E(phi|mc) - K(m)F(phi|mc)]."""
    mm = mpf(m)
    mc = 1 - mm
    with mp.extradps(40):
        # Reduced to |phi'| <= pi/2 first (Lambda_0(phi + pi) = Lambda_0(phi) + 2): for m = 0
        # mpmath's F(phi|1) is infinite beyond pi/2.
        j = mp.nint(mpf(phi) / mp.pi)
        ph = mpf(phi) - j * mp.pi
        K, E = mp.ellipk(mm), mp.ellipe(mm)
        F1, E1 = mp.ellipf(ph, mc), mp.ellipe(ph, mc)
        return 2 * j + 2 / mp.pi * (E * F1 + K * E1 - K * F1)


def heuman_c(phi, m):
    with mp.extradps(60):
        return 1 - heuman(phi, m)


def stable(f, *args):
    """f(*args) at DPS + 40 and DPS + 100 digits (mpmath loses up to ~30 digits next to the
    singularity m = 1); they must agree to DIGITS + 3 digits."""
    mp.mp.dps = DPS + 40
    v1 = f(*args)
    mp.mp.dps = DPS + 100
    v2 = f(*args)
    mp.mp.dps = DPS
    if not mp.isfinite(v2):
        sys.exit(f"reference {f.__name__}{args} is not finite: {v2}")
    if v2 != 0 and abs((v1 - v2) / v2) > mp.mpf(10) ** -(DIGITS + 3):
        sys.exit(f"unstable reference {f.__name__}{args}: {v1} vs {v2}")
    return mp.nstr(v2, DIGITS, min_fixed=1, max_fixed=0)


def main():
    global DIGITS, DPS
    mp.mp.dps = DPS
    two = Fr(2)
    # Parameters m for the m-forms (m <= 1) and mc for the mc-forms (mc >= 0).
    ms = [Fr(0), two**-60, two**-20, Fr(1, 8), Fr(1, 2), Fr(11, 16), Fr(15, 16),
          1 - two**-20, 1 - two**-40, 1 - two**-52, Fr(-1, 2), Fr(-13, 4), Fr(-100),
          -(two**20), Fr(-10**12)]
    mcs = [two**-100, two**-60, two**-40, two**-20, Fr(1, 32), Fr(1, 2), Fr(1), Fr(3, 2),
           Fr(17, 4), two**20, Fr(10**12)]
    # Amplitudes, including the f64 neighbours of pi/2 below and above.
    below = Fr(1.5707963267948966)
    above = Fr(1.5707963267948968)
    phis = [Fr(1, 4), Fr(5, 4), Fr(3, 2), Fr(201, 128), below, above, Fr(15, 4), Fr(-15, 2),
            Fr(21, 2), Fr(401, 4), Fr(-10**6)]
    for v in ms + mcs + phis:
        dyadic(v)

    rows = []
    for m in ms:
        if m < 1:
            rows.append(("ellipk", m, None, stable(f_ellipk, m)))
            rows.append(("ellipd", m, None, stable(f_ellipd, m)))
        rows.append(("ellipe", m, None, stable(f_ellipe, m)))
        rows.append(("ellipb", m, None, stable(f_ellipb, m)))
    for mc in mcs:
        m = 1 - mc  # exact as a Fraction; mpmath receives it exactly
        rows.append(("ellipk_mc", mc, None, stable(f_ellipk, m)))
        rows.append(("ellipe_mc", mc, None, stable(f_ellipe, m)))
        rows.append(("ellipb_mc", mc, None, stable(f_ellipb, m)))
        rows.append(("ellipd_mc", mc, None, stable(f_ellipd, m)))
    for mc in [two**-100, two**-40, Fr(1, 8), Fr(1, 2), Fr(7, 8), 1 - two**-40, Fr(1)]:
        for phi in phis:
            rows.append(("heuman_lambda_c_mc", mc, phi, stable(heuman_c, phi, 1 - mc)))

    here = os.path.dirname(os.path.abspath(__file__))
    out = os.path.join(here, "..", "tests", "data")
    os.makedirs(out, exist_ok=True)
    head = (f"# Generated by tools/gen_elliptic.py with mpmath {mp.__version__} at mp.dps = "
            f"{DPS + 40} (checked at {DPS + 100}); {DIGITS} significant digits.\n"
            "# Inputs are dyadic rationals exact in f64, written as exact decimals.\n")
    with open(os.path.join(out, "elliptic_mpmath.csv"), "w") as fh:
        fh.write(head + "# Parameter column: m for plain names, mc = 1 - m for names ending in _mc.\n")
        fh.write("function,arg,phi,value\n")
        for f, arg, phi, v in rows:
            fh.write(f"{f},{exact(arg)},{'' if phi is None else exact(phi)},{v}\n")
    # A few values at 8192 bits (2466 digits): the spot checks of the highest precision.
    DIGITS, DPS = 2480, 2500
    spot = [("ellipk_mc", two**-100, None, f_ellipk, (1 - two**-100,)),
            ("ellipe_mc", Fr(17, 4), None, f_ellipe, (1 - Fr(17, 4),)),
            ("ellipd_mc", two**-40, None, f_ellipd, (1 - two**-40,))]
    with open(os.path.join(out, "elliptic_mpmath_8192.csv"), "w") as fh:
        fh.write(head.replace(f"{DPS_MAIN + 40}", f"{DPS + 40}").replace(f"{DPS_MAIN + 100}", f"{DPS + 100}")
                 .replace(f"{DIGITS_MAIN} significant", f"{DIGITS} significant"))
        fh.write("function,arg,phi,value\n")
        for name, arg, phi, f, args in spot:
            fh.write(f"{name},{exact(arg)},{'' if phi is None else exact(phi)},{stable(f, *args)}\n")
    print(f"{len(rows)} + {len(spot)} reference values written to {os.path.normpath(out)}")


if __name__ == "__main__":
    main()
