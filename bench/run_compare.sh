#!/bin/bash
# Side-by-side benchmark: LAMMPS (GRANULAR pile, bench/lammps) against Orogen's
# bench_pile on the same problem, same machine, same sitting. Builds nothing: build bench_pile
# first (cmake --build build/release --target bench_pile).
#
# usage: bench/run_compare.sh            (environment variables below change the defaults)
#   NS="5000 20000 80000"  MODES="static push"  REPEATS=3  OROGEN_THREADS="1,2"
#   STEPS_5000=10000 STEPS_20000=5000 STEPS_80000=2000   (timed steps per size; STEPS for others;
#     LAMMPS's README uses 20000/20000/5000: fine on a quiet machine, about 2x the run time)
#   OROGEN_OMP_WAIT_POLICY=passive   (libgomp's default spinning makes 2-thread runs ~100x slower
#     when the 2 cores are shared with other jobs; "" restores the default)
#   BENCH=build/release/bench_pile  LAMMPS_DIR=bench/lammps  LMP=lmp
#   SETTLE (settling steps for every size; default 30000, 40000 for N >= 80000 as LAMMPS's README)
#   OUT=bench/results/compare-<date>.md   KEEP=1 keeps the work directory
# Needs: lmp (Debian package lammps), mpirun (openmpi-bin, for LAMMPS's 2-rank settling),
# /usr/bin/time, python3.
#
# Per size: LAMMPS settles (run_bench.sh, 2 ranks, SETTLE=30000, 40000 for N >= 80000) and
# Orogen settles (same step counts, saved with --save, untimed). Then, for each repeat and mode,
# one LAMMPS run (1 rank) and one Orogen run (each thread count) follow each other, so that
# both codes see the same machine load. The table reports medians over the repeats.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BENCH=${BENCH:-$ROOT/build/release/bench_pile}
LAMMPS_DIR=${LAMMPS_DIR:-$ROOT/bench/lammps}
LMP_BIN=${LMP:-lmp}
NS=${NS:-"5000 20000 80000"}
MODES=${MODES:-"static push"}
REPEATS=${REPEATS:-3}
OROGEN_THREADS=${OROGEN_THREADS:-"1,2"}
WAIT_POLICY=${OROGEN_OMP_WAIT_POLICY-passive}
DATE=$(date +%Y-%m-%d)
OUT=${OUT:-$ROOT/bench/results/compare-$DATE.md}
RAWOUT=${OUT%.md}.raw.txt

steps_for() {
  case $1 in
    5000) echo "${STEPS_5000:-10000}" ;;
    20000) echo "${STEPS_20000:-5000}" ;;
    80000) echo "${STEPS_80000:-2000}" ;;
    *) echo "${STEPS:-10000}" ;;
  esac
}
settle_for() {
  if [ -n "${SETTLE:-}" ]; then echo "$SETTLE"; elif [ "$1" -ge 80000 ]; then echo 40000; else echo 30000; fi
}

[ -x "$BENCH" ] || { echo "no $BENCH: build it first" >&2; exit 1; }
command -v "$LMP_BIN" >/dev/null || { echo "no $LMP_BIN (apt-get install -y lammps openmpi-bin)" >&2; exit 1; }

