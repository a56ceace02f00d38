#!/usr/bin/env python3
"""Markdown tables of the fast-route bench (benches/fast_integrals.rs) for docs/performance.md.

Run after   cargo bench --bench fast_integrals -- --warm-up-time 0.5 --measurement-time 1
Reads target/criterion/<group>/<bench>/new/estimates.json (median point estimates).
"""

import os

from criterion_table import fmt, median_ns  # shared helpers (same directory)

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "target", "criterion")
PRECISIONS = ["f64", "dd", "mpfr128", "mpfr256"]
MRS = ["0.5", "0.9", "0.999", "1-1e-8"]
KS = ["0.01", "0.3", "1"]




def main():
    print("I1 and I2 (`integrals`, `Method::Fixed`) against `Method::Adaptive` (the precision's floor):")
    print("median, and in brackets adaptive / fast.\n")
    for p in PRECISIONS:
        print(f"**{p}**\n")
        print("| M_R \\ k | " + " | ".join(f"k = {k}" for k in KS) + " |")
        print("|---" * (len(KS) + 1) + "|")
        for m in MRS:
            cells = []
            for k in KS:
                f = median_ns(f"fast_{p}", f"fast_M={m},k={k}")
                a = median_ns(f"adaptive_{p}", f"adaptive_M={m},k={k}")
                cells.append(f"{fmt(f)} ({fmt(a)}, ×{a / f:.0f})")
            print(f"| {m} | " + " | ".join(cells) + " |")
        print()
    print("Cost per precision (median over the 12 cases of the ratio to f64):\n")
    print("| | " + " | ".join(PRECISIONS) + " |")
    print("|---" * (len(PRECISIONS) + 1) + "|")
    for kind, label in [("fast", "I1, I2"), ("fast_dk", "I1, I2, dI/dk")]:
        cells = []
        for p in PRECISIONS:
            vals = sorted(median_ns(f"fast_{p}", f"{kind}_M={m},k={k}") for m in MRS for k in KS)
            base = sorted(median_ns("fast_f64", f"{kind}_M={m},k={k}") for m in MRS for k in KS)
            ratios = sorted(
                median_ns(f"fast_{p}", f"{kind}_M={m},k={k}")
                / median_ns("fast_f64", f"{kind}_M={m},k={k}")
                for m in MRS
                for k in KS
            )
            mid = vals[len(vals) // 2]
            r = ratios[len(ratios) // 2]
            cells.append(fmt(mid) if p == "f64" else f"{fmt(mid)} (×{r:.0f})")
            del base
        print(f"| {label}, median of cases | " + " | ".join(cells) + " |")
    def setup_ns(p, m):
        return median_ns(f"fast_{p}", f"fast_dk_M={m},k=0.3") - median_ns(f"fast_{p}", f"at_dk_M={m},k=0.3")

    for kind, label in [("setup", "set-up (fast_dk − at_dk)"), ("at_dk", "Evaluator::at with dI/dk")]:
        cells = []
        for p in PRECISIONS:
            if kind == "setup":
                vals = [setup_ns(p, m) for m in MRS]
                base = [setup_ns("f64", m) for m in MRS]
            else:
                vals = [median_ns(f"fast_{p}", f"at_dk_M={m},k=0.3") for m in MRS]
                base = [median_ns("fast_f64", f"at_dk_M={m},k=0.3") for m in MRS]
            mid = sorted(vals)[len(vals) // 2]
            r = sorted(v / b for v, b in zip(vals, base))[len(vals) // 2]
            cells.append(fmt(mid) if p == "f64" else f"{fmt(mid)} (×{r:.0f})")
        print(f"| {label} | " + " | ".join(cells) + " |")
    print()
    worst = max(median_ns("fast_f64", f"fast_M={m},k={k}") for m in MRS for k in KS)
    print(f"Slowest f64 case of the fixed rule at a new speed: {fmt(worst)} (target 300 ns).")


if __name__ == "__main__":
    main()
