#!/usr/bin/env python3
"""The cost of precision beside Arb and mpmath: I1, I2 of (34) in the normalisation of (37)
(see src/routes/mod.rs) at nu = 0.25, M_R = 0.9990234375, k = 0.5, and the ellipse solve (33)
at A1/B1 = 2, from 256 to 8192 bits.

For each precision, in rounds that alternate the tools (crate, Arb, mpmath, crate, Arb, ...):

* the crate, cold: one `moving-hertz integrals ... --precision BITS` and one
  `moving-hertz ellipse ... --ratio 2 --precision BITS` in a fresh process each (wall time);
* the crate, warm: `ellipse ... --repeat N --json` (the median of N solves after the first);
* Arb (python-flint `acb.integral`, rigorous) and mpmath (`quad`, tanh-sinh, gmpy2 backend):
  the same I1, I2 over alpha in [0, pi/2] with breakpoints at eps, 4 eps, pi/4
  (eps = sqrt(1 - M_R^2), the width of the Rayleigh peak), computed twice in a fresh process:
  the first pair is "cold" (wall time of the process up to it, imports included), the second
  "warm".

Every tool's I1, I2 are checked against the crate's to its working precision, and at the
highest precision the ellipse's k against the k of the precision below (it must agree to the
lower precision). Writes docs/data/precision_scaling.csv (times in seconds: the minimum over
the rounds) and prints the table.

Run from the repository root after `cargo build --release`:
    python3 tools/compare_arb_mpmath.py [--rounds 2] [--bits 256,512,...] [--mpmath-max 8192]
                                        [--bin target/release/moving-hertz]
Needs python-flint, mpmath and gmpy2 (pip install python-flint mpmath gmpy2).
"""

import argparse
import csv
import json
import os
import subprocess
import sys
import time

sys.set_int_max_str_digits(0)  # decimal strings of 8192-bit numbers
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
BIN = os.path.join(ROOT, "target", "release", "moving-hertz")
OUT = os.path.join(ROOT, "docs", "data", "precision_scaling.csv")
NU, MR, K, RATIO = "0.25", "0.9990234375", "0.5", "2"


# ---------------------------------------------------------------------------------------------
# The integrands, written once for both libraries (a worker process runs one of them)

def worker_mpmath(bits):
    """I1, I2 by mpmath's quad at `bits` (+ 20 guard bits), twice; prints JSON."""
    t0 = time.perf_counter()
    import mpmath as mp
    assert mp.libmp.BACKEND == "gmpy", "mpmath must run on gmpy2 (pip install gmpy2)"

    def pair():
        mp.mp.prec = bits + 20
        nu, mr, k = mp.mpf(NU), mp.mpf(MR), mp.mpf(K)
        gam = (1 - 2 * nu) / (2 * (1 - nu))
        m1 = mp.findroot(lambda x: x**3 - 8 * x**2 + 8 * (3 - 2 * gam) * x - 16 * (1 - gam),
                         mp.mpf("0.9"))
        s, q = 8 - m1, 8 / ((1 - nu) * m1)

        def g(t):  # g = pi G/(1 - t), G of (45)
            x = m1 * t
            a = 1 - gam * x
            d = (2 - x) ** 2 + 4 * mp.sqrt(a * (1 - x))
            return mp.sqrt(a) * d / (m1 * (x * (x - s) + q)) / (1 - t)

        def f(al, which):
            c2 = mp.cos(al) ** 2
            s2 = 1 - c2
            d = c2 + k * k * s2
            return 2 * g(mr * mr * c2) * (s2 if which == 1 else c2) / (d * mp.sqrt(d))

        eps = mp.sqrt(1 - mr * mr)
        pts = [0, eps, 4 * eps, mp.pi / 4, mp.pi / 2]
        return [mp.quad(lambda a: f(a, w), pts) for w in (1, 2)]

    first = pair()
    cold = time.perf_counter() - t0
    t1 = time.perf_counter()
    pair()
    warm = time.perf_counter() - t1
    digits = int(bits * 0.30103) + 5
    print(json.dumps({"cold": cold, "warm": warm,
                      "I": [mp.nstr(v, digits, min_fixed=-1, max_fixed=-1) for v in first]}))


