#!/usr/bin/env bash
# Soak test of the campaign database: start a campaign, SIGKILL it at a random moment,
# check the database with an independent reader (the sqlite3 command), repeat; then let the
# rerun finish. After every kill the database must open, pass PRAGMA integrity_check, hold every
# unit the campaign had logged as recorded before the kill, and hold no unit twice; the final
# rerun must record exactly the units still missing.
# Usage: campaign_soak.sh path/to/tripack [KILLS (default 10)] [SEED for the kill moments]
# Extra tripack arguments (e.g. a bigger range) through SOAK_ARGS; SOAK_LAUNCHER="mpirun ..."
# runs the campaign under a launcher.
set -u
TRIPACK=$1
KILLS=${2:-10}
RANDOM=${3:-$$}
ARGS=${SOAK_ARGS:-"--n 40..90 --runs 4 --threads 2"}
LAUNCHER=${SOAK_LAUNCHER:-}
command -v sqlite3 >/dev/null || { echo "soak: needs the sqlite3 command (scripts/install-deps.sh)"; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
db="$work/soak.db"
fail=0
previous=0
q() { sqlite3 -batch -noheader "$db" "$1"; }

for ((i = 1; i <= KILLS; i++)); do
  # shellcheck disable=SC2086
  $LAUNCHER "$TRIPACK" campaign $ARGS --db "$db" >"$work/out.$i" 2>"$work/log.$i" &
  pid=$!
  delay_ms=$((100 + RANDOM % 900))
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -KILL "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  [ -n "$LAUNCHER" ] && sleep 0.5  # let the launcher's ranks go
  logged=$(grep -c '^campaign: recorded' "$work/log.$i")
  if [ ! -f "$db" ]; then
    [ "$logged" -eq 0 ] || { echo "kill $i: $logged units logged but no database"; fail=1; }
    echo "kill $i after ${delay_ms} ms: no database yet"
    continue
  fi
  integrity=$(q "PRAGMA integrity_check" 2>&1)
  [ "$integrity" = ok ] || { echo "kill $i: integrity_check says: $integrity"; fail=1; }
  q "SELECT n || ' ' || seed FROM runs ORDER BY 1" >"$work/stored.$i"
  sed -n 's/^campaign: recorded n = \([0-9]*\) seed = \([0-9]*\):.*/\1 \2/p' "$work/log.$i" |
    sort >"$work/logged.$i"
  missing=$(comm -23 "$work/logged.$i" "$work/stored.$i" | wc -l)
  [ "$missing" -eq 0 ] || { echo "kill $i: $missing logged units missing from the database"; fail=1; }
  duplicates=$(q "SELECT COUNT(*) FROM (SELECT 1 FROM runs GROUP BY n, seed HAVING COUNT(*) > 1)")
  twice=$(q "SELECT COUNT(*) FROM (SELECT 1 FROM packings GROUP BY n, graph_hash, d_key HAVING COUNT(*) > 1)")
  [ "$duplicates" -eq 0 ] && [ "$twice" -eq 0 ] || { echo "kill $i: duplicates: $duplicates runs, $twice packings"; fail=1; }
  stored=$(wc -l <"$work/stored.$i")
  [ "$stored" -ge "$previous" ] || { echo "kill $i: runs went from $previous to $stored"; fail=1; }
  echo "kill $i after ${delay_ms} ms: $stored units stored ($((stored - previous)) new, $logged logged), integrity $integrity"
  previous=$stored
done

# The rerun completes the rest.
# shellcheck disable=SC2086
$LAUNCHER "$TRIPACK" campaign $ARGS --db "$db" >"$work/out.final" 2>"$work/log.final" ||
  { echo "final rerun failed: $(tail -n 3 "$work/log.final")"; fail=1; }
units=$(sed -n 's/.*: \([0-9]*\) units, \([0-9]*\) already in .*, \([0-9]*\) recorded now.*/\1 \2 \3/p' "$work/out.final")
read -r total already recorded <<<"$units"
stored=$(q "SELECT COUNT(*) FROM runs")
in_packings=$(q "SELECT COALESCE(SUM(runs), 0) FROM packings")
certified=$(q "SELECT COUNT(*) FROM runs WHERE packing_id IS NOT NULL")
echo "final rerun: $total units, $already already stored, $recorded recorded now; $stored runs in the database"
[ "${already:-x}" = "$previous" ] || { echo "rerun found ${already:-?} stored, expected $previous"; fail=1; }
[ "$stored" = "${total:-x}" ] && [ $((already + recorded)) -eq "$total" ] ||
  { echo "the database holds $stored runs for $total units"; fail=1; }
[ "$in_packings" = "$certified" ] || { echo "packings count $in_packings runs, $certified runs have a packing"; fail=1; }
[ "$(q 'PRAGMA integrity_check')" = ok ] || { echo "final integrity_check failed"; fail=1; }
[ "$fail" -eq 0 ] && echo "soak: $KILLS kills, every check passed" || echo "soak: FAILED"
exit "$fail"
