#!/usr/bin/env bash
# The README's first command: install what is missing, build, run the main job and draw it.
# Main job: the default doubly-vergent wedge (traction basal condition, random 3-disc clusters,
# h0 = 10 d, S up to 8), with PNG frames, an animation and the charts. Output in runs/main
# (replaced on every call).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
scripts/install-python.sh   # the Python package orogen: charts, statistics, atlas (docs/python.md)
rm -rf runs/main
build/release/orogen run --out runs/main
# The faults of every output (faults.csv), drawn on the fault frames (docs/materials.md).
/usr/bin/python3 -m orogen.analysis.faults runs/main
# Cross-sections: horizon and fault frames with their animations, PNG and PDF stills of the
# last output (python3 -m orogen.charts.sections; docs/rendering.md).
build/release/orogen sections runs/main
build/release/orogen charts runs/main   # python3 -m orogen.charts.wedge runs/main --out runs/main/charts
echo "main job done: runs/main (series.csv, snapshots.h5, run.pvd, frames/, frames_faults/, faults.csv, animation*.mp4/.gif, sections/, charts/)"
