#!/usr/bin/env python3
"""Reference values of I1, I2 (normalisation of (37): pi times the paper's (34)) and of S (49).

Independent of the crate: Gamma by (5)-(6) as printed, with the Rayleigh root found from (6) by
mpmath.findroot; the integrals by mpmath.quad in the original variable phi of (34), split at the
points where the integrand has its narrow features (phi = pi/2 -/+ multiples of sqrt(1 - M_R^2), and
phi = 0, pi -/+ multiples of k); S by mpmath.quad of (49) in alpha. 40 digits.

Usage: python3 tools/gen_integrals.py > tests/data/integrals_mpmath.csv

With --j0: J0 of (32), J0 = int_0^pi g(V sin phi)/(k^2 cos^2 phi + sin^2 phi)^(1/2) dphi, by
mpmath.quad in phi over [0, pi/2] (doubled), split geometrically (ratio 4) at both ends on the
scales eps = sqrt(1 - M_R^2), k and 1/k, with the working digits
raised by the digits the Rayleigh denominator loses near its zero (2 log10(1/eps)); the speed is given
by its gap 1 - M_R (exact binary fractions). 40 digits.

Usage: python3 tools/gen_integrals.py --j0 > tests/data/j0_mpmath.csv
"""
import sys
import mpmath as mp

mp.mp.dps = 50
DIGITS = 40


def rayleigh(x, g):
    return (2 - x) ** 2 - 4 * mp.sqrt((1 - g * x) * (1 - x))


def material(nu):
    g = (1 - 2 * nu) / (2 * (1 - nu))
    m1 = mp.findroot(lambda x: rayleigh(x, g), (mp.mpf("0.3"), mp.mpf("0.999")), solver="anderson")
    return g, m1


def g_norm(nu, g, m1, mr_eff):
    """g = -pi*Gamma at Rayleigh Mach number mr_eff, by (5)-(6) as printed."""
    x = m1 * mr_eff ** 2
    if x == 0:
        return 1 - nu
    # (6) cancels like x as x -> 0: carry enough extra digits to keep 50 after the cancellation.
    extra = int(-mp.log10(x)) + 10 if x < 1 else 10
    with mp.extradps(extra):
        gam = x * mp.sqrt(1 - g * x) / (mp.pi * rayleigh(x, g))
    return -mp.pi * gam


def integrals(nu, mr, k):
    g, m1 = material(nu)
    eps = mp.sqrt(1 - mr ** 2)
    half = mp.pi / 2
    pts = {mp.mpf(0), half, mp.pi}
    for j in range(-6, 6):
        for c in (eps * mp.mpf(4) ** j, k * mp.mpf(4) ** j):
            if 0 < c < half:
                pts.update({half - c, half + c, c, mp.pi - c})
    pts = sorted(pts)
    den = lambda ph: (k ** 2 * mp.cos(ph) ** 2 + mp.sin(ph) ** 2) ** mp.mpf(1.5)
    f1 = lambda ph: g_norm(nu, g, m1, mr * mp.sin(ph)) * mp.cos(ph) ** 2 / den(ph)
    f2 = lambda ph: g_norm(nu, g, m1, mr * mp.sin(ph)) * mp.sin(ph) ** 2 / den(ph)
    i1 = mp.quad(f1, pts, maxdegree=10)
    i2 = mp.quad(f2, pts, maxdegree=10)
    return i1, i2


def s_integral(mr, k):
    e2 = 1 - k ** 2
    eps = mp.sqrt(1 - mr ** 2)
    pts = sorted({mp.mpf(0), mp.pi / 2} | {c for j in range(-6, 6) for c in (eps * mp.mpf(4) ** j,) if 0 < c < mp.pi / 2})
    f = lambda a: mp.cos(a) ** 2 / ((1 - mr ** 2 * mp.cos(a) ** 2) * mp.sqrt(1 - e2 * mp.sin(a) ** 2) ** 3)
    return mp.quad(f, pts, maxdegree=10)


