#!/usr/bin/env bash
# Check exact certificates (format 1) with the independent PARI/GP checker check_exact.gp.
# Usage: checker/check_exact.sh CERT.gp [CERT.gp ...]
# Runs gp once per certificate in a clean session (gp -f: no .gprc), prints the checker's lines,
# then "N certificates: A accepted, R rejected". Exits 0 when every certificate is accepted,
# 1 when any is rejected, 2 on a usage error. Set GP=/path/to/gp to use another gp binary.
# A certificate counts as accepted only when gp exits 0 AND its last line is the checker's
# "certificate LABEL: ACCEPTED (existence)" or "... ACCEPTED (existence, strict-local-optimum)"; anything else (a gp crash, a missing verdict) is a
# rejection.
set -u

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
checker="$here/check_exact.gp"
GP=${GP:-gp}

if [ $# -lt 1 ]; then
  echo "usage: $0 CERT.gp [CERT.gp ...]" >&2
  exit 2
fi
if ! command -v "$GP" >/dev/null 2>&1; then
  echo "check_exact.sh: gp (PARI/GP) not found; install pari-gp or set GP" >&2
  exit 2
fi
if [ ! -r "$checker" ]; then
  echo "check_exact.sh: cannot read $checker" >&2
  exit 2
fi

tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
total=0
accepted=0
rejected=0
for cert in "$@"; do
  total=$((total + 1))
  # parisize: initial PARI stack; parisizemax: the stack may grow to 1 GB (big fields, many
  # points); debugmem=0: no "increasing stack size" warnings. stdin is /dev/null, so gp exits
  # even if the checker never reaches its quit().
  CERT_FILE="$cert" "$GP" -q -f --default parisize=64M --default parisizemax=1G \
    --default debugmem=0 "$checker" </dev/null 2>&1 | tee "$tmp"
  rc=${PIPESTATUS[0]}
  last=$(tail -n 1 "$tmp")
  if [ "$rc" -eq 0 ] && [[ "$last" =~ ^certificate\ .*:\ ACCEPTED\ \((existence|existence,\ strict-local-optimum)\)$ ]]; then
    accepted=$((accepted + 1))
  else
    rejected=$((rejected + 1))
    if [[ ! "$last" =~ ^certificate\ .*:\ REJECTED ]]; then
      echo "certificate $cert: REJECTED (the checker gave no verdict; gp exit status $rc)"
    fi
  fi
done
echo "$total certificates: $accepted accepted, $rejected rejected"
[ "$rejected" -eq 0 ]
