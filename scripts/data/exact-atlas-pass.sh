#!/usr/bin/env bash
# One pass of the exact atlas over the rows still "none" (docs/exact.md "Coverage"), one n at a
# time so that a row that runs too long is stopped (`timeout`) without losing the others: each
# finished row is appended to data/atlas-exact.csv at once (certificate in data/exact/), so the pass
# is resumable: rerun it and the rows already proven are skipped. Every row's wall time and exit
# status go to data/exact-atlas-runs.log (status 124 or 137: stopped at the time limit). Run it
# with TRIPACK= a copy of the binary: a rebuild under a running pass makes the later rows fail to
# start (exit 126). For the same reason never edit this script in place while a pass runs (bash
# reads a script as it goes): write the new version beside it and rename it over this one.
# Usage: scripts/data/exact-atlas-pass.sh ATLAS.csv FIRST_DIGITS DIGITS MAX_DEGREE SECONDS N...
#   e.g. scripts/data/exact-atlas-pass.sh data/atlas.csv 500 2000 64 900 $(seq 2 200)
# ATLAS.csv = rank1: only the best packing of each n (data/atlas.csv's rank-1 rows, written to
# data/atlas-rank1.csv, which is not kept in git: it is made again from data/atlas.csv each time);
# ATLAS.csv = labels=L1,L2,...: only those rows (data/atlas-selected.csv, not kept in git either).
set -u
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
TRIPACK=${TRIPACK:-$root/build/tripack}
atlas=$1 first=$2 digits=$3 degree=$4 seconds=$5
shift 5
if [ "$atlas" = rank1 ]; then
  atlas=$root/data/atlas-rank1.csv
  awk -F, 'NR == 1 || $2 == 1' "$root/data/atlas.csv" >"$atlas"
elif [ "${atlas#labels=}" != "$atlas" ]; then
  wanted=${atlas#labels=}
  atlas=$root/data/atlas-selected.csv
  awk -F, -v wanted="$wanted" 'BEGIN { split(wanted, w, ","); for (i in w) keep[w[i]] = 1 }
    NR == 1 || ($3 in keep)' "$root/data/atlas.csv" >"$atlas"
fi
log=$root/data/exact-atlas-runs.log
[ -f "$log" ] || echo "# n first_digits digits max_degree time_limit_s wall_s exit_status" >"$log"
for n in "$@"; do
  start=$(date +%s.%N)
  # exact-atlas is a long job: a SIGTERM lets the row under way finish, so the time limit ends
  # in a SIGKILL a minute later (the row is then not in the table; a later pass runs it again).
  timeout --kill-after=60 "$seconds" "$TRIPACK" exact-atlas --atlas "$atlas" --out "$root/data" --n "$n" --retry-none \
    --first-digits "$first" --digits "$digits" --max-degree "$degree" --threads 1 >/dev/null 2>&1
  status=$?
  wall=$(echo "$(date +%s.%N) - $start" | bc)
  printf '%s %s %s %s %s %.1f %s\n' "$n" "$first" "$digits" "$degree" "$seconds" "$wall" "$status" >>"$log"
  echo "n = $n: exit $status, ${wall%.*} s"
done
