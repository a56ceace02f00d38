#!/usr/bin/env python3
"""Independent sympy derivation of the crate's symbolic results (tests/symbolic.rs reads the output).

1. The Taylor coefficients F_n(nu) of g = -pi*Gamma in x = M2^2, from (5)-(6) AS PRINTED (not from
   the recurrence (36) nor the rationalised cubic):

       g(x) = -x sqrt(1 - gamma x) / R(x),   R(x) = (2 - x)^2 - 4 sqrt((1 - gamma x)(1 - x)),
       gamma = (1 - 2 nu)/(2 (1 - nu)),

   expanded as a power series in x with coefficients in the field Q(nu) (sympy's rational function
   field): the binomial series of sqrt(1 - t) comes from sympy.series, the products and the
   division by R(x)/x are exact truncated series arithmetic in Q(nu)[[x]].

2. L_n = int_0^{pi/2} cos^{2n} a / D^3 da (39) and M_n = int cos^{2n} a / D da (41), D^2 = 1 - m sin^2 a,
   m = e^2, reduced to K = K(m) and E = E(m) without the recursion (40):
     * T_j = int sin^{2j}/D: T_0 = K, T_1 = (K - E)/m (E = int D), and for j >= 1 the relation that
       sympy obtains by differentiating sin^{2j-1} cos D (its integral over [0, pi/2] vanishes);
     * M_n = sum_i C(n, i) (-1)^i T_i  (cos^2 = 1 - sin^2);
     * S_i = int sin^{2i}/D^3: S_{i+1} = 2 dT_i/dm, S_0 = K + 2 m dK/dm (1/D^3 = 1/D + m sin^2/D^3),
       with sympy's own derivatives of elliptic_k and elliptic_e;
     * L_n = sum_i C(n, i) (-1)^i S_i.

Output (tests/data/symbolic_reference.txt): one line per function,
    name|numerator|denominator
with the coefficient lists in ascending powers, as exact rationals p/q separated by spaces, in
lowest terms with a monic denominator (the canonical form of moving_hertz::symbolic::RatFunc).
Names: F_n (variable nu) for n <= 30; alpha_n, beta_n, gamma_n, delta_n (variable e2 = m) for
n <= 50, with L_n = alpha_n K + beta_n E and M_n = gamma_n K + delta_n E.

Usage: python3 tools/gen_symbolic.py > tests/data/symbolic_reference.txt   (about a minute)
"""
import sympy as sp
from sympy import QQ
from sympy.polys.fields import field

N_COEF = 30
N_MOM = 50


def canonical(name, f):
    """name|num|den of a field element f, denominator monic."""
    num, den = f.numer, f.denom
    lc = den.LC
    def lst(p):
        if p == 0:
            return ""
        d = dict(p.terms())
        deg = max(k[0] for k in d)
        vals = [QQ.convert(d.get((k,), 0)) / lc for k in range(deg + 1)]
        return " ".join(f"{sp.Rational(v.numerator, v.denominator)}" for v in vals)
    return f"{name}|{lst(num)}|{lst(den)}"


def sqrt_series(n):
    """Coefficients of sqrt(1 - t) up to t^(n-1), from sympy.series."""
    t = sp.Symbol("t")
    s = sp.series(sp.sqrt(1 - t), t, 0, n).removeO()
    return [sp.Rational(s.coeff(t, k)) for k in range(n)]


def green_coefficients(n):
    Fnu, nu = field("nu", QQ)
    one = Fnu(1)
    gamma = (1 - 2 * nu) / (2 * (1 - nu))
    b = [one * QQ(c.p, c.q) for c in sqrt_series(n + 2)]
    sg = [b[k] * gamma**k for k in range(n + 2)]  # sqrt(1 - gamma x)
    s1 = b  # sqrt(1 - x)
    def mul(a, c, m):
        return [sum((a[i] * c[k - i] for i in range(k + 1)), Fnu(0)) for k in range(m)]
    root = mul(sg, s1, n + 2)  # sqrt((1 - gamma x)(1 - x))
    sq = [Fnu(4), Fnu(-4), Fnu(1)] + [Fnu(0)] * n
    r = [sq[k] - 4 * root[k] for k in range(n + 2)]
    assert r[0] == 0
    r_over_x = r[1:]
    num = [-c for c in sg[: n + 1]]  # -x sqrt(1 - gamma x) / x
    q = []
    for k in range(n + 1):
        s = num[k] - sum((q[i] * r_over_x[k - i] for i in range(k)), Fnu(0))
        q.append(s / r_over_x[0])
    return q


