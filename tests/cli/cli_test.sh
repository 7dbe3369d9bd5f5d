#!/usr/bin/env bash
# The tripack command line: good input works, bad input gets ONE clear line on stderr and a
# non-zero exit. Usage: cli_test.sh path/to/tripack path/to/tests/data
set -u
TRIPACK=$1
DATA=$2
pass=0
fail=0

# expect_error "description" "needle in the message" args...
expect_error() {
  local what=$1 needle=$2
  shift 2
  local err out rc
  err=$(mktemp)
  out=$("$TRIPACK" "$@" 2>"$err")
  rc=$?
  local lines
  lines=$(wc -l <"$err")
  if [ "$rc" -ne 0 ] && [ "$lines" -eq 1 ] && grep -qi -- "$needle" "$err"; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1))
    echo "FAIL: $what: rc=$rc, stderr lines=$lines: $(cat "$err")"
  fi
  rm -f "$err"
}

# expect_output "description" "needle in stdout" args...
expect_output() {
  local what=$1 needle=$2
  shift 2
  local out rc
  out=$("$TRIPACK" "$@" 2>/dev/null)
  rc=$?
  if [ "$rc" -eq 0 ] && grep -qF -- "$needle" <<<"$out"; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1))
    echo "FAIL: $what: rc=$rc, output: $out"
  fi
}

expect_error "unknown class" "unknown class 'nonsense'" build nonsense --k 2
expect_error "k below 1" "below the valid range" build four-delta --k 0
expect_error "negative k" "below the valid range" build twin --k -3
expect_error "k above the class's range" "above the valid range" build sparse-rows --k 13
expect_error "k below the class's range" "below the valid range" build odd-ripple --k 1
expect_error "a variant below its own k range" "has no variant 'depressed'" build odd-ripple --k 2 --variant depressed
expect_error "matrix without --p" "needs --p" build matrix --k 2
expect_error "p on a class without p" "takes no --p" build four-delta --k 2 --p 3
expect_error "bad variant" "no variant 'cavity-5'" build twin --k 3 --variant cavity-5
expect_error "missing --k" "needs --k" build four-delta
# Every n >= 2 is in a class since vacancy-segment (n = Delta(K) - m, 2 <= m < K) joined the
# hexagonal ones: only n = 1 is in none.
expect_error "N in no class" "no class of the catalogue contains n = 1" classify 1
expect_error "build --n in no class" "contains n = 1" build --n 1
expect_error "malformed classes.yaml" "malformed_classes.yaml" --catalogue "$DATA/malformed_classes.yaml" classes
expect_error "classes.yaml whose n does not grow" "does not grow with k" --catalogue "$DATA/n_not_growing_classes.yaml" classify 22
expect_error "missing classes.yaml" "cannot read catalogue" --catalogue /nonexistent.yaml classes
expect_error "non-numeric k" "k" build four-delta --k two
expect_error "bad k range" "--k expects" check-formula four-delta --k 3..x
expect_error "unwritable output" "cannot open" build four-delta --k 2 -o /nonexistent/dir/out.txt