def worker_arb(bits):
    """I1, I2 by Arb's acb.integral (rigorous) at `bits` (+ 20 guard bits), twice."""
    t0 = time.perf_counter()
    from flint import acb, arb, ctx

    def pair():
        ctx.prec = bits + 20
        nu, mr, k = arb(NU), arb(MR), arb(K)
        gam = (1 - 2 * nu) / (2 * (1 - nu))
        m1 = arb("0.9126")
        for _ in range(40):  # Newton on the Rayleigh cubic, midpoints only
            f = m1**3 - 8 * m1**2 + 8 * (3 - 2 * gam) * m1 - 16 * (1 - gam)
            df = 3 * m1**2 - 16 * m1 + 8 * (3 - 2 * gam)
            m1 = arb((m1 - f / df).mid())
        s, q = 8 - m1, 8 / ((1 - nu) * m1)

        def integrand(which):
            def fn(z, analytic):
                c = z.cos()
                c2 = c * c
                s2 = 1 - c2
                t = mr * mr * c2
                x = m1 * t
                a = 1 - gam * x
                d = (2 - x) ** 2 + 4 * (a * (1 - x)).sqrt(analytic=analytic)
                g = a.sqrt(analytic=analytic) * d / (m1 * (x * (x - s) + q)) / (1 - t)
                dd = c2 + k * k * s2
                return 2 * g * (s2 if which == 1 else c2) / (dd * dd.sqrt(analytic=analytic))
            return fn

        eps = (1 - mr * mr).sqrt()
        pts = [arb(0), eps, 4 * eps, arb.pi() / 4, arb.pi() / 2]
        out = []
        for w in (1, 2):
            tot = acb(0)
            for a, b in zip(pts[:-1], pts[1:]):
                tot += acb.integral(integrand(w), a, b, rel_tol=arb(2) ** (-bits))
            out.append(tot.real)
        return out

    first = pair()
    cold = time.perf_counter() - t0
    t1 = time.perf_counter()
    pair()
    warm = time.perf_counter() - t1
    digits = int(bits * 0.30103) + 5
    print(json.dumps({"cold": cold, "warm": warm,
                      "I": [v.mid().str(digits, radius=False) for v in first]}))


# ---------------------------------------------------------------------------------------------
# The driver

def run(cmd, timeout):
    t = time.perf_counter()
    out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, check=True)
    return time.perf_counter() - t, out.stdout


def crate_integrals(bits, timeout):
    wall, out = run([BIN, "integrals", "--nu", NU, "--speed", MR, "--k", K,
                     "--precision", str(bits), "--json"], timeout)
    r = json.loads(out)
    return wall, [r["I1"], r["I2"]], int(r["work"])


def crate_ellipse(bits, repeat, timeout):
    args = [BIN, "ellipse", "--nu", NU, "--speed", MR, "--ratio", RATIO,
            "--precision", str(bits), "--json"]
    wall, out = run(args, timeout)
    cold_k = json.loads(out)["k"]
    _, out = run(args + ["--repeat", str(repeat)], timeout * (repeat + 1))
    r = json.loads(out)
    return wall, float(r["median_ns"]) * 1e-9, cold_k


def python_worker(tool, bits, timeout):
    t = time.perf_counter()
    try:
        out = subprocess.run([sys.executable, os.path.abspath(__file__), "--worker", tool,
                              str(bits)], capture_output=True, text=True, timeout=timeout,
                             check=True)
    except subprocess.TimeoutExpired:
        return None
    r = json.loads(out.stdout.strip().splitlines()[-1])
    r["wall"] = time.perf_counter() - t
    return r


