#!/usr/bin/env bash
# The runs of docs/isostasy-evidence.md: E(I) at half the thesis's size (h0 = 10, S = 8), seed 1,
# on a rigid base, an Airy base and an elastic plate, without surface laws and with the
# recycling preset (river, hillslopes, deposition, half the eroded area recycled); two at a
# time. Runs already finished are kept. About 20 minutes on two cores.
#   scripts/isostasy_evidence.sh [OUT_DIR]      (default runs/isostasy)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-runs/isostasy}
bin=$PWD/build/release/orogen
small="--set layer.thickness=10 --set wedge.s_end=8 --set wedge.retro_length=10 --set wedge.outputs=40"
small+=" --set output.progress=never --set output.vtp=false --threads 1"
flexure="--set isostasy.model=flexure --set isostasy.rigidity=1000"
airy="--set isostasy.model=airy"
bare="examples/wedge_erosion_EI.toml --set wedge.erosion_height=0"
one() {  # folder, preset and extra keys
  local name=$1; shift
  [ -f "$out/$name/summary.csv" ] || "$bin" run "$@" --out "$out/$name" $small > /dev/null 2>&1
}
mkdir -p "$out"
one rigid $bare & one flexure $bare $flexure; wait
one airy $bare $airy & one recycling_rigid examples/surface_recycling.toml; wait
one recycling_flexure examples/isostasy_flexure.toml & one recycling_airy examples/isostasy_airy.toml; wait
/usr/bin/python3 scripts/isostasy_table.py "$out"
