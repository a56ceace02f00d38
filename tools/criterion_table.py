#!/usr/bin/env python3
"""Markdown table of criterion medians for a bench whose groups are named <prefix>/<precision>.

Usage: python3 tools/criterion_table.py PREFIX
Reads target/criterion/<prefix>_<precision>/<bench>/new/estimates.json (criterion writes '/' as
'_'); rows are the benches, columns the precisions found (f64, dd, mpfrN ascending), each cell the
median with its ratio to f64 from the same run.
"""
import json
import os
import re
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "target", "criterion")


def median_ns(group, bench):
    path = os.path.join(ROOT, group, bench, "new", "estimates.json")
    with open(path) as fh:
        return json.load(fh)["median"]["point_estimate"]


def fmt(ns):
    if ns < 1e3:
        return f"{ns:.1f} ns"
    if ns < 1e6:
        return f"{ns / 1e3:.2f} µs"
    return f"{ns / 1e6:.2f} ms"


def order(prec):
    if prec == "f64":
        return (0, 0)
    if prec == "dd":
        return (1, 0)
    m = re.match(r"mpfr(\d+)", prec)
    return (2, int(m.group(1))) if m else (3, 0)


def main():
    prefix = sys.argv[1]
    # Only <prefix>_<precision>: "ellipse" must not pick up the "ellipse_wide_*" groups.
    groups = sorted(
        (
            g[len(prefix) + 1:]
            for g in os.listdir(ROOT)
            if g.startswith(prefix + "_") and re.fullmatch(r"f64|dd|mpfr\d+", g[len(prefix) + 1:])
        ),
        key=order,
    )
    benches = sorted({b for g in groups for b in os.listdir(os.path.join(ROOT, f"{prefix}_{g}")) if b != "report"})
    print("| bench | " + " | ".join(groups) + " |")
    print("|---" * (len(groups) + 1) + "|")
    for b in benches:
        cells = []
        base = None
        for g in groups:
            try:
                t = median_ns(f"{prefix}_{g}", b)
            except OSError:
                cells.append("—")
                continue
            if g == "f64":
                base = t
                cells.append(fmt(t))
            else:
                cells.append(fmt(t) + (f" (×{t / base:.0f})" if base else ""))
        print(f"| {b} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
