#!/usr/bin/env python3
"""Where the atlas beats a published value: every n whose best row (data/atlas.csv) is denser
than a packing of one of GL1995's classes (the catalogue's classes whose source is the paper:
`tripack classes --json`), with the paper's claim for that class (whether it conjectured the
pattern best at that k), the builder's d and the gain. The builders' d come from the atlas
step's JSON (`tripack atlas --json`, scripts/data/atlas.sh keeps it in data/logs/atlas.log), or, with
--build A..B, from `tripack build CLASS --k K [--p P] [--variant V] --json` of every member of
the paper's classes with n in A..B (`tripack classify N`), against data/atlas.csv.
Prints a markdown table (docs/findings.md §6).
usage: python3 scripts/data/atlas-records.py ATLAS_JSON [--tripack build/tripack]
       python3 scripts/data/atlas-records.py --build 2..300 [--atlas data/atlas.csv]"""
import argparse, csv, json, subprocess, sys
from decimal import Decimal

ap = argparse.ArgumentParser()
ap.add_argument("atlas_json", nargs="?")
ap.add_argument("--tripack", default="build/tripack")
ap.add_argument("--build", default="", help="A..B: build the paper's members of these n")
ap.add_argument("--atlas", default="data/atlas.csv")
a = ap.parse_args()


def run_json(*args):
    return json.loads(subprocess.run([a.tripack, *args, "--json"], capture_output=True,
                                     text=True, check=True).stdout)


classes = run_json("classes")["classes"]
paper = {c["id"]: c["claim"] for c in classes if "GL1995" in c["claim"]["source"]}
if a.build:
    lo, hi = (int(x) for x in a.build.split(".."))
    best = {int(r["n"]): {**r, "rank": 1} for r in csv.DictReader(open(a.atlas))
            if r["rank"] == "1" and lo <= int(r["n"]) <= hi}
    variants = {c["id"]: c["variants"] or [""] for c in classes}
    builders = []
    for n in sorted(best):
        for m in run_json("classify", str(n))["members"]:
            if m["class"] not in paper:
                continue
            vs = [w for v in variants[m["class"]] for w in
                  ([f"cavity-{i}" for i in range(1, m["k"])] if v == "cavity-m" else [v])]
            for v in vs:  # twin's cavity-m is cavity-1 .. cavity-(k-1)
                args = ["build", m["class"], "--k", str(m["k"])]
                args += ["--p", str(m["p"])] if m["p"] else []
                args += ["--variant", v] if v else []
                try:
                    b = run_json(*args)
                except subprocess.CalledProcessError as e:  # a variant not defined at this k
                    print(f"atlas-records: {' '.join(args)}: {e.stderr.strip()}", file=sys.stderr)
                    continue
                name = f"{m['class']} k={m['k']}" + (f" p={m['p']}" if m["p"] else "") + \
                    (f" variant={v}" if v else "")
                builders.append({"n": n, "member": name, "d": b["d"],
                                 "certified": b["certificate"]["certified"]})
    atlas = {"builders": builders}
else:
    atlas = json.load(open(a.atlas_json))
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
