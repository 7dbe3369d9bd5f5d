#!/usr/bin/env bash
# The independent exact-certificate checker (checker/check_exact.sh, PARI/GP).
#  1. the hand-made certificates of tests/data/exact (coordinate files in
#     tests/data/atlas-checker, passed with --atlas) are accepted (optimum/: with both claims;
#     not-optimum/n3_collinear.gp rejected by rigidity); without --atlas they fail provenance;
#     t10a and t11a of data/exact are accepted as they are (format 1) and as format 2;
#  2. the certificates written by tests/checker/tamper_certificates.gp (one tampering per check, the
#     referee's wrong certificates (a)-(e) plain and disguised with a huge multiple of K, format 1
#     and 2) each get the verdict and the named checks of their manifest line;
#  3. tampered copies of format-1 files as they are (text edits of data/exact/t10a.gp): executable
#     or malformed certificates are rejected by "read", provenance tamperings by "provenance";
#  4. the wrapper: exit codes, counts, --atlas;
#  5. when git has the commit before this change (2d4b7ef), its checker is run on the disguised
#     certificates of section 2 and must ACCEPT them (the unsoundness they demonstrate).
# Usage: tests/checker/exact_checker_test.sh [path/to/check_exact.sh]
# (default: the repository's checker/check_exact.sh). Needs gp (PARI/GP).
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
CHECK=${1:-$root/checker/check_exact.sh}
DATA=$root/tests/data/exact
ATLAS=$root/tests/data/atlas-checker
GPBIN=${GP:-gp}
pass=0
fail=0
nread=0
nprov=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

if ! command -v "$GPBIN" >/dev/null 2>&1; then echo "exact_checker: gp (PARI/GP) not found"; exit 1; fi
if [ ! -r "$CHECK" ]; then echo "exact_checker: checker script $CHECK not found"; exit 1; fi

# check OUT RC EXPECTATIONS: the verdict and named checks (comma-separated, see
# tests/checker/tamper_certificates.gp): accept, accept-slo, reject, fail:X, pass:X, skip:X, note:TEXT
check() {
  local out=$1 rc=$2 exps=$3 e miss=""
  local IFS=','
  for e in $exps; do
    case "$e" in
      accept) { [ "$rc" -eq 0 ] && grep -q '^certificate .*: ACCEPTED (existence)$' <<<"$out" &&
        grep -q ' 1 accepted, 0 rejected$' <<<"$out" && ! grep -q '^FAIL' <<<"$out"; } || miss="$miss accept" ;;
      accept-slo) { [ "$rc" -eq 0 ] && grep -q '^certificate .*: ACCEPTED (existence, strict-local-optimum)$' <<<"$out" &&
        grep -q ' 1 accepted, 0 rejected$' <<<"$out" && ! grep -q '^FAIL' <<<"$out" &&
        grep -q '^PASS stress-positive:' <<<"$out" && grep -q '^PASS rigidity:' <<<"$out"; } || miss="$miss accept-slo" ;;
      reject) { [ "$rc" -ne 0 ] && grep -q '^certificate .*: REJECTED (' <<<"$out" &&
        grep -q ' 0 accepted, 1 rejected$' <<<"$out" && ! grep -q 'ACCEPTED' <<<"$out"; } || miss="$miss reject" ;;
      fail:*) grep -q "^FAIL ${e#fail:}:" <<<"$out" || miss="$miss $e" ;;
      pass:*) grep -q "^PASS ${e#pass:}:" <<<"$out" || miss="$miss $e" ;;
      skip:*) grep -q "^SKIP ${e#skip:}:" <<<"$out" || miss="$miss $e" ;;
      note:*) grep -qF "NOTE ${e#note:}" <<<"$out" || miss="$miss $e" ;;
      float300) ;;
      *) miss="$miss unknown-expectation:$e" ;;
    esac
  done
  [ -z "$miss" ] && return 0
  echo "$miss"
  return 1
}
# expect WHAT EXPECTATIONS [--atlas DIR] CERT.gp
expect() {
  local what=$1 exps=$2 out rc m
  shift 2
  out=$(bash "$CHECK" "$@" 2>&1)
  rc=$?
  if m=$(check "$out" "$rc" "$exps"); then ok; else bad "$what: expected [$exps], missing:$m (rc=$rc):"$'\n'"$out"; fi
}

