#!/usr/bin/env bash
# The many-core measurements of docs/performance.md ("Many cores") on a machine that has the
# cores but no Rust toolchain: the built command-line tool and the built `benches/scaling.rs`
# are carried there and run by this script. Writes into OUT:
#   cpu.txt      the processor and the CPU count;
#   scaling.txt  `benches/scaling.rs` (criterion, 1, 2 and all threads) as tools/scaling_table.py prints it;
#   threads.txt  each job of benches/scaling.rs at 1, 2, 4, 8, … all threads: the minimum wall
#                time of 3 runs (one process, RAYON_NUM_THREADS set, output to /dev/null) and
#                the speed-up over one thread;
#   ceiling.txt  the machine's own ceiling for each job: as many one-thread copies of it as
#                CPUs, run at once (minimum of 3), against one copy alone: CPUs × T1 / T(all at
#                once) is the most any thread count can gain when every core is busy (the clock
#                a processor keeps with all its cores loaded, shared caches and memory);
#   bits.txt     the SHA-256 of each sweep's output at 1, 2 and all threads (equal: a point's bits
#                depend only on its block, never on the thread count);
#   cells.txt    the warm f64 ellipse solve in the 12 cells of benches/ellipse.rs
#                (`ellipse --repeat 1000`, median and minimum nanoseconds).
#
# Build here:  cargo build --release && cargo bench --bench scaling --no-run
#              mkdir -p .dev && cp target/release/moving-hertz .dev/ &&
#              cp "$(ls -t target/release/deps/scaling-* | grep -v '\.d$' | head -1)" .dev/scaling
# (.dev is listed in .git/info/exclude). Run there, from the repository root:
#              bash tools/many_cores.sh .dev OUT
# The bench binary runs the tool from the path it was built at (target/release/moving-hertz
# under the checkout it was built in); the script puts the carried tool there first.
set -euo pipefail
export LC_ALL=C
[ -n "${EPOCHREALTIME:-}" ] || { echo "bash 5 or later needed (EPOCHREALTIME)" >&2; exit 1; }
DEV=$1
OUT=$2
BIN=$(realpath "$DEV/moving-hertz")
mkdir -p "$OUT"
CPUS=$(nproc)
{ grep -m1 'model name' /proc/cpuinfo; echo "CPUs: $CPUS"; } > "$OUT/cpu.txt"

# The path the bench binary runs the tool from.
built=$(grep -a -o '/[^ ]*target/release/moving-hertz' "$DEV/scaling" | head -1)
if [ "$built" != "$BIN" ]; then
  mkdir -p "$(dirname "$built")"
  cp -f "$BIN" "$built"
fi
"$DEV/scaling" --bench > "$OUT/bench.log" 2>&1
python3 tools/scaling_table.py > "$OUT/scaling.txt"

JOBS=(
  "sweep_f64|sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio log:1e-2:1e2:20000"
  "sweep_dd|sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio log:1e-2:1e2:2000 --precision dd"
  "sweep_256|sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio log:1e-2:1e2:100 --precision 256"
  "fig2_256|fig2 --precision 256 --out OUTDIR"
  "fig2_f64|fig2 --out OUTDIR"
)
COUNTS=(1)
t=2
while [ "$t" -lt "$CPUS" ]; do COUNTS+=("$t"); t=$((t * 2)); done
COUNTS+=("$CPUS")

wall() { # threads, args: the minimum of 3 wall times in seconds
  local best=""
  for _ in 1 2 3; do
    local t0=$EPOCHREALTIME
    # shellcheck disable=SC2086
    RAYON_NUM_THREADS=$1 "$BIN" ${2//OUTDIR/$OUT/fig2} > /dev/null
    local t1=$EPOCHREALTIME
    best=$(awk -v a="$t0" -v b="$t1" -v m="$best" 'BEGIN { d = b - a; if (m == "" || d < m) m = d; printf "%.4f", m }')
  done
  echo "$best"
}
{
  echo "# bash tools/many_cores.sh: minimum wall time of 3 runs, one process, RAYON_NUM_THREADS set, output to /dev/null; $(cut -d: -f2 "$OUT/cpu.txt" | head -1 | sed 's/^ //'), $CPUS CPUs"
  printf "%-10s %7s %10s %9s %11s\n" job threads seconds speed-up efficiency
  for job in "${JOBS[@]}"; do
    name=${job%%|*}
    args=${job#*|}
    one=""
    for n in "${COUNTS[@]}"; do
      s=$(wall "$n" "$args")
      [ -n "$one" ] || one=$s
      awk -v j="$name" -v n="$n" -v s="$s" -v o="$one" \
        'BEGIN { printf "%-10s %7d %10.4f %9.2f %11.2f\n", j, n, s, o / s, o / s / n }'
    done
  done
} > "$OUT/threads.txt"

together() { # args: the minimum of 3 wall times of $CPUS one-thread copies run at once
  local best=""
  for _ in 1 2 3; do
    local t0=$EPOCHREALTIME
    for c in $(seq "$CPUS"); do
      # shellcheck disable=SC2086
      RAYON_NUM_THREADS=1 "$BIN" ${1//OUTDIR/$OUT/copy$c} > /dev/null &
    done
    wait
    local t1=$EPOCHREALTIME
    best=$(awk -v a="$t0" -v b="$t1" -v m="$best" 'BEGIN { d = b - a; if (m == "" || d < m) m = d; printf "%.4f", m }')
  done
  echo "$best"
}
{
  echo "# $CPUS one-thread copies of each job at once (minimum of 3) against one alone (threads.txt): the gain every core can give"
  printf "%-10s %10s %12s %9s\n" job one-alone all-at-once ceiling
  for job in "${JOBS[@]:0:4}"; do
    name=${job%%|*}
    one=$(awk -v j="$name" '$1 == j && $2 == 1 { print $3 }' "$OUT/threads.txt")
    all=$(together "${job#*|}")
    awk -v j="$name" -v o="$one" -v a="$all" -v n="$CPUS" \
      'BEGIN { printf "%-10s %10.4f %12.4f %9.2f\n", j, o, a, n * o / a }'
  done
} > "$OUT/ceiling.txt"
rm -rf "$OUT"/copy*

{
  echo "# SHA-256 of each sweep's output at 1, 2 and $CPUS threads"
  for job in "${JOBS[@]:0:3}"; do
    for n in 1 2 "$CPUS"; do
      # shellcheck disable=SC2086
      printf "%-10s %3d %s\n" "${job%%|*}" "$n" "$(RAYON_NUM_THREADS=$n "$BIN" ${job#*|} | sha256sum | cut -c1-16)"
    done
  done
} > "$OUT/bits.txt"

{
  echo "# warm f64 ellipse solve, ν = 0.25: moving-hertz ellipse --repeat 1000 (median, minimum ns)"
  for m in 0.5 0.99 0.999 0.9999; do
    for r in 0.01 0.5 2; do
      printf "M_R=%-7s A1/B1=%-5s %s\n" "$m" "$r" \
        "$("$BIN" ellipse --nu 0.25 --speed "$m" --ratio "$r" --repeat 1000 | grep 'time per solve' | sed 's/.*runs: //')"
    done
  done
} > "$OUT/cells.txt"
rm -rf "$OUT/fig2"
