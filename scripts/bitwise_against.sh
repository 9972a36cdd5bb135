#!/usr/bin/env bash
# Runs small runs of every experiment (and a layered crust) with two orogen binaries and compares
# series.csv, checkpoint.bin and bond_breaks.csv byte for byte (a change that must not alter results: refactorings of the
# engine). Usage: scripts/bitwise_against.sh REFERENCE_BINARY [NEW_BINARY] [OUT_DIR]
# Exit 1 if any pair differs. OROGEN_MIN_PARALLEL_ITEMS=16 sends the small runs down the
# parallel paths with two threads.
set -u
ref=${1:?usage: $0 REFERENCE_BINARY [NEW_BINARY] [OUT_DIR]}
new=${2:-build/release/orogen}
out=${3:-$(mktemp -d /tmp/bitwise.XXXXXX)}
mkdir -p "$out"
export OROGEN_MIN_PARALLEL_ITEMS=16
quiet="--set output.progress=never --set output.vtp=false --threads 2"
declare -A runs=(
  [wedge_default]="--set wedge.s_end=0.5 --set wedge.outputs=5"
  [wedge_erosion]="--set layer.thickness=5 --set wedge.tile_length=4 --set wedge.retro_length=4 --set wedge.initial_active=4 --set wedge.s_end=0.6 --set wedge.outputs=4 --set wedge.erosion_height=0.9"
  [wedge_constant_velocity]="--set wedge.basal=constant_velocity --set layer.thickness=6 --set wedge.s_end=0.5 --set wedge.outputs=4"
  [wedge_inflow]="--set layer.thickness=5 --set wedge.tile_length=1 --set wedge.retro_length=4 --set wedge.initial_active=4 --set wedge.s_end=2.5 --set wedge.outputs=5"
  [packing]="--set run.experiment=packing --set particles.packing=random_clusters --set layer.length=40 --set layer.thickness=8"
  [repose_slump]="--set run.experiment=repose --set particles.packing=random_clusters --set repose.size=16 --set repose.min_time=5 --set repose.max_time=15"
  [repose_ledge]="--set run.experiment=repose --set repose.variant=ledge --set repose.size=16 --set repose.min_time=5 --set repose.max_time=15"
  [singly]="--set run.experiment=singly_vergent --set particles.packing=random_discs --set layer.length=60 --set layer.thickness=6 --set contact.kn=2000 --set singly.speed=0.05 --set singly.shortening=1 --set singly.outputs=5"
  [wedge_layered]="examples/wedge_layered.toml --set wedge.s_end=0.2 --set wedge.outputs=2"
  [buiter_exp2]="examples/buiter2016_exp2.toml --set singly.shortening=0.1 --set singly.outputs=2"
  [biaxial]="--set run.experiment=biaxial --set particles.packing=random_clusters --set biaxial.width=10 --set biaxial.height=20 --set biaxial.strain_rate=5e-4 --set biaxial.strain_end=0.02 --set biaxial.outputs=6"
)
status=0
for name in $(printf '%s\n' "${!runs[@]}" | sort); do
  for which in ref new; do
    bin=$ref; [ "$which" = new ] && bin=$new
    "$bin" run ${runs[$name]} $quiet --out "$out/$name.$which" > "$out/$name.$which.log" 2>&1 ||
      { echo "$name: $which failed (see $out/$name.$which.log)"; status=1; }
  done
  for f in series.csv checkpoint.bin bond_breaks.csv; do
    [ "$f" = bond_breaks.csv ] && [ ! -f "$out/$name.ref/$f" ] && continue
    if cmp -s "$out/$name.ref/$f" "$out/$name.new/$f"; then echo "$name $f: same"; else echo "$name $f: DIFFERS"; status=1; fi
  done
done
exit $status