WORK=$(mktemp -d /tmp/orogen_compare.XXXXXX)
[ "${KEEP:-0}" = 1 ] || trap 'rm -rf "$WORK"' EXIT
cp "$LAMMPS_DIR"/* "$WORK"/
# A private copy of the binary: a rebuild of the tree during the run must not change it.
cp "$BENCH" "$WORK/bench_pile"
BENCH=$WORK/bench_pile
chmod u+w "$WORK"/*
RAW=$WORK/raw.txt
: >"$RAW"
mkdir -p "$(dirname "$OUT")"
T_START=$(date +%s)
echo "# work dir $WORK"
{
  echo "# run_compare.sh $(date -Is) on $(hostname), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
  echo "# NS=$NS MODES=$MODES REPEATS=$REPEATS OROGEN_THREADS=$OROGEN_THREADS OMP_WAIT_POLICY=${WAIT_POLICY:-default}"
  echo "# steps: $(for n in $NS; do printf '%s:%s ' "$n" "$(steps_for "$n")"; done)"
  echo "# LAMMPS $($LMP_BIN -h | sed -n 's/^Large-scale[^-]*- //p' | head -1); orogen $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?')$(git -C "$ROOT" diff --quiet HEAD -- src 2>/dev/null || echo ' (src modified)')"
} >>"$RAW"

# One LAMMPS bench log -> one raw line.
lammps_line() {  # N mode log maxrss_kB
  awk -v mode="$2" -v rss="$4" -v load="$(cut -d' ' -f1 /proc/loadavg)" '
    /^Step / {inthermo=1; next}
    inthermo && $1 ~ /^[0-9]+$/ {ncm=$5}
    /^Loop time of/ {inthermo=0; lt=$4; np=$6; steps=$9; atoms=$12}
    /CPU use with/ {cpu=$1; sub("%","",cpu)}
    /^Ave neighs\/atom/ {nn=$NF} /^Neighbor list builds/ {nb=$NF}
    /^Per MPI rank memory allocation/ {mem=$NF; if (mem=="Mbytes") mem=$(NF-1)}
    END {printf "code=lammps N=%d mode=%s threads=%d steps=%d seconds=%.3f Mps=%.3f ns_per_ps_core=%.2f pairs_per_disc=%.3f contacts_per_disc=%.3f builds=%d cpu_pct=%s alloc_B_per_disc=%.0f maxrss_MB=%.1f load=%s\n",
         atoms, mode, np, steps, lt, atoms*steps/lt/1e6, 1e9*lt*np/(atoms*steps), nn, ncm, nb, cpu, mem*1048576/atoms, rss/1024, load}' "$3"
}

for N in $NS; do
  STEPS=$(steps_for "$N")
  NSETTLE=$(settle_for "$N")
  echo "== N=$N: settling both codes ($NSETTLE + 2000 steps)"
  t0=$(date +%s)
  # The settling command of run_bench.sh (which settles only as a side effect of a timed run).
  (cd "$WORK" && mpirun --allow-run-as-root --oversubscribe -np 2 "$LMP_BIN" -in in.settle -var N "$N" \
      -var settle "$NSETTLE" -log "log.settle_$N" -screen none -echo none)
  t1=$(date +%s)
  "$BENCH" --n "$N" --settle "$NSETTLE" --steps 0 --save "$WORK/orogen_settled_$N.bin" | tee "$WORK/orogen_settle_$N.txt"
  t2=$(date +%s)
  echo "# N=$N settle wall time: lammps (2 ranks) $((t1 - t0)) s, orogen (1 thread) $((t2 - t1)) s" | tee -a "$RAW"
  for r in $(seq 1 "$REPEATS"); do
    for mode in $MODES; do
      echo "-- N=$N mode=$mode repeat $r/$REPEATS ($STEPS steps)"
      (cd "$WORK" && LMP="/usr/bin/time -o $WORK/maxrss -f %M $LMP_BIN" ./run_bench.sh "$N" "$STEPS" 1 "$mode" >/dev/null)
      lammps_line "$N" "$mode" "$WORK/log.bench_N${N}_${mode}_np1" "$(tail -1 "$WORK/maxrss")" | tee -a "$RAW"
      OMP_WAIT_POLICY=$WAIT_POLICY "$BENCH" --n "$N" --load "$WORK/orogen_settled_$N.bin" --steps "$STEPS" --mode "$mode" \
          --threads "$OROGEN_THREADS" --repeat 1 | grep '^N=' | sed 's/^/code=orogen /' | tee -a "$RAW"
    done
  done
done
echo "# total wall time $(( $(date +%s) - T_START )) s" >>"$RAW"
cp "$RAW" "$RAWOUT"

# Medians -> markdown table.
python3 - "$RAW" "$OUT" <<'EOF'
import sys, statistics as st, collections
raw, out = sys.argv[1], sys.argv[2]
rows = collections.defaultdict(list)
notes = []
for line in open(raw):
    if line.startswith('#'):
        notes.append(line.strip()); continue
    kv = dict(f.split('=', 1) for f in line.split())
    rows[(kv['code'], int(kv['N']), kv['mode'], int(kv['threads']))].append(kv)
def med(key, field):
    v = [float(r[field]) for r in rows.get(key, []) if r.get(field) not in (None, '')]
    return st.median(v) if v else float('nan')
def rate(key):  # median rate = particle-steps / median seconds
    rs = rows.get(key)
    if not rs: return float('nan')
    return int(rs[0]['N']) * int(rs[0]['steps']) / med(key, 'seconds') / 1e6
cases = sorted({(k[1], k[2]) for k in rows}, key=lambda c: (c[0], c[1] != 'static'))
L = []
L.append('# Orogen vs LAMMPS: 2D granular pile benchmark\n')
L.append('Produced by `bench/run_compare.sh`. Medians over %d repeats; rates in million particle-steps per second (M/s).' %
         max(len(v) for v in rows.values()))
L.append('LAMMPS runs on 1 MPI rank; Orogen on 1 and 2 OpenMP threads. "cpu%" is the median share of a core each')
L.append('thread actually got (process CPU time / wall time / threads): below ~95% the shared machine was busy.\n')
L.append('| N | mode | steps | LAMMPS 1c M/s | Orogen 1t M/s | Orogen 2t M/s | Orogen 1t / LAMMPS | 2t/1t | ns/particle-step/core L, O1 | cpu% L, O1, O2 | pairs/disc L, O | contacts/disc L, O | builds L, O |')
L.append('|---|---|---|---|---|---|---|---|---|---|---|---|---|')
for N, mode in cases:
    l, o1, o2 = ('lammps', N, mode, 1), ('orogen', N, mode, 1), ('orogen', N, mode, 2)
    steps = rows[l][0]['steps'] if l in rows else rows[o1][0]['steps']
    rl, r1, r2 = rate(l), rate(o1), rate(o2)
    L.append('| %d | %s | %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.0f, %.0f | %.0f, %.0f, %.0f | %.3f, %.3f | %.3f, %.3f | %.0f, %.0f |' % (
        N, mode, steps, rl, r1, r2, r1 / rl, r2 / r1, 1e3 / rl, 1e3 / r1,
        med(l, 'cpu_pct'), med(o1, 'cpu_pct'), med(o2, 'cpu_pct'),
        med(l, 'pairs_per_disc'), med(o1, 'pairs_per_disc'), med(l, 'contacts_per_disc'), med(o1, 'contacts_per_disc'),
        med(l, 'builds'), med(o1, 'builds')))
L.append('\nCPU-time-normalised rates (rate x 100 / cpu%: what each code would do with the core to itself):\n')
L.append('| N | mode | LAMMPS M/s per CPU-s | Orogen 1t M/s per CPU-s | ratio |')
L.append('|---|---|---|---|---|')
for N, mode in cases:
    l, o1 = ('lammps', N, mode, 1), ('orogen', N, mode, 1)
    cl = rate(l) * 100 / med(l, 'cpu_pct'); co = rate(o1) * 100 / med(o1, 'cpu_pct')
    L.append('| %d | %s | %.2f | %.2f | %.2f |' % (N, mode, cl, co, co / cl))
L.append('\nMemory (bytes per disc). LAMMPS: its own per-rank allocation estimate and the max RSS of the run;')
L.append('Orogen: bytes held by the World arrays (discs, pairs, wall contacts, scratch) and the process peak')
L.append('(VmHWM above the start-up RSS; the process holds the settled state and a working copy).\n')
L.append('| N | mode | LAMMPS alloc B/disc | LAMMPS max RSS MB | Orogen world B/disc | Orogen VmHWM MB | Orogen HWM B/disc |')
L.append('|---|---|---|---|---|---|---|')
for N, mode in cases:
    l, o1 = ('lammps', N, mode, 1), ('orogen', N, mode, 1)
    L.append('| %d | %s | %.0f | %.1f | %.0f | %.1f | %.0f |' % (N, mode, med(l, 'alloc_B_per_disc'), med(l, 'maxrss_MB'),
             med(o1, 'world_B_per_disc'), med(o1, 'vmhwm_MB'), med(o1, 'hwm_B_per_disc')))
L.append('\nRun notes:\n')
L += ['    ' + n for n in notes]
import os
L.append('\nRaw measurements (one line per run): `%s`.' % os.path.basename(out[:-3] + '.raw.txt'))
open(out, 'w').write('\n'.join(L) + '\n')
print('\n'.join(L))
EOF
echo "wrote $OUT"
