#!/usr/bin/env python3
"""docs/cli.md's option tables and JSON-key list are generated from the binary: the options from
`tripack --markdown-options` (the options as the command line binds them, with their help and
defaults), spliced into each command's section; the JSON keys from the results' descriptions, as
every command prints them in sample runs (below, on fixtures made in a temporary directory),
spliced between the "JSON keys" markers. --check (what the cli_doc test runs) exits 1 when the
manual differs from what the binary generates, naming what differs.
usage: python3 scripts/cli-doc.py [--tripack build/tripack] [--doc docs/cli.md] [--check]"""
import argparse, json, os, re, shlex, subprocess, sys, tempfile

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

# ----- the JSON keys: every key path the commands print, from sample runs ------------------------
# Each command's runs (several where a key appears only with an option), as `tripack ARGS --json`.
SAMPLES = {
    "classes": [""], "classify": ["12"], "table": ["--kmax 1"],
    "check-formula": ["four-delta --k 1..2"],
    "build": ["four-delta --k 2 --points", "--n 12", "four-delta --k 2 --no-certify --digits 30"],
    "build-scan": ["--n 6..7 --table {tmp}/scan.csv"],
    "analyze": ["{tmp}/t12.txt --points"],
    "billiards": ["7 --runs 2 --points"], "compare": ["12 --runs 2"],
    "search": ["12 --steps 3 --seed 1 --target 0.2"],
    "explore": ["--max-n 6 --discovered-max-n 4 --billiards-max-n 4 --search-steps 1 "
                "--no-accuracy --atlas none --out {tmp}/report"],
    "campaign": ["--n 9 --runs 2 --db {tmp}/c2.db"],
    "db best": ["--db {tmp}/c.db"], "db check": ["--db {tmp}/c.db"],
    "db import": ["{tmp}/t12.txt --db {tmp}/c3.db"], "db prune": ["--keep 5 --db {tmp}/c.db"],
    "atlas": ["--db {tmp}/c.db --out {tmp}/atlas2 --n 10 --ranked 10..10 --ranked-count 1"],
    "exact": ["--class four-delta --k 2 --digits 60"],
    "exact-atlas": ["--atlas {tmp}/atlas/atlas.csv --n 10 --digits 60"],
}


def merge(into, value):
    """The union of the key trees of `value` into `into`: dict name -> subtree (None: a leaf)."""
    if isinstance(value, dict):
        for k, v in value.items():
            sub = into.setdefault(k, None)
            if isinstance(v, (dict, list)):
                into[k] = merge(sub if isinstance(sub, dict) else {}, v) if isinstance(v, dict) \
                    else merge_list(sub, v)
        return into
    return into


def merge_list(sub, items):
    tree = sub if isinstance(sub, dict) else {}
    objects = [x for x in items if isinstance(x, dict)]
    for x in objects:
        merge(tree, x)
    return ("[]", tree) if objects or (isinstance(sub, tuple)) else sub


def keys_text(tree):
    parts = []
    for k, v in tree.items():
        if isinstance(v, tuple):
            parts.append(f"{k}[{{{keys_text(v[1])}}}]" if v[1] else f"{k}[]")
        elif isinstance(v, dict):
            parts.append(f"{k}{{{keys_text(v)}}}")
        else:
            parts.append(k)
    return ", ".join(parts)


def generated_keys():
    tmp = tempfile.mkdtemp(prefix="tripack-cli-doc-")
    run = lambda args: subprocess.run([a.tripack] + shlex.split(args.format(tmp=tmp)),
                                      capture_output=True, text=True)
    run("build four-delta --k 2 -o {tmp}/t12.txt")
    run("campaign --n 10..11 --runs 3 --db {tmp}/c.db")
    run("atlas --db {tmp}/c.db --out {tmp}/atlas --n 10..11 --ranked 10..10 --ranked-count 2")
    lines = []
    for command, samples in SAMPLES.items():
        tree = {}
        for args in samples:
            p = run(f"{command} {args} --json")
            if p.returncode != 0:
                sys.exit(f"cli-doc: '{command} {args}' failed: {p.stderr.strip()[-300:]}")
            merge(tree, json.loads(p.stdout))
        lines.append(f"* `{command}`: `{keys_text(tree)}`\n")
    subprocess.run(["rm", "-rf", tmp])
    return ("<!-- JSON keys: generated by scripts/cli-doc.py from sample runs -->\n" +
            "".join(lines) + "<!-- end of the JSON keys -->\n")


keys_block = generated_keys()
text, count = re.subn(r"<!-- JSON keys: generated.*?<!-- end of the JSON keys -->\n",
                      lambda m: keys_block, text, flags=re.S)
if count != 1:
    sys.exit("cli-doc: docs/cli.md has no (or more than one) JSON keys block")
if a.check:
    old = open(a.doc).read()
    differ = [c for c in blocks if blocks[c] not in old]
    if differ or missing or text != old:
        print("docs/cli.md differs from the binary's options or JSON keys: " +
              ", ".join(differ + [f"{c} (no section)" for c in missing] +
                        (["the JSON keys"] if keys_block not in old else [])) +
              " (python3 scripts/cli-doc.py rewrites it)")
        sys.exit(1)
    print(f"docs/cli.md: the options of {len(blocks)} commands and the JSON keys of "
          f"{len(SAMPLES)} equal the binary's")
    sys.exit(0)
if missing:
    sys.exit("cli-doc: no section in docs/cli.md for " + ", ".join(missing))
open(a.doc, "w").write(text)
print(f"docs/cli.md: options of {len(seen)} commands and JSON keys of {len(SAMPLES)} written")
