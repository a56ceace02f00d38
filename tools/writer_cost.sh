#!/usr/bin/env bash
# The writer's share of a long f64 sweep, seen from outside the process: wall, user and system
# seconds and voluntary context switches (GNU time) of the issue's 10⁶-point sweep at 1 and 2
# threads, for two builds of the command-line tool run alternately, ROUNDS rounds (default 5);
# prints each build's minimum wall time and median system seconds and context switches.
# System time and context switches are what callgrind does not see: each write to standard
# output and each wake-up of the writer is a system call, serial in the writer thread.
#
# Run from the repository root: bash tools/writer_cost.sh BASE_BIN HEAD_BIN > docs/data/writer_cost.txt
set -euo pipefail
export LC_ALL=C
BASE=$1
HEAD=$2
ROUNDS=${ROUNDS:-5}
JOB="sweep --nu 0.25 --gap log:1e-1:1e-8:50 --ratio log:1e-2:1e2:20000"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
for _ in $(seq "$ROUNDS"); do
  for t in 1 2; do
    for b in base head; do
      bin=$BASE
      [ "$b" = head ] && bin=$HEAD
      # shellcheck disable=SC2086
      /usr/bin/time -a -o "$TMP/$b.$t" -f "%e %U %S %w" env RAYON_NUM_THREADS=$t "$bin" $JOB > /dev/null
    done
  done
done
echo "# bash tools/writer_cost.sh (base $(basename "$BASE"), head $(basename "$HEAD")); $JOB; $ROUNDS alternating rounds, $(nproc) CPUs"
echo "build threads | wall min (s) | user median (s) | system median (s) | voluntary context switches median"
for t in 1 2; do
  for b in base head; do
    sort -g "$TMP/$b.$t" | awk -v b="$b" -v t="$t" '
      { w[NR] = $1; u[NR] = $2; s[NR] = $3; c[NR] = $4 }
      function med(a, n,   i, j, x, v) { for (i = 1; i <= n; i++) v[i] = a[i];
        for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (v[j] < v[i]) { x = v[i]; v[i] = v[j]; v[j] = x }
        return v[int((n + 1) / 2)] }
      END { printf "%-5s %7d | %12.3f | %15.2f | %17.2f | %d\n", b, t, w[1], med(u, NR), med(s, NR), med(c, NR) }'
  done
done
