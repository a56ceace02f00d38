#!/usr/bin/env python3
"""The ellipse solve at the ends of the supported curvature ratios (docs/calibration.md,
`RATIO_RANGE` and `EXTREME_K_EPS`): k at f64 and double-double against the 256-bit solve of the
same decimal inputs, over nu, the gap 1 - M_R and A1/B1 = 1e+-20 ... 1e+-100. Prints every case
whose error exceeds half its bound, and marks BAD those above it.

Usage (from the repository root, after `cargo build --release`):

    python3 tools/scan_extreme_ratios.py [NUS] [RATIOS]
"""
import json
import subprocess
import sys

from mpmath import mp, mpf

mp.prec = 300
BIN = "target/release/moving-hertz"
NUS = sys.argv[1] if len(sys.argv) > 1 else "0.2,-0.9,0.5,0.4994206"
RATIOS = sys.argv[2] if len(sys.argv) > 2 else \
    "1e-100,1e-80,1e-60,1e-40,1e-30,1e-20,1e20,1e30,1e40,1e60,1e80,1e100"
GAPS = ["0.5", "1e-3", "1e-10", "1e-15"]


def solve(nu, gap, ratio, precision):
    """(k, its bound) or (None, the error line)."""
    out = subprocess.run([BIN, "ellipse", "--nu", nu, "--gap", gap, "--ratio", ratio,
                          "--precision", precision, "--json"], capture_output=True, text=True)
    if out.returncode:
        return None, out.stderr.strip()
    v = json.loads(out.stdout)
    return mpf(v["k"]), float(v["k_error"])


def main():
    worst = 0.0
    for nu in NUS.split(","):
        for gap in GAPS:
            for ratio in RATIOS.split(","):
                want, _ = solve(nu, gap, ratio, "256")
                for precision in ["f64", "dd"]:
                    got, bound = solve(nu, gap, ratio, precision)
                    if got is None:
                        print("ERR", nu, gap, ratio, precision, bound)
                        continue
                    err = float(abs((got - want) / want))
                    worst = max(worst, err / bound)
                    if err > 0.5 * bound:
                        flag = "BAD" if err > bound else ""
                        print(f"{nu} {gap} {ratio} {precision}: error {err:.2e} bound {bound:.2e} {flag}")
    print(f"worst error / bound: {worst:.2f}")


if __name__ == "__main__":
    main()
