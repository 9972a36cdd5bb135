#!/usr/bin/env bash
# The runs of docs/surface-evidence.md: E(I) at half the thesis's size (h0 = 10, S = 8) with each
# surface preset, the threshold and no erosion (seed 1), and seeds 2 and 3 of the river presets;
# two at a time, each analysed by `orogen analyze`; then the tables. Runs already finished are
# kept. About 20 minutes on two cores.
#   scripts/surface_evidence.sh [OUT_DIR]      (default runs/surface)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-runs/surface}
bin=$PWD/build/release/orogen
small="--set layer.thickness=10 --set wedge.s_end=8 --set wedge.retro_length=10 --set wedge.outputs=40"
small+=" --set output.progress=never --set output.vtp=false --threads 1"
one() {  # folder, preset, extra keys
  [ -f "$out/$1/summary.csv" ] || "$bin" run "$2" --out "$out/$1" $small $3 > /dev/null 2>&1
  "$bin" analyze "$out/$1" > /dev/null
}
mkdir -p "$out/seeds"
one hillslope examples/surface_hillslope.toml "" & one nonlinear examples/surface_nonlinear.toml ""; wait
one fluvial examples/surface_fluvial.toml "" & one windward_pro examples/surface_windward_pro.toml ""; wait
one windward_retro examples/surface_windward_retro.toml "" & one recycling examples/surface_recycling.toml ""; wait
one threshold examples/wedge_erosion_EI.toml "" & one none examples/wedge_erosion_EI.toml "--set wedge.erosion_height=0"; wait
for seed in 2 3; do
  one seeds/fluvial_s$seed examples/surface_fluvial.toml "--set run.seed=$seed" &
  one seeds/windward_pro_s$seed examples/surface_windward_pro.toml "--set run.seed=$seed"; wait
  one seeds/windward_retro_s$seed examples/surface_windward_retro.toml "--set run.seed=$seed"
done
/usr/bin/python3 scripts/surface_table.py "$out"
/usr/bin/python3 scripts/surface_table.py "$out/seeds"
