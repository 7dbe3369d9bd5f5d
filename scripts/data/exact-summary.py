#!/usr/bin/env python3
"""Summary of data/atlas-exact.csv (docs/exact.md): proofs by kind, the degree of P against n,
seconds per row against n and degree (median and worst), the reasons rows stopped; markdown on
stdout. With --plot FILE.svg also the degrees over n, drawn by gnuplot (gnuplot-nox).
Usage: scripts/data/exact-summary.py [data/atlas-exact.csv] [--plot docs/figures/exact-degrees.svg]"""
import csv, statistics, subprocess, sys, tempfile, collections, os

args = [a for a in sys.argv[1:]]
plot = None
if "--plot" in args:
    i = args.index("--plot")
    plot = args[i + 1]
    del args[i:i + 2]
path = args[0] if args else "data/atlas-exact.csv"
rows = list(csv.DictReader(open(path)))
print(f"{len(rows)} rows of {path}\n")
count = collections.Counter(r["proof"] for r in rows)
print("| proof | rows |\n|---|---|")
for k in ("exact", "existence", "none"):
    print(f"| {k} | {count[k]} |")
print("\n| n range | rows | with P | exact | median degree | max degree | median s | worst s |")
print("|---|---|---|---|---|---|---|---|")
for lo, hi in ((2, 15), (16, 34), (35, 100), (101, 200)):
    part = [r for r in rows if lo <= int(r["n"]) <= hi]
    if not part:
        continue
    degrees = [int(r["degree"]) for r in part if r["degree"]]
    secs = [float(r["seconds"]) for r in part]
    print(f"| {lo}..{hi} | {len(part)} | {len(degrees)} | {sum(r['proof'] == 'exact' for r in part)} | "
          f"{statistics.median(degrees) if degrees else '-'} | {max(degrees) if degrees else '-'} | "
          f"{statistics.median(secs):.2f} | {max(secs):.2f} |")
print("\n| degree of P | rows | median s | worst s |\n|---|---|---|---|")
by_degree = collections.defaultdict(list)
for r in rows:
    by_degree[int(r["degree"]) if r["degree"] else 0].append(float(r["seconds"]))
for d in sorted(by_degree):
    s = by_degree[d]
    print(f"| {d if d else 'none found'} | {len(s)} | {statistics.median(s):.2f} | {max(s):.2f} |")
print(f"\ntotal seconds of the rows: {sum(float(r['seconds']) for r in rows):.0f}")
reasons = collections.Counter()
for r in rows:
    if r["proof"] != "exact":
        reason = r["reason"].split(" at ")[0].split(": ")[0] if r["reason"] else "-"
        if "not in the field" in reason:
            reason = "a coordinate is not in Q(d, sqrt 3) at the digits tried"
        reasons[reason[:70]] += 1
print("\n| what stopped a row short of 'exact' | rows |\n|---|---|")
for reason, k in reasons.most_common():
    print(f"| {reason} | {k} |")
if plot:
    with tempfile.NamedTemporaryFile("w", suffix=".dat", delete=False) as data:
        for r in rows:
            if r["degree"]:
                data.write(f"{r['n']} {r['degree']} {0 if r['proof'] == 'exact' else 1}\n")
    os.makedirs(os.path.dirname(plot) or ".", exist_ok=True)
    script = f"""set terminal svg size 800,420 font 'DejaVu Sans,12'
set output '{plot}'
set xlabel 'n'
set ylabel 'degree of P_n'
set logscale y 2
set key top left
set grid
plot '{data.name}' using 1:($3==0?$2:1/0) with points pt 7 ps 0.6 lc rgb '#1f77b4' title 'exact (I and II proven)', \\
     '{data.name}' using 1:($3==1?$2:1/0) with points pt 6 ps 0.8 lc rgb '#d62728' title 'P found, proof incomplete'
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    os.unlink(data.name)
    print(f"\nplot: {plot}")
