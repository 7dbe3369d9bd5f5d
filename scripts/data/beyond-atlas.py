#!/usr/bin/env python3
"""Builders beyond the atlas against a search (docs/findings.md §11): for every n in --n (default
201..300), `tripack build --n N --json` (every class containing n, the best kept) and `tripack
search N --seconds 60 --threads 1 --no-lattice-starts --seed 1` (basin hopping from random starts
only, so that it does not start from the lattice-with-vacancies idea the new classes use). One row
per n is appended to --out at once (default data/beyond-atlas.csv); a rerun skips the n already
there, so an interrupted run continues where it stopped. Where the search wins, its packing is
written to beyond-atlas/search-N.txt beside --out. A builder is a conjecture only where the
search does not beat it: the row says which won and by how much.
usage: python3 scripts/data/beyond-atlas.py [--tripack build/tripack] [--n A..B] [--seconds 60]
                                       [--out FILE]"""
import argparse, csv, json, os, subprocess, sys, time
from decimal import Decimal

ap = argparse.ArgumentParser()
ap.add_argument("--tripack", default="build/tripack")
ap.add_argument("--n", default="201..300")
ap.add_argument("--seconds", type=float, default=60)
ap.add_argument("--out", default="data/beyond-atlas.csv")
a = ap.parse_args()
lo, hi = (int(x) for x in a.n.split(".."))
fields = ["n", "builder", "d_builder", "bonds_builder", "certified_builder", "build_seconds",
          "d_search", "bonds_search", "certified_search", "search_seconds", "relative_gap",
          "winner", "note"]
done = set()
if os.path.exists(a.out):
    done = {int(r["n"]) for r in csv.DictReader(open(a.out))}
new_file = not os.path.exists(a.out)
out = open(a.out, "a", newline="")
w = csv.DictWriter(out, fieldnames=fields)
if new_file:
    w.writeheader()
    out.flush()


def run_json(args):
    t = time.monotonic()
    p = subprocess.run(args, capture_output=True, text=True)
    secs = time.monotonic() - t
    if p.returncode != 0:
        return None, secs, (p.stderr.strip().splitlines() or ["failed"])[-1]
    return json.loads(p.stdout), secs, ""


for n in range(lo, hi + 1):
    if n in done:
        continue
    row = {k: "" for k in fields}
    row["n"] = n
    b, row["build_seconds"], err_b = run_json([a.tripack, "build", "--n", str(n), "--digits", "20",
                                               "--json"])
    s, row["search_seconds"], err_s = run_json(
        [a.tripack, "search", str(n), "--seconds", str(a.seconds), "--threads", "1",
         "--no-lattice-starts", "--seed", "1", "--json", "--points"])
    row["build_seconds"] = f"{row['build_seconds']:.1f}"
    row["search_seconds"] = f"{row['search_seconds']:.1f}"
    row["note"] = "; ".join(e for e in (err_b and "build: " + err_b, err_s and "search: " + err_s)
                            if e)
    if b:
        row["builder"] = b["class"] + f" k={b['k']}" + (f" p={b['p']}" if b.get("p") else "") + \
            (f" variant={b['variant']}" if b.get("variant") else "")
        row["d_builder"], row["bonds_builder"] = b["d"], b["bonds"]
        row["certified_builder"] = str(b["certificate"]["certified"]).lower() \
            if isinstance(b.get("certificate"), dict) and "certified" in b["certificate"] else ""
    if s and s.get("best"):
        best = s["best"]
        row["d_search"], row["bonds_search"] = best["d"], best["bonds"]
        row["certified_search"] = str(best["certified"]).lower()
    if row["d_builder"] and row["d_search"]:
        db, ds = Decimal(row["d_builder"]), Decimal(row["d_search"])
        gap = (ds - db) / db
        row["relative_gap"] = f"{gap:.2e}"
        row["winner"] = "search" if gap > Decimal("1e-15") else "builder" \
            if gap < Decimal("-1e-15") else "tie"
    if row["winner"] == "search" and s["best"].get("points"):
        # The pattern that beat the builder, kept for the findings (x y, unit triangle).
        folder = os.path.join(os.path.dirname(a.out) or ".", "beyond-atlas")
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, f"search-{n}.txt")
        with open(path, "w") as f:
            f.write(f"# tripack search {n} --seconds {a.seconds:g} --threads 1 --no-lattice-starts"
                    f" --seed 1: d = {row['d_search']}, beats {row['builder']}\n")
            for x, y in s["best"]["points"]:
                f.write(f"{x} {y}\n")
        row["note"] = (row["note"] + "; " if row["note"] else "") + "search packing: " + path
    w.writerow(row)
    out.flush()
    print(f"{n:4d} {row['winner']:8s} gap {row['relative_gap']:>10s} {row['builder']}"
          f" ({row['build_seconds']} s)", flush=True)
