#!/usr/bin/env python3
"""`tripack build --n N` for every N of a range, one row per N: the class packing of any n, what
it costs and whether it is certified (docs/performance.md, "build --n against n").
Resumable: the rows already in --out are kept and their N skipped, each new row is appended as
its build ends, so an interrupted scan loses at most the builds under way; rerun to continue.
A build over --limit seconds is stopped (SIGINT) and recorded as such.
Prints the count of certified rows and the median and largest seconds at the end.
usage: python3 scripts/analysis/build-scan.py [--tripack build/tripack] [--n 2..1000] [--jobs 1]
                                     [--limit 600] [--out data/build-scan.csv]
                                     [--extra '--exhaustive']"""
import argparse, json, statistics, subprocess, sys, time
from concurrent.futures import ThreadPoolExecutor
from resumable_table import n_values, open_table

ap = argparse.ArgumentParser()
ap.add_argument("--tripack", default="build/tripack")
ap.add_argument("--n", default="2..1000", help="a range A..B, or a list A,B,C")
ap.add_argument("--jobs", type=int, default=1, help="builds at once (1: timings undisturbed)")
ap.add_argument("--limit", type=float, default=600, help="seconds before a build is stopped")
ap.add_argument("--out", default="data/build-scan.csv")
ap.add_argument("--extra", default="", help="more build options, e.g. '--exhaustive'")
a = ap.parse_args()
wanted = n_values(a.n)
FIELDS = ["n", "class", "k", "p", "variant", "d", "bonds", "rattlers", "certified", "seconds",
          "note"]

done, out, writer = open_table(a.out, FIELDS)
todo = [n for n in wanted if n not in done]


def build(n):
    start = time.monotonic()
    try:
        p = subprocess.run([a.tripack, "build", "--n", str(n), "--json"] + a.extra.split(), capture_output=True,
                           text=True, timeout=a.limit)
    except subprocess.TimeoutExpired:
        return {"n": n, "certified": "false", "seconds": f"{a.limit:.0f}",
                "note": f"stopped after {a.limit:.0f} s"}
    seconds = time.monotonic() - start
    if p.returncode != 0:
        lines = p.stderr.strip().splitlines()
        return {"n": n, "certified": "false", "seconds": f"{seconds:.2f}",
                "note": lines[-1] if lines else f"exit {p.returncode}"}
    j = json.loads(p.stdout)
    cert = j.get("certificate") or {}
    return {"n": n, "class": j["class"], "k": j["k"], "p": j.get("p") or "",
            "variant": j.get("variant") or "", "d": j["d"], "bonds": j["bonds"],
            "rattlers": j["rattlers"], "certified": str(bool(cert.get("certified"))).lower(),
            "seconds": f"{seconds:.2f}",
            "note": "" if cert.get("certified") else cert.get("verdict", "not certified")}


try:
    with ThreadPoolExecutor(a.jobs) as pool:
        for row in pool.map(build, todo):
            writer.writerow(row)
            out.flush()
            done[row["n"]] = row
            print(f"n = {row['n']}: {row.get('class', '')} {row['certified']} "
                  f"{row['seconds']} s {row['note']}", file=sys.stderr, flush=True)
except KeyboardInterrupt:
    print("interrupted: every finished row is in " + a.out, file=sys.stderr)
    sys.exit(130)

rows = [done[n] for n in wanted if n in done]
secs = [float(r["seconds"]) for r in rows]
cert = sum(r["certified"] == "true" for r in rows)
if rows:
    print(f"{len(rows)} rows, {cert} certified; seconds: median {statistics.median(secs):.2f}, "
          f"max {max(secs):.1f} (n = {rows[secs.index(max(secs))]['n']})")
