#!/usr/bin/env python3
"""Writes docs/performance.md from criterion's output, so that the page is regenerated, not written.

Usage (from the repository root, after the benches have run):

    for b in dd_arith generic_cost precision_cost physics series fast_integrals ellipse graded sweep contact; do
        cargo bench --bench $b -- --warm-up-time 1 --measurement-time 3
    done
    cargo build --release && python3 tools/baseline_solve.py > target/baseline_solve.md   # optional
    python3 tools/gen_performance.py            # writes docs/performance.md
    python3 tools/gen_performance.py --check    # prints the page instead of writing it
    python3 tools/gen_performance.py --note "load average 3-4 on 2 cores"   # conditions, in the header
    python3 tools/gen_performance.py --section scaling   # one committed output's section alone

It reads every target/criterion/**/new/benchmark.json (the group and function of a benchmark)
with the estimates.json beside it (the median), groups the benchmarks by bench and precision
(f64, dd, mpfrN), and writes one table per bench group with each cell's ratio to the f64 cell of
the same row (same run), a table of the targets computed from those cells, and the scipy/mpmath
comparison if target/baseline_solve.md exists, and the committed outputs of DATA_SECTIONS
(docs/data/scaling.txt of `cargo bench --bench scaling`, the sweep's cost a point, the model
of 16 threads), each as its own section. The measurement header names the command, the
commit (and whether the working tree differed from it in src/ or benches/), the CPU from
/proc/cpuinfo and the dates of the oldest and newest estimate read.
"""
import argparse
import datetime
import glob
import json
import os
import re
import statistics
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
CRIT = os.path.join(ROOT, "target", "criterion")
OUT = os.path.join(ROOT, "docs", "performance.md")
BASELINE = os.path.join(ROOT, "target", "baseline_solve.md")
PAIRED = os.path.join(CRIT, "sweep_paired.json")
BENCHES = "dd_arith generic_cost precision_cost physics series fast_integrals ellipse graded sweep contact"

# Committed outputs included as sections (after the bench tables): title, file under docs/data
# (its own first lines name the command that regenerates it), what it measures. Included as
# they are; `--section NAME` refreshes one of them in the existing page without the benches.
DATA_SECTIONS = [
    ("scaling", "Many cores (`benches/scaling.rs`)", "scaling.txt",
     "Each parallel job of docs/design.md (\"Many cores\") as one process at 1, 2 and every "
     "CPU (`RAYON_NUM_THREADS`), criterion's median wall time and its ratio to one thread. "
     "Targets: two threads ≤ 0.55× one thread for each of the four large jobs."),
    ("scaling_16cpu", "Many cores on 16 CPUs (`benches/scaling.rs` there)", "scaling_16cpu.txt",
     "The same bench built here and run on a lent 16-CPU machine without a toolchain "
     "(`tools/many_cores.sh` carries the built tool and bench there). Target: ≥ 13× one thread "
     "(median ≤ 0.077) at 16 threads for each of the four large jobs; `fig2` at f64 never "
     "slower on 16 threads than on one."),
    ("many_cores", "Every thread count on 16 CPUs (`tools/many_cores.sh`)", "many_cores.txt",
     "The jobs of `benches/scaling.rs` at 1, 2, 4, 8 and 16 threads on the same machine "
     "(minimum of 3 runs), the SHA-256 of each sweep's output at 1, 2 and 16 threads (equal), "
     "and the warm f64 solve of the 12 cells there (target ≤ 1000 ns)."),
    ("writer_cost", "The writer's system calls (`tools/writer_cost.sh`)", "writer_cost.txt",
     "What callgrind does not count: system time and context switches of the 10⁶-point f64 "
     "sweep, the build that writes each block of 64 points at once (base) against the one that "
     "writes tasks of up to 1,024 points (head), run alternately on this machine."),
    ("sweep_point_cost", "The sweep command's cost a point (`tools/sweep_point_cost.sh`)",
     "sweep_point_cost.txt",
     "`moving-hertz sweep` at f64 on a slice of a 10⁶-point grid (10,000 ratios at each speed), "
     "instructions (callgrind) and time a point, against a warm `solve_ellipse` of the same "
     "points. Target: ≤ 0.5× the warm solve."),
    ("scaling_model", "A model of 16 threads from 2 cores (`tools/scaling_model.py`)",
     "scaling_model.txt",
     "Each parallel job's serial part, per-thread work and the imbalance at its end, counted on "
     "this machine, and Amdahl's law with a tail at 16 threads (docs/design.md, \"Many "
     "cores\"). Target: ≥ 13× one thread at 16 threads for each of the four large jobs."),
]