CASES = [
    # nu, M_R, k  (all exact binary fractions)
    ("0.25", "0", "0.5"),
    ("0.25", "0.5", "0.5"),
    ("0.1875", "0.875", "0.25"),
    ("0.1875", "0.998046875", "0.0625"),
    ("0.5", "0.5", "0.03125"),
    ("-0.5", "0.75", "0.75"),
    ("0", "0.9375", "2"),
    ("0.375", "0.25", "16"),
    ("0.25", "0.5", "0.0009765625"),
    ("0.25", "0.9999847412109375", "0.0078125"),
    ("0.4375", "0.99999999976716935634613037109375", "0.001953125"),
    ("-0.875", "0.96875", "0.125"),
]

S_CASES = [("0.5", "0.6"), ("0.875", "0.3125"), ("0.9999847412109375", "0.0625"), ("0.25", "0.9375"), ("0.99999999976716935634613037109375", "0.001953125")]


J0_CASES = [
    # nu, gap = 1 - M_R, k (exact binary fractions), chosen on both sides of the crate's
    # thresholds: eps <= 1/2 and k eps <= 1/2 (the pole at phi = pi/2 taken out), k^2 against
    # the working epsilon at f64, double-double and 128 bits (the peak at phi = 0 taken out)
    ("0.25", "0.5", "0.5"),
    ("0.25", "1", "0.25"),
    ("0.25", "0.125", "0.625"),
    ("0.25", "0.125", "1"),
    ("0.25", "0.125", "1.0625"),
    ("0.5", "2^-10", "0.0625"),
    ("-0.5", "2^-20", "2^-10"),
    ("0.4375", "2^-40", "2^-30"),
    ("-0.875", "2^-60", "2^-80"),
    ("0", "2^-120", "3"),
    ("0.25", "2^-30", "1000"),
    ("0.5", "2^-100", "2^-200"),
]


def parse(text):
    if text.startswith("2^"):
        return mp.mpf(2) ** int(text[2:])
    return mp.mpf(text)


def exact_decimal(text):
    """The exact decimal expansion of a binary fraction."""
    if not text.startswith("2^"):
        return text
    e = -int(text[2:])
    return mp.nstr(mp.mpf(2) ** -e, e + 10, strip_zeros=True) if e > 0 else str(2 ** -e)


def j0_integral(nu, gap, k):
    eps2 = gap * (2 - gap)
    eps = mp.sqrt(eps2)
    with mp.extradps(int(2 * -mp.log10(eps)) + 10 if eps < 1 else 10):
        g, m1 = material(nu)
        mr = 1 - gap
        half = mp.pi / 2
        # eps (the pole, at pi/2), k (the kernel's peak at 0 when k < 1) and 1/k (at pi/2 when
        # k > 1): each scale graded at both ends, which is harmless where it is not needed.
        pts = {mp.mpf(0), half}
        for scale in (eps, k, 1 / k):
            c = scale / 16
            while c < half:
                pts.update({c, half - c})
                c *= 4
        pts = sorted(pts)
        f = lambda ph: g_norm(nu, g, m1, mr * mp.sin(ph)) / mp.sqrt(k ** 2 * mp.cos(ph) ** 2 + mp.sin(ph) ** 2)
        return 2 * mp.quad(f, pts, maxdegree=10)


def main_j0():
    mp.mp.dps = 60
    print(f"# generated by tools/gen_integrals.py --j0 with mpmath {mp.__version__}, 40 digits")
    print("# nu,gap,k,J0  (gap = 1 - M_R; 2^-n written out exactly)")
    for nu, gap, k in J0_CASES:
        j0 = j0_integral(mp.mpf(nu), parse(gap), parse(k))
        print(f"{nu},{exact_decimal(gap)},{exact_decimal(k)},{mp.nstr(j0, DIGITS)}")


def main():
    print(f"# generated by tools/gen_integrals.py with mpmath {mp.__version__} at {mp.mp.dps} digits")
    print("# kind,nu,mr,k,I1_or_S,I2")
    for nu, mr, k in CASES:
        i1, i2 = integrals(mp.mpf(nu), mp.mpf(mr), mp.mpf(k))
        print(f"I,{nu},{mr},{k},{mp.nstr(i1, DIGITS)},{mp.nstr(i2, DIGITS)}")
    for mr, k in S_CASES:
        s = s_integral(mp.mpf(mr), mp.mpf(k))
        print(f"S,,{mr},{k},{mp.nstr(s, DIGITS)},")


if __name__ == "__main__":
    if "--j0" in sys.argv[1:]:
        main_j0()
    else:
        main()
