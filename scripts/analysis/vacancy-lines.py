#!/usr/bin/env python3
"""Where the vacancies of the atlas's best packings lie (docs/search.md, "lattice start"): each
rank-1 packing of n = 20..200 in data/atlas.csv is mapped onto the k-row triangular lattice
Delta(k) (k the smallest with Delta(k) >= n), each disk to its nearest site; when that is one to
one, its m = Delta(k) - n empty sites are classed as one straight segment of a lattice line, a
connected path of nearest neighbours, a path with second-neighbour jogs, or none of these.
usage: python3 scripts/analysis/vacancy-lines.py [--atlas data/atlas.csv] [--list]"""
import argparse, csv, math, os

NEAR = [(1, 0), (-1, 0), (0, 1), (0, -1), (1, -1), (-1, 1)]
SECOND = NEAR + [(1, 1), (-1, -1), (2, -1), (-2, 1), (1, -2), (-1, 2)]

def straight(v):
    """One contiguous segment along rows (j fixed), along i fixed, or along i + j fixed."""
    if len(v) <= 1:
        return True
    for key, along in ((lambda p: p[1], lambda p: p[0]), (lambda p: p[0], lambda p: p[1]),
                       (lambda p: p[0] + p[1], lambda p: p[1])):
        if len({key(p) for p in v}) == 1:
            xs = sorted(along(p) for p in v)
            return xs == list(range(xs[0], xs[0] + len(v)))
    return False

def connected(v, steps):
    sites, seen, todo = set(v), {v[0]}, [v[0]]
    while todo:
        a = todo.pop()
        for dx, dy in steps:
            b = (a[0] + dx, a[1] + dy)
            if b in sites and b not in seen:
                seen.add(b)
                todo.append(b)
    return len(seen) == len(v)

ap = argparse.ArgumentParser()
ap.add_argument("--atlas", default="data/atlas.csv")
ap.add_argument("--list", action="store_true", help="print each n's class and vacancies")
a = ap.parse_args()
counts = {}
for row in csv.DictReader(open(a.atlas)):
    n = int(row["n"])
    if row["rank"] != "1" or n < 20:
        continue
    path = os.path.join(os.path.dirname(a.atlas), row["file"])
    pts = [tuple(map(float, l.split())) for l in open(path) if l.strip() and not l.startswith("#")]
    k = 1
    while k * (k + 1) // 2 < n:
        k += 1
    s, h = 1 / (k - 1), math.sqrt(3) / 2 / (k - 1)
    sites = {(round(x / s - round(y / h) / 2), round(y / h)) for x, y in pts}
    if len(sites) < n:
        kind, vac = "not one to one", []
    else:
        vac = [(i, j) for j in range(k) for i in range(k - j) if (i, j) not in sites]
        kind = ("straight segment" if straight(vac) else "nearest-neighbour path"
                if connected(vac, NEAR) else "path with jogs" if connected(vac, SECOND) else "other")
    counts[kind] = counts.get(kind, 0) + 1
    if a.list:
        print(n, k * (k + 1) // 2 - n, kind, vac)
print(", ".join(f"{c} {k}" for k, c in sorted(counts.items(), key=lambda x: -x[1])))
