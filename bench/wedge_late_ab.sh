#!/usr/bin/env bash
# A late stage of a long wedge, A against B: each binary in turn resumes a copy of a finished
# (or killed) run folder and extends it to S_END, on two threads with the thread tuner off, and
# the run log's stepping rate is compared (pair by pair, medians). The copies hard-link the
# run's large files (snapshots, checkpoint), which a resume replaces by rename and never
# rewrites in place, so the source folder is left as it was; both binaries must read its
# checkpoint.
#   bench/wedge_late_ab.sh A_BINARY B_BINARY RUN_DIR S_END [PAIRS]
# S_END must be a whole number of the run's output spacing (orogen says which if not), e.g.
# 21.21 for the N(I) preset finished at S = 21. docs/performance.md has the numbers.
set -euo pipefail
a=$1; b=$2; src=$3; s_end=$4; pairs=${5:-3}
work=$(mktemp -d /tmp/orogen_late_ab.XXXXXX)
trap 'rm -rf "$work"' EXIT
copy_run() {
  mkdir "$1"
  for f in "$src"/*; do
    case $(basename "$f") in
      run.lock) ;;
      snapshots|vtp) cp -al "$f" "$1/" ;;
      *.bin|*.h5) ln "$f" "$1/$(basename "$f")" ;;
      *) cp -r "$f" "$1/" ;;
    esac
  done
}
run_one() {
  copy_run "$2"
  OMP_PROC_BIND=true "$1" run --resume "$2" --set wedge.s_end="$s_end" --threads 2 \
    --set run.adapt_threads=false --set output.progress=never --set output.vtp=false
}
source "$(dirname "$0")/ab_pairs.sh"
ab_pairs "$a" "$b" "$pairs" "$work" checkpoint.bin "late stage to S = $s_end, 2 threads"
