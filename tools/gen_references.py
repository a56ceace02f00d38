#!/usr/bin/env python3
"""Independent references for the final results: k, e, I1, I2, J0 and the contact quantities.

Writes tests/data/references_arb.csv, read by tests/references.rs. Each row is one problem whose
inputs are exact in binary (dyadic rationals with at most 53 significant bits, written as their
exact decimal expansions): Poisson's ratio nu, the gap 1 - M_R, the ratio A1/B1 = R2/R1, the radii
R1, R2, the shear modulus mu, a load P and an approach d0. Its outputs, to 45 significant digits:

* k = b/a, the root of (33) A1/B1 = I2(k)/I1(k), and the eccentricity e = sqrt(1 - k^2)
  (k <= 1) or sqrt(1 - 1/k^2) (k > 1);
* I1, I2 (normalisation of (37): pi times the paper's (34)) and J0 of (32) at that k, each by its
  own quadrature (J0 is not formed from I1 and I2);
* for the load P: a, b, p0, d0; for the approach d0: a, b, p0, P (docs/theory.md, section 4):
  a^3 = 3 P I1/(8 pi mu B1), a^2 = d0 I1/(B1 J0), b = k a, p0 = 3P/(2 pi a b) = 4 mu a B1/(k I1),
  d0 = p0 b J0/(4 mu), P = (2/3) pi p0 a b, with A1 = 1/(2 R1), B1 = 1/(2 R2).

The engine is Arb (python-flint's acb.integral: rigorous enclosures; about 20 times faster here
than mpmath.quad, which takes 2-16 s for one pair I1, I2 at 50 digits), independent of the crate:

* g = -pi Gamma (g(0) = 1 - nu) from (5)-(6) rationalised, with the monic Rayleigh cubic
  P(x) = x^3 - 8x^2 + 8(3 - 2 gamma)x - 16(1 - gamma) (docs/theory.md) deflated at its root m1,
  P(x) = (x - m1)(x^2 + (m1 - 8)x + m1^2 - 8 m1 + 8(3 - 2 gamma)), and x - m1 written as
  -m1 (1 - M_R^2 + M_R^2 sin^2 alpha) so that the pole near alpha = 0 costs no digits:
  g = sqrt(1 - gamma x)[(2 - x)^2 + 4 sqrt((1 - gamma x)(1 - x))]/(-P(x)), x = m1 M_R^2 cos^2 alpha;
* the integrals (34) in alpha = pi/2 - phi over [0, pi/2] (doubled), split geometrically (ratio
  4) at the scales sqrt(1 - M_R^2) and 1/k near alpha = 0 and k near alpha = pi/2; the working
  precision raised by log2(1/(1 - M_R)) + 30 guard bits.

The ratio A1/B1 of a row is exact by construction: a target ratio 10^u (u uniform in [-6, 6], and
the ends +-6) is solved for k0 at low precision; k0 is rounded to 53 bits; the ratio
I2(k0)/I1(k0) at 120 bits rounded to 53 bits is the row's input; then two Newton steps from k0
(the second at the working precision, with I1', I2' by quadrature) give k, and I1, I2, J0 at k
follow from their values at the Newton point by one Taylor step (the step is below 1e-28 k, the
remainder below 1e-50: checked). The second step and all outputs are computed twice, at 155 and
at 185 bits, and the script stops unless the two agree to 1e-44 relative and each enclosure is
narrower than 1e-45 relative (the check of mpmath's "torture" tests).

Usage: python3 tools/gen_references.py > tests/data/references_arb.csv
       (python-flint >= 0.6; about 7 minutes of CPU time, 1.2 s a row on average). Rows can be
       made in parts, `python3 tools/gen_references.py 0,2,4,...`: each row draws from its own
       seeded generator, so a part writes the same rows as the whole run.
"""

import math
import random
import sys
import time
from fractions import Fraction as Fr

from flint import acb, arb, ctx

T0 = time.time()
ROWS = 320
DIGITS = 45
PRECS = (155, 185)  # the two working precisions (bits of the quadrature's tolerance)
NUS = ["-0.96875", "-0.5", "-0.125", "0", "0.125", "0.25", 0.3, "0.375", "0.4375",
       "0.4990234375", "0.5"]
GAPS = [1, 2**-1, 2**-2, 2**-4, 2**-7, 2**-10, 2**-14, 2**-20, 2**-27, 2**-34, 2**-40]
MUS = [3_500_000, 26_000_000_000, 80_000_000_000, 1]
LOADS = [1, 12.5, 1000, 65536, 1e6]
APPROACHES = [1e-3, 1e-5, 2**-20, 1e-7]