def moment_forms(n):
    Fm, m = field("m", QQ)
    ms = sp.Symbol("m")
    # dK/dm, dE/dm as sympy gives them, as (coefficient of K, coefficient of E) in Q(m).
    Ks, Es = sp.symbols("K E")

    def kdiff(expr):
        d = sp.expand(sp.diff(expr, ms)).subs({sp.elliptic_k(ms): Ks, sp.elliptic_e(ms): Es})
        ck, ce = sp.cancel(d.coeff(Ks)), sp.cancel(d.coeff(Es))
        assert sp.simplify(d - ck * Ks - ce * Es) == 0
        return tuple(Fm.from_expr(c) if c != 0 else Fm(0) for c in (ck, ce))

    dK = kdiff(sp.elliptic_k(ms))
    dE = kdiff(sp.elliptic_e(ms))

    def d_dm(f):
        a, b = f
        return (a.diff(m) + a * dK[0] + b * dE[0], b.diff(m) + a * dK[1] + b * dE[1])

    # The relation for T_{j+1} from d/da[sin^{2j-1} cos D] = P_j(sin^2)/D, derived by sympy.
    al, mm = sp.symbols("alpha m")
    s_, c_, u = sp.symbols("s c u")
    def relation(j):
        D = sp.sqrt(1 - mm * sp.sin(al) ** 2)
        expr = sp.sin(al) ** (2 * j - 1) * sp.cos(al) * D
        num = sp.expand(sp.diff(expr, al) * D)
        num = num.subs({sp.sin(al): s_, sp.cos(al): c_})
        num = sp.expand(num.subs(c_**2, 1 - s_**2))
        num = sp.expand(num.subs(c_**2, 1 - s_**2))
        assert not num.has(c_), num
        p = sp.Poly(num.subs(s_, sp.sqrt(u)), u)
        return [Fm.from_expr(p.coeff_monomial(u**k)) if p.coeff_monomial(u**k) != 0 else Fm(0)
                for k in range(j + 2)]

    one, zero = Fm(1), Fm(0)
    T = [(one, zero), ((1 / m), -(1 / m))]
    for j in range(1, n + 1):
        c = relation(j)  # sum_k c_k T_k = 0, k = j-1, j, j+1
        assert all(ck == 0 for ck in c[: j - 1])
        a = -(c[j - 1] * T[j - 1][0] + c[j] * T[j][0]) / c[j + 1]
        b = -(c[j - 1] * T[j - 1][1] + c[j] * T[j][1]) / c[j + 1]
        T.append((a, b))
    S = [None] * (n + 2)
    dk = d_dm((one, zero))
    S[0] = (one + 2 * m * dk[0], 2 * m * dk[1])
    for i in range(n + 1):
        d = d_dm(T[i])
        S[i + 1] = (2 * d[0], 2 * d[1])
    out = []
    for k in range(n + 1):
        L = [zero, zero]
        M = [zero, zero]
        for i in range(k + 1):
            w = sp.binomial(k, i) * (-1) ** i
            for z in range(2):
                L[z] += S[i][z] * w
                M[z] += T[i][z] * w
        out.append((L, M))
    return out


def main():
    print("# generated by tools/gen_symbolic.py (sympy " + sp.__version__ + "): name|numerator|denominator,")
    print("# ascending coefficients, lowest terms, monic denominator; F_n in nu, alpha..delta in e2")
    for k, f in enumerate(green_coefficients(N_COEF)):
        print(canonical(f"F_{k}", f))
    for k, (L, M) in enumerate(moment_forms(N_MOM)):
        for name, f in (("alpha", L[0]), ("beta", L[1]), ("gamma", M[0]), ("delta", M[1])):
            print(canonical(f"{name}_{k}", f))


if __name__ == "__main__":
    main()