# classify 12: the four members of GL1995 sec. 7, in catalogue order, and 12 = Delta(5) - 3 in
# the two discovered classes that hold it.
out=$("$TRIPACK" classify 12)
want=$'four-delta k=2   (4Delta(k))\nmatrix p=1 k=2   (n_p(k) = Delta((k+1)p-1)+(2p+1)Delta(k))\nripple-of-pairs k=1   (Delta(3k+1)+2)\npairs k=1   (Delta(2k+3)-3)\nvacancy-segment p=3 k=2   (Delta(k+p)-p)\njogged-line p=2 k=3   (Delta(k+p)-k)'
if [ "$out" = "$want" ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: classify 12: $out"; fi

# GL1995 Fig.t22: d(22) = 0.179396908611866, 47 bonds, 2 rattlers.
expect_output "build t22a" "0.179396908611866" build even-ripple --k 3
expect_output "build --n 22 picks a class with d(22)" '"d":"0.1793969086118659' build --n 22 --json
expect_output "json keys" '"rattlers":2' build matrix --p 3 --k 1 --json
expect_output "check-formula" "closed form" check-formula four-delta --k 1..5

# -o writes coordinates that read back: 22 lines of "x y" after the header.
tmp=$(mktemp -d)
"$TRIPACK" build even-ripple --k 3 -o "$tmp/t22a.txt" >/dev/null
if [ "$(grep -vc '^#' "$tmp/t22a.txt")" -eq 22 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: -o text"; fi
"$TRIPACK" build even-ripple --k 3 -o "$tmp/t22a.json" >/dev/null
if grep -q '"points"' "$tmp/t22a.json"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: -o json"; fi
rm -rf "$tmp"

# analyze: bad input gets one line and a non-zero exit.
tmp=$(mktemp -d)
printf '0.1 0.1\n0.5 nan\n' >"$tmp/nan.txt"
printf '0.1 0.1\n0.9 0.9\n' >"$tmp/outside.txt"
printf '0.1 0.1\n0.1 0.1\n0.5 0.2\n' >"$tmp/duplicate.txt"
printf '0.1 0.1\n0.5 0.2 0.3\n' >"$tmp/malformed.txt"
printf '{"points": [[0.1, 0.1], [0.2]]}' >"$tmp/malformed.json"
expect_error "analyze: unreadable file" "cannot read" analyze "$tmp/missing.txt"
expect_error "analyze: NaN" "not a finite number" analyze "$tmp/nan.txt"
expect_error "analyze: outside" "outside the unit triangle" analyze "$tmp/outside.txt"
expect_error "analyze: duplicate points" "coincide" analyze "$tmp/duplicate.txt"
expect_error "analyze: malformed text" "line 2" analyze "$tmp/malformed.txt"
expect_error "analyze: malformed json" "point 1" analyze "$tmp/malformed.json"
expect_error "analyze: wrong point count" "expected 23 points" analyze "$tmp/duplicate.txt" --n 23
expect_error "analyze: unknown convention" "unknown convention" analyze "$tmp/nan.txt" --convention diameter
expect_error "digits out of range" "digits" build four-delta --k 2 --digits 100001

# analyze of a written packing certifies it and finds its 2 rattlers (GL1995 Fig.t22).
"$TRIPACK" build even-ripple --k 3 -o "$tmp/t22a.csv" >/dev/null
expect_output "analyze t22a" "certified: rigid with a strictly positive stress" analyze "$tmp/t22a.csv"
expect_output "analyze t22a rattlers" '"rattler_indices":[8,13]' analyze "$tmp/t22a.csv" --json
rm -rf "$tmp"

# docs/classes.md: d(22) = 5 sqrt3/(20 sqrt3 + 7 + 2 sqrt11) = 0.17939690861186597956121884705073659574141764618876
# to 50 digits (mpmath); build --n 22 --digits 50 prints all of them.
expect_output "build --n 22 --digits 50" "0.17939690861186597956121884705073659574141764618876" build --n 22 --digits 50

# billiards: bad scenes and requests get one line and a non-zero exit.
expect_error "billiards: malformed scene" "scene" billiards --scene "$DATA/scenes/malformed.yaml"
expect_error "billiards: unknown effect" "gravity" billiards --scene "$DATA/scenes/unknown_effect.yaml"
expect_error "billiards: impossible stop rule" "relative_gap" billiards --scene "$DATA/scenes/bad_gap.yaml"
expect_error "billiards: overlapping initial points" "scene" billiards --scene "$DATA/scenes/overlap.yaml"
expect_error "billiards: n < 1" "N" billiards 0
expect_error "billiards: missing scene file" "scene" billiards --scene "$DATA/scenes/none.yaml"
expect_error "billiards: scene n differs" "n = 7" billiards 8 --scene "$DATA/scenes/t7.yaml"
expect_error "billiards: unknown pattern class" "nosuch" billiards --scene "$DATA/scenes/bad_pattern.yaml"
expect_error "billiards: pattern size differs" "pattern matrix" billiards --scene "$DATA/scenes/pattern_n.yaml"
# The shipped scenes: shaking the built t22a (matrix p=3 k=1) names its 2 rattlers, the same two
# the analysis finds (GL1995 Fig.t22: 47 bonds, 2 rattlers).
SCENES="$DATA/../../scenes"
expect_output "scene t22a-shake" "rattlers 2  certified" billiards --scene "$SCENES/t22a-shake.yaml" --runs 1
expect_output "scene t22a-shake rattlers agree" "rattlers [8 13]; analysis rattlers [8 13]" billiards --scene "$SCENES/t22a-shake.yaml" --runs 1
expect_output "scene t22-schedule" "t22a" billiards --scene "$SCENES/t22-schedule.yaml" --runs 20 --threads 2
expect_output "scene default" "t22a" billiards --scene "$SCENES/default.yaml" --runs 20 --threads 2
# Every distinct packing gets its own label (equal d and bonds: .1, .2 as t31a81.1, t31a81.2).
labels=$("$TRIPACK" billiards 22 --runs 50 --threads 2 2>/dev/null | sed -n '/^distinct packings/,$p' | awk 'NR > 1 {print $1}')
if [ -n "$labels" ] && [ "$(sort <<<"$labels" | uniq -d)" = "" ] && grep -qx "t22a" <<<"$labels"; then
  pass=$((pass + 1))
else
  fail=$((fail + 1))
  echo "FAIL: billiards labels not unique or t22a missing: $labels"
fi
# A scene file runs; t7a has d = 1/(1+sqrt3) = 0.366025403784439 (GL1995 Fig.t7).
expect_output "billiards scene t7" "0.366025403784439" billiards --scene "$DATA/scenes/t7.yaml" --runs 10

# Every input layout of t22a reads to the same packing: d(22) = 0.179396908611866 (GL1995
# Fig.t22), certified (tests/data/layouts/make.py writes them from tripack's own t22a).
LAYOUTS="$DATA/layouts"
for f in t22a.xy.txt t22a.xyr.txt t22a.ixy.txt t22a.header.csv t22a.points.json t22a.list.json t22a.pck; do
  expect_output "analyze layout $f" "0.179396908611866" analyze "$LAYOUTS/$f"
done
expect_output "x y r implies the radius convention" '"convention":"radius"' analyze "$LAYOUTS/t22a.xyr.txt" --json
expect_output "i x y layout named" '"layout":"i x y"' analyze "$LAYOUTS/t22a.ixy.txt" --json
# r = d / (2 (1 + sqrt3 d)) of d(22) to 40 digits (mpmath from the closed form in docs/classes.md):
# 0.06843425156850538244567369271218...; --digits 30 carries it through MPFR.
expect_output "r with --digits 30" "r          0.0684342515685053824456736927122" analyze "$LAYOUTS/t22a.xyr.txt" --digits 30

# expect_warning "description" "needle in the one stderr line" "needle in stdout" args...: exit 0.
expect_warning() {
  local what=$1 needle=$2 out_needle=$3
  shift 3
  local err out rc lines
  err=$(mktemp)
  out=$("$TRIPACK" "$@" 2>"$err")
  rc=$?
  lines=$(wc -l <"$err")
  if [ "$rc" -eq 0 ] && [ "$lines" -eq 1 ] && grep -qi -- "$needle" "$err" && grep -qF -- "$out_needle" <<<"$out"; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1))
    echo "FAIL: $what: rc=$rc, stderr: $(cat "$err"), stdout: $out"
  fi
  rm -f "$err"
}
# Rounded to 6 decimals: 4 points lie up to 1.6e-7 outside; accepted with one warning, and relax
# recovers d to 15 digits.
expect_warning "rounded input" "outside the unit triangle by up to 1.6e-07" "0.179396908611866" analyze "$LAYOUTS/t22a.rounded6.txt"
expect_error "beyond the rounding tolerance" "0.001 outside the unit triangle" analyze "$LAYOUTS/t22a.bad-outside.txt"
expect_error "flipped unit-triangle file" "upside down" analyze "$LAYOUTS/t22a.bad-flipped.txt"
expect_warning "upside-down container" "upside down" "0.179396908611866" analyze "$LAYOUTS/t22a.upside-down.txt" --convention radius
expect_warning "transposed container" "quarter turn" "0.179396908611866" analyze "$LAYOUTS/t22a.transposed.txt" --convention radius
expect_error "ambiguous orientation" "orientation" analyze "$LAYOUTS/hexagon.bad-orientation.txt" --convention radius
expect_error "x y r with another convention" "so its convention is radius" analyze "$LAYOUTS/t22a.xyr.txt" --convention unit-disk-side
expect_error "radius varies" "differs" analyze "$LAYOUTS/t22a.bad-radius-varies.txt"
expect_error "index repeats" "repeats" analyze "$LAYOUTS/t22a.bad-index-repeats.txt"
expect_error "csv without y" "no 'y' column" analyze "$LAYOUTS/t22a.bad-no-y.csv"

