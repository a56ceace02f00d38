#!/usr/bin/env python3
"""The Python package against the crate it wraps (the targets of the Python package's issue),
as ratios measured in one run on this machine; writes docs/data/python_bench.txt.

1. One f64 solve_ellipse called from Python (call and result included) against the crate's
   warm solve (`moving-hertz ellipse --repeat 1000`: the median of 1000 in-process solves),
   interleaved round by round, the median of each.
2. sweep_ellipses at f64 over 10^6 points, per point, against `sweep::ellipses` over the same
   10^6 points on the same number of threads (examples/sweep_cost.rs on a warm pool), back to
   back round by round, and the memory the Python sweep takes beyond its output arrays (peak
   RSS of a fresh process).
3. The same sweep against a vectorised numpy Gauss-Legendre + Newton sweep (what a user would
   write: 96 nodes on [0, pi/2], Newton in ln k), per point, with the correct digits of each
   against the crate at 256 bits.
4. moving_hertz.dask over a 256-bit grid of 10^4 points on a LocalCluster of 2 worker
   processes against one.

Run from the repository root with the test environment (bash tools/test.sh makes it):
    target/pyenv/bin/python tools/python_bench.py
"""

import json
import os
import pathlib
import resource
import subprocess
import sys
import time

import numpy as np

import moving_hertz as mh

ROOT = pathlib.Path(__file__).resolve().parents[1]
CLI = ROOT / "target" / "release" / "moving-hertz"
SWEEP_COST = ROOT / "target" / "release" / "examples" / "sweep_cost"
OUT = ROOT / "docs" / "data" / "python_bench.txt"
NU, MR, RATIO = 0.25, 0.9990234375, 2.0
THREADS = 2


def build():
    if not CLI.exists() or not SWEEP_COST.exists():
        subprocess.run(["cargo", "build", "--release", "--bin", "moving-hertz", "--example",
                        "sweep_cost"], cwd=ROOT, check=True)


