#!/usr/bin/env python3
"""After `tripack atlas` rewrote data/atlas.csv: every label of data/atlas-exact.csv whose packing
changed (the label now names a packing of another d or bond count, or is no longer in the atlas)
gets proof `pending` with the reason, and its certificate data/exact/LABEL.gp is removed: the
exact atlas then holds nothing about a replaced packing (docs/exact.md). `tripack exact-atlas`
runs pending rows again. The old atlas is read from git (--before, default HEAD).
usage: python3 scripts/data/exact-pending.py [--before HEAD]"""
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
changed, dropped = [], []
kept = []
for r in rows:
    label = r["label"]
    was, now = old.get(label), new.get(label)
    cert = os.path.join("data/exact", label + ".gp")
    if now is None:  # the label left the atlas: its row and certificate go, a pending row of the
        # label that took its place (same n and rank) comes below
        dropped.append((was["n"] if was else r["n"], was["rank"] if was else "1", label))
        if os.path.exists(cert):
            os.remove(cert)
        continue
    kept.append(r)
    if r["proof"] == "pending" or (was and was["d"] == now["d"] and was["bonds"] == now["bonds"]):
        continue
    changed.append(label)
    for k in ("degree", "polynomial", "root_low", "root_high", "seconds"):
        r[k] = ""
    r["proof"] = "pending"
    r["reason"] = (f"the label's packing changed (d {was['d'] if was else '?'} -> {now['d']}, "
                   f"bonds {was['bonds'] if was else '?'} -> {now['bonds']}); exact-atlas runs "
                   "it again")
    if os.path.exists(cert):
        os.remove(cert)
rows = kept
have = {r["label"] for r in rows}
for n, rank, gone in dropped:
    for label, now in new.items():
        if now["n"] == n and now["rank"] == rank and label not in have:
            changed.append(label)
            have.add(label)
            rows.append({**{k: "" for k in fields}, "n": n, "label": label, "proof": "pending",
                         "reason": f"the atlas's packing of rank {rank} changed (it was {gone}, "
                                   f"d {old[gone]['d'] if gone in old else '?'}; now d "
                                   f"{now['d']}); exact-atlas runs it"})
with open(path, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
print(f"exact-pending: {len(dropped)} rows of labels that left the atlas removed "
      f"({', '.join(l for _, _, l in dropped) or 'none'}); {len(changed)} rows pending: "
      f"{', '.join(changed) or 'none'}")
