#!/usr/bin/env python3
"""Writes data/atlas-unconfirmed.csv: every n whose rank-1 row in data/atlas.csv has
fewer than 3 confirmations, with why, from data/atlas.csv and the runs table of data/atlas.db:
how many independent units ran at n (billiards runs and search chains from random starts;
continued searches and those started from a builder's packing do not count) and what reached the best.
usage: python3 scripts/data/atlas-unconfirmed.py [--next "CONFIRM_LONG_RUNS=24 bash scripts/data/atlas.sh confirm-long"]"""
import argparse, csv, sqlite3

ap = argparse.ArgumentParser()
ap.add_argument("--atlas", default="data/atlas.csv")
ap.add_argument("--db", default="data/atlas.db")
ap.add_argument("--out", default="data/atlas-unconfirmed.csv")
ap.add_argument("--next", default="CONFIRM_LONG_RUNS=24 bash scripts/data/atlas.sh confirm-long")
a = ap.parse_args()
db = sqlite3.connect(f"file:{a.db}?mode=ro", uri=True)
rows = []
for r in csv.DictReader(open(a.atlas)):
    if r["rank"] != "1" or int(r["confirmations"]) >= 3:
        continue
    n = int(r["n"])
    units = dict(db.execute("SELECT method, COUNT(*) FROM runs WHERE n = ? AND method NOT LIKE "
                            "'%, continued' AND method NOT LIKE '%, from builders%' GROUP BY "
                            "method", (n,)).fetchall())
    total = sum(units.values())
    searches = ", ".join(f"{c} of {m[len('search '):]}" for m, c in sorted(units.items())
                         if m.startswith("search"))
    conf = int(r["confirmations"])
    builder = "builder" in r["source"]
    reached = conf - builder
    rows.append((n, f"reached by {'a builder and ' if builder else ''}{reached} of the {total} "
                    f"independent units run at n = {n} (search chains: {searches or 'none'}); "
                    f"next round: {a.next}"))
with open(a.out, "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(["n", "why"])
    w.writerows(rows)
print(f"{len(rows)} n below 3 confirmations: {' '.join(str(n) for n, _ in rows)}")
