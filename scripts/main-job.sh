#!/usr/bin/env bash
# The README's first command: install what is missing, build, run the main job and draw it.
# Main job today: the default packing (random discs settling into a layer), rendered as
# PNG frames and an animation. Output in runs/main (replaced on every call).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
rm -rf runs/main
build/release/orogen run --out runs/main
build/release/orogen render runs/main
echo "main job done: runs/main (snapshots.h5, series.csv, run.pvd, frames/, animation.mp4, animation.gif)"