def bench_const(bench, name, default):
    """An integer constant of a bench source (so that the page follows the bench)."""
    try:
        with open(os.path.join(ROOT, "benches", bench + ".rs")) as fh:
            m = re.search(rf"const {name}: usize = (\d+);", fh.read())
        return int(m.group(1)) if m else default
    except OSError:
        return default


DD_CHAIN = bench_const("dd_arith", "CHAIN", 64)  # operations per dd_arith benchmark
PREC = re.compile(r"^(?:(?P<fam>.+?)[/_-])?(?P<prec>f64|dd|mpfr\d+)$")

# Targets the crate is built to (the generic layer, the fast route, the ellipse solve).
T_GENERIC = 1.05
T_FAST_F64_NS = 300.0
T_ELLIPSE_F64_NS = 2000.0
T_ELLIPSE_DD_RATIO = 25.0
T_ELLIPSE_MP256_NS = 2.0e6
T_SWEEP = {"f64": 0.4, "dd": 0.5, "mpfr256": 0.6}  # sweep on one thread / independent solves
T_SWEEP_THREADS = 0.55  # two threads / one thread
T_EXTREME = 25.0  # a solve at A1/B1 = 1e+-100 / the solve at A1/B1 = 0.5, same precision and speed

# Bench groups in page order: family, title, what it measures.
FAMILIES = [
    ("ellipse", "The ellipse solve (`benches/ellipse.rs`)",
     "`solve_ellipse` for ν = 0.2, A1/B1 = 0.5 (root k < 1) at four speeds: `fixed` is the default "
     "route (fixed rules, Newton in ln k with analytic k-derivatives), `adaptive` the adaptive "
     "quadrature. Above f64 both run the precision ladder."),
    ("ellipse_wide", "The ellipse solve for k > 1 (`benches/graded.rs`, group `ellipse_wide`)",
     "`solve_ellipse` for ν = 0.2 at A1/B1 = 10, 10³, 10⁶ (roots k from 3.1 to 2900, the graded "
     "route)."),
    ("ellipse_extreme", "The ellipse solve at extreme ratios (`benches/ellipse.rs`, group "
     "`ellipse_extreme`)",
     "The default solve at A1/B1 = 10⁻¹⁰⁰ (k ≈ 10⁻⁵³, fixed rule) and 10¹⁰⁰ (k ≈ 10⁵¹, graded rule) "
     "beside A1/B1 = 0.5, at 1 − M_R = 0.5 and 10⁻¹⁰, ν = 0.2: the cost of an extreme input "
     "against a normal one at the same precision."),
    ("contact", "The contact solution (`benches/contact.rs`)",
     "`ContactProblem::solve` (the ellipse, J0 of (32) as k² I1 + I2 from the ellipse's I1, I2, "
     "then a, b, p0, d0) for ν = 0.3, R2/R1 = 2 under a load at 1 − M_R = 0.5, 10⁻⁴, 10⁻¹² (and "
     "10⁻¹⁰⁰⁰ at 256 bits); the ellipse solve alone at 10⁻⁴ (`ellipse_gap=1e-4`); and J0 by "
     "the adaptive route at the 10⁻⁴ case's k (`contact_integrals`: its five integrals from one "
     "evaluation of G a node)."),
    ("graded", "The graded route for k ≥ 1 (`benches/graded.rs`)",
     "I1, I2 and their k-derivatives in one call (layout and evaluation), ν = 0.2."),
    ("fast", "The fixed rule for k ≤ 1 (`benches/fast_integrals.rs`, group `fast`)",
     "I1, I2 at a new speed (`fast`; `integrals` with `Method::Fixed`), with k-derivatives "
     "(`fast_dk`), and one evaluation from a built set-up (`at_dk`; the set-up alone costs "
     "`fast_dk` − `at_dk`); ν = 1/4."),
    ("adaptive", "The adaptive quadrature (`benches/fast_integrals.rs`, group `adaptive`)",
     "I1, I2 by the adaptive route (tolerance ε of the precision) on the same cases, for comparison "
     "with the fixed rule."),
    ("series", "The series route (`benches/series.rs`)",
     "The coefficients f_0 … f_n of (35)–(36), the moments L_n, M_n, D_n up to n = 1000 at three "
     "values of k² (forward, backward with Gauss top values, backward with Pfaff top values), and "
     "I1, I2 by (37)."),
    ("physics", "The physics (`benches/physics.rs`)",
     "The Rayleigh roots by the default (polished) method and the two closed forms, R(V) of (6), "
     "Γ(V) of (5) and G(V) of (45); ν = 0.25, M_R = 0.9."),
    ("sweep", "Sweeps (`benches/sweep.rs`)",
     "A 1,000-point A1/B1 curve (10⁻³ … 10³, log-spaced) at ν = 0.25, M_R = 0.9: one "
     "`solve_ellipse` a point (`independent`), `sweep::ellipses` on one and on two threads; each "
     "timed call runs on a thread of a pool of that size, its threads bound to CPUs "
     "(`sweep::bind_to_cpu`, as the binary binds them); `sweep_2_threads_unbound` runs the "
     "two-thread sweep on threads the operating system places. `sweep_1_thread_from_outside` calls the "
     "one-thread sweep from the bench's own thread (`install` around each call): the difference "
     "from `sweep_1_thread` is the hand-off to the pool, once per call. `two_sweeps_at_once` runs "
     "two one-thread sweeps at the same time on two threads (the wall time of both). The targets "
     "above use ratios paired call by call: `independent`, `sweep_2_threads`, "
     "`sweep_2_threads_unbound` and `two_sweeps_at_once` alternate each timed call with a one-thread sweep, and each sample "
     "gives the ratio of the two (the median over samples is quoted); two one-thread sweeps at "
     "once, over twice one alone, is the best ratio two threads can reach on the machine of the "
     "run (0.5 on two independent cores)."),
    ("elliptic", "Elliptic integrals (`benches/precision_cost.rs`)",
     "K and E together from the complementary parameter mc = 1 − m (`ellipke_mc`)."),
]


