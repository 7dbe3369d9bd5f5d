#!/usr/bin/env bash
# Regenerates the atlas: billiards campaigns into data/atlas.db, then `tripack atlas`,
# which merges them with every builder, certifies and polishes each row to 30 digits and writes
# data/atlas.csv, data/atlas/*.txt and data/atlas-gaps.csv; and the matrix stress set into
# data/stress.db and data/stress/. Every campaign is resumable: rerunning this script skips every
# (n, seed) already in the database, so an interrupted run (Ctrl-C, a killed session) continues
# where it stopped, and a finished one costs only the atlas step (~2 min).
#
# Usage: bash scripts/data/atlas.sh [STEP ...]   steps: small large targeted stress beyond confirm
#        confirm-long prune atlas (default: all but confirm-long, in that order).
#        Env: TRIPACK (build/tripack), THREADS (2), CONFIRM_RUNS (4), CONFIRM_LONG_RUNS (4).
# Each step's wall and CPU time is appended to data/atlas-times.log; docs/atlas.md has the
# totals measured on the project's 2-core machine.
set -euo pipefail
cd "$(dirname "$0")/../.."
T=${TRIPACK:-build/tripack}
THREADS=${THREADS:-2}
DB=data/atlas.db
[ -x "$T" ] || bash scripts/build.sh
steps=("$@")
[ ${#steps[@]} -gt 0 ] || steps=(small large targeted stress beyond confirm prune atlas)
LAST=${ATLAS_LAST:-300}  # the atlas covers n = 2..LAST
TIMEFORMAT="%R s wall, %U s user, %S s sys"

# step NAME COMMAND...: runs it, its output to data/logs/NAME.log, its times to atlas-times.log.
step() {
  local name=$1
  shift
  mkdir -p data/logs
  echo "atlas: $name: $*" >&2
  { time "$@" >"data/logs/$name.log" 2>"data/logs/$name.err"; } 2>"data/logs/$name.time"
  echo "$(date -u +%FT%TZ) $name: $(cat "data/logs/$name.time") :: $*" >>data/atlas-times.log
}

for s in "${steps[@]}"; do
  case $s in
    small)  # the paper's range and below: 2000 runs per n, the default scene
      step small "$T" campaign --n 2..34 --runs 2000 --threads "$THREADS" --db "$DB" ;;
    large)  # every n up to 200: 200 runs per n (default scene: slow growth window above n = 40)
      step large "$T" campaign --n 35..200 --runs 200 --threads "$THREADS" --db "$DB" ;;
    targeted)  # where the default scene is weak or the paper asks (docs/atlas.md says why).
      # Seeds 100001.. : constant growth 0.01 (scenes/constant-growth.yaml). Delta(k+2)-2 at
      # k = 8..12 (the windowed default never found t53a) and the n whose sparse-corner member
      # cannot be certified (k = 15..17: 151, 169, 188), so that the atlas beats it with a
      # certified packing.
      step const-53 "$T" campaign --n 53 --runs 2000 --seed 100001 --threads "$THREADS" \
        --scene scenes/constant-growth.yaml --db "$DB"
      for n in 64 76 89 103 151 169 187 188; do
        step "const-$n" "$T" campaign --n "$n" --runs 1000 --seed 100001 --threads "$THREADS" \
          --scene scenes/constant-growth.yaml --db "$DB"
      done
      # Seeds 200001.. : 600 more default-scene runs where the paper ranks two modifications or
      # says a class pattern gives way (Delta(2k+1)+1: 46, 67, 92, 121; Delta(2k+3)-3: 88, 117).
      for n in 46 67 88 92 117 121; do
        step "more-$n" "$T" campaign --n "$n" --runs 600 --seed 200001 --threads "$THREADS" \
          --db "$DB"
      done ;;
    stress)  # GL1995's matrix stress set from random starts: does billiards find n_p(k)?
      for n in 254 255 256 258 260; do
        step "stress-$n" "$T" campaign --n "$n" --runs 64 --threads "$THREADS" --db data/stress.db
      done
      step stress-atlas "$T" atlas --db data/stress.db --n 254,255,256,258,260 --ranked 0..0 \
        --out data/stress --json ;;
    beyond)  # n = 201..LAST: search chains from random starts (3 of 4 s, seeds 10001..10003), then
      # 4 of 20 s (seeds 20001..20004) at every n, and the searches of data/beyond-atlas.csv
      # that beat the builder there (60 s, seed 1, random starts only) imported as packings.
      step beyond-sweep "$T" campaign --n "201..$LAST" --runs 3 --seed 10001 --search-seconds 4 \
        --threads "$THREADS" --db "$DB"
      step beyond-confirm "$T" campaign --n "201..$LAST" --runs 4 --seed 20001 \
        --search-seconds 20 --threads "$THREADS" --db "$DB"
      step beyond-import "$T" db import data/beyond-atlas/search-*.txt --db "$DB"
      # GL1995's n_p(k) at 254..256 (findings.md §4): the builder's packing, which default
      # billiards runs reach (17 to 32 of 64 in data/stress.db) and 20 s chains rarely do.
      step beyond-billiards "$T" campaign --n 254..256 --runs 16 --threads "$THREADS" --db "$DB" ;;
    prune)  # keep the database small enough to commit: the best 30 (n <= 34) or 5 per n
      step prune-small "$T" db prune --keep 30 --n 2..34 --db "$DB"
      step prune-large "$T" db prune --keep 5 --n 35..100000 --db "$DB"
      step prune-stress "$T" db prune --keep 5 --db data/stress.db ;;
    confirm)  # Fresh searches from random starts (`campaign --search-seconds`) at every
      # n = 35..200 (n <= 34 have 2000 runs each), then 4 of 20 s wherever the atlas's best has
      # fewer than 3 confirmations. Seeds of their own (10001.., 20001..): a chain's first seconds
      # are those of the chain of the same seed with a longer budget, so seeds are never reused.
      # A later round raises CONFIRM_RUNS (8: seeds 20005..20008 are added where still needed).
      step search-35-200 "$T" campaign --n 35..200 --runs 3 --seed 10001 --search-seconds 4 \
        --threads "$THREADS" --db "$DB"
      step atlas "$T" atlas --db "$DB" --n "2..$LAST" --ranked 16..34 --ranked-count 20 \
        --out data --json
      for n in $(awk -F, 'NR > 1 && $2 == 1 && $10 < 3 { print $1 }' data/atlas.csv); do
        step "confirm-$n" "$T" campaign --n "$n" --runs "${CONFIRM_RUNS:-4}" --seed 20001 \
          --search-seconds 20 \
          --threads "$THREADS" --db "$DB"
      done ;;
    confirm-long)  # where 20 s chains are too short (187: the search's median time to t187a was
      # 111 CPU s before the inflation move, docs/performance.md): chains of 120 s (seeds 30001..) at every n listed in
      # data/atlas-unconfirmed.csv; CONFIRM_LONG_RUNS (4) per n, raised in later rounds.
      for n in $(awk -F, 'NR > 1 { print $1 }' data/atlas-unconfirmed.csv); do
        step "confirm-long-$n" "$T" campaign --n "$n" --runs "${CONFIRM_LONG_RUNS:-4}" \
          --seed 30001 --search-seconds 120 --threads "$THREADS" --db "$DB"
      done ;;
    atlas)
      step atlas "$T" atlas --db "$DB" --n "2..$LAST" --ranked 16..34 --ranked-count 20 \
        --out data --json ;;
    *) echo "atlas.sh: unknown step '$s' (small large targeted stress beyond confirm confirm-long prune atlas)" >&2; exit 2 ;;
  esac
done
