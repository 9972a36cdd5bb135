#!/usr/bin/env bash
# Runs a queue of long evidence runs, SLOTS at a time at low priority, and picks up where it was
# left: a run whose folder has summary.csv is done and skipped; one with a checkpoint is resumed
# (`orogen run --resume`); a folder without either is left for you to look at; the others start.
# Safe to call again after a stop or a reboot. Paths without spaces.
#
#   scripts/evidence_queue.sh QUEUE_FILE [SLOTS] [BINARY]
#
# QUEUE_FILE: one run per line, "OUT_DIR CONFIG [orogen run options...]" (# comments allowed),
# e.g. "runs/isostasy_full/flexure_seed3 examples/wedge_erosion_EI.toml --set run.seed=3".
# Each run writes OUT_DIR.out beside its folder. SLOTS: runs at once (1). BINARY: orogen
# (build/release/orogen; copy it elsewhere first so that rebuilds do not touch running runs).
set -u
queue=${1:?usage: $0 QUEUE_FILE [SLOTS] [BINARY]}
slots=${2:-1}
binary=${3:-build/release/orogen}
run_one() {
  local binary=$1 out=$2; shift 2
  if [ -f "$out/summary.csv" ]; then echo "$out: done"; return 0; fi
  if [ -f "$out/checkpoint.bin" ]; then
    echo "$out: resuming"
    nice -n 10 "$binary" run --resume "$out" >> "$out.out" 2>&1
  elif [ -e "$out" ]; then
    echo "$out: exists without a checkpoint (stopped before its first?): remove it to start again"; return 0
  else
    echo "$out: starting"
    mkdir -p "$(dirname "$out")"
    nice -n 10 "$binary" run "$@" --out "$out" --threads 1 > "$out.out" 2>&1
  fi
  echo "$out: exit $?"
}
export -f run_one
grep -v '^\s*#' "$queue" | grep -v '^\s*$' |
  while read -r out config options; do printf '%s\0' "$binary $out $config $options"; done |
  xargs -0 -P "$slots" -I{} bash -c 'run_one {}'
