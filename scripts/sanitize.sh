#!/usr/bin/env bash
# Sanitizer builds of tripack and the tests that exercise them.
#   bash scripts/sanitize.sh [tsan|asan|all]   # default all (tsan, then asan)
# tsan: configures the project into build-tsan/ with -fsanitize=thread (-O1 -g), builds
#       tripack_tests and tripack, and runs the threaded tests (the threaded billiards searches,
#       the campaigns with 2 threads, the explorer and the accuracy study's 2-thread searches)
#       plus tests/cli/cli_test.sh (billiards/compare/campaign --threads 2, the progress ticker
#       thread on a pty) and a 2-thread `tripack campaign` interrupted by SIGINT then resumed,
#       all with TSAN_OPTIONS=halt_on_error=1.
# asan: configures into build-asan/ with -fsanitize=address,undefined
#       -fno-sanitize-recover=undefined (-O1 -g), builds the same targets and runs the whole
#       GoogleTest suite and the cli test through ctest (the explore test, which needs Chromium
#       and is covered by the Explore.* unit tests, is left out) with ASAN_OPTIONS=detect_leaks=1,
#       UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1.
# Every sanitizer report goes to a log file under build-<mode>/san-logs/ (so none is lost inside a
# test's captured output; GCC's UBSan reports, which ignore log_path, are looked for in ctest's
# LastTest.log); the script prints them and exits non-zero if any was written or any test failed. Third-party libraries are not instrumented: scripts/lsan.supp (and
# scripts/tsan.supp, if it exists) list the reports inside them that are not ours, each entry
# saying why; our own code is never suppressed.
# Environment: SAN_CXX / SAN_CC (default g++ / gcc), SAN_JOBS (build jobs, default 2),
# SAN_TEST_JOBS (ctest jobs for asan, default 1), TSAN_FILTER (gtest filter for tsan),
# SAN_INTERRUPT_AFTER (seconds before the campaign's SIGINT, default 1).
set -euo pipefail

mode=${1:-all}
case $mode in
  tsan | asan | all) ;;
  *) echo "usage: bash scripts/sanitize.sh [tsan|asan|all]" >&2; exit 2 ;;
esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
jobs=${SAN_JOBS:-2}
export CXX=${SAN_CXX:-g++} CC=${SAN_CC:-gcc}

# The threaded tests: BilliardsRunsRequest (1 vs 2 threads), Campaign (2 threads), Explore (the
# explorer's searches default to 2 threads), Accuracy.HardCases (2-thread n = 33 searches).
tsan_filter=${TSAN_FILTER:-"BilliardsRuns.*:Campaign.*:Explore.*:Accuracy.HardCases*"}

# configure_and_build DIR "SANITIZER FLAGS"
configure_and_build() {
  local dir=$1 flags=$2
  mkdir -p "$dir"
  echo "== configure + build $dir ($CXX $flags -O1 -g)"
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g -DNDEBUG" \
    -DCMAKE_CXX_FLAGS="$flags -fno-omit-frame-pointer" \
    -DCMAKE_EXE_LINKER_FLAGS="$flags" \
    -DTRIPACK_BUILD_BENCH=OFF -DTRIPACK_BUILD_TESTS=ON >"$dir/configure.log" 2>&1 ||
    { cat "$dir/configure.log" >&2; exit 2; }
  local t0=$SECONDS
  cmake --build "$dir" -j"$jobs" --target tripack_tests tripack >"$dir/build.log" 2>&1 ||
    { tail -n 60 "$dir/build.log" >&2; exit 2; }
  echo "   built in $((SECONDS - t0)) s"
}

