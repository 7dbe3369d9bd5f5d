#!/usr/bin/env bash
# Every certificate of the exact atlas (data/exact/*.gp) through the independent checker
# (checker/check_exact.sh: PARI/GP, no code shared with tripack), two gp processes at a time.
set -u
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
shopt -s nullglob
certificates=("$root"/data/exact/*.gp)
[ ${#certificates[@]} -gt 0 ] || { echo "exact_certificates: no certificates in data/exact"; exit 1; }
log=$(mktemp)
trap 'rm -f "$log"' EXIT
printf '%s\n' "${certificates[@]}" | xargs -P 2 -n 16 bash "$root/checker/check_exact.sh" >"$log" 2>&1
status=$?
accepted=$(grep -c '^certificate .*: ACCEPTED' "$log")
rejected=$(grep -c '^certificate .*: REJECTED' "$log")
echo "exact_certificates: ${#certificates[@]} certificates, $accepted accepted, $rejected rejected"
grep -B3 '^certificate .*: REJECTED' "$log" | grep -E '^FAIL|REJECTED' | head -20
[ "$status" -eq 0 ] && [ "$accepted" -eq ${#certificates[@]} ]
