#!/usr/bin/env python3
"""Where the atlas beats a published value: every n whose best row (data/atlas.csv) is denser
than a packing of one of GL1995's classes (the catalogue's classes whose source is the paper:
`tripack classes --json`), with the paper's claim for that class (whether it conjectured the
pattern best at that k), the builder's d and the gain. The builders' d come from the atlas
step's JSON (`tripack atlas --json`, scripts/atlas.sh keeps it in data/logs/atlas.log).
Prints a markdown table (docs/findings.md §6).
usage: python3 scripts/atlas-records.py ATLAS_JSON [--tripack build/tripack]"""
import argparse, json, subprocess
from decimal import Decimal

ap = argparse.ArgumentParser()
ap.add_argument("atlas_json")
ap.add_argument("--tripack", default="build/tripack")
a = ap.parse_args()
atlas = json.load(open(a.atlas_json))
classes = json.loads(subprocess.run([a.tripack, "classes", "--json"], capture_output=True,
                                    text=True, check=True).stdout)["classes"]
paper = {c["id"]: c["claim"] for c in classes if "GL1995" in c["claim"]["source"]}
best = {r["n"]: r for r in atlas["rows"] if r["rank"] == 1}
print("| n | GL1995 pattern | the paper's claim | d (pattern) | atlas best | d | gain |")
print("|---|---|---|---|---|---|---|")
count = 0
for b in sorted(atlas["builders"], key=lambda b: (b["n"], b["member"])):
    cls = b["member"].split()[0]
    if cls not in paper or b["n"] not in best:
        continue
    row = best[b["n"]]
    d_b, d_a = Decimal(b["d"]), Decimal(row["d"])
    if d_a <= d_b * (1 + Decimal("1e-12")):
        continue
    count += 1
    claim = paper[cls]
    said = f"best: {claim['best']}" if claim["best"] else claim["status"]
    print(f"| {b['n']} | {b['member']}{'' if b['certified'] else ' (not certified)'} | {said} "
          f"({claim['source']}) | {str(d_b)[:18]} | {row['label']} | {str(d_a)[:18]} | "
          f"{float(d_a / d_b - 1):.1e} |")
print(f"\n{count} rows")
