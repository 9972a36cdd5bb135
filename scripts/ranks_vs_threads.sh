#!/usr/bin/env bash
# One run on 1 thread, on 2 threads and on 2 MPI ranks of 1 thread each, ROUNDS rounds
# interleaved (docs/domain-decomposition.md, "First measurement"): the loop time and stepping
# rate of each run's log, and whether the 2 ranks' checkpoint is the 1 thread's, byte for byte.
# Run it on a machine at rest. Default: N(I) to S = 1. KEYS replaces the default keys (a wedge's
# end and outputs) for other experiments. The 2 ranks' `exchange: ...` log line (rank 0's messages,
# bytes and waits per step) of every round is kept in OUT_DIR/r2.log.
#   scripts/ranks_vs_threads.sh [CONFIG] [ROUNDS] [OUT_DIR]
#   KEYS="--set layer.length=6700" scripts/ranks_vs_threads.sh examples/packing_layer_1000x20.toml 2
set -u
cd "$(dirname "$0")/.."
config=${1:-examples/wedge_natural_variability_NI.toml}
rounds=${2:-3}
out=${3:-$(mktemp -d /tmp/ranks_vs_threads.XXXXXX)}
bin=$PWD/build/release/orogen
keys=${KEYS:-"--set wedge.s_end=1 --set wedge.outputs=2"}
keys+=" --set output.progress=never --set output.vtp=false --set run.adapt_threads=false"
rate() { grep finished "$1/run.log" | sed 's/.*steps in \([0-9.]*\) s (\([0-9.]*\) M.*/\1 s, \2 M particle-steps\/s/'; }
for round in $(seq "$rounds"); do
  rm -rf "$out"/t1 "$out"/t2 "$out"/r2
  "$bin" run "$config" $keys --threads 1 --out "$out/t1" > /dev/null 2>&1
  echo "round $round, 1 thread: $(rate "$out/t1")"
  OMP_PROC_BIND=false "$bin" run "$config" $keys --threads 2 --out "$out/t2" > /dev/null 2>&1
  echo "round $round, 2 threads: $(rate "$out/t2")"
  mpirun --allow-run-as-root -n 2 "$bin" run "$config" $keys --threads 1 --out "$out/r2" > /dev/null 2>&1
  echo "round $round, 2 ranks: $(rate "$out/r2")"
  grep "exchange:" "$out/r2/run.log" >> "$out/r2.log"
  cmp -s "$out/t1/checkpoint.bin" "$out/r2/checkpoint.bin" && echo "round $round: the same bits" ||
    echo "round $round: the checkpoints DIFFER"
done