def sh(*cmd):
    try:
        return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def cpu():
    try:
        with open("/proc/cpuinfo") as fh:
            info = fh.read()
        model = re.search(r"^model name\s*:\s*(.+)$", info, re.M)
        n = len(re.findall(r"^processor\s*:", info, re.M))
        mhz = re.search(r"^cpu MHz\s*:\s*([0-9.]+)", info, re.M)
        clock = f" at {float(mhz.group(1)) / 1000:.1f} GHz" if mhz else ""
        return f"{model.group(1).strip() if model else 'unknown CPU'}{clock}, {n} logical cores"
    except OSError:
        return "unknown CPU"


def load():
    """{(group_id, function_id): (median ns, mtime)} for every benchmark criterion has written."""
    out = {}
    for bj in glob.glob(os.path.join(CRIT, "**", "new", "benchmark.json"), recursive=True):
        est = os.path.join(os.path.dirname(bj), "estimates.json")
        try:
            with open(bj) as fh:
                meta = json.load(fh)
            with open(est) as fh:
                median = json.load(fh)["median"]["point_estimate"]
        except (OSError, KeyError, ValueError):
            continue
        fid = meta.get("function_id") or ""
        if meta.get("value_str"):
            fid = f"{fid}/{meta['value_str']}" if fid else meta["value_str"]
        out[(meta["group_id"], fid)] = (median, os.path.getmtime(est))
    return out


