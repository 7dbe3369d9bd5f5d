#!/usr/bin/env bash
# The exact atlas from scratch (docs/exact.md): every row of data/atlas.csv at D = 300 digits,
# then the rows that ended "none" again at D = 500 and D = 1500 (--retry-none). Each pass is
# resumable (rerun the script: rows already in data/atlas-exact.csv are skipped). Prints each
# pass's time. Env: TRIPACK (build/tripack), THREADS (2).
set -euo pipefail
cd "$(dirname "$0")/../.."
TRIPACK=${TRIPACK:-build/tripack}
THREADS=${THREADS:-2}
start=$(date +%s)
"$TRIPACK" exact-atlas --threads "$THREADS" --digits 300
"$TRIPACK" exact-atlas --threads "$THREADS" --digits 500 --retry-none
"$TRIPACK" exact-atlas --threads "$THREADS" --digits 1500 --retry-none --n 2..34
echo "exact atlas: $(($(date +%s) - start)) s in all"