def exact(x):
    """Exact decimal expansion of a dyadic rational (Fraction, int or float)."""
    fr = Fr(x)
    den, n = fr.denominator, 0
    while den % 2 == 0:
        den //= 2
        n += 1
    assert den == 1, f"{x} is not dyadic"
    num = fr.numerator * 5**n
    sign = "-" if num < 0 else ""
    s = str(abs(num)).rjust(n + 1, "0")
    return sign + (s if n == 0 else s[:-n] + "." + s[-n:])


def exact_mid(x):
    """The midpoint of an arb as an exact Fraction."""
    m, e = x.mid().man_exp()
    return Fr(int(m)) * Fr(2) ** int(e)


def f53(x):
    """An arb rounded to the nearest float (53 bits), as an exact Fraction."""
    return Fr(float(x.mid()))


def ab(fr):
    """An exact Fraction as an arb at the current precision."""
    fr = Fr(fr)
    return arb(fr.numerator) / fr.denominator


class Problem:
    """nu and the gap 1 - M_R: the material's constants and the integrals at any k."""

    def __init__(self, nu, gap):
        self.nu, self.gap = Fr(nu), Fr(gap)

    def constants(self, prec):
        ctx.prec = prec + 30 + int(math.log2(1 / self.gap))
        nu = ab(self.nu)
        gam = (1 - 2 * nu) / (2 * (1 - nu))
        P = lambda x: ((x - 8) * x + 8 * (3 - 2 * gam)) * x - 16 * (1 - gam)
        dP = lambda x: (3 * x - 16) * x + 8 * (3 - 2 * gam)
        m1 = arb("0.9")
        for _ in range(400):
            new = arb((m1 - P(m1) / dP(m1)).mid())
            if new == m1:
                break
            m1 = new
        assert abs(P(m1)) < arb(2) ** (-ctx.prec + 8), "Rayleigh root"
        mr = 1 - ab(self.gap)
        return gam, m1, mr

    def integrals(self, k, prec, which, prec_d=None):
        """[I1, I2, I1', I2', J0] (the ones in `which`) at the exact k, to 2^-prec relative
        (derivatives to 2^-prec_d)."""
        gam, m1, mr = self.constants(prec)
        k = ab(k)
        k2 = k * k
        e2 = ab(self.gap * (2 - self.gap))  # 1 - M_R^2, exactly
        q0 = (m1 - 8) * m1 + 8 * (3 - 2 * gam)

        def g(c2, s2, an):
            x = m1 * mr * mr * c2
            a = 1 - gam * x
            num = a.sqrt(analytic=an) * ((2 - x) ** 2 + 4 * (a * (1 - x)).sqrt(analytic=an))
            return num / (m1 * (e2 + mr * mr * s2) * ((x + (m1 - 8)) * x + q0))

        def integrand(w):
            def fn(z, an):
                c, s = z.cos(), z.sin()
                c2, s2 = c * c, s * s
                d = c2 + k2 * s2
                v = 2 * g(c2, s2, an) / (d * d.sqrt(analytic=an))
                return [v * s2, v * c2, -3 * k * v * s2 * s2 / d, -3 * k * v * s2 * c2 / d, v * d][w]
            return fn

        pts = breakpoints(float(e2.sqrt().mid()), float(k.mid()))
        out = {}
        for w in which:
            p = prec if w in (0, 1, 4) or prec_d is None else prec_d
            tot = acb(0)
            for a, b in zip(pts[:-1], pts[1:]):
                tot += acb.integral(integrand(w), a, b, rel_tol=arb(2) ** (-p),
                                    eval_limit=10**7, deg_limit=4 * p)
            v = tot.real
            assert v.rad() < abs(v.mid()) * arb(2) ** (-p + 10), f"enclosure too wide: {v}"
            out[w] = v
        return out


def breakpoints(eps, k):
    half = arb.pi() / 2
    hf = float(half.mid())
    pts = {0.0}
    for scale, near_zero in ((eps, True), (1 / k, True), (k, False)):
        c = scale / 16
        while 0 < c < 1.2:
            pts.add(c if near_zero else hf - c)
            c *= 4
    return [arb(p) for p in sorted(pts) if p < hf] + [half]


def seed_k(pb, target):
    """k with I2/I1 = target to about 8 digits: secant in ln k at 64 bits."""
    def f(lk):
        v = pb.integrals(Fr(math.exp(lk)), 40, (0, 1))
        return math.log(float((v[1] / v[0]).mid())) - math.log(target)
    x0, x1 = 0.0, math.log(target) / 2
    f0, f1 = f(x0), f(x1)
    for _ in range(60):
        if abs(f1) < 1e-9 or f1 == f0:
            break
        x0, x1, f0 = x1, x1 - f1 * (x1 - x0) / (f1 - f0), f1
        x1 = max(min(x1, x0 + 3), x0 - 3)
        f1 = f(x1)
    assert abs(f1) < 1e-6, "seed"
    return Fr(math.exp(x1))