def family_of(group, function):
    """(family, precision or None) of a benchmark."""
    m = PREC.match(group)
    if not m:
        return group, None
    fam, prec = m.group("fam"), m.group("prec")
    if fam is None:  # physics and precision_cost name their groups by the precision alone
        fam = "elliptic" if function.startswith("ellip") else "physics"
    return fam, prec


def prec_key(p):
    if p == "f64":
        return (0, 0)
    if p == "dd":
        return (1, 0)
    return (2, int(p[4:]))


def fmt(ns):
    if ns < 1e3:
        return f"{ns:.1f} ns"
    if ns < 1e6:
        return f"{ns / 1e3:.2f} µs"
    if ns < 1e9:
        return f"{ns / 1e6:.2f} ms"
    return f"{ns / 1e9:.2f} s"


def ratio(x):
    return f"×{x:.0f}" if x >= 10 else f"×{x:.1f}"


def natural(s):
    """Sort key that orders the numbers inside labels numerically (M=0.5 < M=0.9 < M=0.999)."""
    return [(0, float(t)) if re.fullmatch(r"\d+(\.\d+)?(e-?\d+)?", t) else (1, t)
            for t in re.split(r"([0-9.]+(?:e-?\d+)?)", s) if t]


def precision_table(cells):
    """Markdown rows for {function: {precision: ns}}, ratios to the f64 cell of the row."""
    precs = sorted({p for row in cells.values() for p in row}, key=prec_key)
    lines = ["| bench | " + " | ".join(precs) + " |", "|---" * (len(precs) + 1) + "|"]
    for f in sorted(cells, key=natural):
        row, base = cells[f], cells[f].get("f64")
        out = []
        for p in precs:
            if p not in row:
                out.append("—")
            elif p == "f64" or base is None:
                out.append(fmt(row[p]))
            else:
                out.append(f"{fmt(row[p])} ({ratio(row[p] / base)})")
        lines.append(f"| {f} | " + " | ".join(out) + " |")
    return lines


def targets(fams, flat):
    """The targets table, computed from the cells."""
    rows = []

    def verdict(ok):
        return "yes" if ok else "**no**"

    gen = [(f.replace("/generic/", "/"), t, flat.get(("generic_cost", f.replace("generic", "hand"))))
           for (g, f), t in flat.items() if g == "generic_cost" and "/generic/" in f]
    gen = [(f, t, h[0]) for f, t, h in gen if h]
    if gen:
        rs = [t[0] / h for _, t, h in gen]
        rows.append((f"generic code at f64 against hand-written f64: ratio ≤ {T_GENERIC}",
                     f"{min(rs):.2f}–{max(rs):.2f} ({len(rs)} cases)", verdict(max(rs) <= T_GENERIC)))
    fast = [v["f64"] for f, v in fams.get("fast", {}).items() if f.startswith("fast/") and "f64" in v]
    if fast:
        rows.append((f"I1 and I2 at f64 ≤ {T_FAST_F64_NS:.0f} ns for every M_R ≤ 1 − 10⁻⁸, k ≤ 1",
                     f"{fmt(min(fast))}–{fmt(max(fast))} ({len(fast)} cases)",
                     verdict(max(fast) <= T_FAST_F64_NS)))
    solves = [v for fam in ("ellipse", "ellipse_wide") for f, v in fams.get(fam, {}).items()
              if not f.startswith("adaptive")]
    f64 = [v["f64"] for v in solves if "f64" in v]
    if f64:
        rows.append((f"ellipse solve at f64 ≤ {fmt(T_ELLIPSE_F64_NS)}, M_R ≤ 0.9999, A1/B1 = 0.5 … 10⁶",
                     f"{fmt(min(f64))}–{fmt(max(f64))} ({len(f64)} cases)",
                     verdict(max(f64) <= T_ELLIPSE_F64_NS)))
    dd = [v["dd"] / v["f64"] for v in solves if "dd" in v and "f64" in v]
    if dd:
        rows.append((f"ellipse solve at double-double ≤ {T_ELLIPSE_DD_RATIO:.0f}× f64 (same run)",
                     f"{ratio(min(dd))}–{ratio(max(dd))}", verdict(max(dd) <= T_ELLIPSE_DD_RATIO)))
    mp = [v["mpfr256"] for v in solves if "mpfr256" in v]
    if mp:
        rows.append((f"ellipse solve at 256 bits ≤ {fmt(T_ELLIPSE_MP256_NS)}",
                     f"{fmt(min(mp))}–{fmt(max(mp))} ({len(mp)} cases)",
                     verdict(max(mp) <= T_ELLIPSE_MP256_NS)))
    rows += sweep_targets(fams.get("sweep", {}))
    rows += extreme_targets(fams.get("ellipse_extreme", {}))
    lines = ["| target | measured (range over the bench's cases) | met? |", "|---|---|---|"]
    lines += [f"| {a} | {b} | {c} |" for a, b, c in rows]
    return lines


