#!/usr/bin/env bash
# Issue 17's wedge speed check: two orogen binaries, A and B, on the same wedge workload, run in
# turn (A B A B ...) so that both see the same machine; prints each run's stepping rate (the
# run log's "finished ... M particle-steps/s", set-up and outputs not counted), the medians and
# the median of the pair-by-pair ratios B/A, and whether the two wrote the same series.csv.
#   bench/wedge_ab.sh A_BINARY B_BINARY [WORKLOAD] [PAIRS] [THREADS]
# WORKLOAD: main (the main job's default wedge to S = 0.5, the default) or ni (the N(I) preset,
# 17,616 discs, to S = 0.3) or layered (examples/wedge_layered.toml to S = 0.5: bonds, named
# materials); PAIRS: 5; THREADS: 1 (2 = both cores, with run.adapt_threads off
# so that both binaries step on the same number of threads throughout).
# docs/performance.md ("A faster wedge") has the numbers.
set -euo pipefail
cd "$(dirname "$0")/.."
a=$1; b=$2; workload=${3:-main}; pairs=${4:-5}; threads=${5:-1}
case $workload in
  main) args=(--set wedge.s_end=0.5 --set wedge.outputs=2) ;;
  ni) args=(examples/wedge_natural_variability_NI.toml --set wedge.s_end=0.3 --set wedge.outputs=2) ;;
  layered) args=(examples/wedge_layered.toml --set wedge.s_end=0.5 --set wedge.outputs=2) ;;
  *) echo "workload: main, ni or layered, not '$workload'" >&2; exit 2 ;;
esac
work=$(mktemp -d /tmp/orogen_wedge_ab.XXXXXX)
trap 'rm -rf "$work"' EXIT
run_one() {
  OMP_PROC_BIND=true "$1" run "${args[@]}" --threads "$threads" --set run.adapt_threads=false \
    --set output.progress=never --set output.vtp=false --out "$2"
}
source bench/ab_pairs.sh
ab_pairs "$a" "$b" "$pairs" "$work" series.csv "workload $workload, $threads thread(s)"
