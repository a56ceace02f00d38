#!/usr/bin/env python3
"""Reference axis ratios k = b/a of the contact ellipse near the Rayleigh speed, for the CLI's
decimal inputs taken exactly (tests/rayleigh_gap.rs: `ellipse --precision f64 --json` with
--speed and with --gap must give k within 8 eps of these).

Independent of the crate: mpmath only, with the formulas of docs/theory.md (checked against
docs/errata.md):
  * gamma = (1 - 2 nu)/(2 (1 - nu)); the Rayleigh root m1 = (c_R/c2)^2 from R(x) = 0 with
    R(x) = (2 - x)^2 - 4 sqrt((1 - gamma x)(1 - x)) (6), by mpmath.findroot;
  * g = -pi Gamma with Gamma(V) = M2^2 sqrt(1 - M1^2)/(pi R(V)) (5) as printed, x = M2^2 =
    m1 (M_R sin phi)^2, M1^2 = gamma x (the normalisation of (37), errata #3; it cancels in the
    ratio), evaluated with extra digits where R cancels near x = m1;
  * I1, I2 of (34) over [0, pi/2] (the integrands are symmetric about pi/2),
        I1 = 2 int g(M_R sin phi) cos^2 phi/(k^2 cos^2 phi + sin^2 phi)^(3/2) dphi,
        I2 = 2 int g(M_R sin phi) sin^2 phi/(k^2 cos^2 phi + sin^2 phi)^(3/2) dphi,
    by mpmath.quad, split where the integrand has its narrow features (phi = pi/2 - c and c
    for c = sqrt(1 - M_R^2) 4^j and k 4^j), as in tools/gen_integrals.py;
  * k solves (33) I2(k)/I1(k) = A1/B1 by the secant method in ln k.
The speed is taken exactly from its decimal text: M_R = mpf(text) at the working precision, or
M_R = 1 - gap for a gap given directly (the CSV carries both decimals, exact complements of each
other). Every case is solved at 30 digits, then again at 40 digits from the 30-digit root (different
quadrature nodes and roundings; the 40-digit integrals move the root if the 30-digit ones were
off); the script stops if the two disagree beyond 1e-20 relative (the tests need k to well below an
f64 ulp), and writes the 40-digit solve to 25 digits.

Usage: python3 tools/gen_rayleigh_gap.py > tests/data/rayleigh_gap.csv   (two processes; about six
minutes on 2 cores)
"""
import multiprocessing
import sys
from decimal import Decimal, getcontext

import mpmath as mp

DIGITS = 25
AGREE = 20  # the two solves must agree to 10^-AGREE relative
getcontext().prec = 60

NUS = ["0.25", "0.45"]
SPEEDS = ["0.99999", "0.9999999", "0.999999999", "0.999999999999"]
GAPS = ["7.5e-11", "2.5e-13"]
RATIOS = ["2", "0.5"]


def rayleigh(x, gamma):
    return (2 - x) ** 2 - 4 * mp.sqrt((1 - gamma * x) * (1 - x))


def material(nu):
    gamma = (1 - 2 * nu) / (2 * (1 - nu))
    m1 = mp.findroot(lambda x: rayleigh(x, gamma), (mp.mpf("0.3"), mp.mpf("0.999")), solver="anderson")
    return gamma, m1


def g_norm(gamma, m1, mr_eff):
    """g = -pi Gamma at the Rayleigh Mach number mr_eff, by (5)-(6) as printed."""
    x = m1 * mr_eff ** 2
    if x == 0:
        raise ValueError("phi = 0 is an endpoint; quad never evaluates it")
    # R cancels like x near 0 and like (m1 - x) near m1: carry the digits both lose.
    extra = 10 + int(max(-mp.log10(x), -mp.log10(abs(m1 - x)), 0))
    with mp.extradps(extra):
        r = rayleigh(x, gamma)
        return -x * mp.sqrt(1 - gamma * x) / r


