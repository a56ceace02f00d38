#!/usr/bin/env bash
# Instructions per warm ellipse solve on the 12 cells of the cost target (nu = 0.25,
# M_R in {0.5, 0.99, 0.999, 0.9999} x A1/B1 in {0.01, 0.5, 2}), at f64, double-double and
# MPFR 256 bits: callgrind counts the region `measured` of examples/solve_cells.rs (REPEAT warm
# solves of one cell, after one solve outside it, which builds the speed's fixed-rule set-up),
# divided by REPEAT; f64-fresh: the f64 solve at a speed made anew each time (set-up included).
# Repeatable to a few instructions on a loaded machine, unlike wall times.
#
# Run from the repository root: bash tools/solve_cells_count.sh [BIN]
# (BIN: a solve_cells binary, by default the one `cargo build --release --example solve_cells`
# leaves; about five minutes under valgrind.)
set -euo pipefail
BIN=${1:-target/release/examples/solve_cells}
[ $# -ge 1 ] || cargo build -q --release --example solve_cells
echo "# instructions per solve (callgrind, region 'measured' / REPEAT); cell = M_R, A1/B1"
for prec in f64:20 f64-fresh:20 dd:10 256:4; do
  p=${prec%:*}; reps=${prec#*:}
  for i in $(seq 0 11); do
    n=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null --toggle-collect='*measured*' \
      "$BIN" "$p" "$i" "$reps" 2>&1 | sed -n 's/.*Collected : //p')
    cell=$("$BIN" "$p" "$i" 0 | sed 's/: k = .*//; s/ *//g')
    echo "$p $cell $((n / reps))"
  done
done