# report_logs DIR: prints every sanitizer log written under DIR/san-logs; returns 1 if any.
report_logs() {
  local logs=("$1"/san-logs/*)
  [[ -e ${logs[0]} ]] || return 0
  for f in "${logs[@]}"; do
    echo "---- $f"
    cat "$f"
  done
  return 1
}

status=0

run_tsan() {
  local dir="$root/build-tsan"
  configure_and_build "$dir" "-fsanitize=thread"
  rm -rf "$dir/san-logs"
  mkdir -p "$dir/san-logs"
  local opts="halt_on_error=1:second_deadlock_stack=1:log_path=$dir/san-logs/tsan"
  [[ -f $root/scripts/tsan.supp ]] && opts+=":suppressions=$root/scripts/tsan.supp"
  local t0=$SECONDS rc=0
  echo "== tsan: tripack_tests --gtest_filter=$tsan_filter"
  (cd "$dir/tests" && TSAN_OPTIONS=$opts ./tripack_tests --gtest_filter="$tsan_filter" \
    --gtest_brief=1) || rc=1
  echo "   $((SECONDS - t0)) s"
  t0=$SECONDS
  echo "== tsan: tests/cli/cli_test.sh (threaded billiards, compare, campaign; progress ticker)"
  TSAN_OPTIONS=$opts bash "$root/tests/cli/cli_test.sh" "$dir/tripack" "$root/tests/data" || rc=1
  echo "   $((SECONDS - t0)) s"
  t0=$SECONDS
  echo "== tsan: a 2-thread campaign interrupted by SIGINT (as Ctrl-C), then resumed"
  local db="$dir/san-campaign.db" out1="$dir/san-campaign-1.out" out2="$dir/san-campaign-2.out"
  rm -f "$db" "$db-wal" "$db-shm"
  TSAN_OPTIONS=$opts "$dir/tripack" campaign --n 20..60 --runs 2 --threads 2 --db "$db" \
    >"$out1" 2>&1 &
  local pid=$! rc1=0 rc2=0
  sleep "${SAN_INTERRUPT_AFTER:-1}"
  kill -INT "$pid" 2>/dev/null || true
  wait "$pid" || rc1=$?
  TSAN_OPTIONS=$opts "$dir/tripack" campaign --n 20..60 --runs 2 --threads 2 --db "$db" \
    >"$out2" 2>&1 || rc2=$?
  # "campaign 20..60 x 2 runs: 82 units, A already in DB, B recorded now ...": the interrupted
  # run's units are kept and none is repeated (A + B = 82, A = what the first run recorded).
  local first second
  first=$(grep -oE '[0-9]+ recorded now' "$out1" | grep -oE '^[0-9]+' || echo "?")
  second=$(grep -oE '[0-9]+ already in .*, [0-9]+ recorded now' "$out2" |
    sed -E 's/^([0-9]+) already in .*, ([0-9]+) recorded now/\1 \2/' || true)
  echo "   first run exit $rc1 (130 = interrupted), $first recorded; rerun exit $rc2," \
    "already + recorded = ${second:-?}"
  if [[ $rc1 -ne 130 && $rc1 -ne 0 ]] || [[ $rc2 -ne 0 ]] ||
     [[ $second != "$first $((82 - ${first//[!0-9]/0}))" ]]; then
    echo "   FAIL: interrupted campaign"; cat "$out1" "$out2"; rc=1
  fi
  [[ $rc1 -eq 130 ]] || echo "   note: the first run finished before the signal: lower SAN_INTERRUPT_AFTER"
  rm -f "$db" "$db-wal" "$db-shm"
  echo "   $((SECONDS - t0)) s"
  if command -v mpirun >/dev/null; then
    echo "== tsan: tests/cli/mpi_test.sh (rank 0's worker thread beside its MPI thread; a killed rank)"
    t0=$SECONDS
    TSAN_OPTIONS=$opts bash "$root/tests/cli/mpi_test.sh" "$dir/tripack" || rc=1
    echo "   $((SECONDS - t0)) s"
  fi
  report_logs "$dir" || { echo "tsan: REPORTS (above)"; rc=1; }
  if [[ $rc -eq 0 ]]; then echo "tsan: clean"; else echo "tsan: FAILED"; status=1; fi
}

run_asan() {
  local dir="$root/build-asan"
  configure_and_build "$dir" "-fsanitize=address,undefined -fno-sanitize-recover=undefined"
  rm -rf "$dir/san-logs"
  mkdir -p "$dir/san-logs"
  local t0=$SECONDS rc=0
  echo "== asan+ubsan: ctest (every GoogleTest test, one process each, and the cli test)"
  (cd "$dir" &&
    ASAN_OPTIONS="detect_leaks=1:log_path=$dir/san-logs/asan" \
    LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0" \
    UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:log_path=$dir/san-logs/ubsan" \
    ctest --output-on-failure --timeout 3600 --parallel "${SAN_TEST_JOBS:-1}" \
      -E '^(explore|mpi_campaign)$') ||
    rc=1
  echo "   $((SECONDS - t0)) s"
  # Campaigns under mpirun: every memory error and undefined behaviour is still checked, but not
  # leaks: OpenMPI keeps allocations for the life of the process (libmpi, libopen-pal, hwloc and
  # its dlopen'ed components, whose frames the fast unwinder cannot even name), ~120 kB per rank
  # with no tripack frame in any stack (seen here), and MPI_Finalize does not free them.
  if command -v mpirun >/dev/null && [[ -f $dir/tests/CTestTestfile.cmake ]]; then
    echo "== asan+ubsan: tests/cli/mpi_test.sh (leak detection off: OpenMPI's own allocations)"
    t0=$SECONDS
    ASAN_OPTIONS="detect_leaks=0:log_path=$dir/san-logs/asan" \
      UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:log_path=$dir/san-logs/ubsan" \
      bash "$root/tests/cli/mpi_test.sh" "$dir/tripack" || rc=1
    echo "   $((SECONDS - t0)) s"
  fi
  # GCC's UBSan runtime ignores log_path when linked beside ASan: its reports go to stderr, which
  # ctest keeps (passing tests too) in LastTest.log. (They also fail the test: no recovery.)
  if grep -nE "runtime error:|ERROR: [A-Za-z]+Sanitizer" "$dir/Testing/Temporary/LastTest.log"; then
    echo "asan+ubsan: REPORTS in $dir/Testing/Temporary/LastTest.log (above)"
    rc=1
  fi
  report_logs "$dir" || { echo "asan+ubsan: REPORTS (above)"; rc=1; }
  if [[ $rc -eq 0 ]]; then echo "asan+ubsan: clean"; else echo "asan+ubsan: FAILED"; status=1; fi
}

case $mode in
  tsan) run_tsan ;;
  asan) run_asan ;;
  all) run_tsan; run_asan ;;
esac
exit $status
