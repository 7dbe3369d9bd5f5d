#!/usr/bin/env python3
"""docs/cli.md's option tables are generated from the binary (`tripack --markdown-options`, the
options as the command line binds them, with their help and defaults): this script splices each
command's block into its section of the manual. --check (what the cli_doc test runs) exits 1
when the manual differs from what the binary generates, naming the commands that differ.
The first run also replaced the hand-kept tables, one per command section, by the blocks.
usage: python3 scripts/cli-doc.py [--tripack build/tripack] [--doc docs/cli.md] [--check]"""
import argparse, re, subprocess, sys

ap = argparse.ArgumentParser()
ap.add_argument("--tripack", default="build/tripack")
ap.add_argument("--doc", default="docs/cli.md")
ap.add_argument("--check", action="store_true")
a = ap.parse_args()

generated = subprocess.run([a.tripack, "--markdown-options"], capture_output=True, text=True,
                           check=True).stdout
blocks = {m.group(1): m.group(0) for m in re.finditer(
    r"<!-- options of (.+?): generated.*?-->\n.*?<!-- end of the options of \1 -->\n",
    generated, re.S)}

lines = open(a.doc).read().splitlines(keepends=True)
out, section, current, i, seen = [], None, None, 0, []
while i < len(lines):
    line = lines[i]
    if line.startswith("### "):
        section = current = line[4:].strip()
    bold = re.match(r"\*\*`(db \w+)", line)
    if section == "db" and bold:
        current = bold.group(1)
    marker = re.match(r"<!-- options of (.+?): generated", line)
    hand = section and line.startswith("| ") and ("option" in line.split("|")[1]) \
        and current not in seen and current in blocks
    if marker or hand:
        name = marker.group(1) if marker else current
        end = i
        if marker:
            while not lines[end].startswith("<!-- end of the options of"):
                end += 1
        else:
            while end + 1 < len(lines) and lines[end + 1].startswith("|"):
                end += 1
        if name not in blocks:
            sys.exit(f"cli-doc: docs/cli.md has options of '{name}', which the binary does not have")
        out.append(blocks[name])
        seen.append(name)
        i = end + 1
        continue
    out.append(line)
    i += 1

missing = [c for c in blocks if c not in seen]
text = "".join(out)
if a.check:
    old = open(a.doc).read()
    differ = [c for c in blocks if blocks[c] not in old]
    if differ or missing or text != old:
        print("docs/cli.md differs from the binary's options: " +
              ", ".join(differ + [f"{c} (no section)" for c in missing]) +
              " (python3 scripts/cli-doc.py rewrites it)")
        sys.exit(1)
    print(f"docs/cli.md: the options of {len(blocks)} commands equal the binary's")
    sys.exit(0)
if missing:
    sys.exit("cli-doc: no section in docs/cli.md for " + ", ".join(missing))
open(a.doc, "w").write(text)
print(f"docs/cli.md: options of {len(seen)} commands written")
