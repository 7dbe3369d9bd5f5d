#!/usr/bin/env python3
"""After `tripack atlas` rewrote data/atlas.csv: every label of data/atlas-exact.csv whose packing
changed (the label now names a packing of another d or bond count, or is no longer in the atlas)
gets proof `pending` with the reason, and its certificate data/exact/LABEL.gp is removed: the
exact atlas then holds nothing about a replaced packing (docs/exact.md). `tripack exact-atlas`
runs pending rows again. The old atlas is read from git (--before, default HEAD).
usage: python3 scripts/exact-pending.py [--before HEAD]"""
import argparse, csv, io, os, subprocess

ap = argparse.ArgumentParser()
ap.add_argument("--before", default="HEAD")
a = ap.parse_args()
old_text = subprocess.run(["git", "show", f"{a.before}:data/atlas.csv"], capture_output=True,
                          text=True, check=True).stdout
old = {r["label"]: r for r in csv.DictReader(io.StringIO(old_text))}
new = {r["label"]: r for r in csv.DictReader(open("data/atlas.csv"))}
path = "data/atlas-exact.csv"
rows = list(csv.DictReader(open(path)))
fields = list(rows[0].keys())
changed = []
for r in rows:
    label = r["label"]
    if r["proof"] == "pending":
        continue
    was, now = old.get(label), new.get(label)
    if now is None:
        why = "the label left the atlas"
    elif was is None or was["d"] != now["d"] or was["bonds"] != now["bonds"]:
        why = (f"the label's packing changed (d {was['d'] if was else '?'} -> {now['d']}, "
               f"bonds {was['bonds'] if was else '?'} -> {now['bonds']})")
    else:
        continue
    changed.append(label)
    for k in ("degree", "polynomial", "root_low", "root_high", "seconds"):
        r[k] = ""
    r["proof"] = "pending"
    r["reason"] = why + "; exact-atlas runs it again"
    cert = os.path.join("data/exact", label + ".gp")
    if os.path.exists(cert):
        os.remove(cert)
with open(path, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
print(f"exact-pending: {len(changed)} rows pending: {', '.join(changed) or 'none'}")
