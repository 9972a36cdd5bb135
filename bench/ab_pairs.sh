# Sourced by bench/wedge_ab.sh and bench/wedge_late_ab.sh: runs two orogen binaries in turn
# (A B A B ...), PAIRS times, and prints each run's stepping rate (the run log's "finished ...
# M particle-steps/s": set-up and outputs not counted), the medians and the median of the
# pair-by-pair ratios B/A, and whether the two runs wrote the same COMPARE_FILE.
# The caller defines `run_one BINARY DIR` (one run into the fresh folder DIR).
#   ab_pairs A_BINARY B_BINARY PAIRS WORK_DIR COMPARE_FILE LABEL

ab_rate() { grep -o 'finished .*(\([0-9.]*\) M particle-steps/s' "$1/run.log" | tail -1 | sed 's/.*(\([0-9.]*\) M.*/\1/'; }
ab_median() { printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

ab_pairs() {
  local a=$1 b=$2 pairs=$3 work=$4 compare=$5 label=$6
  local ra=() rb=() ratios=() k which bin r_a r_b same
  for k in $(seq "$pairs"); do
    for which in a b; do
      bin=$a; [ "$which" = b ] && bin=$b
      rm -rf "${work:?}/$which"
      run_one "$bin" "$work/$which" > "$work/$which.out" 2>&1 ||
        { echo "$bin failed:" >&2; tail -5 "$work/$which.out" >&2; exit 1; }
    done
    r_a=$(ab_rate "$work/a"); r_b=$(ab_rate "$work/b")
    ra+=("$r_a"); rb+=("$r_b")
    same=different; cmp -s "$work/a/$compare" "$work/b/$compare" && same=same
    echo "pair $k: A $r_a  B $r_b  M particle-steps/s  ($compare $same)"
  done
  for k in "${!ra[@]}"; do ratios+=("$(awk -v a="${ra[$k]}" -v b="${rb[$k]}" 'BEGIN {printf "%.3f", b / a}')"); done
  echo "$label, $pairs pairs: median A $(ab_median "${ra[@]}"), B $(ab_median "${rb[@]}") M particle-steps/s;" \
    "B/A median $(ab_median "${ratios[@]}") (pairs: ${ratios[*]})"
}
