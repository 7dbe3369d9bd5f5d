#!/usr/bin/env bash
# The README's tour as a reader runs it: every line of the ```sh blocks of its "A tour" section
# (trailing "# comments" dropped), run in order from the root of a clean clone of the repository's
# committed HEAD, with the binary under test as build/tripack. Each must exit 0, and afterwards
# `git status --porcelain` must be empty: the tour writes only into ignored places (out/).
# Usage: tour_test.sh path/to/tripack [SOURCE_REPOSITORY]   (default: this script's repository)
set -u
TRIPACK=$(realpath "$1")
src=${2:-$(dirname "$(realpath "${BASH_SOURCE[0]}")")/../..}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone --quiet "$src" "$work/repo" || { echo "FAIL: git clone $src"; exit 1; }
mkdir "$work/repo/build"  # ignored by .gitignore's /build*/
ln -s "$TRIPACK" "$work/repo/build/tripack"

# The commands: the ```sh blocks between "## A tour" and the next "## " heading; a line ending in
# a backslash continues on the next.
mapfile -t commands < <(awk '
  /^## / { tour = ($0 ~ /^## A tour/) }
  tour && /^```sh/ { block = 1; next }
  block && /^```/ { block = 0; next }
  block {
    line = $0
    sub(/[ \t]+#.*$/, "", line)  # a trailing comment
    if (line ~ /^[ \t]*(#|$)/) next
    if (line ~ /\\$/) { sub(/\\$/, "", line); pending = pending line; next }
    print pending line; pending = ""
  }' "$work/repo/README.md")

pass=0
fail=0
start=$(date +%s.%N)
if [ "${#commands[@]}" -lt 15 ]; then
  echo "FAIL: only ${#commands[@]} commands found in the README's tour"
  fail=$((fail + 1))
fi
i=0
for cmd in "${commands[@]}"; do
  i=$((i + 1))
  t0=$(date +%s.%N)
  (cd "$work/repo" && bash -c "$cmd") >"$work/log.$i" 2>&1
  rc=$?
  seconds=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  if [ $rc -eq 0 ]; then
    pass=$((pass + 1))
    printf 'ok    %6s s  %s\n' "$seconds" "$cmd"
  else
    fail=$((fail + 1))
    printf 'FAIL  %6s s  %s  (exit %d; its last lines:)\n' "$seconds" "$cmd" $rc
    tail -5 "$work/log.$i" | sed 's/^/        /'
  fi
done

left=$(git -C "$work/repo" status --porcelain)
if [ -z "$left" ]; then
  pass=$((pass + 1))
  echo "ok             git status --porcelain is empty: the tour wrote only into ignored places"
else
  fail=$((fail + 1))
  echo "FAIL           git status --porcelain after the tour:"
  sed 's/^/        /' <<<"$left"
fi
total=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", b - a }')
echo "$pass passed, $fail failed ($total s)"
[ $fail -eq 0 ]
