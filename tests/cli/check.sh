# Sourced by the shell tests: pass and fail counters, and check "description" command... which
# runs the command and counts it (printing FAIL: description when it fails).
pass=0
fail=0
check() {
  local what=$1
  shift
  if "$@"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $what"; fi
}
