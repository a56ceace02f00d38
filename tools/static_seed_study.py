#!/usr/bin/env python3
"""The first Newton step of the f64 ellipse solve (33) on the 12 cells of the cost target
(nu = 0.25, M_R in {0.5, 0.99, 0.999, 0.9999} x A1/B1 in {0.01, 0.5, 2}) from three starts:
Hamrock & Brewe's static seed (the solve's), the exact static root (I2/I1 at rest in closed
form from K and E, (43): I2/I1 = k^2 (K - E)/(E - k^2 K), m = 1 - k^2), and a step on the static
model fitted to F and F' at the seed (F = F_static + c + d (lambda - lambda0)). Prints the
error in lambda = ln k of each start and of the iterate after one step (docs/calibration.md,
"The static seed").

Run from the repository root after `cargo build --release`:
    python3 tools/static_seed_study.py [target/release/moving-hertz]
(needs mpmath; about a minute).
"""
import json
import math
import subprocess
import sys

from mpmath import diff, ellipk, ellipe, findroot, log, mp

mp.dps = 30
BIN = sys.argv[1] if len(sys.argv) > 1 else "target/release/moving-hertz"


def residual(nu, mr, lam, ratio):
    """F = ln(I2/(I1 A1/B1)) and F' = dF/d(ln k) by the crate's f64 fixed rules."""
    k = math.exp(lam)
    out = subprocess.run(
        [BIN, "integrals", "--nu", str(nu), "--speed", str(mr), "--k", repr(k),
         "--derivatives", "--json"],
        capture_output=True, text=True, check=True).stdout
    o = json.loads(out)
    i1, i2, d1, d2 = (float(o[x]) for x in ("I1", "I2", "dI1_dk", "dI2_dk"))
    return math.log(i2 / i1 / ratio), k * (d2 / i2 - d1 / i1)


def static_f(lam):
    """ln(I2/I1) at rest, (43)."""
    k = mp.e ** lam
    m = 1 - k * k
    kk, ee = ellipk(m), ellipe(m)
    return log(k * k * (kk - ee) / (ee - k * k * kk))


def main():
    print("# M_R A1/B1 root_k | start: error of the start, after a Newton step, after the model step")
    for mr in (0.5, 0.99, 0.999, 0.9999):
        for ratio in (0.01, 0.5, 2.0):
            hb = math.log(ratio ** (2 / math.pi))
            lam = hb
            for _ in range(8):
                f, d = residual(0.25, mr, lam, ratio)
                lam -= f / d
            root = lam
            exact = float(findroot(lambda x: static_f(x) - log(ratio), hb))
            cols = []
            for name, l0 in (("H&B", hb), ("static", exact)):
                f0, d0 = residual(0.25, mr, l0, ratio)
                newton = l0 - f0 / d0
                c = f0 - (float(static_f(l0)) - math.log(ratio))
                d = d0 - float(diff(static_f, l0))
                model = float(findroot(
                    lambda x, c=c, d=d, l0=l0: static_f(x) - log(ratio) + c + d * (x - l0), newton))
                cols.append(f"{name}: {l0 - root:+.2e} {newton - root:+.2e} {model - root:+.2e}")
            print(f"{mr} {ratio} {math.exp(root):.4f} | " + " | ".join(cols))


if __name__ == "__main__":
    main()
