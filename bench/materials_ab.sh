#!/usr/bin/env bash
# Issue 39's cost of a layered, bonded crust: the main job's wedge (A: the thesis's one
# material) against the same wedge built of examples/wedge_layered.toml's materials (B: a
# weak base, a bonded, weakening rock, a cover), one binary, run in turn (A B A B ...) to
# S = S_END; prints each run's stepping rate per particle-step (the run log's "finished ... M
# particle-steps/s": the bonded wedge steps at a smaller dt, so the rate per particle-step is
# what compares), the medians and the median ratio B/A, and each run's peak memory.
#   bench/materials_ab.sh [BINARY] [PAIRS] [THREADS] [S_END] [CONFIG_B]
# BINARY: build/release/orogen; PAIRS: 5; THREADS: 1; S_END: 0.5; CONFIG_B: examples/wedge_layered.toml
# (examples/wedge_cohesion.toml: one bonded material, no weakening).
# docs/performance.md ("A bonded crust") has the numbers.
set -euo pipefail
cd "$(dirname "$0")/.."
orogen_bin=${1:-build/release/orogen}; pairs=${2:-5}; threads=${3:-1}; s_end=${4:-0.5}
config_b=${5:-examples/wedge_layered.toml}
work=$(mktemp -d /tmp/orogen_materials_ab.XXXXXX)
trap 'rm -rf "$work"' EXIT
run_one() {
  local config=()
  [ "$1" = bonded ] && config=("$config_b")
  OMP_PROC_BIND=true /usr/bin/time -f "peak memory %M kB" "$orogen_bin" run "${config[@]}" --threads "$threads" \
    --set run.adapt_threads=false --set wedge.s_end="$s_end" --set wedge.outputs=2 --set output.progress=never \
    --set output.vtp=false --out "$2"
}
source bench/ab_pairs.sh
ab_pairs plain bonded "$pairs" "$work" config.toml "main wedge A: one material, B: $config_b, $threads thread(s)"
for which in a b; do
  echo "$which: $(grep -o 'peak memory.*' "$work/$which.out"), $(grep -o '[0-9]* discs' "$work/$which/run.log" | tail -1)," \
    "$(grep -o 'intact: [0-9]*' "$work/$which/bond_breaks.csv" 2>/dev/null || echo 'no') bonds"
done
