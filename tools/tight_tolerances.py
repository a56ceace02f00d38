#!/usr/bin/env python3
"""Tolerances far below the f64 range, checked against Arb: `moving-hertz integrals --tol T`
(the precision chosen from the tolerance) for T = 1e-300, 1e-1000 and 1e-5000 at nu = 0.25,
M_R = 0.9990234375, k = 0.5, and the same I1, I2 by Arb's rigorous `acb.integral` 64 bits
above the precision the crate chose (the worker of tools/compare_arb_mpmath.py, the same
integrands).

For each tolerance: the precision and route the crate chose, its error estimates, the true
relative error of I1 and I2 against Arb, and whether true error <= estimate <= tolerance.
Writes docs/data/tight_tolerances.csv and prints it. (tests/choose.rs checks 1e-300 and 1e-1000
in `cargo test` against the crate's adaptive route; 1e-5000 needs 16,616 bits, minutes of work,
hence this committed output.)

Run from the repository root after `cargo build --release` (minutes; Arb's 16,680-bit pair is
most of it):
    python3 tools/tight_tolerances.py [--tols 1e-300,1e-1000,1e-5000]
Needs python-flint and mpmath (pip install python-flint mpmath gmpy2).
"""

import argparse
import csv
import json
import os
import subprocess
import sys

sys.set_int_max_str_digits(0)
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
BIN = os.path.join(ROOT, "target", "release", "moving-hertz")
OUT = os.path.join(ROOT, "docs", "data", "tight_tolerances.csv")
sys.path.insert(0, HERE)
from compare_arb_mpmath import K, MR, NU, python_worker  # noqa: E402


def rel_err(got, want, bits):
    """|got - want| / |want| of two decimal strings, as a decimal string (mpmath at bits)."""
    import mpmath as mp
    mp.mp.prec = bits
    x, y = mp.mpf(got), mp.mpf(want)
    return mp.nstr(abs(x - y) / abs(y), 3)


def le(a, b, bits):
    import mpmath as mp
    mp.mp.prec = bits
    return mp.mpf(a) <= mp.mpf(b)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tols", default="1e-300,1e-1000,1e-5000")
    ap.add_argument("--out", default=OUT)
    ap.add_argument("--bin", default=BIN)
    a = ap.parse_args()
    rows = []
    for tol in a.tols.split(","):
        out = subprocess.run([a.bin, "integrals", "--nu", NU, "--speed", MR, "--k", K,
                              "--tol", tol, "--json"], capture_output=True, text=True, check=True)
        r = json.loads(out.stdout)
        bits = int(r["bits"])
        ref = python_worker("arb", bits + 64, 7200)
        if ref is None:
            sys.exit(f"Arb at {bits + 64} bits timed out")
        row = {"tol": tol, "bits": bits, "route": r["route"]}
        ok = True
        for name, want in zip(("I1", "I2"), ref["I"]):
            err = rel_err(r[name], want, bits + 128)
            est = r[f"{name}_error"]
            row[f"{name}_error_estimate"] = est
            row[f"{name}_true_error"] = err
            ok &= le(err, est, bits + 128) and le(est, tol, bits + 128)
        row["true_le_estimate_le_tol"] = "yes" if ok else "NO"
        rows.append(row)
        print(row, file=sys.stderr)
    with open(a.out, "w", newline="") as fh:
        fh.write(f"# python3 tools/tight_tolerances.py --tols {a.tols}\n"
                 f"# nu = {NU}, M_R = {MR}, k = {K}; reference: Arb acb.integral 64 bits above "
                 "the crate's precision; errors are relative\n")
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    with open(a.out) as fh:
        print(fh.read())
    if any(r["true_le_estimate_le_tol"] != "yes" for r in rows):
        sys.exit(1)


if __name__ == "__main__":
    main()
