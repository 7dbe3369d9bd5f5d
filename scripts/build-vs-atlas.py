#!/usr/bin/env python3
"""How many atlas bests the catalogue's builders reproduce: runs `tripack build --n N --digits 20
--json` for every n of data/atlas.csv's rank-1 rows and counts the n where the built packing has
the atlas's d (relative 1e-15) and the same bond count, and is certified (docs/findings.md §11).
Builders never read the atlas, so this measures what the classes carry to any k.
Writes one row per n to --out (default data/build-vs-atlas.csv) and prints the count.
usage: python3 scripts/build-vs-atlas.py [--tripack build/tripack] [--atlas data/atlas.csv]
                                         [--n A..B] [--jobs 2] [--out FILE]"""
import argparse, csv, json, os, subprocess, sys
from concurrent.futures import ThreadPoolExecutor
from decimal import Decimal

ap = argparse.ArgumentParser()
ap.add_argument("--tripack", default="build/tripack")
ap.add_argument("--atlas", default="data/atlas.csv")
ap.add_argument("--n", default="2..200")
ap.add_argument("--jobs", type=int, default=2)
ap.add_argument("--out", default="data/build-vs-atlas.csv")
a = ap.parse_args()
lo, hi = (int(x) for x in a.n.split(".."))
best = {int(r["n"]): r for r in csv.DictReader(open(a.atlas)) if r["rank"] == "1"}
ns = [n for n in sorted(best) if lo <= n <= hi]

def run(n):
    p = subprocess.run([a.tripack, "build", "--n", str(n), "--digits", "20", "--json"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        return n, None, p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "failed"
    return n, json.loads(p.stdout), ""

rows, hits = [], 0
with ThreadPoolExecutor(a.jobs) as pool:
    for n, j, err in pool.map(run, ns):
        at = best[n]
        row = {"n": n, "atlas_label": at["label"], "atlas_d": at["d"], "atlas_bonds": at["bonds"],
               "builder": "", "d": "", "bonds": "", "certified": "", "relative_gap": "",
               "reproduced": "false", "note": err}
        if j is not None:
            member = j["class"] + f" k={j['k']}" + (f" p={j['p']}" if j.get("p") else "") + \
                (f" variant={j['variant']}" if j.get("variant") else "")
            gap = (Decimal(at["d"]) - Decimal(j["d"])) / Decimal(at["d"])
            ok = abs(gap) <= Decimal("1e-15") and j["bonds"] == int(at["bonds"]) and \
                j["certificate"]["certified"]
            row.update(builder=member, d=j["d"], bonds=j["bonds"],
                       certified=str(j["certificate"]["certified"]).lower(),
                       relative_gap=f"{gap:.2e}", reproduced=str(ok).lower())
            hits += ok
        rows.append(row)
        print(f"{n:4d} {row['reproduced']:5s} {row['builder']:34s} gap {row['relative_gap']:>10s} "
              f"bonds {row['bonds']}/{row['atlas_bonds']} {row['note']}", file=sys.stderr, flush=True)
with open(a.out, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
print(f"build --n reproduces the atlas's best at {hits} of {len(rows)} n = {lo}..{hi} ({a.out})")
