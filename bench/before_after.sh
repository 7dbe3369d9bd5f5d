#!/usr/bin/env bash
# Before/after on one machine in one run, interleaved (before, after, before, after, ...) so a
# noisy neighbour hits both alike: billiards events/s (bench_billiards, jamming at n = 100, 1000,
# 10000), certify at n = 10^4 (bench_analysis BM_CertifyBuilt/71: built Delta(142)+1, n = 10,154)
# campaign runs/s (`tripack campaign --threads 2` at n = 22 x 300 runs and n = 100 x 24 runs,
# a fresh database each time, wall time of the command) and search steps/s (`tripack search 60
# --steps 100 --threads 1 --seed 1`: the same steps every time; steps over the search's own wall
# time from its JSON). Prints medians and after/before ratios.
# Usage: bench/before_after.sh BEFORE_DIR AFTER_DIR   (each holding tripack, bench_billiards,
# bench_analysis). Env: REPS (5).
set -euo pipefail
before=$1
after=$2
REPS=${REPS:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
# csv_column FILE NAME_REGEX COLUMN: the column (by header name) of the row whose name matches.
csv_column() {
  awk -F, -v pat="$2" -v col="$3" '
    NR == 1 { for (i = 1; i <= NF; i++) { h = $i; gsub(/"/, "", h); idx[h] = i }; next }
    $1 ~ pat { print $idx[col] }' "$1"
}
billiards_cases=(100 1000 10000)
campaign_cases=(22:300 100:24)
for ((rep = 0; rep < REPS; rep++)); do
  for side in before after; do
    dir=${!side}
    "$dir/bench_billiards" --benchmark_filter='BM_CompressToJamming/(100|1000|10000)/' \
      --benchmark_format=csv 2>/dev/null >"$work/billiards.$side.$rep.csv"
    "$dir/bench_analysis" --benchmark_filter='BM_CertifyBuilt/71/' --benchmark_format=csv \
      2>/dev/null >"$work/analysis.$side.$rep.csv"
    for case in "${campaign_cases[@]}"; do
      n=${case%%:*} runs=${case##*:} db="$work/c.db"
      rm -f "$db" "$db-wal" "$db-shm"
      start=$(date +%s.%N)
      "$dir/tripack" campaign --n "$n" --runs "$runs" --threads 2 --db "$db" >/dev/null 2>&1
      end=$(date +%s.%N)
      awk -v r="$runs" -v s="$start" -v e="$end" 'BEGIN { print r / (e - s) }' >>"$work/campaign.$side.$n"
    done
    # the search's own steps: without the builder start where the binary has one
    no_builder=$("$dir/tripack" search --help 2>/dev/null | grep -o -- --no-builder-starts || true)
    "$dir/tripack" search 60 --steps 100 --threads 1 --seed 1 $no_builder --json 2>/dev/null |
      python3 -c 'import json, sys; j = json.load(sys.stdin); print(j["steps"] / j["seconds"])' \
        >>"$work/search.$side"
  done
  echo "round $((rep + 1)) of $REPS done" >&2
done

echo "| measure | before (median) | after (median) | after / before |"
echo "|---|---|---|---|"
row() {  # row LABEL BEFORE_VALUES_FILE AFTER_VALUES_FILE
  local b a
  b=$(median <"$2")
  a=$(median <"$3")
  awk -v label="$1" -v b="$b" -v a="$a" 'BEGIN { printf "| %s | %.4g | %.4g | %.3f |\n", label, b, a, a / b }'
}
# csv_row LABEL FILE_STEM NAME_REGEX COLUMN: a table row from every round's CSV of both sides.
csv_row() {
  for side in before after; do
    for ((rep = 0; rep < REPS; rep++)); do csv_column "$work/$2.$side.$rep.csv" "$3" "$4"; done >"$work/v.$side"
  done
  row "$1" "$work/v.before" "$work/v.after"
}
for n in "${billiards_cases[@]}"; do
  csv_row "billiards events/s, n = $n" billiards "BM_CompressToJamming/$n/" events_per_s
done
csv_row "certify n = 10,154: ms (lower is better)" analysis "BM_CertifyBuilt/71/" real_time
for case in "${campaign_cases[@]}"; do
  n=${case%%:*}
  row "campaign runs/s, n = $n, 2 threads" "$work/campaign.before.$n" "$work/campaign.after.$n"
done
row "search steps/s, n = 60, 1 thread, 100 steps" "$work/search.before" "$work/search.after"