# Export for the record tables: i x y lines, d, r and S in the header, with --digits.
tmp=$(mktemp -d)
"$TRIPACK" build even-ripple --k 3 --digits 30 -o "$tmp/t22a.pck" >/dev/null
if grep -q '^# d: 0.179396908611865979561218847051$' "$tmp/t22a.pck" && grep -q '^# r: 0.0684342515685053824456736927122$' "$tmp/t22a.pck" &&
  grep -q '^# S: 14.6125657412788477036406723266$' "$tmp/t22a.pck" && [ "$(grep -vc '^#' "$tmp/t22a.pck")" -eq 22 ] &&
  grep -q '^0 0.5000000000000000000000000000' "$tmp/t22a.pck"; then
  pass=$((pass + 1))
else
  fail=$((fail + 1))
  echo "FAIL: records export: $(head -12 "$tmp/t22a.pck")"
fi
expect_output "records read back" "0.179396908611866" analyze "$tmp/t22a.pck"
rm -rf "$tmp"

# With --json an error is one JSON object on stdout too (and one line on stderr).
out=$("$TRIPACK" build nonsense --k 2 --json 2>/dev/null)
if [ "$out" = '{"error":"unknown class '"'"'nonsense'"'"'"}' ] || grep -q '^{"error":"unknown class' <<<"$out"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: json error: $out"; fi
expect_error "json error keeps one stderr line" "unknown class" build nonsense --k 2 --json
out=$("$TRIPACK" analyze /nonexistent.txt --json 2>/dev/null)
if grep -q '^{"error":"cannot read' <<<"$out"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: json error analyze: $out"; fi
out=$("$TRIPACK" billiards 0 --json 2>/dev/null)
if grep -q '^{"error":' <<<"$out"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: json parse error: $out"; fi
# Every command's JSON is one object with a total "seconds".
for args in "classes" "classify 12" "build four-delta --k 2" "check-formula four-delta --k 1..3" "table --kmax 1" "billiards 7 --runs 2" "analyze $LAYOUTS/t22a.xy.txt"; do
  # shellcheck disable=SC2086
  expect_output "json seconds: $args" '"seconds":' $args --json
done
expect_output "table --json rows" '"rows":[' table --kmax 1 --json

