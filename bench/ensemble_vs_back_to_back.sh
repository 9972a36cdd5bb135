#!/usr/bin/env bash
# Issue 16's speed check: four N(I) members (the standard resolution, h0 = 20 d, about 17,600
# discs) as one `orogen ensemble` (two members at a time, one thread each, on a 2-core machine)
# against the same four runs back to back on two threads each. Both to S = S_END.
#   bench/ensemble_vs_back_to_back.sh ensemble|sequential [S_END] [WORK_DIR]
# Time each mode as a whole process (e.g. /usr/bin/time -v, alternating the two); docs/performance.md.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=$1; s_end=${2:-1.0}; work=${3:-/tmp/orogen_ensemble_bench}
orogen=${OROGEN:-build/release/orogen}
outputs=$(awk -v s="$s_end" 'BEGIN { n = int(s * 10 + 0.5); print (n < 2 ? 2 : n) }')
rm -rf "$work/$mode" && mkdir -p "$work/$mode"
case $mode in
  ensemble)
    cat > "$work/$mode.toml" <<TOML
[ensemble]
preset = "$PWD/examples/wedge_natural_variability_NI.toml"
title = "N(I)-N(IV), speed check"
seeds = [1, 2, 3, 4]
[ensemble.set]
"wedge.s_end" = $s_end
"wedge.outputs" = $outputs
"output.progress" = "never"
TOML
    "$orogen" ensemble "$work/$mode.toml" --out "$work/$mode/ens" --no-stats > /dev/null 2>&1 ;;
  sequential)
    for seed in 1 2 3 4; do
      "$orogen" run examples/wedge_natural_variability_NI.toml --threads 2 --set run.seed=$seed \
        --set wedge.s_end=$s_end --set wedge.outputs=$outputs --set output.progress=never \
        --out "$work/$mode/seed$seed" > /dev/null 2>&1
    done ;;
  *) echo "mode: ensemble or sequential" >&2; exit 2 ;;
esac