# ---------------------------------------------------------------------------------------------
# 1. hand-made certificates and real ones as they are
certs=("$DATA"/*.gp)
if [ "${#certs[@]}" -lt 6 ]; then bad "expected at least 6 certificates in $DATA, found ${#certs[@]}"; fi
for c in "${certs[@]}"; do expect "$(basename "$c")" accept,pass:provenance --atlas "$ATLAS" "$c"; done
out=$(bash "$CHECK" --atlas "$ATLAS" "${certs[@]}" 2>&1)
rc=$?
if [ "$rc" -eq 0 ] && grep -qx "${#certs[@]} certificates: ${#certs[@]} accepted, 0 rejected" <<<"$out"; then ok; else
  bad "all hand-made certificates in one call (rc=$rc): $(tail -n 1 <<<"$out")"; fi
for c in "$DATA"/optimum/*.gp; do expect "optimum/$(basename "$c")" accept-slo,pass:stress-balance --atlas "$ATLAS" "$c"; done
expect "not-optimum/n3_collinear.gp: positive stress, G of rank 4 < 6" reject,fail:rigidity,pass:stress-balance,pass:stress-positive \
  --atlas "$ATLAS" "$DATA/not-optimum/n3_collinear.gp"
# without --atlas the default <dir>/../atlas (tests/data/atlas) has no coordinate file
expect "n4_centre.gp without --atlas" reject,fail:provenance "$DATA/n4_centre.gp"
# real certificates, format 1 as tripack wrote them (coordinate files in data/atlas)
expect "data/exact/t10a.gp" accept-slo,pass:provenance,pass:separation "$root/data/exact/t10a.gp"
expect "data/exact/t11a.gp (a rattler)" accept-slo,pass:provenance "$root/data/exact/t11a.gp"

# ---------------------------------------------------------------------------------------------
# 2. generated certificates
gen=$tmp/gen
mkdir -p "$gen"
if ! ROOT="$root" OUT="$gen" "$GPBIN" -q -f --default parisize=64M --default parisizemax=1G \
  "$here/tamper_certificates.gp" </dev/null >"$tmp/gen.log" 2>&1 || ! grep -q '^tamper_certificates: ' "$tmp/gen.log"; then
  bad "tests/checker/tamper_certificates.gp failed:"$'\n'"$(cat "$tmp/gen.log")"
fi
ngen=0
nfloat=0
nattack=0
while IFS='|' read -r name exps path desc; do
  [ -n "$name" ] || continue
  ngen=$((ngen + 1))
  case ",$exps," in *,float300,*) nfloat=$((nfloat + 1)) ;; esac
  case "$name" in [a-e]_*) nattack=$((nattack + 1)) ;; esac
  expect "$name ($desc)" "$exps" "$path"
done <"$gen/manifest.txt"
if [ "$ngen" -lt 80 ] || [ "$nfloat" -lt 18 ]; then bad "expected >= 80 generated certificates (>= 18 disguised), got $ngen ($nfloat)"; fi

# ---------------------------------------------------------------------------------------------
# 3. text edits of format-1 files as they are: data/exact/t10a.gp with its coordinate file
# mk NAME [FILE]: a fresh copy NAME/exact/t10a.gp + NAME/atlas/t10a.txt; prints the certificate path
mk() {
  local d=$tmp/txt/$1
  mkdir -p "$d/exact" "$d/atlas"
  cp "$root/data/exact/t10a.gp" "$d/exact/t10a.gp"
  cp "$root/data/atlas/t10a.txt" "$d/atlas/t10a.txt"
  echo "$d/exact/t10a.gp"
}
# sedit FILE 'sed script': edit in place; fails the test if nothing changed
sedit() {
  cp "$1" "$1.orig"
  sed -i -e "$2" "$1"
  if cmp -s "$1" "$1.orig"; then bad "sed '$2' changed nothing in $1"; fi
  rm -f "$1.orig"
}
# rd NAME 'text appended' | rd_sed NAME 'sed script': expect "FAIL read:"
rd() { local f; f=$(mk "$1"); printf '%s\n' "$2" >>"$f"; nread=$((nread + 1)); expect "read: $1" reject,fail:read "$f"; }
rd_sed() { local f; f=$(mk "$1"); sedit "$f" "$2"; nread=$((nread + 1)); expect "read: $1" reject,fail:read "$f"; }

rd print_quit 'print("certificate t10a: ACCEPTED (existence, strict-local-optimum)"); quit(0)'
rd quit 'quit(0);'
rd system 'system("touch /tmp/exact_checker_pwned");'
rd metacommand '\r /etc/hostname'
rd metacommand2 '\\ comment'$'\n''\q'
rd function_def 'f(y) = y^2;'
rd closure 'g = (y) -> y;'
rd duplicate 'n = 10;'
rd unknown_var 'zz = 1;'
rd syntax 'zz = [1,'
rd garbage ']'
rd index_assign 'points[1] = [0, 0];'
rd unterminated_string 'label = "t10a;'
rd unterminated_comment '/* no end'
rd nested_braces '{{n = 10;}}'
rd_sed unknown_ident 's/^label = "t10a"; n = 10;/label = "t10a"; n = foo;/'
rd_sed call_in_value 's/^label = "t10a"; n = 10;/label = "t10a"; n = print(10);/'
rd_sed str_call 's/^label = "t10a";/label = Str("t10a");/'
rd_sed eval_call 's/^d_in_K = 1\/3;/d_in_K = eval("1\/3");/'
rd_sed mod_call 's/^d_in_K = 1\/3;/d_in_K = Mod(1\/3, K);/'
rd_sed float_literal 's/^given_tolerance = 10^-25;/given_tolerance = 1e-25;/'
rd_sed decimal_literal 's/^given_tolerance = 10^-25;/given_tolerance = 0.0000000000000000000000001;/'
rd_sed newline_in_statement 's/^bonds = \[\[1, 3\], /bonds = [[1, 3],\n/'
rd_sed missing_semicolon 's/^claims = \["existence", "strict-local-optimum"\];/claims = ["existence", "strict-local-optimum"]/'
rd_sed string_escape 's/^label = "t10a";/label = "t10\\"a";/'
rd_sed division_by_t 's/^d_in_K = 1\/3;/d_in_K = 1\/t;/'
rd_sed power_of_power 's/^given_tolerance = 10^-25;/given_tolerance = 10^-5^5;/'
rd_sed huge_power 's/^given_tolerance = 10^-25;/given_tolerance = 10^-100000000;/'
rd_sed backslash_op 's/^d_in_K = 1\/3;/d_in_K = 1\\3;/'
rd_sed deep_nesting "s/^rattlers = \[\];/rattlers = $(printf '[%.0s' $(seq 40))$(printf ']%.0s' $(seq 40));/"
rd_sed poly_power 's/^d_in_K = 1\/3;/d_in_K = (t + 1)^5000;/'
f=$(mk unreadable); rm -f "$f"; nread=$((nread + 1)); expect "read: unreadable file" reject,fail:read "$f"
# expressions that would keep gp busy for minutes or hours: each rejected by one of the parser's
# bounds ("FAIL read", one line) well within a time limit of 10 s
# bounded NAME VARIABLE COMMAND...: t10a.gp with VARIABLE's one-line assignment replaced by one
# whose value COMMAND prints (too long for a sed argument)
bounded() {
  local name=$1 var=$2 f
  shift 2
  f=$(mk "$name")
  grep -v "^$var = " "$f" >"$f.tmp"
  { cat "$f.tmp"; printf '%s = ' "$var"; "$@"; printf ';\n'; } >"$f"
  rm -f "$f.tmp"
  nread=$((nread + 1))
  expect "bounded: $name, within --time-limit 10" reject,fail:read --time-limit 10 "$f"
}
bounded product_20000 d_in_K sh -c 'printf "(t + 1)*%.0s" $(seq 19999); printf "(t + 1)"'
bounded chained_powers given_tolerance sh -c 'printf "2^-1000000*%.0s" $(seq 999); printf "2^-1000000"'
bounded sum_of_powers d_in_K sh -c 'printf "(t + 1)^3000 + %.0s" $(seq 2000); printf "1"'
bounded sum_12000 d_in_K sh -c 'printf "1 + %.0s" $(seq 12000); printf "1"'
# a NUL byte: gp's readstr ends the line there, so the checker would read d_high as the text before
# it while grep, an editor or Python show the text after it too
f=$(mk nul); LC_ALL=C sed -i 's/\(d_high = [^;]*\);/\1\x00 + 1;/' "$f"
if LC_ALL=C grep -qaP '\x00' "$f"; then expect "a NUL byte in the certificate" reject,fail:text "$f"; else bad "the NUL test file has no NUL byte"; fi
f=$(mk latin1); printf 'label_note = "caf\351";\n' >>"$f"; expect "a non-ASCII byte" reject,fail:text "$f"
# the time limit ends in a rejection: t62a (the largest real certificate, ~20 s) given 2 s
out=$(bash "$CHECK" --time-limit 2 "$root/data/exact/t62a.gp" 2>&1); rc=$?
if [ "$rc" -eq 1 ] && grep -q '^FAIL time:' <<<"$out" && grep -q 'REJECTED (time)' <<<"$out"; then ok; else
  bad "t62a with --time-limit 2 (rc=$rc): $(tail -n 3 <<<"$out")"; fi
# coordinate files written on Windows (CR LF) read as the same lines
f=$(mk crlf); sed -i 's/$/\r/' "${f%/exact/t10a.gp}/atlas/t10a.txt"
expect "t10a with a CR LF coordinate file" accept-slo,pass:provenance "$f"

# provenance
pv() { nprov=$((nprov + 1)); expect "provenance: $1" reject,fail:provenance "$2"; }
f=$(mk prov_file_n); sedit "${f%/exact/t10a.gp}/atlas/t10a.txt" 's/^# n: 10$/# n: 11/'; pv "the file says n = 11" "$f"
f=$(mk prov_cert_n); sedit "$f" 's/^label = "t10a"; n = 10;/label = "t10a"; n = 11;/'; pv "the certificate says n = 11" "$f"
f=$(mk prov_label); sedit "$f" 's/^label = "t10a";/label = "t11a";/'
cp "$root/data/atlas/t11a.txt" "${f%/exact/t10a.gp}/atlas/t11a.txt"; pv "label t11a on t10a's packing (format 1: atlas/t11a.txt)" "$f"
f=$(mk prov_label2); sedit "$f" 's/^label = "t10a";/label = "t11a";/'
sedit "$f" 's/^cert_format = 1;/cert_format = 2; coordinates_file = "..\/atlas\/t10a.txt";/'; pv "format 2: label t11a naming t10a.txt" "$f"
f=$(mk prov_label3); sedit "${f%/exact/t10a.gp}/atlas/t10a.txt" 's/^# label: t10a$/# label: t10b/'; pv "the file's label is t10b" "$f"
f=$(mk prov_given); sedit "$f" '0,/^  \[500000000000000000000000000000\/10^30, 288675134594812882254574390251\/10^30\],/s//  [500000000000000000000000000000\/10^30, 288675134594812882254574390252\/10^30],/'
pv "a given point changed in its last digit" "$f"
f=$(mk prov_file_pt); sedit "${f%/exact/t10a.gp}/atlas/t10a.txt" 's/^0.333333333333333333333333333333 0.000000000000000000000000000000$/0.333333333333333333333333333334 0.000000000000000000000000000000/'
pv "a coordinate of the file changed in its last digit" "$f"
f=$(mk prov_tol); sedit "$f" 's/^given_tolerance = 10^-25;/given_tolerance = 10^-3;/'; pv "given_tolerance inflated to 1e-3" "$f"
f=$(mk prov_tol2); sedit "$f" 's/^given_tolerance = 10^-25;/given_tolerance = 10^-24;/'; pv "given_tolerance 1e-24 > 10^(5-30)" "$f"
f=$(mk prov_missing); rm "${f%/exact/t10a.gp}/atlas/t10a.txt"; pv "no coordinate file" "$f"
f=$(mk prov_d); sedit "${f%/exact/t10a.gp}/atlas/t10a.txt" 's/^# d: 0.333333333333333333333333333333$/# d: 0.333333333333333333333333333000/'; pv "the file's d off by 3e-28" "$f"
f=$(mk prov_garbage); printf '1.0 2.0 3.0\n' >>"${f%/exact/t10a.gp}/atlas/t10a.txt"; pv "a malformed line in the file" "$f"
f=$(mk prov_extra); printf '0.1 0.1\n' >>"${f%/exact/t10a.gp}/atlas/t10a.txt"; pv "an 11th point in the file" "$f"
f=$(mk f2_abs); sedit "$f" 's/^cert_format = 1;/cert_format = 2; coordinates_file = "\/etc\/t10a.txt";/'
expect "format 2 with an absolute coordinates_file" reject,fail:types "$f"
f=$(mk f2_missing); sedit "$f" 's/^cert_format = 1;/cert_format = 2;/'; expect "format 2 without coordinates_file" reject,fail:variables "$f"
f=$(mk f1_cfile); sedit "$f" 's/^cert_format = 1;/cert_format = 1; coordinates_file = "..\/atlas\/t10a.txt";/'
expect "format 1 with coordinates_file" reject,fail:format "$f"
f=$(mk f4); sedit "$f" 's/^cert_format = 1;/cert_format = 4;/'; expect "cert_format = 4" reject,fail:format "$f"
f=$(mk f3_missing); sedit "$f" 's/^cert_format = 1;/cert_format = 3;/'; expect "format 3 without coordinates_file" reject,fail:variables "$f"
f=$(mk f2_ok); sedit "$f" 's/^cert_format = 1;/cert_format = 2; coordinates_file = "..\/atlas\/t10a.txt";/'
expect "t10a as format 2" accept-slo,pass:provenance "$f"
# strict mode (--atlas DIR): a format-2 certificate's coordinate file must be DIR/LABEL.txt's
f=$(mk strict_own); d=${f%/exact/t10a.gp}; mkdir -p "$d/own"
{ echo "# my own copy"; cat "$d/atlas/t10a.txt"; } >"$d/own/t10a.txt"
sedit "$f" 's/^cert_format = 1;/cert_format = 2; coordinates_file = "..\/own\/t10a.txt";/'
expect "format 2 naming its own copy, no --atlas" accept-slo,pass:provenance "$f"
nprov=$((nprov + 1))
expect "strict: format 2 naming its own copy, --atlas DIR" reject,fail:provenance --atlas "$d/atlas" "$f"
f=$(mk strict_f2); sedit "$f" 's/^cert_format = 1;/cert_format = 2; coordinates_file = "..\/atlas\/t10a.txt";/'
expect "strict: format 2 naming ../atlas/t10a.txt, --atlas that directory" accept-slo,pass:provenance --atlas "${f%/exact/t10a.gp}/atlas" "$f"
expect "strict: format 2, an --atlas without t10a.txt" reject,fail:provenance --atlas "$ATLAS" "$f"
# --atlas: the certificate alone in a directory without ../atlas
mkdir -p "$tmp/txt/alone/x"; cp "$root/data/exact/t10a.gp" "$tmp/txt/alone/x/t10a.gp"
expect "t10a without its atlas directory" reject,fail:provenance "$tmp/txt/alone/x/t10a.gp"
expect "t10a with --atlas data/atlas" accept-slo,pass:provenance --atlas "$root/data/atlas" "$tmp/txt/alone/x/t10a.gp"
expect "t10a with --atlas=data/atlas" accept-slo --atlas="$root/data/atlas" "$tmp/txt/alone/x/t10a.gp"
# (b) and (c) on the file as it is
f=$(mk b_sed); sedit "$f" 's/^bonds = \[\[1, 3\], /bonds = [/'; expect "(b) t10a.gp, bond [1, 3] deleted by sed" reject,fail:separation "$f"
f=$(mk c_sed); sedit "$f" '0,/^  2600154457184653\/2251799813685248\*t - 9355553898240397\/6755399441055744,$/s//  0,/'
expect "(c) t10a.gp, first stress entry set to 0 by sed" reject,fail:stress-positive "$f"
# format 3 (points and stress as a(x) + s*b(x), mapped into K): the hand-made
# optimum/n6_delta3_f3.gp (P of degree 1) and tripack's data/exact/t17b.gp (P of degree 2)
# mk3 NAME FIXTURE LABEL ATLASFILE: a copy NAME/exact/LABEL.gp naming ../atlas/LABEL.txt
mk3() {
  local d=$tmp/txt/$1
  mkdir -p "$d/exact" "$d/atlas"
  sed 's|^coordinates_file = .*|coordinates_file = "../atlas/'"$3"'.txt";|' "$2" >"$d/exact/$3.gp"
  cp "$4" "$d/atlas/$3.txt"
  echo "$d/exact/$3.gp"
}
n6f3() { mk3 "$1" "$DATA/optimum/n6_delta3_f3.gp" n6-delta3-slo "$ATLAS/n6-delta3-slo.txt"; }
t17f3() { mk3 "$1" "$root/data/exact/t17b.gp" t17b "$root/data/atlas/t17b.txt"; }
f=$(n6f3 f3_ok); expect "format 3: n6_delta3_f3 as it is" accept-slo,pass:provenance "$f"
f=$(t17f3 f3_t17b); expect "format 3: t17b as it is" accept-slo,pass:provenance,pass:bond-identities "$f"
f=$(mk f1_s); cp "$DATA/optimum/n6_delta3_slo.gp" "$f"; cp "$ATLAS/n6-delta3-slo.txt" "${f%/exact/t10a.gp}/atlas/n6-delta3-slo.txt"
sedit "$f" 's|\[1/4, t/2\]|[1/4, s/4]|'; expect "format 1 with s in a point" reject,fail:coordinates "$f"
f=$(n6f3 f3_t); sedit "$f" 's|\[1/4, s/4\]|[1/4, t/2]|'; expect "format 3 with t in a point" reject,fail:coordinates "$f"
f=$(n6f3 f3_xdeg); sedit "$f" 's|\[1/2, 0\]|[x, 0]|'; expect "format 3: x^1 with deg P = 1 (its value d = 1/2 is right)" reject,fail:coordinates "$f"
f=$(n6f3 f3_s2); sedit "$f" 's|\[1/2, 0\]|[s^2/6, 0]|'; expect "format 3: s^2 (its value 1/2 is right)" reject,fail:coordinates "$f"
f=$(n6f3 f3_moved); sedit "$f" 's|\[1/4, s/4\]|[1/4, s/4 + 1/10^40]|'; expect "format 3: a point moved by 1e-40" reject,fail:bond-identities "$f"
f=$(n6f3 f3_neg); sedit "$f" '0,/s\/2, s\/2/s//-s\/2, s\/2/'; expect "format 3: a wall stress negated" reject,fail:stress-positive "$f"
f=$(n6f3 f3_sdeg); sedit "$f" '0,/s\/2, s\/2/s//s\/2*x, s\/2/'; expect "format 3: a stress entry of x-degree 1" reject,fail:stress-format "$f"
f=$(n6f3 f3_msqrt3); sedit "$f" 's|^sqrt3_in_K = 2\*t;|sqrt3_in_K = -2*t;|'; expect "format 3: s mapped to -sqrt(3)" reject,fail:sqrt3-sign "$f"
f=$(t17f3 f3_t17b_deg); sedit "$f" 's|^  \[1/2, -1/2\*s\*(2\*x - 1)\],|  [1/2 + (124*x^2 - 69*x + 9), -1/2*s*(2*x - 1)],|'
expect "format 3: t17b's first x plus P(x), degree 2 = deg P (the same value)" reject,fail:coordinates "$f"
f=$(t17f3 f3_t17b_moved); sedit "$f" 's|^  \[1/2, -1/2\*s\*(2\*x - 1)\],|  [1/2 + 1/10^40, -1/2*s*(2*x - 1)],|'
expect "format 3: t17b's first point moved by 1e-40" reject,fail:bond-identities "$f"
f=$(t17f3 f3_t17b_stress); sedit "$f" 's|^  -414720\*(|  414720*(|'; expect "format 3: t17b's first stress entry's a(x) negated" reject,fail:stress-balance "$f"
[ -e /tmp/exact_checker_pwned ] && bad "a certificate executed system()"

# ---------------------------------------------------------------------------------------------
# 4. the wrapper
out=$(bash "$CHECK" --atlas "$ATLAS" "$DATA/n3_corners.gp" "$gen/P_coef/exact/n4-centre.gp" 2>&1)
rc=$?
if [ "$rc" -eq 1 ] && grep -qx '2 certificates: 1 accepted, 1 rejected' <<<"$out"; then ok; else
  bad "mixed call (rc=$rc): $(tail -n 1 <<<"$out")"; fi
out=$(bash "$CHECK" --atlas "$ATLAS" "$DATA/optimum/n3_corners_slo.gp" "$DATA/n3_corners.gp" 2>&1)
rc=$?
if [ "$rc" -eq 0 ] && grep -qx '2 certificates: 2 accepted, 0 rejected' <<<"$out"; then ok; else
  bad "both verdict forms counted as accepted (rc=$rc): $(tail -n 1 <<<"$out")"; fi
for args in "" "--atlas" "--atlas $tmp/no-such-dir $DATA/n3_corners.gp" "--bogus $DATA/n3_corners.gp"; do
  # shellcheck disable=SC2086
  bash "$CHECK" $args >/dev/null 2>&1
  rc=$?
  if [ "$rc" -eq 2 ]; then ok; else bad "usage error '$args': exit $rc, expected 2"; fi
done

# ---------------------------------------------------------------------------------------------
# 5. the checker before this change accepted the disguised certificates
old=$tmp/old_check_exact.gp
if git -C "$root" cat-file -e 2d4b7ef:checker/check_exact.gp 2>/dev/null &&
  git -C "$root" show 2d4b7ef:checker/check_exact.gp >"$old" 2>/dev/null; then
  nold=0
  while IFS='|' read -r name exps path desc; do
    case ",$exps," in *,float300,*) ;; *) continue ;; esac
    case "$name" in *-f2) continue ;; esac   # the old checker reads format 1 only
    nold=$((nold + 1))
    out=$(CERT_FILE="$path" "$GPBIN" -q -f --default parisize=64M --default parisizemax=1G --default debugmem=0 "$old" </dev/null 2>&1)
    if [ "$(tail -n 1 <<<"$out" | grep -c ': ACCEPTED (')" -eq 1 ]; then ok; else
      bad "old checker (2d4b7ef) did not accept the disguised $name (the disguise should fool it):"$'\n'"$out"; fi
  done <"$gen/manifest.txt"
  echo "exact_checker: the checker of 2d4b7ef accepts all $nold disguised format-1 certificates; this one rejects them"
else
  echo "NOTE: commit 2d4b7ef not available (no git history): the old checker is not run on the disguised certificates"
fi

echo "exact_checker: $ngen generated certificates ($nattack of the referee's kinds (a)-(e), $nfloat disguised with a huge C*K(t)), $nread read and $nprov provenance tamperings of t10a.gp"
echo "exact_checker: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