# build --n: the candidates are part of the result (stdout), nothing on stderr.
err=$("$TRIPACK" build --n 22 2>&1 >/dev/null)
if [ -z "$err" ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: build --n wrote to stderr: $err"; fi
expect_output "build --n candidates" "candidate  matrix k=1 p=3" build --n 22

# billiards -o DIR: one file per distinct packing, named by its label, that reads back.
tmp=$(mktemp -d)
"$TRIPACK" billiards 22 --runs 8 --threads 2 -o "$tmp/found" --format pck >"$tmp/out.txt" 2>/dev/null
labels=$(sed -n '/^distinct packings/,$p' "$tmp/out.txt" | awk 'NR > 1 {print $1}')
files=$(cd "$tmp/found" && ls | sed 's/\.pck$//')
if [ -n "$labels" ] && [ "$(sort <<<"$labels")" = "$(sort <<<"$files")" ] && grep -q '^# label: t22a$' "$tmp/found/t22a.pck"; then
  pass=$((pass + 1))
else
  fail=$((fail + 1))
  echo "FAIL: billiards -o: labels [$labels] files [$files]"
fi
expect_output "billiards -o file reads back" "0.179396908611866" analyze "$tmp/found/t22a.pck"
expect_error "billiards -o unwritable" "cannot write to directory" billiards 7 --runs 1 -o /proc/nonexistent
expect_error "billiards --format unknown" "--format" billiards 7 --runs 1 -o "$tmp/x" --format xls
expect_output "billiards --json --points" '"points":[["' billiards 7 --runs 2 --json --points
rm -rf "$tmp"

# More than 40 distinct packings (fast growth at n = 80): labels stay valid and unique past z
# (t80a .. t80z, t80aa, ...), and the JSON is valid.
csv=$("$TRIPACK" billiards --scene "$DATA/scenes/many_distinct.yaml" --runs 60 --threads 2 --csv 2>/dev/null)
# The label column, found by its name in the header (docs/formats.md, "Results").
labels=$(awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) if ($i == "label") c = i; next} {print $c}' <<<"$csv")
total=$(wc -l <<<"$labels")
unique=$(sort -u <<<"$labels" | wc -l)
valid=$(grep -c '^t80[a-z]\+\([0-9]\+\)\?\(\.[0-9]\+\)\?$' <<<"$labels")
out=$("$TRIPACK" billiards --scene "$DATA/scenes/many_distinct.yaml" --runs 60 --threads 2 --json 2>/dev/null)
rc=$?
if [ "$total" -gt 40 ] && [ "$total" -eq "$unique" ] && [ "$valid" -eq "$total" ] && [ "$rc" -eq 0 ] &&
  grep -q '"label":"t80aa' <<<"$out" && grep -qx 't80aa' <<<"$labels"; then
  pass=$((pass + 1))
else
  fail=$((fail + 1))
  echo "FAIL: many distinct packings: $total labels, $unique unique, $valid valid, json rc $rc"
fi
# build-scan resumes through the runner: a second range over the first builds only the new N,
# and the table holds each N once, in order; a table of another format is refused, not appended.
tmp=$(mktemp -d)
"$TRIPACK" build-scan --n 10..12 --table "$tmp/scan.csv" >/dev/null 2>&1
out=$("$TRIPACK" build-scan --n 8..14 --table "$tmp/scan.csv" --json 2>/dev/null)
if grep -q '"already_done":3,"built_now":4,"certified_now":4' <<<"$out" &&
  [ "$(cut -d, -f1 "$tmp/scan.csv" | tr '\n' ' ')" = "n 8 9 10 11 12 13 14 " ]; then
  pass=$((pass + 1))
else
  fail=$((fail + 1))
  echo "FAIL: build-scan resume: $out; $(cut -d, -f1 "$tmp/scan.csv" | tr '\n' ' ')"
fi
echo "a,b" >"$tmp/foreign.csv"
expect_error "build-scan foreign table" "not a tripack build-scan table" build-scan --n 8..9 --table "$tmp/foreign.csv"
rm -rf "$tmp"
# compare: the builder's t22a and the best billiards packing are the same packing (GL1995 Fig.t22).
expect_output "compare 22" "the same packing" compare 22 --runs 10 --threads 2
expect_output "compare 22 csv" ",true,true," compare 22 --runs 10 --threads 2 --csv

# draw and --svg/--png/--pdf: the same input gives the same bytes (PDF date fixed).
tmp=$(mktemp -d)
"$TRIPACK" draw even-ripple --k 3 -o "$tmp/a.png" >/dev/null && "$TRIPACK" draw even-ripple --k 3 -o "$tmp/b.png" >/dev/null
if [ -s "$tmp/a.png" ] && cmp -s "$tmp/a.png" "$tmp/b.png"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: draw png"; fi
"$TRIPACK" build even-ripple --k 3 --svg "$tmp/t22a.svg" --pdf "$tmp/a.pdf" -o "$tmp/t22a.txt" >/dev/null
"$TRIPACK" draw "$tmp/t22a.txt" --forces -o "$tmp/b.pdf" >/dev/null
"$TRIPACK" build even-ripple --k 3 --pdf "$tmp/c.pdf" >/dev/null
if grep -q '<svg' "$tmp/t22a.svg" && [ "$(head -c 4 "$tmp/b.pdf")" = "%PDF" ] && cmp -s "$tmp/a.pdf" "$tmp/c.pdf"; then
  pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: build --svg/--pdf, draw FILE"; fi
