#!/usr/bin/env python3
"""Pattern continuation between consecutive terms of Delta(k+2)-2 (docs/class6.md).

A packing of n = Delta(K+1)-2 disks (side ~K in disk units) becomes a start for
n' = Delta(K+2)-2 by inserting one lattice line: in each of the triangle's 6 orientations and
for each cut c = 0..K, the disks with lattice coordinate l >= c - 1/2 (l = distance to the left
wall in rows) move right by one disk, and new disks fill the line l = c and the part of the
right wall above it. `--remove` does the inverse (n' = Delta(K)-2). Every start is relaxed and
certified by `tripack analyze`; the result is named by its (d, bonds) among the packings of the
target n found by billiards (files DIR/*.txt as `tripack billiards ... -o DIR --format txt`
writes them). Two packings of consecutive n "share a pattern" here when one line inserted away
from the defect turns one into the other.

usage: continuation.py SOURCE.txt TARGET_DIR [TARGET_DIR ...] [--remove] [--tripack build/tripack]
"""
import argparse, glob, json, math, os, subprocess, sys, tempfile

S3 = math.sqrt(3)


def load(fn):
    pts, d = [], None
    for line in open(fn):
        if line.startswith('#'):
            if line.startswith('# d:'):
                d = float(line.split()[2])
            continue
        t = line.split()
        if len(t) >= 2:
            pts.append((float(t[0]), float(t[1])))
    return pts, d


def header(fn):
    d = b = None
    for line in open(fn):
        if not line.startswith('#'):
            break
        if line.startswith('# d:'):
            d = float(line.split()[2])
        if line.startswith('# bonds:'):
            b = int(line.split()[2])
    return d, b


def symmetries(pts):
    """The 6 images of the points under the triangle's symmetries (unit triangle)."""
    cx, cy = 0.5, S3 / 6
    rot = lambda p: (cx - 0.5 * (p[0] - cx) - S3 / 2 * (p[1] - cy),
                     cy + S3 / 2 * (p[0] - cx) - 0.5 * (p[1] - cy))
    out = []
    for mirror in (False, True):
        q = [(1 - x, y) for x, y in pts] if mirror else list(pts)
        for r in range(3):
            out.append((('m' if mirror else '') + 'r%d' % r, q))
            q = [rot(p) for p in q]
    return out


def lattice_l(X, Y):
    return (S3 * X - Y) / S3  # distance to the left wall in rows


def insert(pts, d, c):
    L = 1 / d
    out = []
    for x, y in pts:
        X, Y = x / d, y / d
        out.append((X + 1, Y) if lattice_l(X, Y) >= c - 0.5 else (X, Y))
    L2, K = L + 1, round(L + 1)
    for b in range(0, K - c + 1):
        bb = min(b, L2 - c)
        out.append((c + bb / 2, bb * S3 / 2))
    for l in range(0, c):
        b = L2 - l
        out.append((l + b / 2, b * S3 / 2))
    return out, L2


def remove(pts, d, c):
    L = 1 / d
    out = []
    for x, y in pts:
        X, Y = x / d, y / d
        l = lattice_l(X, Y)
        r = L - l - Y / (S3 / 2)
        if c - 0.5 <= l < c + 0.5 or (r < 0.5 and l < c - 0.5):
            continue
        out.append((X - 1, Y) if l >= c + 0.5 else (X, Y))
    return out, L - 1


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('source')
    ap.add_argument('targets', nargs='+')
    ap.add_argument('--remove', action='store_true')
    ap.add_argument('--tripack', default='build/tripack')
    a = ap.parse_args()
    known = {}
    for t in a.targets:
        for fn in glob.glob(os.path.join(t, '*.txt')):
            d, b = header(fn)
            if d is not None:
                known.setdefault((round(d, 13), b), os.path.basename(fn)[:-4])
    pts, d = load(a.source)
    K = round(1 / d)
    n2 = len(pts) + (K + 2 if not a.remove else -(K + 1))
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, q in symmetries(pts):
            for c in range(0, K + 1):
                P, L2 = (remove if a.remove else insert)(q, d, c)
                if len(P) != n2:
                    continue
                fn = os.path.join(tmp, f'{name}-c{c}.txt')
                with open(fn, 'w') as f:
                    for X, Y in P:
                        f.write('%.17g %.17g\n' % (min(max(X, 0), L2) / L2, max(Y, 0) / L2))
                out = subprocess.run([a.tripack, 'analyze', fn, '--json'], capture_output=True,
                                     text=True).stdout
                try:
                    j = json.loads(out)
                except ValueError:
                    continue
                if 'error' in j or not j['certificate']['certified']:
                    continue
                key = (round(float(j['d']), 13), j['bonds'])
                label = known.get(key, 'new d=%s bonds=%d' % (j['d'][:17], j['bonds']))
                results.setdefault(label, []).append(f'{name}-c{c}')
    for label, starts in sorted(results.items(), key=lambda t: -len(t[1])):
        print('%-34s %3d starts (e.g. %s)' % (label, len(starts), starts[0]))


if __name__ == '__main__':
    main()
