#!/usr/bin/env python3
"""Markdown tables of criterion medians for docs/performance.md.

Run after   cargo bench --bench precision_cost -- --warm-up-time 1 --measurement-time 3
      and   cargo bench --bench generic_cost -- --warm-up-time 1 --measurement-time 3
Reads target/criterion/<group>/<bench>/new/estimates.json (median point estimates).

`python3 tools/bench_table.py series` prints instead the table of the series bench
(after `cargo bench --bench series -- --warm-up-time 1 --measurement-time 2`).
"""

import os

from criterion_table import fmt, median_ns  # shared helpers (same directory)
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "target", "criterion")
PRECISIONS = ["f64", "dd", "mpfr64", "mpfr128", "mpfr256", "mpfr1024"]
FUNCS = ["ellipk_m=0.7", "ellipe_m=0.7", "ellipk_mc_mc=1e-12", "ellipe_mc_mc=1e-12",
         "ellipke_mc_mc=1e-12", "ellipf_phi=1.25,m=0.7", "ellipe_inc_phi=1.25,m=0.7"]




def main():
    print("| function | " + " | ".join(PRECISIONS) + " |")
    print("|---" * (len(PRECISIONS) + 1) + "|")
    for f in FUNCS:
        base = median_ns("f64", f)
        cells = []
        for p in PRECISIONS:
            t = median_ns(p, f)
            cells.append(fmt(t) if p == "f64" else f"{fmt(t)} (×{t / base:.0f})")
        print(f"| `{f.replace('_m=', '` m=').replace('_mc=', '` mc=').replace('_phi=', '` φ=')} | "
              + " | ".join(cells) + " |")
    print()
    print("| case | generic over `T: Real` at f64 | hand-written f64 | ratio |")
    print("|---|---|---|---|")
    for kind, a, b in [("kernel", "generic", "hand"), ("ellipk_mc", "library", "hand")]:
        for case in ["mc=0.3", "mc=1e-12"]:
            g = median_ns("generic_cost", f"{kind}_{a}_{case}")
            h = median_ns("generic_cost", f"{kind}_{b}_{case}")
            print(f"| {kind} ({a}), {case} | {fmt(g)} | {fmt(h)} | {g / h:.2f} |")


SERIES_PRECISIONS = ["f64", "dd", "mpfr128", "mpfr256"]
SERIES_BENCHES = [
    ("f_n_n=100", "f_0 … f_100 (35)–(36)"),
    ("f_n_n=1000", "f_0 … f_1000"),
    ("moments_n=1000,k2=0.25", "M_n, L_n, D_n, n ≤ 1000, k² = 1/4 (forward)"),
    ("moments_n=1000,k2=0.75", "M_n, L_n, D_n, n ≤ 1000, k² = 3/4 (backward, ₂F₁ in e²)"),
    ("moments_n=1000,k2=4", "M_n, L_n, D_n, n ≤ 1000, k² = 4 (backward, cos² expansion)"),
    ("integrals_M_R=0.5", "I1 and I2 by (37), M_R = 0.5"),
    ("integrals_M_R=0.9", "I1 and I2 by (37), M_R = 0.9"),
]


def series_table():
    print("| benchmark | " + " | ".join(SERIES_PRECISIONS) + " |")
    print("|---" * (len(SERIES_PRECISIONS) + 1) + "|")
    for key, label in SERIES_BENCHES:
        base = median_ns("series-f64", key)
        cells = []
        for p in SERIES_PRECISIONS:
            t = median_ns("series-" + p, key)
            cells.append(fmt(t) if p == "f64" else f"{fmt(t)} (×{t / base:.0f})")
        print(f"| {label} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    if sys.argv[1:] == ["series"]:
        series_table()
    else:
        main()
