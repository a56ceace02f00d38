#!/usr/bin/env python3
"""Reference values of the moments L_n (39), M_n (41) and D_n = L_n - L_{n+1} of the paper.

Independent of the crate (no recursion): mpmath's hyp2f1 at 110 digits,

    M_n = W_n 2F1(1/2, 1/2; n+1; e2),  L_n = W_n 2F1(3/2, 1/2; n+1; e2),
    D_n = W_n/(2n+2) 2F1(3/2, 3/2; n+2; e2),   W_n = (pi/2) C(2n, n)/4^n,  e2 = 1 - k^2,

(term-by-term integration of (1 - e2 sin^2)^(-s) against cos^(2n) sin^(2j)), checked against
mpmath's tanh-sinh quadrature of (39), (41) at a few points (40 digits, agreement to 25), and against a rerun at 130 digits.
k^2 = mc is exactly representable in binary (so every precision reads the same input).

Usage: python3 tools/gen_moments.py > tests/data/moments_mpmath.csv
"""
from mpmath import mp, mpf, hyp2f1, binomial, pi, quad, cos, sin, nstr

DPS = 110
MCS = ["9.094947017729282379150390625e-13",  # 2^-40: k = 9.5e-7
       "9.5367431640625e-7",  # 2^-20
       "0.0009765625", "0.0625", "0.25", "0.375", "0.46875", "0.5", "0.53125", "0.625",
       "0.75", "0.9375", "0.984375", "1", "1.015625", "1.25", "1.75", "2", "4", "16", "100",
       "1048576", "1000000000000"]
NS = [0, 1, 2, 3, 4, 5, 7, 10, 17, 31, 56, 100, 178, 316, 562, 1000, 1778, 3162, 5623, 10000]


def mom(mc, n):
    e2 = 1 - mc
    w = pi / 2 * binomial(2 * n, n) / mpf(4) ** n
    m = w * hyp2f1(mpf(1) / 2, mpf(1) / 2, n + 1, e2)
    l = w * hyp2f1(mpf(3) / 2, mpf(1) / 2, n + 1, e2)
    d = w / (2 * n + 2) * hyp2f1(mpf(3) / 2, mpf(3) / 2, n + 2, e2)
    return m, l, d


def main():
    spot_checks()
    print("# mc = k^2, n, M_n, L_n, D_n = L_n - L_{n+1}; tools/gen_moments.py (mpmath hyp2f1, %d digits)" % DPS)
    for s in MCS:
        for n in NS:
            mp.dps = DPS
            mc = mpf(s)
            vals = mom(mc, n)
            mp.dps = DPS + 20
            check = mom(mpf(s), n)
            mp.dps = DPS
            for a, b in zip(vals, check):
                assert abs(a / b - 1) < mpf(10) ** (-DPS + 5), (s, n)
            print("%s,%d,%s" % (s, n, ",".join(nstr(v, 95, strip_zeros=False) for v in vals)))


def spot_checks():
    # Spot checks against quadrature (40 digits).
    mp.dps = 40
    for s in ["0.25", "1.75", "100", "1000000000000"]:
        mc = mpf(s)
        e2 = 1 - mc
        for n in [0, 3, 40]:
            m, l, d = mom(mc, n)
            # Breakpoints following the peak of width ~1/k at alpha = 0 when k is large.
            pts = [mpf(0)]
            b = 1 / mc.sqrt()
            while mc > 10 and b < 1:
                pts.append(b)
                b *= 2
            pts.append(pi / 2)
            mq = quad(lambda a: cos(a) ** (2 * n) / (1 - e2 * sin(a) ** 2) ** 0.5, pts)
            lq = quad(lambda a: cos(a) ** (2 * n) / (1 - e2 * sin(a) ** 2) ** 1.5, pts)
            dq = quad(lambda a: cos(a) ** (2 * n) * sin(a) ** 2 / (1 - e2 * sin(a) ** 2) ** 1.5, pts)
            for a, b in ((m, mq), (l, lq), (d, dq)):
                assert abs(a / b - 1) < mpf(10) ** -25, (s, n, a, b)


if __name__ == "__main__":
    main()
