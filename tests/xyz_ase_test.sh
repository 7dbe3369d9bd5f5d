#!/usr/bin/env bash
# Extended XYZ read back by a real client of the field: ASE (Debian's python3-ase, the reader
# OVITO users' scripts use). A packing with a rattler (the atlas's t11a) is analysed and written
# as .xyz by tripack; ASE must read n particles at the centres, radius d/2 and the rattler flag of
# exactly the disks tripack calls rattlers. Usage: xyz_ase_test.sh path/to/tripack
set -u
TRIPACK=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$TRIPACK" analyze "$root/data/atlas/t11a.txt" --json --points -o "$tmp/t11a.xyz" >"$tmp/t11a.json" || {
  echo "FAIL: tripack analyze -o .xyz"
  exit 1
}
/usr/bin/python3 - "$tmp/t11a.xyz" "$tmp/t11a.json" <<'PY'
import json, sys
from ase.io import read

atoms = read(sys.argv[1], format="extxyz")
result = json.load(open(sys.argv[2]))
failures = []
def check(what, ok):
    print(("ok: " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)

points = [[float(c) for c in p] for p in result["points"]]
d = float(result["d"])
check(f"ASE reads {len(atoms)} particles, tripack has {len(points)}", len(atoms) == len(points))
pos = atoms.get_positions()
# The file's coordinates have 21 digits; as doubles they agree to a double's rounding (1e-15).
check("positions are the centres (z = 0)",
      all(abs(pos[i][0] - p[0]) < 1e-15 and abs(pos[i][1] - p[1]) < 1e-15 and pos[i][2] == 0
          for i, p in enumerate(points)))
check("radius is d/2 on every disk", all(abs(r - d / 2) < 1e-15 for r in atoms.arrays["radius"]))
rattlers = sorted(result["rattler_indices"])
flagged = sorted(i for i, f in enumerate(atoms.arrays["rattler"]) if f == 1)
check(f"rattler flags {flagged} are tripack's rattlers {rattlers}", flagged == rattlers and rattlers)
check("d in the comment line", abs(float(atoms.info["d"]) - d) < 1e-15)
sys.exit(1 if failures else 0)
PY
