#!/usr/bin/env bash
# Fuzz tripack's input parsers with libFuzzer (clang, ASan + UBSan).
#   bash scripts/fuzz.sh [SECONDS_PER_TARGET]   # default 60 s per target
#   bash scripts/fuzz.sh --smoke                # 10 s per target (CI)
# Configures fuzz/ into build-fuzz/ with clang, builds the targets, runs each one on a copy of
# its seed corpus (fuzz/corpus/<target>/ plus the past findings' reproducers in
# fuzz/findings/<target>/; the committed files are never modified) and prints one
# line per target: "N runs, no crash" or the reproducer file. Exits non-zero on any finding
# (crash, sanitizer report, leak, timeout, out-of-memory).
# Environment: FUZZ_TARGETS="fuzz_points ..." to run a subset, FUZZ_JOBS (build jobs, default 2),
# FUZZ_RUN_JOBS (targets fuzzed at once, default one per core),
# FUZZ_CXX / FUZZ_CC (default clang++ / clang; CXX and CC are ignored: libFuzzer needs clang).
set -euo pipefail

seconds=60
case "${1:-}" in
  --smoke) seconds=10 ;;
  "") ;;
  *[!0-9]*) echo "usage: bash scripts/fuzz.sh [SECONDS_PER_TARGET | --smoke]" >&2; exit 2 ;;
  *) seconds=$1 ;;
esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="$root/build-fuzz"
targets=${FUZZ_TARGETS:-"fuzz_points fuzz_scene fuzz_catalogue fuzz_formula"}

mkdir -p "$build"
CC=${FUZZ_CC:-clang} CXX=${FUZZ_CXX:-clang++} cmake -S "$root/fuzz" -B "$build" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >"$build/configure.log" 2>&1 ||
  { cat "$build/configure.log" >&2; exit 2; }
cmake --build "$build" -j"${FUZZ_JOBS:-2}" >"$build/build.log" 2>&1 ||
  { tail -n 40 "$build/build.log" >&2; exit 2; }

max_len_of() {
  case $1 in
    fuzz_points) echo 16384 ;;
    fuzz_scene) echo 4096 ;;
    fuzz_catalogue) echo 16384 ;;
    fuzz_formula) echo 256 ;;
    *) echo 4096 ;;
  esac
}

# One target on its corpus copy; its one line goes to $build/run/<target>/line.
fuzz_one() {
  local t=$1 run="$build/run/$1" log rc runs artifact kind line
  rm -rf "$run"
  mkdir -p "$run/corpus" "$run/artifacts"
  cp "$root/fuzz/corpus/$t/"* "$run/corpus/"
  # Past findings (fuzz/findings/<target>/) join the start corpus, so every run, the CI smoke
  # included, replays them first (inputs longer than the target's max_len are cut to it).
  if [[ -d $root/fuzz/findings/$t ]]; then cp "$root/fuzz/findings/$t/"* "$run/corpus/"; fi
  log="$run/fuzz.log"
  set +e
  ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} \
  UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
    "$build/$t" "$run/corpus" -max_total_time="$seconds" -max_len="$(max_len_of "$t")" \
      -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$run/artifacts/" >"$log" 2>&1
  rc=$?
  set -e
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -n1)
  runs=${runs:-$(grep -oE '^#[0-9]+' "$log" | tail -n1 | tr -d '#')}
  artifact=$(ls -1 "$run/artifacts/" 2>/dev/null | head -n1)
  if [[ $rc -eq 0 && -z $artifact ]]; then
    line="$t: ${runs:-?} runs in ${seconds} s, no crash"
  else
    kind=$(grep -m1 -oE 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer): [a-z-]+|runtime error: .*' "$log" || true)
    line="$t: FINDING after ${runs:-?} runs (${kind:-exit $rc}): ${artifact:+$run/artifacts/$artifact} (log $log)"
  fi
  echo "$line" >"$run/line"
  echo "$line"
}

# The targets run FUZZ_RUN_JOBS at a time (default: one per core); each gets its full seconds.
parallel=${FUZZ_RUN_JOBS:-$(nproc)}
running=0
for t in $targets; do
  fuzz_one "$t" &
  running=$((running + 1))
  if [[ $running -ge $parallel ]]; then
    wait -n || true  # a failed target is reported from its line below
    running=$((running - 1))
  fi
done
wait || true

failed=0
summary=()
for t in $targets; do
  line=$(cat "$build/run/$t/line" 2>/dev/null || echo "$t: FINDING: no result (the run did not finish)")
  [[ $line == "$t: FINDING"* ]] && failed=1
  summary+=("$line")
done

echo "== fuzz summary (${seconds} s per target) =="
printf '%s\n' "${summary[@]}"
exit $failed
