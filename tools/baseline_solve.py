#!/usr/bin/env python3
"""What a user would script instead of moving-hertz: the ellipse solve (33) with scipy
(quad + brentq) and with mpmath (quad + findroot), timed on this machine, with the accuracy of k
measured against moving-hertz at 256 bits (called through its CLI, built in release mode).

The scripts are written as a careful user would: Gamma by (5)-(6) (normalisation irrelevant for
the ratio I2/I1), the Rayleigh root by brentq on (6), the integrals (34) over [0, pi] with a
breakpoint at pi/2, the root in k bracketed in [1e-6, 1e3].

Usage: python3 tools/baseline_solve.py [path/to/moving-hertz]
"""
import json
import statistics
import subprocess
import sys
import time

import mpmath as mp
import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

BIN = sys.argv[1] if len(sys.argv) > 1 else "target/release/moving-hertz"
CASES = [(0.2, 0.5, 0.5), (0.2, 0.9, 0.5), (0.2, 0.999, 0.5)]


def scipy_solve(nu, mr, ratio, tight=True):
    g = (1 - 2 * nu) / (2 * (1 - nu))
    R = lambda x: (2 - x) ** 2 - 4 * np.sqrt((1 - g * x) * (1 - x))
    m1 = brentq(R, 0.3, 0.999, xtol=1e-16, rtol=8.9e-16)

    def gamma(mre):
        x = m1 * mre * mre
        if x < 1e-8:
            return -(1 - nu) / np.pi
        return x * np.sqrt(1 - g * x) / (np.pi * R(x))

    def integrals(k):
        f1 = lambda ph: -gamma(mr * np.sin(ph)) * np.cos(ph) ** 2 / (k * k * np.cos(ph) ** 2 + np.sin(ph) ** 2) ** 1.5
        f2 = lambda ph: -gamma(mr * np.sin(ph)) * np.sin(ph) ** 2 / (k * k * np.cos(ph) ** 2 + np.sin(ph) ** 2) ** 1.5
        if tight:
            i1 = quad(f1, 0, np.pi, points=[np.pi / 2], limit=200, epsabs=0, epsrel=1.2e-14)[0]
            i2 = quad(f2, 0, np.pi, points=[np.pi / 2], limit=200, epsabs=0, epsrel=1.2e-14)[0]
        else:
            i1 = quad(f1, 0, np.pi, points=[np.pi / 2])[0]
            i2 = quad(f2, 0, np.pi, points=[np.pi / 2])[0]
        return i1, i2

    def F(lnk):
        i1, i2 = integrals(np.exp(lnk))
        return np.log(i2 / i1) - np.log(ratio)

    return np.exp(brentq(F, np.log(1e-6), np.log(1e3), xtol=1e-15, rtol=8.9e-16))


def mpmath_solve(nu, mr, ratio, dps=15):
    with mp.workdps(dps):
        nu, mr, ratio = mp.mpf(nu), mp.mpf(mr), mp.mpf(ratio)
        g = (1 - 2 * nu) / (2 * (1 - nu))
        R = lambda x: (2 - x) ** 2 - 4 * mp.sqrt((1 - g * x) * (1 - x))
        m1 = mp.findroot(R, (mp.mpf("0.3"), mp.mpf("0.999")), solver="anderson")

        def gamma(mre):
            x = m1 * mre * mre
            if x < mp.mpf(10) ** (-dps // 2):
                return -(1 - nu) / mp.pi
            return x * mp.sqrt(1 - g * x) / (mp.pi * R(x))

        def F(lnk):
            k = mp.exp(lnk)
            den = lambda ph: (k * k * mp.cos(ph) ** 2 + mp.sin(ph) ** 2) ** mp.mpf(1.5)
            i1 = mp.quad(lambda ph: -gamma(mr * mp.sin(ph)) * mp.cos(ph) ** 2 / den(ph), [0, mp.pi / 2, mp.pi])
            i2 = mp.quad(lambda ph: -gamma(mr * mp.sin(ph)) * mp.sin(ph) ** 2 / den(ph), [0, mp.pi / 2, mp.pi])
            return mp.log(i2 / i1) - mp.log(ratio)

        return mp.exp(mp.findroot(F, (mp.log(mp.mpf("0.05")), mp.log(mp.mpf("1"))), solver="anderson"))


def reference(nu, mr, ratio):
    out = subprocess.run([BIN, "ellipse", "--nu", str(nu), "--speed", str(mr), "--ratio", str(ratio),
                          "--precision", "256", "--json"], capture_output=True, text=True, check=True)
    return mp.mpf(json.loads(out.stdout)["k"])


def ours(nu, mr, ratio):
    out = subprocess.run([BIN, "ellipse", "--nu", str(nu), "--speed", str(mr), "--ratio", str(ratio),
                          "--repeat", "200", "--json"], capture_output=True, text=True, check=True)
    j = json.loads(out.stdout)
    return float(j["median_ns"]), mp.mpf(j["k"])


def timed(fn, reps):
    ts = []
    for _ in range(reps):
        t = time.perf_counter()
        v = fn()
        ts.append(time.perf_counter() - t)
    return statistics.median(ts), v


def main():
    mp.mp.dps = 80
    import warnings
    warnings.simplefilter("ignore")
    print("| M_R | moving-hertz f64: time, rel. error of k | scipy quad+brentq, default tolerances "
          "| scipy, tolerances 1.2e-14 | mpmath quad+findroot (15 digits) |")
    print("|---|---|---|---|---|")
    for nu, mr, ratio in CASES:
        ref = reference(nu, mr, ratio)
        t_ours, k_ours = ours(nu, mr, ratio)
        t_sd, k_sd = timed(lambda: scipy_solve(nu, mr, ratio, tight=False), 5)
        t_sp, k_sp = timed(lambda: scipy_solve(nu, mr, ratio), 5)
        t_mp, k_mp = timed(lambda: mpmath_solve(nu, mr, ratio), 1)
        err = lambda k: float(abs((mp.mpf(k) - ref) / ref))
        print(f"| {mr} | {t_ours / 1e3:.1f} µs, {err(k_ours):.1e} | {t_sd * 1e3:.2f} ms, {err(k_sd):.1e} "
              f"| {t_sp * 1e3:.2f} ms, {err(k_sp):.1e} "
              f"| {t_mp:.2f} s, {err(k_mp):.1e} |")


if __name__ == "__main__":
    main()
