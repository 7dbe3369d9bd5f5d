#!/usr/bin/env bash
# tripack exact end to end: certificates of real atlas packings are written and the independent
# checker (checker/check_exact.sh, PARI/GP, no code shared with tripack) accepts them; copies with a
# changed coefficient of P, a removed bond, a moved coordinate or a wrong root are rejected.
# GL1995's closed form for n = 13 and the values 1/sqrt(3) (n = 4) are the reference polynomials.
# Usage: tests/cli/exact_test.sh path/to/tripack
set -u
TRIPACK=${1:?usage: exact_test.sh path/to/tripack}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
CHECK=$root/checker/check_exact.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0
fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# The polynomials: n = 4, d = 1/sqrt(3): 3x^2 - 1; n = 13: GL1995's 4x^4 - 144x^3 + 180x^2 - 72x + 9.
for f in t4a t13a t22a t17b; do
  "$TRIPACK" exact "$root/data/atlas/$f.txt" --digits 120 --certificates "$tmp" --json >"$tmp/$f.json" 2>"$tmp/$f.err" ||
    bad "exact $f failed: $(cat "$tmp/$f.err")"
done
grep -q '"polynomial":"3\*x^2 - 1"' "$tmp/t4a.json" && ok || bad "t4a: P is not 3*x^2 - 1"
grep -q '"polynomial":"4\*x^4 - 144\*x^3 + 180\*x^2 - 72\*x + 9"' "$tmp/t13a.json" && ok ||
  bad "t13a: P is not GL1995's closed form"
for f in t4a t13a t22a t17b; do
  grep -q '"proof":"exact"' "$tmp/$f.json" && ok || bad "$f: statements (I) and (II) not proven"
done

# The checker accepts every real certificate.
out=$(bash "$CHECK" "$tmp"/t*.gp 2>&1)
if [ $? -eq 0 ] && grep -qx '4 certificates: 4 accepted, 0 rejected' <<<"$out"; then ok; else
  bad "the checker should accept the 4 certificates:"$'\n'"$(grep -E 'FAIL|certificates' <<<"$out")"; fi

# expect_reject WHAT FILE
expect_reject() {
  local out rc
  out=$(bash "$CHECK" "$2" 2>&1)
  rc=$?
  if [ "$rc" -ne 0 ] && grep -q 'REJECTED' <<<"$out" && ! grep -q 'ACCEPTED' <<<"$out"; then ok; else
    bad "$1 should be rejected (rc=$rc)"; fi
}
cert=$tmp/t22a.gp
mkdir -p "$tmp/tampered"
# (a) a changed coefficient of P: the constant term + 1.
sed -E '/^P = /s/;$/ + 1;/' "$cert" >"$tmp/tampered/a.gp"
# (b) a removed disk-disk bond (the first one).
sed -E '/^bonds = /s/\[[0-9]+, [0-9]+\], //' "$cert" >"$tmp/tampered/b.gp"
# (c) a moved coordinate: the first point's x plus 10^-30.
awk '/^\{points = \[/ {print; getline; sub(/^  \[/, "  [1/10^30 + "); print; next} {print}' "$cert" >"$tmp/tampered/c.gp"
# (d) a wrong root: an interval far from d (no root of P there, or another one).
sed -E 's/^d_low = .*$/d_low = 9\/10; d_high = 1;/' "$cert" >"$tmp/tampered/d.gp"
for kind in a b c d; do
  cmp -s "$cert" "$tmp/tampered/$kind.gp" && bad "tampering ($kind) changed nothing" && continue
  expect_reject "t22a tampered ($kind)" "$tmp/tampered/$kind.gp"
done
# Class members as built: format-2 certificates naming the coordinate file written beside them
# (no atlas file exists for them), accepted by the checker with both claims.
mkdir -p "$tmp/members"
"$TRIPACK" exact --class four-delta --k 2..3 --digits 120 --certificates "$tmp/members" --csv >/dev/null 2>&1 ||
  bad "exact --class four-delta --k 2..3 --certificates failed"
out=$(bash "$CHECK" "$tmp/members"/*.gp 2>&1)
if [ $? -eq 0 ] && grep -qx '2 certificates: 2 accepted, 0 rejected' <<<"$out" &&
  [ "$(grep -c '^cert_format = 2;' "$tmp/members"/*.gp | awk -F: '{s += $2} END {print s}')" = 2 ] &&
  [ -f "$tmp/members/four-delta-k2.txt" ]; then ok; else
  bad "the member certificates (format 2) should be accepted:"$'\n'"$(grep -E 'FAIL|certificates' <<<"$out")"; fi

# The 4Delta(k) packings as built, k = 1..50 (n = 4 .. 5100): P equals the minimal polynomial of
# the closed form d = 1/(a + sqrt 3), a = 2k - 2 (docs/classes.md): (a^2 - 3) x^2 - 2a x + 1,
# made primitive with a positive leading coefficient (k = 1: 3x^2 - 1).
"$TRIPACK" exact --class four-delta --k 1..50 --digits 60 --no-existence --csv >"$tmp/four-delta.csv" 2>&1 ||
  bad "exact --class four-delta failed: $(tail -1 "$tmp/four-delta.csv")"
for k in $(seq 1 50); do
  a=$((2 * k - 2))
  lead=$((a * a - 3))
  if [ "$lead" -lt 0 ]; then expected="$((-lead))*x^2 - 1"; else expected="$lead*x^2 - $((2 * a))*x + 1"; fi
  [ "$lead" -eq 1 ] && expected="x^2 - $((2 * a))*x + 1"
  got=$(awk -F, -v k="four-delta k=$k" '$2 == k {print $4}' "$tmp/four-delta.csv")
  [ "$got" = "$expected" ] && ok || bad "4Delta($k): P = '$got', the closed form gives '$expected'"
done

echo "exact: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