def extreme_targets(cells):
    """Per precision: the worst ratio of a solve at A1/B1 = 1e±100 to the A1/B1 = 0.5 solve at
    the same speed."""
    rows = []
    precs = sorted({p for row in cells.values() for p in row}, key=prec_key)
    for prec in precs:
        rs = []
        for f, row in cells.items():
            m = re.fullmatch(r"ratio=(1e-?100)_gap=(.+)", f)
            base = cells.get(f"ratio=0.5_gap={m.group(2)}", {}).get(prec) if m else None
            if base and prec in row:
                rs.append(row[prec] / base)
        if rs:
            rows.append((f"ellipse solve at A1/B1 = 10^±100, {prec}: ≤ {T_EXTREME:.0f}× the solve at "
                         "A1/B1 = 0.5 (same speed)", f"{ratio(min(rs))}–{ratio(max(rs))}",
                         "yes" if max(rs) <= T_EXTREME else "**no**"))
    return rows


def paired():
    """The sweep bench's paired ratios, {precision: {bench: median of its samples}} (see
    benches/sweep.rs), or {} when the bench has not written them."""
    try:
        with open(PAIRED) as fh:
            data = json.load(fh)
    except (OSError, ValueError):
        return {}
    return {prec: {name: statistics.median(rs) for name, rs in v.items() if rs}
            for prec, v in data.items()}


def sweep_targets(cells):
    """The sweep bench's targets: per point against independent solves, two threads against one,
    from the ratios paired call by call (the medians' ratios where those are missing)."""
    rows, pair = [], paired()
    ind, one, two = (cells.get(f, {}) for f in ("independent", "sweep_1_thread", "sweep_2_threads"))
    how = " (paired)"

    def measured(prec, name, fallback):
        r = pair.get(prec, {}).get(name)
        return (r, how) if r is not None else (fallback(), "")

    for prec, target in T_SWEEP.items():
        if prec in ind and prec in one:
            r, h = measured(prec, "independent", lambda: one[prec] / ind[prec])
            rows.append((f"1,000-point A1/B1 curve at {prec}, one thread: ≤ {target} × independent solves",
                         f"{r:.2f}{h}", "yes" if r <= target else "**no**"))
    for prec in T_SWEEP:
        if prec in one and prec in two:
            r, h = measured(prec, "sweep_2_threads", lambda: two[prec] / one[prec])
            best = pair.get(prec, {}).get("two_sweeps_at_once")
            ceiling = f"; two one-thread sweeps at once: {best:.2f}" if best is not None else ""
            free = pair.get(prec, {}).get("sweep_2_threads_unbound")
            if free is not None and h:
                h = f" (paired, threads bound to CPUs; unbound: {free:.2f})"
            rows.append((f"the same curve at {prec} on two threads: ≤ {T_SWEEP_THREADS} × one thread",
                         f"{r:.2f}{h}{ceiling}", "yes" if r <= T_SWEEP_THREADS else "**no**"))
    return rows


