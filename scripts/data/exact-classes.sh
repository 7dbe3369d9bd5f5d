#!/usr/bin/env bash
# The classes, exact (docs/exact.md): `tripack exact --class` on the first members of every
# catalogue class (k from k_min while n <= NMAX, at most KCOUNT values; classes with a matrix row
# p: p = p_min and p_min + 1; a class with variants: its default one), statement (I) included,
# into data/exact-classes.csv.
# Usage: scripts/data/exact-classes.sh [NMAX (300)] [KCOUNT (10)]. Env: TRIPACK (build/tripack),
# DIGITS (200).
set -euo pipefail
cd "$(dirname "$0")/../.."
TRIPACK=${TRIPACK:-build/tripack}
NMAX=${1:-300}
KCOUNT=${2:-10}
DIGITS=${DIGITS:-200}
out=data/exact-classes.csv
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
start=$(date +%s)
echo "class,p,k,$("$TRIPACK" exact --class hexagonal --k 2 --digits 40 --no-existence --csv | head -1)" >"$out"
"$TRIPACK" classes --json | python3 -c '
import json, sys
for c in json.load(sys.stdin)["classes"]:
    ps = [c["p_min"], c["p_min"] + 1] if c["p_min"] is not None else [0]
    for p in ps:
        print(c["id"], p, c["k_min"], c["k_max"] if c["k_max"] is not None else 1000000)' |
  while read -r id p kmin kmax; do
    for ((k = kmin, count = 0; k <= kmax && count < KCOUNT; ++k, ++count)); do
      prow=()
      [ "$p" -gt 0 ] && prow=(--p "$p")
      n=$("$TRIPACK" build "$id" --k "$k" "${prow[@]}" --no-certify --json 2>/dev/null |
        python3 -c 'import json,sys; print(json.load(sys.stdin)["n"])' 2>/dev/null || echo 0)
      [ "$n" -gt 0 ] && [ "$n" -le "$NMAX" ] || break
      if "$TRIPACK" exact --class "$id" --k "$k" "${prow[@]}" --digits "$DIGITS" --csv >"$tmp" 2>&1; then
        tail -n +2 "$tmp" | sed "s/^/$id,$p,$k,/" >>"$out"
      else
        echo "$id,$p,$k,$n,,,,,,none,\"$(tail -1 "$tmp" | tr -d '"')\"," >>"$out"
      fi
    done
  done
echo "data/exact-classes.csv: $(($(wc -l <"$out") - 1)) members in $(($(date +%s) - start)) s"
