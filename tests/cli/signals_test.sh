#!/usr/bin/env bash
# Ctrl-C and SIGTERM as GNU timeout sends them (to the process and to its group, so one request
# arrives twice): every long job counts the pair as one request, stops, and still prints and
# records what finished (docs/cli.md, "Ctrl-C"). A second request a few seconds later abandons
# the items under way, and the result of what finished is still printed.
# Usage: signals_test.sh path/to/tripack
set -u
TRIPACK=$1
source "$(dirname "${BASH_SOURCE[0]}")/check.sh"
PY=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# A JSON result on stdout that holds at least one packing.
json_has_packing() {
  "$PY" -c 'import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if j.get("packings") else 1)' "$1"
}

# search: 10 tries under SIGINT, 2 under SIGTERM, its chains interrupted (without the builder
# start, which takes about 3 s at n = 150 and is tried below).
ok=0
for try in $(seq 1 10); do
  timeout --preserve-status -s INT 3 "$TRIPACK" search 150 --seconds 60 --no-builder-starts --json \
    >"$tmp/s.json" 2>"$tmp/s.err"
  rc=$?
  [ "$rc" -eq 130 ] && json_has_packing "$tmp/s.json" && ok=$((ok + 1))
done
check "search 150 under timeout -s INT 3: a result in $ok of 10 tries" [ "$ok" -eq 10 ]
check "stderr is the one line 'tripack: cancelled: ...' ($(wc -l <"$tmp/s.err") lines)" \
  bash -c "[ \$(wc -l <'$tmp/s.err') -eq 1 ] && grep -q '^tripack: cancelled: interrupted' '$tmp/s.err'"
check "stderr does not start with an empty line" [ -n "$(head -c1 "$tmp/s.err" | tr -d '\n')" ]
ok=0
for try in 1 2; do
  timeout --preserve-status 3 "$TRIPACK" search 150 --seconds 60 --no-builder-starts --json \
    >"$tmp/s.json" 2>/dev/null
  rc=$?
  [ "$rc" -eq 130 ] && json_has_packing "$tmp/s.json" && ok=$((ok + 1))
done
check "search 150 under timeout (SIGTERM) 3: a result in $ok of 2 tries" [ "$ok" -eq 2 ]
# Interrupted while it builds its start (build --n 150 on one thread: several seconds): exit
# 130, one line, and a result that says the build was interrupted and no chain ran a step.
timeout --preserve-status -s INT 1 "$TRIPACK" search 150 --seconds 60 --json >"$tmp/b.json" \
  2>"$tmp/b.err"
rc=$?
check "search 150 interrupted in its build: rc 130 ($rc), one line, builder 'interrupted', 0 steps" \
  bash -c "[ $rc -eq 130 ] && [ \$(wc -l <'$tmp/b.err') -eq 1 ] && '$PY' -c '
import json, sys
j = json.load(open(sys.argv[1]))
assert j[\"builder\"][\"error\"] == \"interrupted\" and j[\"steps\"] == 0, j[\"builder\"]' '$tmp/b.json'"

# search --db: the chains that finished are recorded.
timeout --preserve-status -s INT 3 "$TRIPACK" search 60 --seconds 60 --db "$tmp/search.db" \
  --json >"$tmp/d.json" 2>/dev/null
rc=$?
chains=$(sqlite3 "$tmp/search.db" 'select count(*) from runs' 2>/dev/null || echo 0)
check "search --db under timeout -s INT: rc 130 ($rc), a result, $chains chains recorded" \
  bash -c "[ $rc -eq 130 ] && [ ${chains:-0} -gt 0 ] && '$PY' -c 'import json; json.load(open(\"$tmp/d.json\"))'"

# campaign: every finished unit recorded, the result printed; the same command continues.
ok=0
for try in 1 2 3; do
  rm -f "$tmp/c.db"*
  timeout --preserve-status -s INT 3 "$TRIPACK" campaign --n 40..60 --runs 20 --threads 2 \
    --db "$tmp/c.db" --json >"$tmp/c.json" 2>"$tmp/c.err"
  rc=$?
  units=$(sqlite3 "$tmp/c.db" 'select count(*) from runs' 2>/dev/null || echo 0)
  if [ "$rc" -eq 130 ] && [ "${units:-0}" -gt 0 ] &&
    "$PY" -c 'import json,sys; json.load(open(sys.argv[1]))' "$tmp/c.json"; then
    ok=$((ok + 1))
  fi
done
check "campaign under timeout -s INT 3: result printed and units recorded in $ok of 3 tries" [ "$ok" -eq 3 ]

# A build is one item: the first request stops it at its next check (between the relaxes of
# its enumeration), with one line and exit 130.
timeout --preserve-status -s INT 3 "$TRIPACK" build --n 298 >"$tmp/build.out" 2>"$tmp/build.err"
rc=$?
check "build --n 298 under timeout -s INT 3: rc 130 ($rc), one line" \
  bash -c "[ $rc -eq 130 ] && [ \$(wc -l <'$tmp/build.err') -eq 1 ] && grep -q 'nothing was built' '$tmp/build.err'"
# Inside a long library call (even-ripple k=150's certificate: 9 s with no check; a 10^6-disk
# polish: minutes) the build ends kOneItemGrace (2 s) after the request, with the same line.
timeout --preserve-status -s TERM 3 "$TRIPACK" build even-ripple --k 150 >"$tmp/build2.out" 2>"$tmp/build2.err"
rc=$?
check "build even-ripple --k 150 under timeout -s TERM 3: rc 130 ($rc), one line, nothing printed" \
  bash -c "[ $rc -eq 130 ] && [ \$(wc -l <'$tmp/build2.err') -eq 1 ] && grep -q 'nothing was built' '$tmp/build2.err' && [ ! -s '$tmp/build2.out' ]"
# On a terminal (script(1) gives it a pty) a build over 2 s shows the enumeration's progress.
if command -v script >/dev/null; then
  script -qec "timeout --preserve-status -s INT 4 $TRIPACK build --n 298" /dev/null >"$tmp/pty.txt"
  check "build --n 298 on a terminal shows the segments relaxed" \
    grep -q $'\rbuild: [0-9]*/[0-9]* .*segments relaxed' "$tmp/pty.txt"
fi

# Two requests 1.5 s apart: the second abandons the billiards runs under way; the runs that
# finished are still printed, and the program ends promptly.
"$TRIPACK" billiards 1500 --runs 4 --threads 2 --json >"$tmp/b.json" 2>"$tmp/b.err" &
pid=$!
sleep 3
kill -INT "$pid"
sleep 1.5
kill -INT "$pid"
start=$(date +%s)
wait "$pid"
rc=$?
took=$(($(date +%s) - start))
check "billiards: a second Ctrl-C stops at once (rc=$rc, ${took} s after it)" \
  bash -c "[ $rc -eq 130 ] && [ $took -le 5 ]"
check "billiards: the second Ctrl-C says it abandons the runs under way" grep -q 'at once:' "$tmp/b.err"
check "billiards: the result after two Ctrl-C is JSON" \
  "$PY" -c 'import json,sys; json.load(open(sys.argv[1]))' "$tmp/b.json"

echo "signals: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
