#!/usr/bin/env python3
"""How many atlas bests the catalogue's builders reproduce: runs `tripack build --n N --digits 20
--json --points` for every n of data/atlas.csv's rank-1 rows (docs/findings.md §11). The built
packing reproduces the atlas's best when it is certified, has the atlas's d (relative 1e-15) and
is the same packing: the same bond count, or, where the counts differ, every disk the build holds
(its non-rattlers) lies within 1e-9 of a disk of the atlas's file under one of the triangle's six
symmetries, so that the two differ only in where rattlers sit (a rattler resting against its
cage adds bonds without changing d). Builders never read the atlas, so this measures what the
classes carry to any k.
Resumable: one row per n is appended to --out (default data/build-vs-atlas.csv); n already there
are skipped (--redo A,B re-runs them). Prints the count over --n and every n not reproduced.
usage: python3 scripts/analysis/build-vs-atlas.py [--tripack build/tripack] [--atlas data/atlas.csv]
                                         [--n A..B | A,B,C] [--out FILE] [--redo LIST]"""
import argparse, csv, json, math, os, subprocess, sys
from decimal import Decimal
from resumable_table import n_values, open_table

ap = argparse.ArgumentParser()
ap.add_argument("--tripack", default="build/tripack")
ap.add_argument("--atlas", default="data/atlas.csv")
ap.add_argument("--n", default="2..200")
ap.add_argument("--out", default="data/build-vs-atlas.csv")
ap.add_argument("--redo", default="", help="n to run again although --out has them")
a = ap.parse_args()
best = {int(r["n"]): r for r in csv.DictReader(open(a.atlas)) if r["rank"] == "1"}
ns = [n for n in n_values(a.n) if n in best]
FIELDS = ["n", "atlas_label", "atlas_d", "atlas_bonds", "builder", "d", "bonds",
          "certified", "relative_gap", "same_packing", "reproduced", "note"]
redo = set(n_values(a.redo)) if a.redo else set()
if redo and os.path.exists(a.out):  # drop the rows to redo, keep the rest
    kept = [r for r in csv.DictReader(open(a.out)) if int(r["n"]) not in redo]
    with open(a.out, "w", newline="") as f:
        w = csv.DictWriter(f, FIELDS, lineterminator="\n")
        w.writeheader()
        w.writerows({k: r.get(k, "") for k in FIELDS} for r in kept)
done, out, writer = open_table(a.out, FIELDS)
SQRT3 = math.sqrt(3)


def atlas_points(row):
    path = os.path.join(os.path.dirname(a.atlas), row["file"])
    return [tuple(float(v) for v in line.split()[:2]) for line in open(path)
            if line.strip() and not line.startswith("#")]


def symmetries(p):
    """The six images of p under the symmetries of the triangle (0,0) (1,0) (1/2, sqrt3/2)."""
    cx, cy = 0.5, SQRT3 / 6
    out = []
    for x, y in (p, (1 - p[0], p[1])):
        for turn in range(3):
            c, s = math.cos(2 * math.pi * turn / 3), math.sin(2 * math.pi * turn / 3)
            out.append((cx + c * (x - cx) - s * (y - cy), cy + s * (x - cx) + c * (y - cy)))
    return out


def held_disks_match(built, rattlers, atlas, tol=1e-9):
    held = [p for i, p in enumerate(built) if i not in rattlers]
    images = [symmetries(p) for p in held]
    for g in range(6):
        if all(any(abs(img[g][0] - q[0]) < tol and abs(img[g][1] - q[1]) < tol for q in atlas)
               for img in images):
            return True
    return False


def build(n):
    p = subprocess.run([a.tripack, "build", "--n", str(n), "--digits", "20", "--json", "--points"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        return None, p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "failed"
    return json.loads(p.stdout), ""


for n in ns:
    if n in done:
        continue
    j, err = build(n)
    at = best[n]
    row = {k: "" for k in FIELDS}
    row.update(n=n, atlas_label=at["label"], atlas_d=at["d"], atlas_bonds=at["bonds"],
               same_packing="false", reproduced="false", note=err)
    if j is not None:
        member = j["class"] + f" k={j['k']}" + (f" p={j['p']}" if j.get("p") else "") + \
            (f" variant={j['variant']}" if j.get("variant") else "")
        gap = (Decimal(at["d"]) - Decimal(j["d"])) / Decimal(at["d"])
        certified = bool(j["certificate"] and j["certificate"]["certified"])
        same_d = abs(gap) <= Decimal("1e-15")
        same = same_d and (j["bonds"] == int(at["bonds"]) or held_disks_match(
            [(float(x), float(y)) for x, y in j["points"]], set(j["rattler_indices"]),
            atlas_points(at)))
        if same_d and j["bonds"] != int(at["bonds"]):
            row["note"] = ("the same held disks, rattlers placed otherwise" if same
                           else "the same d, another packing")
        row.update(builder=member, d=j["d"], bonds=j["bonds"],
                   certified=str(certified).lower(), relative_gap=f"{gap:.2e}",
                   same_packing=str(same).lower(), reproduced=str(same and certified).lower())
    writer.writerow(row)
    out.flush()
    done[n] = row
    print(f"{n:4d} {row['reproduced']:5s} {row['builder']:34s} gap {row['relative_gap']:>10s} "
          f"bonds {row['bonds']}/{row['atlas_bonds']} {row['note']}", file=sys.stderr, flush=True)

rows = [done[n] for n in ns if n in done]
missed = [r for r in rows if r["reproduced"] != "true"]
print(f"build --n reproduces the atlas's best at {len(rows) - len(missed)} of {len(rows)} n in "
      f"{a.n} ({a.out}); not at: {', '.join(str(r['n']) for r in missed) or 'none'}")
