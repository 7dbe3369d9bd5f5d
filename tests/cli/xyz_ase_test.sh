#!/usr/bin/env bash
# Extended XYZ read back by a real client of the field: ASE (Debian's python3-ase, the reader
# OVITO users' scripts use; run with /usr/bin/python3). For each packing tripack prints (--json
# --points) and writes (-o FILE.xyz), ASE must read back exactly what tripack printed:
#   * every key of atoms.info and nothing else: d (the same digits in the comment line, the same
#     double in ASE), bonds (an int), triangle (the unit triangle's corners), label where tripack
#     has one (and no label key where it has none);
#   * every array and nothing else: n particles at the centres (z = 0), radius d/2, the rattler
#     flag of exactly the disks tripack calls rattlers; pbc all false.
# The packings: the atlas's t11a (a rattler) and t22a (a label from its "# label:" header), a
# built member without a label (even-ripple k=3: ASE once read label="" as label = "bonds=47"),
# and t11a under a label with spaces, double quotes and backslashes (given by a JSON file).
# Usage: xyz_ase_test.sh path/to/tripack
set -u
TRIPACK=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
run() {  # run NAME EXPECTED_LABEL_OR_- tripack-arguments...
  local name=$1 label=$2
  shift 2
  "$TRIPACK" "$@" --json --points -o "$tmp/$name.xyz" >"$tmp/$name.json" || {
    echo "FAIL: $name: tripack $* -o .xyz"
    fail=1
    return
  }
  /usr/bin/python3 - "$name" "$label" "$tmp/$name.xyz" "$tmp/$name.json" <<'PY' || fail=1
import json, math, sys
from decimal import Decimal
import numpy as np
from ase.io import read

name, label, xyz, js = sys.argv[1:5]
atoms = read(xyz, format="extxyz")
result = json.load(open(js))
failures = []
def check(what, ok):
    print(("ok: " if ok else "FAIL: ") + name + ": " + what)
    if not ok:
        failures.append(what)

points = result["points"]
n = len(points)
d = float(result["d"])
comment = open(xyz).read().split("\n")[1]

# atoms.info: every key, and only these.
expected_keys = {"d", "bonds", "triangle"} | ({"label"} if label != "-" else set())
check(f"info keys {sorted(atoms.info)} are {sorted(expected_keys)}",
      set(atoms.info) == expected_keys)
# The comment line's d has the file's digits (at least tripack's printed ones), agreeing with the
# printed d to within a unit of its last digit.
written = [w[2:] for w in comment.split() if w.startswith("d=")]
printed = Decimal(result["d"])
check(f"d={written} in the comment line agrees with tripack's d {result['d']}",
      len(written) == 1 and len(written[0].lstrip("0.")) >= len(result["d"].lstrip("0."))
      and abs(Decimal(written[0]) - printed) <= Decimal(1).scaleb(printed.as_tuple().exponent))
check(f"info d {atoms.info.get('d')!r} is tripack's d {d!r}", atoms.info.get("d") == d)
bonds = atoms.info.get("bonds")
check(f"info bonds {bonds!r} is the int {result['bonds']}",
      isinstance(bonds, (int, np.integer)) and not isinstance(bonds, (bool, np.bool_))
      and bonds == result["bonds"])
triangle = atoms.info.get("triangle")
check("info triangle is the unit triangle's corners",
      isinstance(triangle, np.ndarray) and triangle.shape == (6,)
      and list(triangle) == [0, 0, 1, 0, 0.5, math.sqrt(3) / 2])
if label != "-":
    if "label" in result:
        check(f"tripack prints label {result['label']!r}", result["label"] == label)
    check(f"info label {atoms.info.get('label')!r} is {label!r}", atoms.info.get("label") == label)
check(f"pbc {list(atoms.pbc)} is all false", not any(atoms.pbc))

# atoms.arrays: every array, and only these.
check(f"arrays {sorted(atoms.arrays)} are numbers, positions, radius, rattler",
      set(atoms.arrays) == {"numbers", "positions", "radius", "rattler"})
check(f"ASE reads {len(atoms)} particles, tripack has {n}", len(atoms) == n)
check("every species is X (number 0)", all(z == 0 for z in atoms.arrays["numbers"]))
pos = atoms.get_positions()
# The file's coordinates have 21 digits; as doubles they agree to a double's rounding (1e-15).
check("positions are the centres (z = 0)",
      len(pos) == n and all(abs(pos[i][0] - float(p[0])) < 1e-15
                            and abs(pos[i][1] - float(p[1])) < 1e-15 and pos[i][2] == 0
                            for i, p in enumerate(points)))
check("radius is d/2 on every disk", all(abs(r - d / 2) < 1e-15 for r in atoms.arrays["radius"]))
rattlers = sorted(result["rattler_indices"])
flagged = sorted(i for i, f in enumerate(atoms.arrays["rattler"]) if f == 1)
check(f"rattler flags {flagged} are tripack's rattlers {rattlers}",
      flagged == rattlers and all(f in (0, 1) for f in atoms.arrays["rattler"]))
sys.exit(1 if failures else 0)
PY
}

run t11a t11a analyze "$root/data/atlas/t11a.txt"
run t22a t22a analyze "$root/data/atlas/t22a.txt"
run built - build even-ripple --k 3
# A label ASE's parser must be given escaped: spaces, double quotes, backslashes, an = sign.
/usr/bin/python3 - "$root/data/atlas/t11a.txt" "$tmp/odd-label.json" <<'PY'
import json, sys
points = [[float(w) for w in line.split()] for line in open(sys.argv[1])
          if line.strip() and not line.startswith("#")]
json.dump({"label": 'odd "label" \\ a=b \\"', "points": points}, open(sys.argv[2], "w"))
PY
run odd 'odd "label" \ a=b \"' analyze "$tmp/odd-label.json"
exit $fail