expect_error "draw: bad extension" "extension" draw even-ripple --k 3 -o "$tmp/x.gif"
expect_error "draw: class without k" "needs --k" draw even-ripple -o "$tmp/x.png"
rm -rf "$tmp"

# A random start without growth would run to max_seconds doing nothing: refused in one line.
expect_error "zero growth scene" "needs growth with a rate > 0" billiards --scene "$DATA/scenes/zero_growth.yaml"
# Growth without a thermostat never reaches its stop gap (measured: runs end at max_seconds).
printf 'n: 10\neffects:\n  growth: {rate: 0.01}\n' >"${TMPDIR:-/tmp}/tripack_no_thermostat.yaml"
expect_error "growth without thermostat" "growth needs a thermostat" billiards --scene "${TMPDIR:-/tmp}/tripack_no_thermostat.yaml"
rm -f "${TMPDIR:-/tmp}/tripack_no_thermostat.yaml"

# Campaigns: a small campaign, its rerun (nothing repeated), db best, bad input.
cdb="${TMPDIR:-/tmp}/tripack_cli_campaign_$$.db"
rm -f "$cdb" "$cdb-wal" "$cdb-shm"
expect_output "campaign records units" "6 recorded now" campaign --n 10..11 --runs 3 --threads 2 --db "$cdb"
expect_output "campaign rerun repeats nothing" "6 already in" campaign --n 10..11 --runs 3 --db "$cdb"
expect_output "db best, one line per n" "t11a" db best --db "$cdb"
expect_error "campaign range without n >= 2" "has no n >= 2" campaign --n 0..1 --db "$cdb"
expect_error "campaign range backwards" "--n range 40..30 is empty" campaign --n 40..30 --db "$cdb"
expect_error "campaign range not numbers" "--n expects" campaign --n 16..x --db "$cdb"
printf 'x y\n0.1 0.2\n' >"$cdb.txt"
expect_error "db best on a text file" "not a tripack database" db best --db "$cdb.txt"
expect_error "campaign on a text file" "not a tripack database" campaign --n 5 --db "$cdb.txt"
expect_output "campaign --json" '"recorded":0' campaign --n 10..11 --runs 3 --db "$cdb" --json
expect_output "db best --json" '"label":"t11a"' db best 11 --db "$cdb" --json
expect_output "db check" "integrity ok" db check --db "$cdb"
expect_output "db prune" "kept 2 packings" db prune --keep 1 --db "$cdb"
expect_error "db prune without --keep" "--keep is required" db prune --db "$cdb"
expect_error "db prune of a missing database" "no database" db prune --keep 1 --db "$cdb.missing"
expect_output "db check --json: no duplicates" '"duplicates":0' db check --db "$cdb" --json
expect_output "db check --json: runs" '"runs":6' db check --db "$cdb" --json
# db export / import: the best of n = 11 out in every format and convention, and back in.
ctmp=$(mktemp -d)
expect_output "db export to stdout" "# label: t11a" db export 11 --db "$cdb"
expect_output "db export records radius" "# convention: radius" db export 11 --db "$cdb" --format records --convention radius
for f in txt csv json pck; do
  for c in unit-triangle radius unit-disk-side; do
    "$TRIPACK" db export 11 --db "$cdb" --convention "$c" -o "$ctmp/t11a.$c.$f" >/dev/null 2>&1
  done
done
expect_output "db import of every export: a new database" "1 stored, 2 already there" db import "$ctmp"/t11a.*.txt --db "$ctmp/copy.db"
expect_output "db import of every export: recognised" "12 already there" db import "$ctmp"/t11a.* --db "$cdb"
expect_output "db import --json" '"stored":false' db import "$ctmp/t11a.radius.json" --db "$cdb" --json
expect_output "db export --all -o DIR" "t11a.csv" db export 11 --db "$cdb" --all --format csv -o "$ctmp/all"
if [ "$(ls "$ctmp/all" | wc -l)" -eq "$("$TRIPACK" db export 11 --db "$cdb" --all --format json | grep -c '"label"')" ]; then
  pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: db export --all: one file per packing"; fi
