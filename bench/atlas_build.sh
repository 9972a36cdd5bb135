#!/usr/bin/env bash
# Times `orogen report` on a site of N runs (default 100) whose figures exist: N copies of one
# run folder with 100 outputs, rendered (horizons and faults, frames and animations) and
# charted. Prints the cold build (empty site), the update with nothing changed, and the update
# after 5 runs changed. Results: docs/performance.md ("The atlas").
#   bench/atlas_build.sh [--run RUN_DIR] [--n N] [--work DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
orogen=build/release/orogen
export PYTHONPATH="$PWD/python${PYTHONPATH:+:$PYTHONPATH}"  # this tree's package (orogen charts, report)
run="" n=100 work=$(mktemp -d /tmp/atlas_bench.XXXXXX)
while [ $# -gt 0 ]; do
  case "$1" in
    --run) run=$2; shift 2 ;;
    --n) n=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    *) echo "usage: $0 [--run RUN_DIR] [--n N] [--work DIR]" >&2; exit 2 ;;
  esac
done
[ -x "$orogen" ] || { echo "build $orogen first (cmake --preset release && ninja -C build/release orogen)" >&2; exit 2; }
if [ -z "$run" ]; then  # a small wedge with the output count of a real run, and its figures
  run=$work/source
  $orogen run --out "$run" --threads 1 --set layer.thickness=5 --set wedge.tile_length=4 --set wedge.retro_length=4 \
    --set wedge.initial_active=4 --set wedge.s_end=2 --set wedge.outputs=100 --set output.vtp=false \
    --set output.progress=never 2>/dev/null
  $orogen render "$run" --width 800 >/dev/null
  $orogen render "$run" --width 800 --color field:max_rel_disp --frames-dir frames_faults >/dev/null
  $orogen charts "$run" >/dev/null
fi
mkdir -p "$work/runs"
for i in $(seq -w 1 "$n"); do
  [ -d "$work/runs/run_$i" ] || cp -a "$run" "$work/runs/run_$i"  # real copies: n times the files
done
echo "$n runs of $(find "$run" -type f | wc -l) files each ($(du -sh "$work/runs" | cut -f1)) in $work/runs"
rm -rf "$work/site"
t() { local s e; s=$(date +%s.%N); "$@" >/dev/null; e=$(date +%s.%N); echo "$e - $s" | bc; }
echo "cold build:          $(t $orogen report "$work/runs" --out "$work/site") s"
echo "update, no change:   $(t $orogen report "$work/runs" --out "$work/site") s"
for i in $(seq -w 1 5); do touch "$work/runs/run_$(printf "%0${#n}d" "$i")/series.csv"; done
echo "update, 5 changed:   $(t $orogen report "$work/runs" --out "$work/site") s"
echo "site: $(du -sh "$work/site" | cut -f1) (frames hard-linked where the file system allows)"