def rel_diff_bits(a, b, bits):
    """-log2 of the relative difference of two decimal strings, at `bits` + 64 bits."""
    import mpmath as mp
    mp.mp.prec = bits + 64
    x, y = mp.mpf(a), mp.mpf(b)
    d = abs(x - y) / abs(y)
    return float("inf") if d == 0 else float(-mp.log(d, 2))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--bits", default="256,512,1024,2048,4096,8192")
    ap.add_argument("--mpmath-max", type=int, default=8192,
                    help="skip mpmath above this precision")
    ap.add_argument("--timeout", type=float, default=3600)
    ap.add_argument("--out", default=OUT)
    ap.add_argument("--bin", default=BIN, help="the moving-hertz binary (release build)")
    a = ap.parse_args()
    globals()["BIN"] = a.bin
    bits_list = [int(b) for b in a.bits.split(",")]
    rows, k_by_bits = [], {}
    for bits in bits_list:
        best = {}
        agree = {}
        repeat = 20 if bits <= 1024 else (5 if bits <= 4096 else 3)

        def keep(name, v):
            if v is not None:
                best[name] = min(best.get(name, v), v)

        for rnd in range(a.rounds):
            wall, vals, work = crate_integrals(bits, a.timeout)
            keep("crate_integrals_cold", wall)
            wall, warm, k = crate_ellipse(bits, repeat, a.timeout)
            keep("crate_ellipse_cold", wall)
            keep("crate_ellipse_warm", warm)
            k_by_bits[bits] = k
            for tool in ("arb", "mpmath"):
                if tool == "mpmath" and bits > a.mpmath_max:
                    continue
                r = python_worker(tool, bits, a.timeout)
                if r is None:
                    continue
                keep(f"{tool}_cold", r["cold"])
                keep(f"{tool}_warm", r["warm"])
                agree[tool] = min(rel_diff_bits(r["I"][i], vals[i], bits) for i in range(2))
            print(f"{bits} bits, round {rnd + 1}: " +
                  ", ".join(f"{n} {v:.3f} s" for n, v in sorted(best.items())), flush=True)
        row = {"bits": bits, "fixed_rule_nodes": work}
        row.update({n: f"{v:.4g}" for n, v in best.items()})
        for tool in ("arb", "mpmath"):
            if f"{tool}_cold" in best:
                row[f"integrals_cold_vs_{tool}"] = (
                    f"{best['crate_integrals_cold'] / best[f'{tool}_cold']:.3g}")
                row[f"{tool}_agrees_bits"] = f"{agree[tool]:.0f}"
        row["ellipse_cold_over_warm"] = (
            f"{best['crate_ellipse_cold'] / best['crate_ellipse_warm']:.3g}")
        rows.append(row)
    base = next((r for r in rows if r["bits"] == 256), None)
    for r in rows:
        if base:
            r["ellipse_warm_over_256"] = (
                f"{float(r['crate_ellipse_warm']) / float(base['crate_ellipse_warm']):.4g}")
    # k at each precision against the precision below (to the lower one's bits).
    for lo, hi in zip(bits_list, bits_list[1:]):
        for r in rows:
            if r["bits"] == hi:
                r["k_agrees_with_lower_bits"] = f"{rel_diff_bits(k_by_bits[hi], k_by_bits[lo], lo):.0f}"
    cols = ["bits", "fixed_rule_nodes", "crate_integrals_cold", "arb_cold", "arb_warm",
            "mpmath_cold", "mpmath_warm", "integrals_cold_vs_arb", "integrals_cold_vs_mpmath",
            "crate_ellipse_cold", "crate_ellipse_warm", "ellipse_cold_over_warm",
            "ellipse_warm_over_256", "k_agrees_with_lower_bits", "arb_agrees_bits",
            "mpmath_agrees_bits"]
    with open(a.out, "w", newline="") as fh:
        shown, skip = [], False
        for arg in sys.argv[1:]:  # the command without the local paths
            if skip or arg in ("--bin", "--out"):
                skip = not skip
                continue
            shown.append(arg)
        fh.write("# python3 tools/compare_arb_mpmath.py " + " ".join(shown) + "\n")
        cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo")
                    if l.startswith("model name")), "unknown")
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                                capture_output=True, text=True).stdout.strip() or "unknown"
        day = time.strftime("%Y-%m-%d", time.gmtime())
        fh.write(f"# commit {commit}, {day}, {cpu}, {os.cpu_count()} cores shared with other jobs; "
                 "ratios are within one run, the tools alternating\n")
        fh.write("# times in seconds (minimum over the rounds); cold = a fresh process; "
                 "*_agrees_bits = -log2 of the relative difference from the crate's I1, I2; "
                 "k_agrees_with_lower_bits = the same for k against the precision below\n")
        w = csv.DictWriter(fh, fieldnames=cols, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r)
    with open(a.out) as fh:
        print(fh.read())


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--worker":
        {"arb": worker_arb, "mpmath": worker_mpmath}[sys.argv[2]](int(sys.argv[3]))
    else:
        main()
