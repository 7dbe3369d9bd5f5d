#!/usr/bin/env bash
# Hit rates of billiards growth protocols against n (docs/performance.md, "Billiards defaults
# against n"). Not a test: the full table takes about 20-30 minutes on 2 cores.
#
# For each (n, protocol) cell: `tripack billiards N --scene S --runs R --threads T --json` from
# seed 1 (run r uses seed 1 + r, so hit counts are deterministic); a run hits when it is certified
# and its d equals the best d to 1e-12 relative. The best d: n = 22 t22a (GL1995), n = 79 the
# built t79a (`tripack build --n 79`), n = 254 t254a (GL1995's text); other n: the largest
# certified d of any run of any protocol in OUT (say so in the table).
# Prints a markdown table: hits, events per run (deterministic), billiards seconds per run (the
# JSON's per-run wall time), CPU seconds per run (user + sys of the command / runs: billiards plus
# the analysis of every end state), and the expected times to a first hit (per run / hit fraction).
#
# Usage: bench/hit_rates.sh            (from the repository root, after building build/tripack)
# Env:   TRIPACK (build/tripack), OUT (directory for the raw JSON; default /tmp/tripack-hit-rates;
#        existing cells are reused, so an interrupted run resumes), THREADS (2),
#        ONLY (a regex on "n protocol": run only those cells; the table shows every cell in OUT).
# Needs python3 (the table) and bash.
set -euo pipefail
TRIPACK=${TRIPACK:-build/tripack}
OUT=${OUT:-/tmp/tripack-hit-rates}
THREADS=${THREADS:-2}
ONLY=${ONLY:-.}
mkdir -p "$OUT"

# Protocols (the YAML of effects.growth; `default` = the built-in scene, no --scene):
#   cR     constant rate R
#   wR     0.01, then R while the estimated gap is in [0.01, 0.1), then 0.01 again to the stop
#   slow   0.01, then 1e-3 below a gap of 0.1, 1e-4 below 0.01 (slows as the gap shrinks)
growth_of() {
  case $1 in
  c*) echo "{rate: ${1#c}}" ;;
  w*) echo "{rate: 0.01, schedule: [{gap: 0.1, rate: ${1#w}}, {gap: 0.01, rate: 0.01}]}" ;;
  slow) echo "{rate: 0.01, schedule: [{gap: 0.1, rate: 1e-3}, {gap: 0.01, rate: 1e-4}]}" ;;
  *) echo "unknown protocol $1" >&2 && exit 2 ;;
  esac
}

# n protocol runs
CELLS="
22 c0.01 64
22 c3e-3 32
22 c1e-3 32
22 c3e-4 32
22 c1e-4 16
22 w1e-3 32
22 w3e-4 32
22 w1e-4 32
53 c0.01 64
53 c3e-3 32
53 c1e-3 32
53 c3e-4 32
53 c1e-4 16
53 w1e-3 32
53 w3e-4 32
53 w1e-4 32
79 c0.01 64
79 c3e-3 32
79 c1e-3 32
79 c3e-4 32
79 c1e-4 16
79 w1.8e-3 32
79 w1e-3 32
79 w3e-4 32
79 w1e-4 32
121 c0.01 64
121 c3e-3 32
121 c1e-3 32
121 c3e-4 16
121 c1e-4 16
121 w1e-3 32
121 w3e-4 32
121 w1e-4 32
254 c0.01 64
254 c3e-3 32
254 c1e-3 32
254 c3e-4 16
254 c1e-4 8
254 w1e-3 32
254 w3e-4 32
254 w1e-4 32
254 w3e-5 16
254 slow 8
22 default 64
53 default 64
79 default 32
121 default 32
254 default 32
"

while read -r n proto runs; do
  [ -n "$n" ] || continue
  grep -Eq -- "$ONLY" <<<"$n $proto" || continue
  base="$OUT/n${n}_${proto}_r${runs}"
  [ -s "$base.json" ] && [ -s "$base.time" ] && continue
  args=(billiards "$n" --runs "$runs" --seed 1 --threads "$THREADS" --json)
  if [ "$proto" != default ]; then
    printf 'n: %s\neffects:\n  growth: %s\n  thermostat: {}\n  stop: {relative_gap: 1e-12}\n' \
      "$n" "$(growth_of "$proto")" >"$base.yaml"
    args+=(--scene "$base.yaml")
  fi
  echo "n = $n $proto: $runs runs" >&2
  TIMEFORMAT='%R %U %S'
  { time "$TRIPACK" "${args[@]}" >"$base.json.part" 2>/dev/null; } 2>"$base.time.part"
  mv "$base.json.part" "$base.json"
  mv "$base.time.part" "$base.time"
done <<<"$CELLS"

best79=$("$TRIPACK" build --n 79 --json | python3 -c 'import json, sys; print(json.load(sys.stdin)["d"])')

python3 - "$OUT" "$best79" <<'PY'
import glob, json, os, re, sys
out, best79 = sys.argv[1], float(sys.argv[2])
known = {22: (0.179396908611866, "t22a (GL1995)"), 79: (best79, "t79a (built)"),
         254: (0.0467170396481042, "t254a (GL1995)")}
cells = []
for f in glob.glob(os.path.join(out, "n*_r*.json")):
    m = re.match(r"n(\d+)_(.+)_r(\d+)\.json$", os.path.basename(f))
    j = json.load(open(f))
    t = open(f[:-5] + ".time").read().split()
    cells.append((int(m.group(1)), m.group(2), j, float(t[1]) + float(t[2])))
best = {}
for n, _, j, _ in cells:
    for r in j["runs"]:
        if r.get("certificate", {}).get("certified"):
            best[n] = max(best.get(n, 0.0), float(r["d"]))
def key(c):
    p = c[1]
    if p == "default": return (c[0], 0, 0)
    return (c[0], {"c": 1, "w": 2}.get(p[0], 3), -float(p[1:]) if p[0] in "cw" else 0)
def fmt(x):
    return "∞ (no hit)" if x is None else (f"{x:.3g}" if x < 100 else f"{x:.0f}")
print("| n | best d | protocol | runs | hits | hit fraction | events/run | s/run (billiards) "
      "| CPU s/run | expected s to a hit | expected CPU s to a hit |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for n, proto, j, cpu in sorted(cells, key=key):
    d, src = known.get(n, (best[n], "best found here"))
    runs = j["runs"]
    hits = sum(1 for r in runs if r.get("certificate", {}).get("certified")
               and abs(float(r["d"]) / d - 1) <= 1e-12)
    k = len(runs)
    ev = sum(r["events"] for r in runs) / k
    s = sum(r["seconds"] for r in runs) / k
    c = cpu / k
    frac = hits / k
    print(f"| {n} | {d:.15g} {src} | {proto} | {k} | {hits} | {frac:.2f} | {ev / 1e6:.3g} M "
          f"| {fmt(s)} | {fmt(c)} | {fmt(s / frac if hits else None)} "
          f"| {fmt(c / frac if hits else None)} |")
PY
