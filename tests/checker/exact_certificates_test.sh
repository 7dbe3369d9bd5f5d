#!/usr/bin/env bash
# Every certificate of the exact atlas (data/exact/*.gp) through the independent checker
# (checker/check_exact.sh: PARI/GP, no code shared with tripack), two gp processes at a time, and
# the verdicts against tripack's own (Arb) results in data/atlas-exact.csv:
#  * every data/exact/LABEL.gp has a row LABEL with proof = exact, and every row with proof = exact
#    has its certificate data/exact/LABEL.gp;
#  * the row's polynomial, root_low and root_high are the certificate's P, d_low and d_high;
#  * the checker prints "certificate LABEL: ACCEPTED (existence, strict-local-optimum)" (proof =
#    exact means tripack proved existence and strict local optimality) and exits 0, in strict
#    mode (--atlas data/atlas): every certificate's coordinate file is the atlas's LABEL.txt.
# Prints the wall time. Usage: tests/checker/exact_certificates_test.sh
set -u
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
csv=$root/data/atlas-exact.csv
shopt -s nullglob
# Largest first: the few certificates of tens of MB take minutes each, and started last (in name
# order) they left one checker running alone at the end.
mapfile -t certificates < <(ls -S "$root"/data/exact/*.gp)
[ ${#certificates[@]} -gt 0 ] || { echo "exact_certificates: no certificates in data/exact"; exit 1; }
[ -r "$csv" ] || { echo "exact_certificates: $csv not found"; exit 1; }
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
problems=0
problem() { problems=$((problems + 1)); [ "$problems" -le 30 ] && echo "exact_certificates: $*"; }

# the labels of the rows with proof = exact (column 2; column 7 is proof)
header=$(head -n 1 "$csv")
[ "$header" = "n,label,degree,polynomial,root_low,root_high,proof,reason,seconds" ] ||
  { echo "exact_certificates: unexpected header in $csv: $header"; exit 1; }
awk -F, 'NR > 1 && $7 == "exact" { print $2 }' "$csv" | sort >"$logs/exact-labels"
for c in "${certificates[@]}"; do basename "$c" .gp; done | sort >"$logs/cert-labels"
while read -r l; do problem "data/exact/$l.gp has no row with proof = exact in data/atlas-exact.csv"; done \
  < <(comm -23 "$logs/cert-labels" "$logs/exact-labels")
while read -r l; do problem "data/atlas-exact.csv: $l has proof = exact but no certificate data/exact/$l.gp"; done \
  < <(comm -13 "$logs/cert-labels" "$logs/exact-labels")
# the CSV's polynomial and interval are the certificate's P, d_low, d_high (text)
awk -F, 'NR > 1 && $7 == "exact" { print $2 "|" $4 "|" $5 "|" $6 }' "$csv" |
while IFS='|' read -r l poly lo hi; do
  f=$root/data/exact/$l.gp
  [ -r "$f" ] || continue
  grep -qxF "P = $poly;" "$f" || echo "data/atlas-exact.csv: $l: polynomial differs from the certificate's P"
  grep -qF "d_low = $lo; d_high = $hi;" "$f" || echo "data/atlas-exact.csv: $l: [root_low, root_high] differs from the certificate's [d_low, d_high]"
done >"$logs/csv-mismatch"
while read -r line; do problem "$line"; done <"$logs/csv-mismatch"

start=$(date +%s)
printf '%s\n' "${certificates[@]}" |
  xargs -P 2 -I{} sh -c 'bash "$1/checker/check_exact.sh" --atlas "$1/data/atlas" --time-limit 1800 "$2" >"$3/$(basename "$2" .gp).log" 2>&1' _ "$root" {} "$logs"
wall=$(( $(date +%s) - start ))

accepted=0
rejected=0
for c in "${certificates[@]}"; do
  l=$(basename "$c" .gp)
  log=$logs/$l.log
  if grep -qx "certificate $l: ACCEPTED (existence, strict-local-optimum)" "$log" &&
    grep -qx '1 certificates: 1 accepted, 0 rejected' "$log" && ! grep -q '^FAIL' "$log"; then
    accepted=$((accepted + 1))
  else
    rejected=$((rejected + 1))
    problem "$l: not ACCEPTED (existence, strict-local-optimum), although data/atlas-exact.csv says proof = exact: $(grep -E '^FAIL|^certificate' "$log" | head -3 | tr '\n' ' ')"
  fi
done
echo "exact_certificates: ${#certificates[@]} certificates, $accepted accepted (existence, strict-local-optimum), $rejected rejected; $(wc -l <"$logs/exact-labels") rows with proof = exact in data/atlas-exact.csv; wall time ${wall} s (2 gp at a time)"
[ "$problems" -eq 0 ] && [ "$accepted" -eq ${#certificates[@]} ]
