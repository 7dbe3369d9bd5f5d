#!/usr/bin/env python3
"""Is data/atlas.csv the best known? For every n of --n (default 2..300) its rank-1 d must be at
least (1e-15 relative):
  * `build --n N`'s d, from a table of build rows (--builds, default data/search-vs-build.csv,
    column d_build; scripts/analysis/search-vs-build.py writes it), and every certified class member's d
    from the atlas step's JSON (--atlas-json: data/logs/atlas.log);
  * every certified packing in the atlas's databases (data/atlas.db, data/stress.db);
  * both columns of data/beyond-atlas.csv (the builder and the 60 s search of n = 201..300);
and its confirmations must be 3 or more, or the n listed with a reason in
data/atlas-unconfirmed.csv. Prints one line per failure and a summary; exit 1 if any.
usage: python3 scripts/data/atlas-check.py [--n 2..300] [--builds data/search-vs-build.csv]"""
import argparse, csv, json, sqlite3, sys
from decimal import Decimal

ap = argparse.ArgumentParser()
ap.add_argument("--n", default="2..300")
ap.add_argument("--atlas", default="data/atlas.csv")
ap.add_argument("--builds", default="data/search-vs-build.csv")
ap.add_argument("--atlas-json", default="",
                help="the atlas step's JSON (tripack atlas --json): every builder member's d")
ap.add_argument("--dbs", default="data/atlas.db,data/stress.db")
ap.add_argument("--beyond", default="data/beyond-atlas.csv")
ap.add_argument("--unconfirmed", default="data/atlas-unconfirmed.csv")
a = ap.parse_args()
lo, hi = (int(x) for x in a.n.split(".."))
tol = Decimal("1e-15")
best = {int(r["n"]): r for r in csv.DictReader(open(a.atlas)) if r["rank"] == "1"}
unconfirmed = {int(r["n"]): r["why"] for r in csv.DictReader(open(a.unconfirmed))}
others = {}  # n -> [(d, what)]


def add(n, d, what):
    if d:
        others.setdefault(n, []).append((Decimal(d), what))


for r in csv.DictReader(open(a.builds)):  # search-vs-build.py's d_build, or build-scan's d
    if r.get("certified_build", r.get("certified", "true")) == "true":
        add(int(r["n"]), r.get("d_build") or r.get("d"), "build --n")
if a.atlas_json:  # every member of every class containing n, as the atlas built it
    with open(a.atlas_json) as f:
        for b in json.loads(f.readline())["builders"]:
            if b["certified"]:
                add(b["n"], b["d"], f"builder {b['member']}")
for path in a.dbs.split(","):
    db = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
    for n, d, pid in db.execute("SELECT n, d, id FROM packings WHERE certified = 1"):
        add(n, d, f"{path} packing {pid}")
for r in csv.DictReader(open(a.beyond)):
    add(int(r["n"]), r["d_builder"] if r["certified_builder"] == "true" else "", "beyond-atlas builder")
    add(int(r["n"]), r["d_search"] if r["certified_search"] == "true" else "", "beyond-atlas search")

failures = 0
checked = 0
for n in range(lo, hi + 1):
    if n not in best:
        print(f"n = {n}: no best row")
        failures += 1
        continue
    checked += 1
    d = Decimal(best[n]["d"])
    for other, what in others.get(n, []):
        if other > d * (1 + tol):
            print(f"n = {n}: {what} has d = {other} above the atlas's {best[n]['label']} ({d})")
            failures += 1
    c = int(best[n]["confirmations"])
    if c < 3 and n not in unconfirmed:
        print(f"n = {n}: {best[n]['label']} has {c} confirmations and no reason listed")
        failures += 1
    if c >= 3 and n in unconfirmed:
        print(f"n = {n}: listed as unconfirmed but has {c} confirmations")
        failures += 1
print(f"atlas-check: {checked} n checked, {failures} failures; "
      f"{sum(1 for n in range(lo, hi + 1) if n in best and int(best[n]['confirmations']) >= 3)} "
      f"confirmed 3 or more times, {sum(1 for n in unconfirmed if lo <= n <= hi)} listed unconfirmed")
sys.exit(1 if failures else 0)
