#!/usr/bin/env bash
# Per-solve cost of the f64, double-double and 256-bit ellipse solve (nu = 0.2, A1/B1 = 0.5,
# M_R in {0.5, 0.9, 0.999, 0.9999}) at HEAD against the last commit before the
# public API (26b8fbb), each through its own API: the same harness, built in two worktrees.
# Prints wall-clock minima per solve (six alternating runs) and, with valgrind installed, the
# f64 instruction count per solve at each M_R (callgrind, 200 solves minus 100).
#
# Run from the repository root: bash tools/pre_api_cost.sh > docs/data/pre_api_cost.txt
# (about five minutes, cold; the cargo builds' output goes to stderr)
set -euo pipefail
BASE=26b8fbb
WORK=${TMPDIR:-/tmp}/moving-hertz-pre-api
mkdir -p "$WORK"
rm -rf "$WORK/base" "$WORK/head" "$WORK"/base.* "$WORK"/head.*
git worktree add -q --detach "$WORK/base" "$BASE"
git worktree add -q --detach "$WORK/head" HEAD
trap 'git worktree remove --force "$WORK/base"; git worktree remove --force "$WORK/head"' EXIT

harness() { # $1: imports, $2: the solve of (mat, sp, ratio)
cat <<RS
$1
use moving_hertz::scalar::{Dd, Mp, MpPrec, Real};
use std::hint::black_box;
use std::time::Instant;
fn run<T: Real>(label: &str, p: T::Prec, reps: usize) {
    let mat = Material::new(T::parse("0.2", p).unwrap()).unwrap();
    let ratio = T::parse("0.5", p).unwrap();
    for mr in ["0.5", "0.9", "0.999", "0.9999"] {
        let sp = mat.speed(T::parse(mr, p).unwrap()).unwrap();
        let mut best = f64::INFINITY;
        for _ in 0..7 {
            let t = Instant::now();
            for _ in 0..reps { black_box($2); }
            best = best.min(t.elapsed().as_secs_f64() / reps as f64);
        }
        println!("{label} M_R={mr} {:.0}", best * 1e9);
    }
}
fn main() {
    if let Some(n) = std::env::args().nth(1) {
        let (mat, ratio) = (Material::new(0.2f64).unwrap(), 0.5f64);
        let mr: f64 = std::env::args().nth(2).map_or(0.9, |s| s.parse().unwrap());
        let sp = mat.speed(mr).unwrap();
        for _ in 0..n.parse::<usize>().unwrap() { black_box($2); }
        return;
    }
    run::<f64>("f64", (), 20000);
    run::<Dd>("dd", (), 2000);
    run::<Mp>("mpfr256", MpPrec::new(256).unwrap(), 100);
}
RS
}
harness "use moving_hertz::contact::ellipse::{solve_ellipse_with, EllipseMethod};
use moving_hertz::physics::Material;" \
  "solve_ellipse_with(black_box(&mat), black_box(&sp), black_box(&ratio), EllipseMethod::Auto).unwrap()" \
  > "$WORK/base/examples/pre_api_cost.rs"
harness "use moving_hertz::{solve_ellipse, Material, Options};" \
  "solve_ellipse(black_box(&sp), black_box(&ratio), &Options::default()).unwrap()" \
  > "$WORK/head/examples/pre_api_cost.rs"
for t in base head; do
  (cd "$WORK/$t" && CARGO_TARGET_DIR="$WORK/target-$t" cargo build -q --release --example pre_api_cost)
done
bin() { echo "$WORK/target-$1/release/examples/pre_api_cost"; }
ROUNDS=6
for round in $(seq $ROUNDS); do
  for t in base head; do "$(bin $t)" > "$WORK/$t.$round"; done
done
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')
echo "# bash tools/pre_api_cost.sh   (HEAD $(git rev-parse --short HEAD) against $BASE, the last commit before the public API; $(date -u +%Y-%m-%d), $cpu, $(nproc) cores)"
echo "ns per solve (minimum over $ROUNDS alternating runs): base $BASE, head, head/base"
# Each file has lines "label M_R=… ns"; the minimum of column 3 over the rounds, per line.
for t in base head; do
  for r in $(seq $ROUNDS); do cat "$WORK/$t.$r"; done | awk '{ k = $1 " " $2; if (!(k in m) || $3 < m[k]) m[k] = $3;
    if (!(k in seen)) { seen[k] = 1; order[n++] = k } }
    END { for (i = 0; i < n; i++) print order[i], m[order[i]] }' > "$WORK/$t.min"
done
paste "$WORK/base.min" "$WORK/head.min" |
  awk '{ printf "%-8s %-12s %10d %10d %7.3f\n", $1, $2, $3, $6, $6 / $3 }'
if command -v valgrind > /dev/null; then
  echo "f64 instructions per solve (callgrind, 200 solves minus 100): M_R, base, head, head/base"
  for mr in 0.5 0.9 0.999 0.9999; do
    row=()
    for t in base head; do
      c=()
      for n in 100 200; do
        c+=("$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$(bin $t)" $n $mr 2>&1 |
          sed -n 's/.*Collected : //p')")
      done
      row+=($(( (c[1] - c[0]) / 100 )))
    done
    awk -v m=$mr -v b=${row[0]} -v h=${row[1]} 'BEGIN { printf "%-8s %8d %8d %7.3f\n", m, b, h, h / b }'
  done
fi