def page(data, note=None):
    fams, other = {}, {}
    for (g, f), (ns, _) in data.items():
        fam, prec = family_of(g, f)
        if prec is None:
            other.setdefault(g, {})[f] = ns
        else:
            fams.setdefault(fam, {}).setdefault(f, {})[prec] = ns
    flat = data
    times = [t for _, t in data.values()]
    day = lambda t: datetime.datetime.fromtimestamp(t, datetime.timezone.utc).strftime("%Y-%m-%d")
    head = sh("git", "rev-parse", "--short=12", "HEAD") or "unknown"
    code = sh("git", "log", "-1", "--format=%h", "--abbrev=12", "--", "src", "benches", "Cargo.lock") or head
    dirty = sh("git", "status", "--porcelain", "--", "src", "benches", "Cargo.toml", "Cargo.lock")
    rustc = sh("rustc", "--version") or "rustc (unknown version)"

    L = ["# Performance", "",
         "<!-- Generated by tools/gen_performance.py from target/criterion; do not edit by hand. -->", "",
         "This page is generated by `tools/gen_performance.py` from criterion's output of one bench run "
         "of the code named below; re-running the benches and the script refreshes it. Every figure is "
         "a criterion median; ratios (×N) are to the `f64` cell of the same row, measured in the same "
         "run. The machine is shared with other work, so single cells can be disturbed by tens of per "
         "cent: compare ratios, and re-run a cell that stands out from its neighbours.", "",
         "**Measurement.**", "",
         f"* command: `for b in {BENCHES}; do cargo bench --bench $b -- --warm-up-time 1 "
         "--measurement-time 3; done`, then `python3 tools/gen_performance.py`",
         f"* code: src/ and benches/ as of commit `{code}` (page generated at `{head}`)"
         + (", with uncommitted changes in src/ or benches/" if dirty else ""),
         f"* CPU: {cpu()}; {rustc}; `--release`, default target (double-double uses the FMA "
         "instruction, detected at run time)",
         ("* date: " + " to ".join(sorted({day(min(times)), day(max(times))}))) if times else "* date: (no data)"]
    if note:
        L.append(f"* conditions: {note}")
    L += ["",
         "The accuracy behind each route is asserted by the tests and stated in each item's rustdoc; "
         "how the cost grows beyond 256 bits is in [precision.md](precision.md); the thresholds the "
         "solvers use and how they were chosen are in [calibration.md](calibration.md).", "",
         "## Against the targets", ""]
    L += targets(fams, flat)
    for fam, title, what in FAMILIES:
        if fam not in fams:
            continue
        L += ["", f"## {title}", "", what, ""]
        L += precision_table(fams[fam])
    if "generic_cost" in other:
        cells = other["generic_cost"]
        L += ["", "## Cost of genericity (`benches/generic_cost.rs`)", "",
              "The AGM for K written once over `T: Real` and instantiated at `f64`, against the same "
              "kernel written by hand for `f64` (target: ratio ≤ 1.05).", "",
              "| case | generic at f64 | hand-written f64 | ratio |", "|---|---|---|---|"]
        for f in sorted(cells, key=natural):
            if "/generic/" in f:
                h = cells.get(f.replace("generic", "hand"))
                if h:
                    L.append(f"| {f} | {fmt(cells[f])} | {fmt(h)} | {cells[f] / h:.2f} |")
    for g in sorted(o for o in other if o.startswith("dd_arith")):
        cells = other[g]
        base = cells.get("mul/f64")
        L += ["", f"## Double-double arithmetic (`benches/dd_arith.rs`, group `{g}`)", "",
              f"Each benchmark is a dependent chain of {DD_CHAIN} operations (latency) or "
              f"{DD_CHAIN} independent products (`mul-throughput`), for `Dd` and twofloat; the "
              "time per operation is the median divided by the count, and the ratio is to the f64 "
              "product chain (`mul/f64`).", "",
              "| operation | per operation | ratio to an f64 product |", "|---|---|---|"]
        for f in sorted(cells, key=natural):
            L.append(f"| {f} | {fmt(cells[f] / DD_CHAIN)} | {ratio(cells[f] / base) if base else '—'} |")
    for name, _, _, _ in DATA_SECTIONS:
        L += [""] + data_section(name)
    L += ["", "## Against what a user would script (`tools/baseline_solve.py`)", ""]
    if os.path.exists(BASELINE):
        with open(BASELINE) as fh:
            table = fh.read().strip()
        when = day(os.path.getmtime(BASELINE))
        L += ["The same ellipse solve (ν = 0.2, A1/B1 = 0.5) scripted as a careful user would — Γ by "
              "(5)–(6), the Rayleigh root by brentq, I1 and I2 by `scipy.integrate.quad` over [0, π] "
              "with a breakpoint at π/2, the root in k by brentq; or the same with mpmath at 15 "
              "digits — against `moving-hertz ellipse` at f64 (median of 200 repeats); every k is "
              "compared with moving-hertz at 256 bits. Command: `cargo build --release && python3 "
              f"tools/baseline_solve.py > target/baseline_solve.md` ({when}, same machine).", "", table]
    else:
        L += ["Not measured for this page: `python3 tools/baseline_solve.py > target/baseline_solve.md` "
              "(needs scipy and mpmath, tools/requirements.txt), then re-run this script."]
    return "\n".join(L) + "\n"