def median_ns(fn, n=2000):
    """The median of ``n`` calls each timed alone (a preempted call is one sample, not a
    share of the total: the machine is shared)."""
    clock = time.perf_counter_ns
    times = []
    for _ in range(n):
        t = clock()
        fn()
        times.append(clock() - t)
    return sorted(times)[n // 2]


def median(xs):
    return sorted(xs)[len(xs) // 2]


ROUNDS = 15


def single_solve(lines):
    """ROUNDS interleaved rounds, each the CLI's median of 1000 warm solves then the median of
    2000 Python calls; the median of each series, and the spread of the rounds' ratios."""
    args = [str(CLI), "ellipse", "--nu", str(NU), "--speed", str(MR), "--ratio", str(RATIO),
            "--repeat", "1000", "--json"]
    rust, py = [], []
    call = lambda: mh.solve_ellipse(NU, speed=MR, ratio=RATIO)  # noqa: E731
    median_ns(call, 2000)  # warm: the first call builds the rules
    for _ in range(ROUNDS):
        out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
        rust.append(float(json.loads(out)["median_ns"]))
        py.append(median_ns(call))
    ratios = sorted(p / r for p, r in zip(py, rust))
    rust, py = median(rust), median(py)
    lines.append("## 1. One f64 solve_ellipse (nu = 0.25, M_R = 0.9990234375, A1/B1 = 2)")
    lines.append(f"{ROUNDS} rounds interleaved, each: the CLI's median of 1000 warm solves, then the median of 2000 Python calls")
    lines.append(f"rust warm solve (CLI --repeat 1000), median of rounds   {rust:8.0f} ns")
    lines.append(f"python solve_ellipse, median of rounds                  {py:8.0f} ns")
    lines.append(f"ratio python / rust                                     {py / rust:8.2f}  (target <= 2; "
                 f"rounds {ratios[0]:.2f} .. {ratios[-1]:.2f})")


SWEEP_POINTS = 10**6
SWEEP_ROUNDS = 3


def rust_sweep_ns_per_point(n_points):
    """examples/sweep_cost: n_points ratios A1/B1 = 10^-3 .. 10^3 on a warm pool of THREADS."""
    out = subprocess.run([str(SWEEP_COST), "f64", "sweep", "-3", "3", str(THREADS),
                          str(n_points)], capture_output=True, text=True, check=True).stdout
    ms = float(out.split(",")[-1].split()[0])
    return ms * 1e6 / n_points


def python_sweep(n_points, threads):
    """The same curve as examples/sweep_cost, ns per point."""
    ratio = 10.0 ** (-3 + 6 * np.arange(n_points) / (n_points - 1))
    t = time.perf_counter()
    r = mh.sweep_ellipses(0.25, speed=0.9, ratio=ratio, threads=threads)
    return (time.perf_counter() - t) * 1e9 / n_points, r


MEMORY = """
import resource, sys, numpy as np, moving_hertz as mh
def rss():
    return int(open('/proc/self/statm').read().split()[1]) * resource.getpagesize() / 2**20
n = int(sys.argv[1])
ratio = 10.0 ** (-3 + 6 * np.arange(n) / (n - 1))
mh.sweep_ellipses(0.25, speed=0.9, ratio=ratio[:1000], threads=2)
base = rss()
r = mh.sweep_ellipses(0.25, speed=0.9, ratio=ratio, threads=2)
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
arrays = [v for v in r.to_dict().values() if isinstance(v, np.ndarray)]
out = sum(a.nbytes for a in arrays if a.dtype != object) + 8 * r.messages.size
print(peak - base, out / 2**20)
"""


def sweep(lines):
    """The Rust sweep and the Python sweep of the same 10^6 points, back to back,
    SWEEP_ROUNDS times (the median of each), then the memory of the Python sweep."""
    rust, py = [], []
    python_sweep(20000, THREADS)  # warm the pool and the rules
    for _ in range(SWEEP_ROUNDS):
        rust.append(rust_sweep_ns_per_point(SWEEP_POINTS))
        t, r = python_sweep(SWEEP_POINTS, THREADS)
        py.append(t)
        assert r.ok.all()
    ratios = sorted(p / q for p, q in zip(py, rust))
    rust, py = median(rust), median(py)
    peak, out = map(float, subprocess.run([sys.executable, "-c", MEMORY, str(SWEEP_POINTS)],
                                          capture_output=True, text=True,
                                          check=True).stdout.split())
    lines.append("")
    lines.append(f"## 2. sweep_ellipses at f64, nu = 0.25, M_R = 0.9, A1/B1 = 1e-3 .. 1e3, 10^6 points, {THREADS} threads")
    lines.append(f"{SWEEP_ROUNDS} rounds, each: examples/sweep_cost (sweep::ellipses), then the Python sweep of the same points")
    lines.append(f"rust sweep::ellipses (examples/sweep_cost ... {THREADS} {SWEEP_POINTS}), median  {rust:7.0f} ns/point")
    lines.append(f"python sweep_ellipses, median                                    {py:7.0f} ns/point")
    lines.append(f"ratio python / rust                                              {py / rust:7.2f}  (target <= 1.2; "
                 f"rounds {ratios[0]:.2f} .. {ratios[-1]:.2f})")
    lines.append(f"memory of the 10^6-point sweep: peak RSS {peak:.0f} MiB above the process before it, "
                 f"output arrays {out:.0f} MiB: {peak - out:.0f} MiB beyond them (target <= 100 MB)")
    return r


def numpy_gl_sweep(nu, mr, ratio, nodes=96, iterations=12, chunk=4000):
    """k by Newton on ln(I2/I1) = ln(A1/B1), I1, I2 of (34) by Gauss-Legendre on [0, pi/2]
    (the integrands are symmetric about pi/2), vectorised over the points."""
    g = (1 - 2 * nu) / (2 * (1 - nu))

    def rayleigh(x):
        return (2 - x) ** 2 - 4 * np.sqrt((1 - g * x) * (1 - x))

    lo, hi = 0.3, 0.999  # the Rayleigh root m1 = (c_R/c2)^2 by bisection: R(lo) < 0 < R(hi)
    for _ in range(80):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if rayleigh(mid) < 0 else (lo, mid)
    m1 = (lo + hi) / 2
    t, w = np.polynomial.legendre.leggauss(nodes)
    phi, w = (t + 1) * np.pi / 4, w * np.pi / 4
    s2, c2 = np.sin(phi) ** 2, np.cos(phi) ** 2
    x = m1 * mr * mr * s2
    safe = np.where(x < 1e-8, 1.0, x)
    gamma = np.where(x < 1e-8, -(1 - nu) / np.pi,
                     safe * np.sqrt(1 - g * safe) / (np.pi * rayleigh(safe)))
    wg = -gamma * w
    out = np.empty_like(ratio)
    np.seterr(all="ignore")
    for lo in range(0, ratio.size, chunk):
        r = ratio[lo:lo + chunk, None]
        lnk = -0.6 * np.log(r)
        for _ in range(iterations):
            k = np.exp(lnk)
            d = k * k * c2 + s2
            p3, p5 = d ** -1.5, d ** -2.5
            i1, i2 = (wg * c2 * p3).sum(1, keepdims=True), (wg * s2 * p3).sum(1, keepdims=True)
            d1 = (-3 * k * wg * c2 * c2 * p5).sum(1, keepdims=True)
            d2 = (-3 * k * wg * s2 * c2 * p5).sum(1, keepdims=True)
            f = np.log(i2 / i1) - np.log(r)
            lnk = lnk - np.clip(f / (k * (d2 / i2 - d1 / i1)), -1.0, 1.0)
        out[lo:lo + chunk] = np.exp(lnk[:, 0])
    return out


def digits(k, ref):
    with np.errstate(divide="ignore"):
        return -np.log10(np.maximum(np.abs(k / ref - 1), 1e-17))


def against_numpy(lines):
    n = 20000
    gap = np.geomspace(1e-1, 1e-6, 20)[:, None]
    ratio = np.geomspace(1e-2, 1e2, n // 20)
    mr = 1 - gap
    t = time.perf_counter()
    ours = mh.sweep_ellipses(0.25, gap=gap, ratio=ratio, threads=THREADS)
    t_ours = (time.perf_counter() - t) * 1e9 / n
    t = time.perf_counter()
    gl = np.stack([numpy_gl_sweep(0.25, m, ratio) for m in mr[:, 0]])
    t_gl = (time.perf_counter() - t) * 1e9 / n
    sub = (slice(None, None, 4), slice(None, None, 50))
    ref = mh.sweep_ellipses(0.25, gap=gap[sub[0]], ratio=ratio[sub[1]], precision=256)
    ref_k = np.array([[float(v) for v in row] for row in ref.k.data])
    d_ours = digits(ours.k.data[sub], ref_k).min()
    d_gl = digits(gl[sub], ref_k).min()
    lines.append("")
    lines.append("## 3. Against a vectorised numpy Gauss-Legendre + Newton sweep (96 nodes, 12 Newton steps)")
    lines.append("grid: nu = 0.25, 1 - M_R = 1e-1 .. 1e-6 (20), A1/B1 = 1e-2 .. 1e2 (1000); digits against 256 bits on a 5 x 20 subgrid")
    lines.append(f"python sweep_ellipses   {t_ours:9.0f} ns/point, worst {d_ours:5.1f} correct digits")
    lines.append(f"numpy Gauss-Legendre    {t_gl:9.0f} ns/point, worst {d_gl:5.1f} correct digits")
    lines.append(f"speed-up                {t_gl / t_ours:9.1f}x  (target >= 10x with >= 15 digits)")


def dask_ratio(lines):
    from distributed import Client, LocalCluster

    import moving_hertz.dask as mhd

    gap = np.geomspace(1e-1, 1e-8, 10)[:, None]
    ratio = np.geomspace(1e-2, 1e2, 1000)
    times = {}
    for workers in (1, 2):
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                          dashboard_address=None) as cluster, Client(cluster) as client:
            grid = mhd.sweep_ellipses(0.25, gap=gap, ratio=ratio, precision=256)
            # Every worker builds its 256-bit rules before the clock starts.
            client.run(lambda: mh.sweep_ellipses(0.25, gap=gap[:, 0], ratio=1.0,
                                                 precision=256, threads=1).ok.all())
            t = time.perf_counter()
            out = client.compute(grid).result()
            times[workers] = time.perf_counter() - t
            assert out["ok"].all()
    lines.append("")
    lines.append("## 4. moving_hertz.dask, 256 bits, 10^4 points (10 gaps x 1000 ratios), "
                 f"chunks of {mhd.chunk_points(256)} points")
    lines.append(f"1 worker process   {times[1]:8.2f} s")
    lines.append(f"2 worker processes {times[2]:8.2f} s")
    lines.append(f"ratio              {times[1] / times[2]:8.2f}x  (target >= 1.6x on 2 cores)")


def main():
    build()
    start = os.getloadavg()[0]
    body = []
    single_solve(body)
    sweep(body)
    against_numpy(body)
    dask_ratio(body)
    end = os.getloadavg()[0]
    lines = ["# tools/python_bench.py (the Python package against the crate; ratios in one run)",
             f"# {os.cpu_count()} CPUs, load average {start:.1f} at the start and {end:.1f} at the "
             "end (other processes share the cores: ratios, not absolute times, carry over)", ""]
    text = "\n".join(lines + body) + "\n"
    OUT.write_text(text)
    print(text, end="")


if __name__ == "__main__":
    main()