def newton(pb, k, ratio, prec, prec_d):
    """One Newton step for I2/I1 = ratio from the exact k: (step, integrals at k)."""
    v = pb.integrals(k, prec, (0, 1, 2, 3, 4) if prec_d else (0, 1, 2, 3), prec_d or 64)
    i1, i2, d1, d2 = v[0], v[1], v[2], v[3]
    f = i2 - ab(ratio) * i1
    df = d2 - ab(ratio) * d1
    return -f / df, v


def solve_row(pb, ratio, k0, prec):
    """k, I1, I2, J0 at the root of I2/I1 = ratio, from the Newton point k0 (exact)."""
    step, v = newton(pb, k0, ratio, prec, 110)
    assert abs(step) < ab(k0) * arb(2) ** -93, f"second step too large: {step}"
    k = ab(k0) + step
    i1 = v[0] + v[2] * step
    i2 = v[1] + v[3] * step
    j0 = v[4] - k * v[0] * step  # J0' = -k I1
    return k, i1, i2, j0


def contact(k, i1, j0, r1, r2, mu, load, approach):
    a1, b1 = 1 / (2 * ab(r1)), 1 / (2 * ab(r2))
    mu, pl, d = ab(mu), ab(load), ab(approach)
    pi = arb.pi()
    a = (3 * pl * i1 / (8 * pi * mu * b1)).root(3)
    b = k * a
    p0 = 3 * pl / (2 * pi * a * b)
    d0 = p0 * b * j0 / (4 * mu)
    aa = (d * i1 / (b1 * j0)).sqrt()
    ba = k * aa
    pa = 4 * mu * aa * b1 / (k * i1)
    la = 2 * pi * pa * aa * ba / 3
    assert abs(a1 * a * a + b1 * b * b - d0) < d0 * arb(2) ** -140, "d0 = A1 a^2 + B1 b^2"
    return [a, b, p0, d0, aa, ba, pa, la]


def ecc(k):
    return (1 - k * k).sqrt() if k <= 1 else (1 - 1 / (k * k)).sqrt()


def row(rng, nu, gap, u):
    pb = Problem(nu, gap)
    k00 = Fr(float(seed_k(pb, 10.0**u)))
    v0 = pb.integrals(k00, 120, (0, 1, 2, 3), 64)
    ratio = f53(v0[1] / v0[0])
    f = v0[1] - ab(ratio) * v0[0]
    df = v0[3] - ab(ratio) * v0[2]
    k0 = exact_mid(ab(k00) - f / df)  # exact, within ~1e-32 of the root
    r1 = Fr(2) ** rng.randint(-8, 2)
    r2 = ratio * r1
    mu, load, appr = rng.choice(MUS), Fr(rng.choice(LOADS)), Fr(rng.choice(APPROACHES))
    outs = []
    for prec in PRECS:
        k, i1, i2, j0 = solve_row(pb, ratio, k0, prec)
        outs.append([k, ecc(k), i1, i2, j0] + contact(k, i1, j0, r1, r2, mu, load, appr))
    for x, y in zip(*outs):
        assert abs(x - y) < abs(y) * arb(10) ** -44 + arb(10) ** -60, f"precisions disagree: {x} {y}"
        assert x.rad() < abs(x.mid()) * arb(10) ** -45 + arb(10) ** -60, f"wide: {x}"
    ins = [exact(Fr(nu)), exact(gap), exact(ratio), exact(r1), exact(r2), exact(mu), exact(load),
           exact(appr)]
    return ins + [y.mid().str(DIGITS, radius=False) for y in outs[1]]


def main():
    print("# generated by: python3 tools/gen_references.py > tests/data/references_arb.csv")
    print(f"# Arb (python-flint {__import__('flint').__version__}) at {PRECS[0]} and {PRECS[1]} bits, "
          f"agreeing to 1e-44; {DIGITS} digits")
    print("# nu,gap,ratio,r1,r2,mu,load,approach,k,e,i1,i2,j0,"
          "a_load,b_load,p0_load,d0_load,a_appr,b_appr,p0_appr,load_appr")
    rows = range(ROWS) if len(sys.argv) < 2 else [int(a) for a in sys.argv[1].split(',')]
    for i in rows:
        rng = random.Random(4500 + i)  # per row: any subset of rows reproduces the same rows
        nu = NUS[i % len(NUS)]
        gap = Fr(GAPS[(i // len(NUS) + i) % len(GAPS)])
        u = -6.0 if i % 40 == 0 else 6.0 if i % 40 == 20 else rng.uniform(-6, 6)
        print(",".join(row(rng, Fr(nu), gap, u)), flush=True)
        print(f"row {i} {time.time() - T0:.1f} s", file=sys.stderr, flush=True)


if __name__ == "__main__":
    main()
