#!/usr/bin/env bash
# Check exact certificates (formats 1, 2 and 3) with the independent PARI/GP checker check_exact.gp.
# Usage: checker/check_exact.sh [--atlas DIR] [--time-limit S] CERT.gp [CERT.gp ...]
#   --atlas DIR  strict mode: every certificate's coordinate file is the atlas's DIR/LABEL.txt (a
#                format-2 or -3 certificate's coordinates_file must hold exactly its lines). Without
#                it, format 1 reads <the certificate's directory>/../atlas/LABEL.txt and formats 2, 3 the
#                file it names (coordinates_file, relative to its own directory).
#   --time-limit S  seconds each certificate may take (default 600; the largest real one takes
#                about 20 s); past it the certificate is rejected.
# A certificate is text: a byte other than printable ASCII, tab, CR and LF (a NUL, which gp's
# readstr would silently end the line at) rejects it before gp reads it.
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
usage() { echo "usage: $0 [--atlas DIR] [--time-limit S] CERT.gp [CERT.gp ...]" >&2; exit 2; }

atlas=""
time_limit=600
while [ $# -gt 0 ]; do
  case "$1" in
    --atlas) [ $# -ge 2 ] && [ -n "$2" ] || usage; atlas=$2; shift 2 ;;
    --atlas=*) atlas=${1#--atlas=}; [ -n "$atlas" ] || usage; shift ;;
    --time-limit) [ $# -ge 2 ] && [[ "$2" =~ ^[1-9][0-9]*$ ]] || usage; time_limit=$2; shift 2 ;;
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
# reject CERT WHY DETAIL: a rejection decided here, before or instead of gp's verdict
reject() {
  echo "FAIL $2: $3"
  echo "certificate $1: REJECTED ($2)"
  rejected=$((rejected + 1))
}
for cert in "$@"; do
  total=$((total + 1))
  if [ -r "$cert" ]; then
    nontext=$(LC_ALL=C tr -d '\011\012\015\040-\176' <"$cert" | wc -c)
    if [ "$nontext" -gt 0 ]; then
      line=$(LC_ALL=C grep -n -a -m 1 -P '[^\t\r\x20-\x7e]' "$cert" | cut -d: -f1)
      reject "$cert" "text" "$nontext bytes are not printable ASCII (tab, CR and LF allowed), the first on line ${line:-?}: gp would read another value than a person reads"
      continue
    fi
  fi
  # parisize: initial PARI stack; parisizemax: the stack may grow to 4 GB (big fields, many
  # points); debugmem=0: no "increasing stack size" warnings. stdin is /dev/null, so gp exits
  # even if the checker never reaches its quit(). CHECK_ATLAS_DIR: empty = the default directory.
  CERT_FILE="$cert" CHECK_ATLAS_DIR="$atlas" timeout -k 5 "$time_limit" "$GP" -q -f --default parisize=64M \
    --default parisizemax=4G --default debugmem=0 "$checker" </dev/null 2>&1 | tee "$tmp"
  rc=${PIPESTATUS[0]}
  if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
    reject "$cert" "time" "no verdict within the time limit of $time_limit s (--time-limit)"
    continue
  fi
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
