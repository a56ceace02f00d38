#!/usr/bin/env python3
"""Ellipse-solve timings over a grid of curvature ratios and speeds, from the CLI.

Usage: python3 tools/ellipse_grid.py [--precision f64|dd|BITS] [--rounds N] [--repeat N]
           [--ratios "2 10 100 1e3 1e4 1e6"] [--speeds "0 0.9 0.99 0.9999"] [--nu 0.2]

Runs `moving-hertz ellipse ... --repeat N --json` (release build, target/release) for every
(ratio, speed) cell, `--rounds` times, cells interleaved so that a disturbance of the shared
machine hits every cell alike, and prints a Markdown table of the best `min_ns` of the rounds,
with k and the error estimate. A complement to the criterion benches (benches/ellipse.rs,
benches/graded.rs), which cover fewer cells; quote its figures as minima of one run.
"""
import argparse
import json
import os
import subprocess

from criterion_table import fmt  # same directory: the time formatter of the bench tables

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
BIN = os.path.join(ROOT, "target", "release", "moving-hertz")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--precision", default="f64")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--repeat", type=int, default=1000)
    ap.add_argument("--ratios", default="2 10 100 1e3 1e4 1e6")
    ap.add_argument("--speeds", default="0 0.9 0.99 0.9999")
    ap.add_argument("--nu", default="0.2")
    a = ap.parse_args()
    ratios, speeds = a.ratios.split(), a.speeds.split()
    best, info = {}, {}
    for _ in range(a.rounds):
        for r in ratios:
            for s in speeds:
                out = subprocess.run(
                    [BIN, "ellipse", "--nu", a.nu, "--speed", s, "--ratio", r,
                     "--precision", a.precision, "--repeat", str(a.repeat), "--json"],
                    capture_output=True, text=True, check=True).stdout
                d = json.loads(out)
                best[(r, s)] = min(best.get((r, s), float("inf")), float(d["min_ns"]))
                info[(r, s)] = (float(d["k"]), float(d["error_estimate"]))
    print(f"ellipse solve at {a.precision}, nu = {a.nu}: best min_ns of {a.rounds} rounds "
          f"of --repeat {a.repeat} (k, relative error estimate)\n")
    print("| A1/B1 | " + " | ".join(f"M_R = {s}" for s in speeds) + " |")
    print("|---" * (len(speeds) + 1) + "|")
    for r in ratios:
        cells = [f"{fmt(best[(r, s)])} (k = {info[(r, s)][0]:.3g}, {info[(r, s)][1]:.1e})"
                 for s in speeds]
        print(f"| {r} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
