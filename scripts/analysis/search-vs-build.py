#!/usr/bin/env python3
"""`tripack search N` never returns less than `tripack build --n N` (docs/search.md, "Starting
from the builders"): for every N of --n, both are run as separate commands, and one row per N
is appended to --out (build's d and member, search's best d, the relative difference, whether it
holds to 1e-15 relative). The search runs one thread for --seconds (its build counts in that
budget, so a budget shorter than the build gives the builder's packing and no step).
With --builds, build's row is read from that table (the same binary's builds, e.g.
data/build-vs-atlas.csv) rather than run again. Resumable: N already in --out are skipped. Prints the count that hold and every N that does not.
usage: python3 scripts/analysis/search-vs-build.py [--tripack build/tripack] [--n 2..300]
                                         [--seconds 0.001] [--out data/search-vs-build.csv]"""
import argparse, csv, json, subprocess, sys
from decimal import Decimal
from resumable_table import n_values, open_table

ap = argparse.ArgumentParser()
ap.add_argument("--tripack", default="build/tripack")
ap.add_argument("--n", default="2..300", help="a range A..B, or a list A,B,C")
ap.add_argument("--seconds", default="0.001")
ap.add_argument("--out", default="data/search-vs-build.csv")
ap.add_argument("--builds", default="",
                help="a table of build --n rows (scripts/analysis/build-vs-atlas.py's: n, builder, d, "
                     "certified) used instead of running build again, for the n it has")
a = ap.parse_args()
wanted = n_values(a.n)
FIELDS = ["n", "builder", "d_build", "certified_build", "d_search", "search_steps",
          "relative_difference", "holds"]
done, out, writer = open_table(a.out, FIELDS)
builds = {}
if a.builds:
    builds = {int(r["n"]): r for r in csv.DictReader(open(a.builds)) if r.get("d")}


def run_json(args):
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"search-vs-build: {' '.join(args)} failed: "
                 + (p.stderr.strip().splitlines() or ["?"])[-1])
    return json.loads(p.stdout)


for n in wanted:
    if n in done:
        continue
    if n in builds:
        r = builds[n]
        member = r["builder"].split(" variant=")[0]
        b = {"d": r["d"], "certificate": {"certified": r["certified"] == "true"},
             "class": member.split(" k=")[0], "k": member.split(" k=")[1].split(" ")[0],
             "p": member.split(" p=")[1] if " p=" in member else None}
    else:
        b = run_json([a.tripack, "build", "--n", str(n), "--json"])
    s = run_json([a.tripack, "search", str(n), "--seconds", a.seconds, "--threads", "1",
                  "--seed", "1", "--json"])
    d_build = Decimal(b["d"])
    d_search = Decimal(s["best"]["d"]) if s.get("best") else Decimal(0)
    rel = (d_search - d_build) / d_build
    row = {"n": n, "builder": b["class"] + f" k={b['k']}" + (f" p={b['p']}" if b.get("p") else ""),
           "d_build": b["d"], "certified_build": str(bool(b.get("certificate") and b["certificate"]["certified"])).lower(),
           "d_search": str(d_search), "search_steps": s["steps"],
           "relative_difference": f"{float(rel):.3e}", "holds": str(rel >= Decimal("-1e-15")).lower()}
    writer.writerow(row)
    out.flush()
    done[n] = row
    print(f"n = {n}: build {b['d']}, search {d_search}, {row['holds']}", file=sys.stderr)

rows = [done[n] for n in wanted if n in done]
bad = [r["n"] for r in rows if r["holds"] != "true"]
print(f"{len(rows) - len(bad)} of {len(rows)} N: search >= build --n (1e-15 relative); "
      f"not: {', '.join(map(str, bad)) or 'none'}")
