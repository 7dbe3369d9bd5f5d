#!/usr/bin/env bash
# Campaigns under mpirun: the same units give the same database as threads, with rank
# 0 computing or only handing out; a worker rank killed mid-campaign loses nothing recorded and
# the rerun completes the rest. Usage: mpi_test.sh path/to/tripack
set -u
TRIPACK=$1
command -v sqlite3 >/dev/null || { echo "needs the sqlite3 command (scripts/install-deps.sh)"; exit 2; }
# As root (CI) mpirun needs --allow-run-as-root; --oversubscribe allows more ranks than cores.
MPIRUN=(mpirun --allow-run-as-root --oversubscribe)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/check.sh"
# Every distinct packing with its d, contact-graph hash and number of runs: the database's content
# that does not depend on the order in which units finished.
packings() { sqlite3 -batch "$1" "SELECT n, d, graph_hash, runs FROM packings ORDER BY n, d, graph_hash"; }
runs() { sqlite3 -batch "$1" "SELECT n, seed, outcome FROM runs ORDER BY n, seed"; }

range=(--n 12..22 --runs 6)
"$TRIPACK" campaign "${range[@]}" --threads 2 --db "$work/threads.db" >/dev/null 2>&1
"${MPIRUN[@]}" -np 2 "$TRIPACK" campaign "${range[@]}" --threads 1 --db "$work/np2.db" >"$work/np2.out" 2>"$work/np2.err"
check "mpirun -np 2 exits 0" [ $? -eq 0 ]
check "mpirun -np 2: one report, from rank 0" [ "$(grep -c '^campaign 12..22' "$work/np2.out")" -eq 1 ]
check "mpirun -np 2: the same distinct packings as 2 threads" \
  cmp -s <(packings "$work/threads.db") <(packings "$work/np2.db")
check "mpirun -np 2: the same runs and outcomes" cmp -s <(runs "$work/threads.db") <(runs "$work/np2.db")
check "the packings are there" [ "$(packings "$work/np2.db" | wc -l)" -ge 11 ]
"${MPIRUN[@]}" -np 3 "$TRIPACK" campaign "${range[@]}" --threads 0 --db "$work/np3.db" >/dev/null 2>&1
check "mpirun -np 3, rank 0 only hands out: the same packings" \
  cmp -s <(packings "$work/threads.db") <(packings "$work/np3.db")
"${MPIRUN[@]}" -np 2 "$TRIPACK" campaign "${range[@]}" --db "$work/np2.db" >"$work/again.out" 2>/dev/null
check "a rerun under mpirun repeats nothing" grep -q "66 already in" "$work/again.out"
"${MPIRUN[@]}" -np 2 "$TRIPACK" campaign --n 0..1 --db "$work/bad.db" >/dev/null 2>"$work/bad.err"
check "a bad range under mpirun: non-zero exit" [ $? -ne 0 ]
check "... with the reason" grep -q "has no n >= 2" "$work/bad.err"

# SIGKILL the worker rank in the middle: mpirun ends the job; every unit logged as recorded is
# in the database, which passes integrity_check; the rerun completes the rest, nothing twice.
big=(--n 40..80 --runs 3 --threads 1)
"${MPIRUN[@]}" -np 2 "$TRIPACK" campaign "${big[@]}" --db "$work/kill.db" >/dev/null 2>"$work/kill.err" &
launcher=$!
sleep 1.5
worker=""
for p in $(pgrep -f "campaign ${big[*]}"); do
  grep -qz '^OMPI_COMM_WORLD_RANK=1$' "/proc/$p/environ" 2>/dev/null && worker=$p
done
check "the worker rank was found" [ -n "$worker" ]
[ -n "$worker" ] && kill -KILL "$worker"
wait "$launcher"
check "mpirun reports the dead rank with a non-zero exit" [ $? -ne 0 ]
check "integrity_check after the kill" [ "$(sqlite3 "$work/kill.db" 'PRAGMA integrity_check')" = ok ]
sed -n 's/^campaign: recorded n = \([0-9]*\) seed = \([0-9]*\):.*/\1 \2/p' "$work/kill.err" | sort >"$work/logged"
sqlite3 -batch "$work/kill.db" "SELECT n || ' ' || seed FROM runs ORDER BY 1" >"$work/stored"
check "every unit logged before the kill is stored" [ "$(comm -23 "$work/logged" "$work/stored" | wc -l)" -eq 0 ]
check "some units were recorded before the kill" [ "$(wc -l <"$work/logged")" -gt 0 ]
check "and not all of them" [ "$(wc -l <"$work/stored")" -lt 123 ]
"${MPIRUN[@]}" -np 2 "$TRIPACK" campaign "${big[@]}" --db "$work/kill.db" >"$work/rerun.out" 2>/dev/null
check "the rerun completes" grep -q "123 units, $(wc -l <"$work/stored") already in" "$work/rerun.out"
check "123 runs, none twice" [ "$(sqlite3 "$work/kill.db" 'SELECT COUNT(DISTINCT n || "/" || seed) FROM runs')" -eq 123 ]

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