def make_integrals(nu, mr):
    gamma, m1 = material(nu)
    eps = mp.sqrt(1 - mr ** 2)
    cache = {}

    def g(phi):
        v = cache.get(phi)
        if v is None:
            v = cache[phi] = g_norm(gamma, m1, mr * mp.sin(phi))
        return v

    def integrals(k):
        half = mp.pi / 2
        pts = {mp.mpf(0), half}
        for j in range(-6, 7):
            for c in (eps * mp.mpf(4) ** j, k * mp.mpf(4) ** j):
                if 0 < c < half:
                    pts.update({half - c, c})
        pts = sorted(pts)
        den = lambda ph: (k ** 2 * mp.cos(ph) ** 2 + mp.sin(ph) ** 2) ** mp.mpf(1.5)
        i1 = 2 * mp.quad(lambda ph: g(ph) * mp.cos(ph) ** 2 / den(ph), pts, maxdegree=10)
        i2 = 2 * mp.quad(lambda ph: g(ph) * mp.sin(ph) ** 2 / den(ph), pts, maxdegree=10)
        return i1, i2

    return integrals


def secant(F, x0, x1, tol, maxit=40):
    """The root of F by the secant method from x0, x1: stops when a step is below tol."""
    f0, f1 = F(x0), F(x1)
    for _ in range(maxit):
        x2 = x1 - f1 * (x1 - x0) / (f1 - f0)
        if abs(x2 - x1) < tol:
            return x2
        x0, f0, x1, f1 = x1, f1, x2, F(x2)
    sys.exit("the secant method did not converge")


def solve(nu_text, mr_exact, ratio_text, dps, lnk_start=None):
    """k, I1, I2 at the working precision dps; mr_exact() gives M_R at that precision. Without
    a start, from k ~ 1.3 (1 - M_R)^(1/4) A1/B1 (the trend near c_R)."""
    with mp.workdps(dps):
        nu, mr, ratio = mp.mpf(nu_text), mr_exact(), mp.mpf(ratio_text)
        integrals = make_integrals(nu, mr)

        def F(lnk):
            i1, i2 = integrals(mp.exp(lnk))
            return mp.log(i2 / i1) - mp.log(ratio)

        if lnk_start is None:
            x0 = mp.log((1 - mr) ** mp.mpf(0.25) * ratio * mp.mpf(1.3))
            x1 = x0 + mp.mpf("0.01")
        else:
            x0 = mp.mpf(lnk_start)
            x1 = x0 + mp.mpf(10) ** (-(dps - 25))
        k = mp.exp(secant(F, x0, x1, mp.mpf(10) ** (-(dps - 10))))
        i1, i2 = integrals(k)
        residual = abs(mp.log(i2 / i1) - mp.log(ratio))
        if residual > mp.mpf(10) ** (-(dps - 8)):
            sys.exit(f"no convergence: nu={nu_text} M_R={mr} ratio={ratio_text} residual {residual}")
        return k, i1, i2


def case(row):
    """k, I1, I2 at 30 digits, then at 40 digits by the secant method started from the 30-digit
    root (so that the 40-digit integrals decide the root again); the speed from its decimal
    text or, for a gap given directly, 1 - gap."""
    nu, speed, gap, ratio = row
    mr = (lambda: mp.mpf(speed)) if speed is not None else (lambda: 1 - mp.mpf(gap))
    k50, a50, b50 = solve(nu, mr, ratio, 30)
    k70, a70, b70 = solve(nu, mr, ratio, 40, lnk_start=mp.log(k50))
    with mp.workdps(40):
        for name, x, y in (("k", k50, k70), ("I1", a50, a70), ("I2", b50, b70)):
            if abs(x / y - 1) > mp.mpf(10) ** -AGREE:
                sys.exit(f"{name} disagrees between 30 and 40 digits: {x} vs {y}")
        return [mp.nstr(v, DIGITS) for v in (k70, a70, b70)]


def main():
    rows = [(nu, s, None, r) for nu in NUS for s in SPEEDS for r in RATIOS]
    rows += [(nu, None, g, r) for nu in NUS for g in GAPS for r in RATIOS]
    with multiprocessing.Pool(2) as pool:
        results = pool.map(case, rows)
    print(f"# generated by tools/gen_rayleigh_gap.py with mpmath {mp.__version__} at 30 and 40 digits")
    print("# nu,speed,gap,ratio,k,I1,I2 (speed and gap exact complements; I1, I2 in the normalisation of (37) at k)")
    for (nu, speed, gap, ratio), (k, i1, i2) in zip(rows, results):
        if speed is not None:
            speed_text, gap_text = speed, str(Decimal(1) - Decimal(speed))
        else:
            speed_text, gap_text = str(Decimal(1) - Decimal(gap)), gap
        print(f"{nu},{speed_text},{gap_text},{ratio},{k},{i1},{i2}")


if __name__ == "__main__":
    main()