expect_output "db best shows the import's source" "t11a" db best --db "$ctmp/copy.db"
# Bad input: one line, non-zero exit, nothing created or stored.
expect_error "db export: missing database" "no database" db export 11 --db "$ctmp/none.db"
expect_error "db best: missing database" "no database" db best --db "$ctmp/none.db"
expect_error "db check: missing database" "no database" db check --db "$ctmp/none.db"
if [ ! -e "$ctmp/none.db" ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: a read command created a database"; fi
expect_error "db export: a text file as --db" "not a tripack database" db export 11 --db "$cdb.txt"
expect_error "db check: a text file as --db" "not a tripack database" db check --db "$cdb.txt"
expect_error "db import: a text file as --db" "not a tripack database" db import "$ctmp/t11a.radius.txt" --db "$cdb.txt"
expect_error "db export: n with no packings" "no packings of n = 40" db export 40 --db "$cdb"
expect_error "db export: rank out of range" "rank 99 is out of range" db export 11 --db "$cdb" --rank 99
expect_error "db export: unknown format" "--format must be" db export 11 --db "$cdb" --format xml
expect_error "db export: unknown convention" "unknown convention 'diameter'" db export 11 --db "$cdb" --convention diameter
expect_error "db export: --rank and --all" "exclude" db export 11 --db "$cdb" --rank 2 --all
out=$("$TRIPACK" db best 40 --db "$cdb" --json 2>/dev/null)
if [ $? -ne 0 ] && grep -qF '{"error":"no packings of n = 40' <<<"$out"; then
  pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: db errors as JSON: $out"; fi
before=$("$TRIPACK" db check --db "$cdb" --json | sed 's/"seconds":[^,}]*//')
sed 's/^# d: .*/# d: 0.3/' "$ctmp/t11a.unit-triangle.txt" >"$ctmp/overlap.txt"
expect_error "db import: overlapping disks" "overlapping disks" db import "$ctmp/overlap.txt" --db "$cdb"
printf '0.1 0.1\n0.5 abc\n0.9 0.05\n' >"$ctmp/malformed.txt"
expect_error "db import: malformed file" "malformed.txt: line 2" db import "$ctmp/malformed.txt" --db "$cdb"
expect_error "db import: one bad file stores none" "overlapping disks" db import "$ctmp/t11a.radius.csv" "$ctmp/overlap.txt" --db "$ctmp/copy2.db"
if [ ! -e "$ctmp/copy2.db" ] && [ "$("$TRIPACK" db check --db "$cdb" --json | sed 's/"seconds":[^,}]*//')" = "$before" ]; then
  pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: a refused import changed a database"; fi
# Another schema version, and a database another process is writing (sqlite3's shell or
# Python's module holds a write transaction; skipped when neither is installed).
hold_lock() {
  if command -v sqlite3 >/dev/null; then
    (echo "BEGIN IMMEDIATE;"; sleep "$2"; echo "COMMIT;") | sqlite3 "$1" >/dev/null &
  elif command -v python3 >/dev/null; then
    python3 -c "import sqlite3, sys, time; c = sqlite3.connect(sys.argv[1], isolation_level=None); c.execute('BEGIN IMMEDIATE'); time.sleep(float(sys.argv[2]))" "$1" "$2" &
  else
    return 1
  fi
  sleep 0.5
}
set_version() {
  if command -v sqlite3 >/dev/null; then
    sqlite3 "$1" "UPDATE meta SET value = '$2' WHERE key = 'schema_version'"
  else
    python3 -c "import sqlite3, sys; c = sqlite3.connect(sys.argv[1]); c.execute(\"UPDATE meta SET value = ? WHERE key = 'schema_version'\", (sys.argv[2],)); c.commit()" "$1" "$2"
  fi
}
if command -v sqlite3 >/dev/null || command -v python3 >/dev/null; then
  cp "$ctmp/copy.db" "$ctmp/v99.db"
  set_version "$ctmp/v99.db" 99
  expect_error "db of another schema version" "schema version 99" db export 11 --db "$ctmp/v99.db"
  expect_error "import into another schema version" "schema version 99" db import "$ctmp/t11a.radius.txt" --db "$ctmp/v99.db"
  hold_lock "$cdb" 8
  expect_error "db import: a locked database" "locked" db import "$ctmp/t11a.unit-triangle.json" --db "$cdb"
  expect_output "db check reads while another process writes" "integrity ok" db check --db "$cdb"
  wait
  hold_lock "$cdb" 8
  expect_error "campaign on a locked database" "locked" campaign --n 10 --runs 4 --db "$cdb"
  wait
fi
# A read-only database (a file and directory this user cannot write; root ignores permissions,
# so as root the commands run as nobody through setpriv): the read commands work, a campaign or
# an import is refused in one line, and the file is unchanged.
rodir=$(mktemp -d)
cp "$ctmp/copy.db" "$rodir/ro.db"
chmod 755 "$rodir"
chmod 444 "$rodir/ro.db"
as_reader=()
if [ "$(id -u)" -eq 0 ]; then
  command -v setpriv >/dev/null && as_reader=(setpriv --reuid=65534 --regid=65534 --clear-groups)
fi
if [ "$(id -u)" -ne 0 ] || [ ${#as_reader[@]} -gt 0 ]; then
  before=$(md5sum <"$rodir/ro.db")
  ro_err=$(mktemp)
  if "${as_reader[@]}" "$TRIPACK" db best --db "$rodir/ro.db" 2>"$ro_err" | grep -q t11a &&
     "${as_reader[@]}" "$TRIPACK" db check --db "$rodir/ro.db" >/dev/null 2>>"$ro_err" &&
     "${as_reader[@]}" "$TRIPACK" db export 11 --db "$rodir/ro.db" >/dev/null 2>>"$ro_err"; then
    pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: read commands on a read-only database: $(cat "$ro_err")"; fi
  cp "$ctmp/t11a.unit-triangle.json" "$rodir/t11a.json"
  chmod 644 "$rodir/t11a.json"
  for cmd in "campaign --n 12 --runs 2" "db import $rodir/t11a.json"; do
    # shellcheck disable=SC2086
    "${as_reader[@]}" "$TRIPACK" $cmd --db "$rodir/ro.db" >/dev/null 2>"$ro_err"
    rc=$?
    if [ "$rc" -ne 0 ] && [ "$(wc -l <"$ro_err")" -eq 1 ] && grep -q "read-only" "$ro_err"; then
      pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $cmd on a read-only database: rc=$rc $(cat "$ro_err")"; fi
  done
  if [ "$(md5sum <"$rodir/ro.db")" = "$before" ]; then
    pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: the read-only database changed"; fi
  rm -f "$ro_err"
fi
chmod 755 "$rodir/ro.db"
rm -rf "$rodir"
rm -rf "$ctmp"
rm -f "$cdb" "$cdb-wal" "$cdb-shm" "$cdb.txt"

# search: the JSON a program reads; one seed, one thread and a step budget print the
# same packings twice; --db records each chain once as a unit (n, seed, "search S s").
sdb=$(mktemp -u /tmp/tripack-search-XXXX.db)
out1=$("$TRIPACK" search 12 --steps 15 --seed 4 --json 2>/dev/null)
out2=$("$TRIPACK" search 12 --steps 15 --seed 4 --json 2>/dev/null)
if python3 - "$out1" "$out2" <<'PY'
import json, re, sys
a, b = (json.loads(x) for x in sys.argv[1:3])
best = a["best"]
assert a["n"] == 12 and a["seconds"] > 0 and a["steps"] == 15
assert set(["d", "label", "bonds", "rattlers", "certified", "seconds_to_best"]) <= set(best)
assert isinstance(best["d"], str) and len(re.sub(r"[^0-9]", "", best["d"]).lstrip("0")) >= 17
assert best["certified"] and a["packings"][0]["label"] == best["label"]
strip = lambda j: [(p["d"], p["label"], p["bonds"]) for p in j["packings"]]
assert strip(a) == strip(b)
base = a["chains"][0]["base"]  # 12 = Delta(5) - 3 is the inflation of Delta(3) - 2 = 4
assert base["n"] == 4 and 0 < base["steps"] <= 15
PY
then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: search --json"; fi
# Random starts only (the explorer's search): reproducible too, and every chain's time is split
# into analysis and billiards.
out1=$("$TRIPACK" search 12 --steps 15 --seed 4 --no-lattice-starts --json 2>/dev/null)
out2=$("$TRIPACK" search 12 --steps 15 --seed 4 --no-lattice-starts --json 2>/dev/null)
if python3 - "$out1" "$out2" <<'PY'
import json, sys
a, b = (json.loads(x) for x in sys.argv[1:3])
assert [p["d"] for p in a["packings"]] == [p["d"] for p in b["packings"]]
chain = a["chains"][0]
assert 0 <= chain["analysis_cpu_seconds"] <= chain["cpu_seconds"] and chain["analyses"] >= 1
PY
then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: search --no-lattice-starts"; fi
# search never returns less than build --n (a sample; scripts/analysis/search-vs-build.py covers every
# N <= 300): at 48 and 102 the builder's packings are denser than any search from random found.
for n in 48 102; do
  b=$("$TRIPACK" build --n "$n" --json 2>/dev/null)
  s=$("$TRIPACK" search "$n" --steps 2 --seed 3 --json 2>/dev/null)
  if python3 - "$b" "$s" <<'PY'
import json, sys
from decimal import Decimal
b, s = (json.loads(x) for x in sys.argv[1:3])
assert Decimal(s["best"]["d"]) >= Decimal(b["d"]) * (1 - Decimal("1e-15")), (b["d"], s["best"]["d"])
assert s["builder"]["member"].startswith(b["class"]) and s["builder"]["certified"]
PY
  then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: search $n below build --n $n"; fi
done
"$TRIPACK" search 12 --steps 3 --seed 9 --db "$sdb" >/dev/null 2>&1
"$TRIPACK" search 12 --steps 3 --seed 9 --db "$sdb" >/dev/null 2>"$sdb.err"
# (chains started from the builder's packing: `search 10 s, from builders`, docs/search.md)
if [ "$(sqlite3 "$sdb" "SELECT COUNT(*) FROM runs WHERE n = 12 AND seed = 9 AND method = 'search 10 s, from builders'")" = 1 ] &&
   [ "$(sqlite3 "$sdb" "SELECT COUNT(*) FROM runs WHERE method = 'search 10 s, from builders, continued'")" = 1 ]; then
  pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: search --db"; fi
rm -f "$sdb" "$sdb-wal" "$sdb-shm" "$sdb.err"
expect_error "search with an unknown method" "--method must be one of basin-hopping, restarts" search 12 --method anneal
expect_error "search with a bad target" "--target must be a positive decimal" search 12 --target 0.2x
expect_error "search of one disk" "N: Value 1 not in range" search 1
# Range errors and the help show an option's bounds as numbers are written: 2 to 100000, 0.001
# (CLI11's Range printed 2.000000 to 100000.000000).
expect_error "an integer option's range in integers" "max-n: Value 1 not in range 2 to 100000$" \
  explore --max-n 1
expect_error "a real option's range in shortest form" \
  "seconds: Value 0 not in range 0.001 to 10000000$" search 10 --seconds 0
expect_error "a range check of a word" "'abc' is not a number" explore --max-n abc
if "$TRIPACK" explore --help | grep -q -- '--max-n INT in \[2 - 100000\]'; then
  pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: help shows --max-n INT in [2 - 100000]"; fi
# build and analyze print L and delta(n) to the --digits asked: from the MPFR polish, delta =
# L - t(n) in MPFR to L's decimals. The values: L = 1/d and delta = L - (-3 + sqrt(177))/2 from
# t22a's d to 60 digits (build --digits 60), in Python's decimal module at 120 digits, rounded.
L50=5.5742320630705465582928898217985976803360110461759
delta49=0.4221647152455111957698744147368660378637397383078
digits_out=$("$TRIPACK" build even-ripple --k 3 --digits 50 2>&1)
if grep -qx "L          $L50" <<<"$digits_out" && grep -qx "delta(n)   $delta49" <<<"$digits_out"; then
  pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: build --digits 50: L, delta: $digits_out"; fi
digits_out=$("$TRIPACK" build even-ripple --k 3 --digits 50 --json 2>&1)
if grep -q "\"L\":\"$L50\"" <<<"$digits_out"; then
  pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: build --digits 50 --json: L"; fi
digits_out=$("$TRIPACK" analyze "$(dirname "$0")/../../data/atlas/t22a.txt" --digits 40 2>&1)
if grep -qx "L          ${L50:0:41}" <<<"$digits_out" &&
  grep -qx "delta(n)   0.422164715245511195769874414736866037864" <<<"$digits_out"; then
  pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: analyze --digits 40: L, delta: $digits_out"; fi
digits_out=$("$TRIPACK" build even-ripple --k 3 --digits 5 2>&1)
if grep -qx "L          5.5742" <<<"$digits_out" && grep -qx "delta(n)   0.42216" <<<"$digits_out"; then
  pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: build --digits 5: L, delta: $digits_out"; fi

# Progress: on a terminal (script(1) gives the command a pty), a stage running over 2 s
# shows a live line with the stage; a quick command shows none.
if command -v script >/dev/null; then
  slow=$(script -qec "$TRIPACK build four-delta --k 150" /dev/null)
  quick=$(script -qec "$TRIPACK build even-ripple --k 3" /dev/null)
  if grep -q $'\rbuild: [0-9.]* s, LP-free certificate of the start' <<<"$slow" &&
     grep -q "verdict *certified" <<<"$slow" && ! grep -q $'\rbuild:' <<<"$quick"; then
    pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: progress line on a terminal"; fi
fi

# A file whose header states n but holds another number of points (a truncated t22a.txt) is
# refused by analyze and by db import, and nothing is stored; a header d the points contradict
# is a warning for analyze and a refusal for import unless asked.
ttmp=$(mktemp -d)
atlas22="$(dirname "$0")/../../data/atlas/t22a.txt"
{ grep '^#' "$atlas22"; grep -v '^#' "$atlas22" | head -n 12; } >"$ttmp/t22a.txt"  # the header and the first 12 points
expect_error "analyze refuses a truncated file" "n = 22 but the file holds 12 points" \
  analyze "$ttmp/t22a.txt"
expect_error "db import refuses a truncated file" "n = 22 but the file holds 12 points" \
  db import "$ttmp/t22a.txt" --db "$ttmp/runs.db"
if [ ! -e "$ttmp/runs.db" ]; then pass=$((pass + 1)); else
  fail=$((fail + 1)); echo "FAIL: a refused import created the database"; fi
sed 's/^# d: .*/# d: 0.1793/' "$atlas22" >"$ttmp/d22.txt"
if "$TRIPACK" analyze "$ttmp/d22.txt" >/dev/null 2>"$ttmp/warn.txt" &&
  grep -q "warning: the header's d" "$ttmp/warn.txt"; then pass=$((pass + 1)); else
  fail=$((fail + 1)); echo "FAIL: analyze warns of a header d the points contradict"; fi
expect_error "db import refuses a header d the points contradict" "differs from the points' d" \
  db import "$ttmp/d22.txt" --db "$ttmp/runs.db"
if "$TRIPACK" db import "$ttmp/d22.txt" --accept-header-d --db "$ttmp/runs.db" >/dev/null 2>&1; then
  pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: import --accept-header-d stores it"; fi
# The label read is the label written by analyze -o, in every format that carries one.
for ext in txt json xyz pck; do
  "$TRIPACK" analyze "$atlas22" -o "$ttmp/out.$ext" >/dev/null 2>&1
  if grep -qE '(label: t22a|"label": ?"t22a"|label=t22a|label="t22a")' "$ttmp/out.$ext"; then
    pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: analyze -o out.$ext keeps the label t22a"; fi
done
rm -rf "$ttmp"

echo "cli: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
