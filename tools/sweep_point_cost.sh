#!/usr/bin/env bash
# The `sweep` command's cost a point against a warm single solve of the same points, at f64, on
# a slice of the issue's grid (`sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio
# log:1e-2:1e2:20000`): the gaps 1e-1, 1e-4, 1e-6 and 1e-8 (points of that gap axis), 10,000
# log-spaced ratios from 1e-2 to 1e2 at each.
#
# Instructions (callgrind, repeatable): the sweep's a point is the whole process's count with
# the four gaps less its count with the gap 1e-1 alone, over the 30,000 points added (what a
# point adds: its solve, its row, writing it; the axes' values, start-up and the ratio axis are
# shared and cancel); a warm single solve's is examples/sweep_cost's `indep` (1,000
# `solve_ellipse` calls at one gap, A1/B1 from 1e-2 to 1e2) less its `none`, over 1,000, at
# each of the three gaps added; the library's part of a sweep point, `sweep::ellipses_at` at the
# warm speed (examples/sweep_cost `at` less `none`, the same 1,000 points), likewise. Times: the
# same differences of the processes' CPU time (user + system, least of 5 runs each, one thread,
# output to /dev/null; the single solves timed over 10,000 points, so that each difference is
# milliseconds): CPU time, not wall time, so that a loaded machine's waits are left out (its
# caches are shared all the same: re-run on an idle machine for times to quote).
#
# Run from the repository root: bash tools/sweep_point_cost.sh > docs/data/sweep_point_cost.txt
# (builds the binary and the example; about two minutes under valgrind.)
set -euo pipefail
cargo build -q --release --bin moving-hertz --example sweep_cost
BIN=target/release/moving-hertz
EX=target/release/examples/sweep_cost
RATIOS=log:1e-2:1e2:10000
GAPS="1e-4 1e-6 1e-8"
export RAYON_NUM_THREADS=1
count() {
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" 2>&1 >/dev/null |
    sed -n 's/.*Collected : //p'
}
one=$(count "$BIN" sweep --nu 0.25 --gap 1e-1 --ratio "$RATIOS")
four=$(count "$BIN" sweep --nu 0.25 --gap "1e-1,${GAPS// /,}" --ratio "$RATIOS")
sweep_ir=$(((four - one) / 30000))
echo "# bash tools/sweep_point_cost.sh (HEAD $(git rev-parse --short HEAD), $(nproc) CPUs)"
echo "# sweep: moving-hertz sweep --nu 0.25 --gap 1e-1,1e-4,1e-6,1e-8 --ratio $RATIOS,"
echo "# less the same with --gap 1e-1, over 30,000 points; solve: examples/sweep_cost indep"
echo "# less none, 1,000 warm solve_ellipse calls (A1/B1 1e-2..1e2) at each gap, over 1,000"
echo
echo "instructions a point"
echo "sweep (whole process, marginal)  $sweep_ir"
echo "sweep (whole process, 10,000 points at gap 1e-1, all counted)  $((one / 10000))"
total=0
for g in $GAPS; do
  indep=$(count "$EX" f64 indep -2 2 1 1000 "$g")
  none=$(count "$EX" f64 none -2 2 1 1000 "$g")
  per=$(((indep - none) / 1000))
  total=$((total + per))
  echo "warm solve_ellipse at gap $g  $per"
done
solve_ir=$((total / 3))
echo "warm solve_ellipse, mean of the three gaps  $solve_ir"
awk -v a="$sweep_ir" -v b="$solve_ir" 'BEGIN { printf "sweep / warm solve  %.3f\n", a / b }'
at_total=0
for g in $GAPS; do
  at=$(count "$EX" f64 at -2 2 1 1000 "$g")
  none=$(count "$EX" f64 none -2 2 1 1000 "$g")
  at_total=$((at_total + (at - none) / 1000))
done
echo "sweep::ellipses_at at a warm speed (the solve alone, no row), mean of the three gaps  $((at_total / 3))"
echo
echo "CPU time a point (user + system, least of 5 runs, 1 thread)"
cpu_us() { # least CPU time of 5 runs of the command, in microseconds
  python3 - "$@" <<'PY'
import resource, subprocess, sys
best = None
for _ in range(5):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    best = t if best is None else min(best, t)
print(round(best * 1e6))
PY
}
t1=$(cpu_us "$BIN" sweep --nu 0.25 --gap 1e-1 --ratio "$RATIOS")
t4=$(cpu_us "$BIN" sweep --nu 0.25 --gap "1e-1,${GAPS// /,}" --ratio "$RATIOS")
sweep_ns=$(((t4 - t1) * 1000 / 30000))
echo "sweep (whole process, marginal)  $sweep_ns ns"
sum=0
for g in $GAPS; do
  indep=$(cpu_us "$EX" f64 indep -2 2 1 10000 "$g")
  none=$(cpu_us "$EX" f64 none -2 2 1 10000 "$g")
  ns=$(((indep - none) * 1000 / 10000))
  sum=$((sum + ns))
  echo "warm solve_ellipse at gap $g  $ns ns"
done
solve_ns=$((sum / 3))
echo "warm solve_ellipse, mean of the three gaps  $solve_ns ns"
awk -v a="$sweep_ns" -v b="$solve_ns" 'BEGIN { printf "sweep / warm solve  %.3f\n", a / b }'
