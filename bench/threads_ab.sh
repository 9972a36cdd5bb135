#!/usr/bin/env bash
# Issue 41 point 5: what a user's default run gains from the second core. One orogen binary,
# in turn (one, default, one, default ...): A = `--threads 1`, B = the defaults a user runs
# (every core, the thread tuner on, no OMP_* variables set). Prints each run's stepping rate
# (the run log's "finished ... M particle-steps/s"), the medians and the median of the pair-by-
# pair ratios B/A, and whether both wrote the same series.csv (they must: results do not depend
# on the thread count).
#   bench/threads_ab.sh BINARY WORKLOAD [PAIRS]
# WORKLOAD: main (the main job whole, to S = 8), main-half (to S = 4), or from RUN_DIR S_END
# (a branch from the last output of RUN_DIR to S_END, set-up not timed: e.g. an N(I) run,
# examples/wedge_natural_variability_NI.toml, 22,000 discs). PAIRS: 3. docs/performance.md
# ("Two threads by default").
set -euo pipefail
cd "$(dirname "$0")/.."
orogen_bin=$1; workload=$2; shift 2
case $workload in
  main) args=(--set output.vtp=false) ;;
  main-half) args=(--set wedge.s_end=4 --set wedge.outputs=50 --set output.vtp=false) ;;
  from) src=$1; s_end=$2; shift 2 ;;
  *) echo "workload: main, main-half or from RUN_DIR S_END, not '$workload'" >&2; exit 2 ;;
esac
pairs=${1:-3}
work=$(mktemp -d /tmp/orogen_threads_ab.XXXXXX)
trap 'rm -rf "$work"' EXIT
run_one() {  # $1: "one" or "default"
  local threads=()
  [ "$1" = one ] && threads=(--threads 1)
  if [ "$workload" = from ]; then
    env -u OMP_PROC_BIND -u OMP_PLACES -u OMP_NUM_THREADS -u OMP_WAIT_POLICY \
      "$orogen_bin" run --from "$src" --out "$2" --set wedge.s_end="$s_end" "${threads[@]}" --set output.progress=never
  else
    env -u OMP_PROC_BIND -u OMP_PLACES -u OMP_NUM_THREADS -u OMP_WAIT_POLICY \
      "$orogen_bin" run "${args[@]}" "${threads[@]}" --set output.progress=never --out "$2"
  fi
}
source bench/ab_pairs.sh
ab_pairs one default "$pairs" "$work" series.csv "workload $workload, --threads 1 (A) against the defaults (B)"
grep -h '^.*threads: ' "$work/b/run.log" | tail -1
