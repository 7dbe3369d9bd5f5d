#!/usr/bin/env bash
# Every command that prints a result takes --output-format (with --json and --csv as its aliases),
# and under json its stdout parses as one JSON object: its result, and its error when it fails
# (docs/cli.md, "Output formats"). The commands come from the binary's own help, so a command
# added to the command table without a cheap invocation here fails this test.
# Usage: output_formats_test.sh path/to/tripack
set -u
TRIPACK=$1
PY=/usr/bin/python3
pass=0
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ok() { pass=$((pass + 1)); }
bad() {
  fail=$((fail + 1))
  echo "FAIL: $*"
}
is_json() { "$PY" -c 'import json,sys; json.loads(sys.stdin.read())' 2>/dev/null; }
is_error_json() { "$PY" -c 'import json,sys; assert "error" in json.loads(sys.stdin.read())' 2>/dev/null; }

# Inputs the invocations below share: a packing file, a campaign database and an atlas of it.
"$TRIPACK" build four-delta --k 2 -o "$tmp/t12.txt" >/dev/null 2>&1
"$TRIPACK" campaign --n 10..11 --runs 3 --db "$tmp/c.db" >/dev/null 2>&1
"$TRIPACK" atlas --db "$tmp/c.db" --out "$tmp/atlas" --n 10..11 --ranked 10..10 --ranked-count 2 \
  >/dev/null 2>&1

# A cheap invocation of every command that prints a result.
declare -A ARGS=(
  [classes]=""
  [classify]="12"
  [table]="--kmax 1"
  [check-formula]="four-delta --k 1..3"
  [build]="four-delta --k 2"
  [analyze]="$tmp/t12.txt"
  [build-scan]="--n 6..7 --table $tmp/scan.csv"
  [billiards]="7 --runs 2"
  [compare]="12 --runs 2"
  [search]="12 --steps 3 --seed 1"
  [explore]="--max-n 6 --discovered-max-n 4 --billiards-max-n 4 --search-steps 1 --no-accuracy --atlas none --out $tmp/report"
  [campaign]="--n 9 --runs 2 --db $tmp/c2.db"
  [atlas]="--db $tmp/c.db --out $tmp/atlas2 --n 10 --ranked 10..10 --ranked-count 1"
  [exact]="--class four-delta --k 2 --digits 60"
  [exact-atlas]="--atlas $tmp/atlas/atlas.csv --n 10 --digits 60"
  [db best]="--db $tmp/c.db"
  [db check]="--db $tmp/c.db"
  [db import]="$tmp/t12.txt --db $tmp/c3.db"
  [db prune]="--keep 5 --db $tmp/c.db"
)
# Commands whose output is files, not a result: they take no --output-format.
declare -A WRITES_FILES=([draw]="a picture (-o)" [db export]="packing files (--format)")

commands=$("$TRIPACK" --help | sed -n '/^Subcommands:/,/^$/p' | awk '/^  [a-z]/ {print $1}')
for group in db; do
  for sub in $("$TRIPACK" $group --help | sed -n '/^Subcommands:/,/^$/p' | awk '/^  [a-z]/ {print $1}'); do
    commands+=$'\n'"$group $sub"
  done
done
commands=$(grep -vx db <<<"$commands")

count=0
while IFS= read -r cmd; do
  [ -z "$cmd" ] && continue
  declares=$("$TRIPACK" $cmd --help | grep -c -- '--output-format')
  if [ -n "${WRITES_FILES[$cmd]+x}" ]; then
    if [ "$declares" -eq 0 ]; then ok; else bad "$cmd writes ${WRITES_FILES[$cmd]} but declares --output-format"; fi
    continue
  fi
  if [ -z "${ARGS[$cmd]+x}" ]; then
    bad "no invocation for '$cmd' in this test (add one, or list it among the commands that write files)"
    continue
  fi
  count=$((count + 1))
  [ "$declares" -ge 1 ] && ok || bad "$cmd has no --output-format"
  # shellcheck disable=SC2086
  out=$("$TRIPACK" $cmd ${ARGS[$cmd]} --output-format json 2>"$tmp/err")
  rc=$?
  if [ "$rc" -eq 0 ] && is_json <<<"$out"; then ok; else bad "$cmd --output-format json: rc $rc, $(head -c 300 <<<"$out") $(tail -1 "$tmp/err")"; fi
  # The same through the alias.
  out=$("$TRIPACK" $cmd ${ARGS[$cmd]} --json 2>/dev/null)
  is_json <<<"$out" && ok || bad "$cmd --json: $(head -c 300 <<<"$out")"
  # An error (an option it does not know) under json: one JSON object, non-zero exit.
  out=$("$TRIPACK" $cmd --no-such-option --output-format json 2>/dev/null)
  rc=$?
  if [ "$rc" -ne 0 ] && is_error_json <<<"$out"; then ok; else bad "$cmd error under json: rc $rc, $out"; fi
done <<<"$commands"

# Two formats at once are an error, not a silent choice.
out=$("$TRIPACK" build four-delta --k 2 --json --csv 2>"$tmp/err")
rc=$?
if [ "$rc" -eq 2 ] && grep -q "give one format" "$tmp/err" && is_error_json <<<"$out"; then ok; else bad "--json --csv: rc $rc, $out"; fi
# --csv is --output-format csv: the same bytes.
a=$("$TRIPACK" classify 12 --csv)
b=$("$TRIPACK" classify 12 --output-format csv)
[ "$a" = "$b" ] && [ -n "$a" ] && ok || bad "--csv differs from --output-format csv"
# An error under csv is a one-column table.
out=$("$TRIPACK" build nonsense --k 2 --output-format=csv 2>/dev/null)
[ "$(head -1 <<<"$out")" = "error" ] && ok || bad "csv error: $out"

# A field is described once and every writer prints it: build's `verified` (one line in
# report/results/build.hpp) in text (after the view, by name), JSON and CSV (a column by name).
grep -qx 'verified   true' <<<"$("$TRIPACK" build four-delta --k 3)" && ok || bad "verified not in the text"
grep -q '"verified":true' <<<"$("$TRIPACK" build four-delta --k 3 --json)" && ok || bad "verified not in the JSON"
/usr/bin/python3 -c 'import csv, sys; assert next(csv.DictReader(sys.stdin))["verified"] == "true"' \
  <<<"$("$TRIPACK" build four-delta --k 3 --csv)" && ok || bad "verified not in the CSV"

echo "output formats ($count commands): $pass passed, $fail failed"
[ "$fail" -eq 0 ]
