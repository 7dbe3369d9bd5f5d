"""A CSV table that a long script appends to one row at a time and a rerun continues: the rows
already there, keyed by their n, are returned, and the writer appends (the header only to a new
file). Shared by scripts/analysis/build-scan.py and scripts/analysis/search-vs-build.py and scripts/analysis/build-vs-atlas.py."""
import csv, os


def n_values(spec):
    """'A..B' or 'A,B,C' as a list of n."""
    if ".." in spec:
        lo, hi = (int(x) for x in spec.split(".."))
        return list(range(lo, hi + 1))
    return [int(x) for x in spec.split(",")]


def open_table(path, fields):
    """(rows already in the file by n, the open file, a DictWriter appending to it)."""
    done = {}
    if os.path.exists(path):
        done = {int(r["n"]): r for r in csv.DictReader(open(path))}
    new_file = not os.path.exists(path)
    out = open(path, "a", newline="")
    writer = csv.DictWriter(out, fields)
    if new_file:
        writer.writeheader()
        out.flush()
    return done, out, writer