def data_section(name):
    """The lines of the section of DATA_SECTIONS named `name`: its heading, what it measures,
    and its committed file as a block (or a line saying how to make it)."""
    _, title, fname, what = next(d for d in DATA_SECTIONS if d[0] == name)
    path = os.path.join(ROOT, "docs", "data", fname)
    L = [f"## {title}", "", what, ""]
    if os.path.exists(path):
        with open(path) as fh:
            L += [f"From `docs/data/{fname}`:", "", "```text", fh.read().rstrip("\n"), "```"]
    else:
        L += [f"Not measured for this page: `docs/data/{fname}` is missing."]
    return L


def refresh_section(name):
    """Rewrites the section `name` of the existing page from its committed file (the rest of
    the page unchanged); appended before the last section if the page lacks it."""
    with open(OUT) as fh:
        lines = fh.read().rstrip("\n").split("\n")
    heading = data_section(name)[0]
    order = [data_section(n)[0] for n, _, _, _ in DATA_SECTIONS]
    starts = [i for i, l in enumerate(lines) if l.startswith("## ")]
    if heading in lines:
        at = lines.index(heading)
        end = next((i for i in starts if i > at), len(lines))
    else:
        # after the last section of DATA_SECTIONS that precedes it, else before the last one
        before = [lines.index(h) for h in order[:order.index(heading)] if h in lines]
        after = [i for i in starts if before and i > before[-1]]
        at = end = (after[0] if after else starts[-1])
    new = data_section(name) + [""]
    lines[at:end] = new
    with open(OUT, "w") as fh:
        fh.write("\n".join(lines).rstrip("\n") + "\n")
    print(f"rewrote the section '{heading[3:]}' of {os.path.relpath(OUT, ROOT)}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true", help="print the page instead of writing it")
    ap.add_argument("--note", help="conditions of the run for the header, e.g. the machine's load")
    ap.add_argument("--section", choices=[d[0] for d in DATA_SECTIONS],
                    help="rewrite only this section of the existing page, from its docs/data file")
    args = ap.parse_args()
    if args.section:
        refresh_section(args.section)
        return
    data = load()
    if not data:
        sys.exit(f"gen_performance: no criterion output under {CRIT}; run the benches first")
    text = page(data, args.note)
    if args.check:
        sys.stdout.write(text)
    else:
        with open(OUT, "w") as fh:
            fh.write(text)
        print(f"wrote {os.path.relpath(OUT, ROOT)} from {len(data)} benchmarks")


if __name__ == "__main__":
    main()
