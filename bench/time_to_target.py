#!/usr/bin/env python3
"""Time to target: CPU seconds until the atlas's best d of n is first reached, by
`tripack search` (basin hopping) and by independent default billiards runs (`--method restarts`),
the same binary, one thread each, the two methods interleaved seed by seed in one run. A chain
that has not reached the target within the cap counts as the CPU seconds it spent (a lower
bound); a median that is such a bound is printed with ">" and its speed-up is a lower bound.

usage: bench/time_to_target.py [--tripack build/tripack]
       [--atlas bench/results/time-to-target-targets.csv]
       [--n 26,31,...] [--seeds 9] [--cap 120] [--jobs 2] [--out FILE.json]
Prints a markdown table; --out keeps every measurement (resumable: measurements already in the
file are not run again)."""
import argparse, csv, json, os, statistics, subprocess, sys
from concurrent.futures import ThreadPoolExecutor

DEFAULT_N = "26,31,53,94,102,187,61,74,134,150,166"

def atlas_best(path):
    best = {}
    with open(path) as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            if row["rank"] == "1":
                best[int(row["n"])] = row["d"]
    return best

def measure(tripack, n, target, seed, method, cap):
    out = subprocess.run([tripack, "search", str(n), "--seconds", str(cap), "--seed", str(seed),
                          "--method", method, "--target", target, "--threads", "1", "--json"],
                         capture_output=True, text=True, check=True).stdout
    chain = json.loads(out)["chains"][0]
    reached = chain["target_reached"]
    return {"n": n, "seed": seed, "method": method, "cap": cap, "reached": reached,
            "cpu": chain["cpu_seconds_to_target"] if reached else chain["cpu_seconds"],
            "steps": chain["steps"]}

def median_of(ms, cap):
    """The median CPU seconds and whether it is only a lower bound (a missed chain at or below
    the median position)."""
    ordered = sorted(ms, key=lambda m: m["cpu"])
    m = statistics.median(x["cpu"] for x in ordered)
    upper = ordered[len(ordered) // 2]  # the larger middle one decides the median
    censored = not upper["reached"] or not ordered[(len(ordered) - 1) // 2]["reached"]
    return m, censored

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tripack", default="build/tripack")
    # The targets: the atlas's best before the search's own campaigns (commit 279e5c0), so that a
    # search that finds a denser packing counts as reaching it.
    ap.add_argument("--atlas", default="bench/results/time-to-target-targets.csv")
    ap.add_argument("--n", default=DEFAULT_N)
    ap.add_argument("--seeds", type=int, default=9)
    ap.add_argument("--cap", type=float, default=120)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default="")
    ap.add_argument("--table-only", action="store_true",
                    help="print the table of what --out holds, run nothing (n not measured "
                         "with every seed are marked)")
    a = ap.parse_args()
    best = atlas_best(a.atlas)
    ns = [int(x) for x in a.n.split(",")]
    done = []
    if a.out and os.path.exists(a.out):
        done = json.load(open(a.out))
    have = {(m["n"], m["seed"], m["method"], m["cap"]) for m in done}
    if a.table_only:
        ns = [n for n in ns if any(m["n"] == n and m["cap"] == a.cap for m in done)]
    todo = [] if a.table_only else [(n, s, meth) for n in ns for s in range(1, a.seeds + 1)
            for meth in ("basin-hopping", "restarts") if (n, s, meth, a.cap) not in have]
    with ThreadPoolExecutor(a.jobs) as pool:
        futures = [pool.submit(measure, a.tripack, n, best[n], s, meth, a.cap)
                   for n, s, meth in todo]
        for f in futures:
            m = f.result()
            done.append(m)
            print(f"n={m['n']} seed={m['seed']} {m['method']}: "
                  f"{'%.3f' % m['cpu'] if m['reached'] else '>%g' % m['cap']} CPU s",
                  file=sys.stderr, flush=True)
            if a.out:
                json.dump(done, open(a.out + ".tmp", "w"), indent=0)
                os.replace(a.out + ".tmp", a.out)
    print("| n | atlas best d | search: median CPU s (reached) | default runs: median CPU s "
          "(reached) | speed-up |")
    print("|---|---|---|---|---|")
    ups = []
    for n in ns:
        row = {}
        for meth in ("basin-hopping", "restarts"):
            ms = [m for m in done if m["n"] == n and m["method"] == meth and m["cap"] == a.cap]
            # A chain that missed the target counts as the CPU seconds it spent (>= the cap on a
            # quiet machine; less when it shared the cores): a lower bound either way.
            med, cens = median_of(ms, a.cap) if ms else (a.cap, True)
            row[meth] = (med, cens, sum(m["reached"] for m in ms), len(ms))
        (bm, bc, br, bt), (rm, rc, rr, rt) = row["basin-hopping"], row["restarts"]
        if bt < a.seeds or rt < a.seeds:
            print(f"| {n} | {best[n][:18]} | (measured {bt} and {rt} of {a.seeds} seeds) | | |")
            continue
        up = rm / bm
        bound = "≥ " if rc and not bc else ("?" if bc else "")
        ups.append(up)
        fmt = lambda m, c: (">" if c else "") + ("%.3g" % m)
        print(f"| {n} | {best[n][:18]} | {fmt(bm, bc)} ({br}/{bt}) | {fmt(rm, rc)} ({rr}/{rt}) "
              f"| {bound}{up:.3g}x |")
    print(f"\nmedian speed-up over the {len(ups)} n measured with every seed: {statistics.median(ups):.3g}x "
          f"(a censored default-runs median makes its speed-up a lower bound)")

main()
