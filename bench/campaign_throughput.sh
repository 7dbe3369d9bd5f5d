#!/usr/bin/env bash
# Campaign throughput: runs per second of `tripack campaign` at one n, on 1 and 2
# threads and under mpirun (2 ranks, rank 0 computing on one thread; 3 ranks, rank 0 only handing
# out), the same seeds for every configuration (deterministic work), a fresh database each time.
# Wall time of the whole command (process and MPI start-up included); the median of REPS runs,
# configurations interleaved so that a noisy neighbour hits them alike; ratios against 1 thread.
# Usage: bench/campaign_throughput.sh [N:RUNS ...]   (default: 22:300 100:24)
# Env: TRIPACK (build/tripack), REPS (3).
set -euo pipefail
TRIPACK=${TRIPACK:-build/tripack}
REPS=${REPS:-3}
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(22:300 100:24)
MPIRUN=(mpirun --allow-run-as-root --oversubscribe)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
configs=("threads 1" "threads 2" "mpirun -np 2 (rank 0 + 1 worker)" "mpirun -np 3 (rank 0 hands out)")
command_of() {  # command_of CONFIG_INDEX N RUNS DB
  local args=(campaign --n "$2" --runs "$3" --db "$4")
  case $1 in
    0) echo "$TRIPACK ${args[*]} --threads 1" ;;
    1) echo "$TRIPACK ${args[*]} --threads 2" ;;
    2) echo "${MPIRUN[*]} -np 2 $TRIPACK ${args[*]} --threads 1" ;;
    3) echo "${MPIRUN[*]} -np 3 $TRIPACK ${args[*]} --threads 0" ;;
  esac
}
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

echo "| n | runs | configuration | median wall s | runs/s | vs 1 thread |"
echo "|---|---|---|---|---|---|"
for case in "${cases[@]}"; do
  n=${case%%:*}
  runs=${case##*:}
  for ((rep = 0; rep < REPS; rep++)); do
    for c in "${!configs[@]}"; do
      db="$work/c$c.db"
      rm -f "$db" "$db-wal" "$db-shm"
      start=$(date +%s.%N)
      # shellcheck disable=SC2046
      $(command_of "$c" "$n" "$runs" "$db") >/dev/null 2>&1
      end=$(date +%s.%N)
      awk -v a="$start" -v b="$end" 'BEGIN {print b - a}' >>"$work/t.$n.$c"
    done
  done
  base=$(median <"$work/t.$n.0")
  for c in "${!configs[@]}"; do
    t=$(median <"$work/t.$n.$c")
    awk -v n="$n" -v r="$runs" -v c="${configs[$c]}" -v t="$t" -v b="$base" \
      'BEGIN {printf "| %s | %s | %s | %.2f | %.1f | %.2fx |\n", n, r, c, t, r / t, b / t}'
  done
done
