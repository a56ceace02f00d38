#!/usr/bin/env bash
# Wall times of the commands that run sweeps (`fig2` at f64 and double-double, `study poisson`)
# at HEAD against the last commit before the library sweep (73027fb), both release builds of
# the command-line tool, run alternately (base, head, base, head, …) and timed from outside the
# process (from the fork to the exit, as /usr/bin/time), each writing into a directory of its
# own. Prints the minimum and the median wall time of each command over the rounds and
# head/base.
#
# Run from the repository root: bash tools/sweep_wall_times.sh > docs/data/sweep_wall_times.txt
# (the two builds share one target directory: the first compiles GMP and MPFR, about five
# minutes; then about two minutes of runs). ROUNDS=N sets the number of rounds (default 20).
set -euo pipefail
export LC_ALL=C
# EPOCHREALTIME needs bash 5.
[ -n "${EPOCHREALTIME:-}" ] || { echo "bash 5 or later needed (EPOCHREALTIME)" >&2; exit 1; }
BASE=73027fb
ROUNDS=${ROUNDS:-20}
WORK=${TMPDIR:-/tmp}/moving-hertz-sweep-times
mkdir -p "$WORK"
rm -rf "$WORK/base" "$WORK/head" "$WORK/out" "$WORK/times"
git worktree add -q --detach "$WORK/base" "$BASE"
git worktree add -q --detach "$WORK/head" HEAD
trap 'git worktree remove --force "$WORK/base"; git worktree remove --force "$WORK/head"' EXIT
for t in base head; do
  (cd "$WORK/$t" && CARGO_TARGET_DIR="$WORK/target" cargo build -q --release --bin moving-hertz)
  cp "$WORK/target/release/moving-hertz" "$WORK/$t.bin"
done
mkdir -p "$WORK/out" "$WORK/times"
CMDS=("fig2" "fig2 --precision dd" "study poisson")
for round in $(seq "$ROUNDS"); do
  for i in "${!CMDS[@]}"; do
    for t in base head; do
      out="$WORK/out/$t.$i"
      rm -rf "$out"
      # Bash's microsecond clock around the process, as /usr/bin/time measures it from the
      # fork to the exit (its %e has 10 ms steps, as long as fig2; a `date` process on each
      # side would add its own start, about 1 ms here, to every time).
      t0=$EPOCHREALTIME
      # shellcheck disable=SC2086
      "$WORK/$t.bin" ${CMDS[$i]} --out "$out" > /dev/null
      t1=$EPOCHREALTIME
      awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.5f\n", b - a }' >> "$WORK/times/$t.$i"
    done
  done
done
stats() { sort -g "$1" | awk '{ v[NR] = $1 } END { m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2;
  printf "%.4f %.4f", v[1], m }'; }
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')
echo "# bash tools/sweep_wall_times.sh   (HEAD $(git rev-parse --short HEAD) against $BASE, the last commit before the library sweep; $(date -u +%Y-%m-%d), $cpu, $(nproc) cores)"
echo "wall seconds over $ROUNDS alternating rounds: command | base min, median | head min, median | head/base of the minima, of the medians"
for i in "${!CMDS[@]}"; do
  read -r bmin bmed <<< "$(stats "$WORK/times/base.$i")"
  read -r hmin hmed <<< "$(stats "$WORK/times/head.$i")"
  awk -v c="${CMDS[$i]}" -v a="$bmin" -v b="$bmed" -v x="$hmin" -v y="$hmed" \
    'BEGIN { printf "%-22s | %7.4f %7.4f | %7.4f %7.4f | %5.2f %5.2f\n", c, a, b, x, y, x / a, y / b }'
done
