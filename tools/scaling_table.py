#!/usr/bin/env python3
"""Prints the many-core table of `cargo bench --bench scaling` (benches/scaling.rs) from
target/criterion: each job's median wall time at 1, 2 and all threads and its speed-up over one
thread, with the machine's CPU count. Usage, from the repository root:

    cargo bench --bench scaling && python3 tools/scaling_table.py > docs/data/scaling.txt
"""
import glob
import json
import os
import re

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
CRIT = os.path.join(ROOT, "target", "criterion")


def medians():
    out = {}
    # criterion names a group's folder by its name with '/' as '_': scaling_<job>/threads=N
    for est in glob.glob(os.path.join(CRIT, "scaling_*", "*", "new", "estimates.json")):
        group, cell = est.split(os.sep)[-4:-2]
        job = group[len("scaling_"):]
        m = re.fullmatch(r"threads=(\d+)", cell)
        if m:
            with open(est) as fh:
                out.setdefault(job, {})[int(m.group(1))] = json.load(fh)["median"]["point_estimate"]
    return out


def main():
    data = medians()
    cpus = os.cpu_count()
    print(f"benches/scaling.rs: median wall time of each job (one process, RAYON_NUM_THREADS set), "
          f"{cpus} CPUs")
    print("command: cargo bench --bench scaling && python3 tools/scaling_table.py > docs/data/scaling.txt")
    print()
    print(f"{'job':<10} {'threads':>7} {'median':>10} {'vs 1 thread':>12}")
    for job in ("sweep_f64", "sweep_dd", "sweep_256", "fig2_256", "fig2_f64"):
        cells = data.get(job, {})
        one = cells.get(1)
        for t in sorted(cells):
            ns = cells[t]
            rel = f"{ns / one:.3f}" if one else "-"
            print(f"{job:<10} {t:>7} {ns / 1e6:>8.1f} ms {rel:>12}")


if __name__ == "__main__":
    main()
