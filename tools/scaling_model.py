#!/usr/bin/env python3
"""A model of each parallel job of benches/scaling.rs at 16 threads, from instruction counts on
a machine of 2 cores (no machine of 8 or more cores was at hand).

Each job runs once under callgrind with RAYON_NUM_THREADS=2 and --separate-threads=yes, which
counts every thread's instructions apart (repeatably, whatever the load):

* the calling thread's count is the serial part S (process start, argument checks, the Rayleigh
  root and the first rules, handing the work to the pool, the charts' and files' hand-off, exit)
  plus, in the `sweep` command, the writer Wr (`write_in_order`: writing the solved rows in
  input order while the pool solves; its inclusive count is taken from the calling thread);
* the pool threads' counts are the parallel work W, and their difference at 2 threads is the
  imbalance measured at the end (max over mean);
* a block's mean cost b is W over the job's blocks (64 points a block in the sweeps; fig2's tasks
  as docs/design.md counts them).

Amdahl's law with a tail, in instructions (the threads' rates taken as equal):
T(P) = S + max(W/P + b, Wr) for P > 1 (the last block started runs alone at the end, and the
writer bounds the job when it cannot keep up), T(1) = S + max(W, Wr); the modelled speed-up at P
threads is T(1)/T(P). Thread start and wake-ups (tens of microseconds a thread) and memory
bandwidth are not in the model. The check: the model's T(2)/T(1) beside the measured ratio of
docs/data/scaling.txt.

Usage, from the repository root (about ten minutes on 2 cores under valgrind):

    cargo build --release --bin moving-hertz
    python3 tools/scaling_model.py > docs/data/scaling_model.txt
    python3 tools/scaling_model.py fig2_f64 sweep_dd     # some jobs only
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
BIN = os.path.join(ROOT, "target", "release", "moving-hertz")
SCALING = os.path.join(ROOT, "docs", "data", "scaling.txt")

# job, arguments (benches/scaling.rs), the number of blocks the pool takes
JOBS = [
    ("sweep_f64", "sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio log:1e-2:1e2:20000", 1_000_000 // 64 + 1),
    ("sweep_dd", "sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio log:1e-2:1e2:2000 --precision dd",
     100_000 // 64 + 1),
    ("sweep_256", "sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio log:1e-2:1e2:100 --precision 256",
     5_000 // 64 + 1),
    ("fig2_256", "fig2 --precision 256", 160),
    ("fig2_f64", "fig2", 41),
]
THREADS = 16


def total(path):
    """The instruction count of one callgrind output file."""
    with open(path) as fh:
        for line in fh:
            if line.startswith(("summary:", "totals:")):
                return int(line.split()[1])
    return 0


def inclusive(path, name):
    """The inclusive count of the functions whose name contains `name` in one thread's file."""
    out = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", path],
                         capture_output=True, text=True, check=True).stdout
    best = 0
    for line in out.splitlines():
        m = re.match(r"\s*([\d,]+)\s.*" + re.escape(name), line)
        if m:
            best = max(best, int(m.group(1).replace(",", "")))
    return best


def count(args, tmp):
    """Per-thread counts of one run on 2 threads: (calling thread, writer, [pool threads])."""
    words = args.split()
    if words[0] == "fig2":
        words += ["--out", tmp]
    prefix = os.path.join(tmp, "cg")
    subprocess.run(["valgrind", "--tool=callgrind", "--separate-threads=yes",
                    f"--callgrind-out-file={prefix}.%p", BIN] + words,
                   env={**os.environ, "RAYON_NUM_THREADS": "2"},
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    files = sorted(glob.glob(prefix + ".*-*"), key=lambda f: int(f.rsplit("-", 1)[1]))
    counts = [total(f) for f in files]
    main, others = counts[0], counts[1:]
    writer = inclusive(files[0], "write_in_order")
    # The pool's threads: the two busiest of the others (a thread that only hands the work to
    # the pool and waits counts little, and is counted with the serial part).
    pool = sorted(others, reverse=True)[:2]
    rest = sum(others) - sum(pool)
    for f in files:
        os.remove(f)
    return main + rest - writer, writer, pool


def measured_two():
    """Two threads over one, per job, from docs/data/scaling.txt."""
    out = {}
    if os.path.exists(SCALING):
        with open(SCALING) as fh:
            for line in fh:
                m = re.match(r"(\w+)\s+2\s+[\d.]+ ms\s+([\d.]+)", line)
                if m:
                    out[m.group(1)] = float(m.group(2))
    return out


def model(s, wr, w, b, p):
    """Amdahl's law with a tail: the job's instructions on the critical path at p threads."""
    return s + max(w, wr) if p == 1 else s + max(w / p + b, wr)


def main():
    if not os.path.exists(BIN):
        sys.exit("scaling_model: build first: cargo build --release --bin moving-hertz")
    head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                          capture_output=True, text=True).stdout.strip()
    two = measured_two()
    print(f"# python3 tools/scaling_model.py (HEAD {head}; callgrind, RAYON_NUM_THREADS=2, "
          f"{os.cpu_count()} CPUs)")
    print("# S: serial instructions (calling thread less the writer); Wr: the writer's; W: the")
    print("# pool's work; imbalance: the busier pool thread over the mean at 2 threads; b: W over")
    print("# the blocks; model T(P) = S + max(W/P + b, Wr), T(1) = S + max(W, Wr), in instructions")
    print()
    print(f"{'job':<10} {'S (M)':>8} {'Wr (M)':>8} {'W (M)':>9} {'S/T1':>7} {'imbal':>6} "
          f"{'blocks':>6} {'b/(W/16)':>8} {'T2/T1':>6} {'meas.':>6} {'x16':>6}  bound at 16")
    for job, args, blocks in [j for j in JOBS if not sys.argv[1:] or j[0] in sys.argv[1:]]:
        with tempfile.TemporaryDirectory() as tmp:
            s, wr, pool = count(args, tmp)
        w = sum(pool)
        b = w / blocks
        t1 = model(s, wr, w, b, 1)
        t2, t16 = model(s, wr, w, b, 2), model(s, wr, w, b, THREADS)
        imbalance = max(pool) / (w / len(pool)) if w else 1.0
        parts = {"serial": s, "tail": b, "writer": wr - w / THREADS if wr > w / THREADS + b else 0}
        bound = max(parts, key=parts.get) if t1 / t16 < 13 else "-"
        meas = f"{two[job]:.3f}" if job in two else "-"
        print(f"{job:<10} {s / 1e6:>8.1f} {wr / 1e6:>8.1f} {w / 1e6:>9.1f} {s / t1:>7.4f} "
              f"{imbalance:>6.3f} {blocks:>6} {b / (w / THREADS):>8.3f} {t2 / t1:>6.3f} "
              f"{meas:>6} {t1 / t16:>6.2f}  {bound}")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
