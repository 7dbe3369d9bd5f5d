#!/usr/bin/env bash
# Check exact certificates (formats 1 and 2) with the independent PARI/GP checker check_exact.gp.
# Usage: checker/check_exact.sh [--atlas DIR] CERT.gp [CERT.gp ...]
#   --atlas DIR  the directory of the atlas coordinate files LABEL.txt for format-1 certificates
#                (default: <the certificate's directory>/../atlas); a format-2 certificate names
#                its coordinate file itself (coordinates_file, relative to its own directory).
# Runs gp once per certificate in a clean session (gp -f: no .gprc), prints the checker's lines,
# then "N certificates: A accepted, R rejected". Exits 0 when every certificate is accepted,
# 1 when any is rejected, 2 on a usage error. Set GP=/path/to/gp to use another gp binary.
# A certificate counts as accepted only when gp exits 0 AND its last line is the checker's
# "certificate LABEL: ACCEPTED (existence)" or "... ACCEPTED (existence, strict-local-optimum)";
# anything else (a gp crash, a missing verdict) is a rejection.
set -u

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
checker="$here/check_exact.gp"
GP=${GP:-gp}
usage() { echo "usage: $0 [--atlas DIR] CERT.gp [CERT.gp ...]" >&2; exit 2; }

atlas=""
while [ $# -gt 0 ]; do
  case "$1" in
    --atlas) [ $# -ge 2 ] && [ -n "$2" ] || usage; atlas=$2; shift 2 ;;
    --atlas=*) atlas=${1#--atlas=}; [ -n "$atlas" ] || usage; shift ;;
    --) shift; break ;;
    -h|--help) usage ;;
    -*) echo "check_exact.sh: unknown option $1" >&2; usage ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] || usage
if [ -n "$atlas" ] && [ ! -d "$atlas" ]; then
  echo "check_exact.sh: --atlas $atlas is not a directory" >&2
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
  # even if the checker never reaches its quit(). CHECK_ATLAS_DIR: empty = the default directory.
  CERT_FILE="$cert" CHECK_ATLAS_DIR="$atlas" "$GP" -q -f --default parisize=64M --default parisizemax=1G \
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
