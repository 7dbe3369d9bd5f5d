#!/usr/bin/env python3
"""Every repository path named in docs/ and in the code's comments exists (a moved file leaves
no stale reference behind). A path is a word starting with one of the repository's top-level
folders (docs/, core/, scripts/, ...); `core/io` names core/io.hpp and core/io.cpp; a word with a
placeholder (LABEL, N, NAME, FORMAT), a glob or a string being concatenated is a pattern, not a
path. A path .gitignore covers is a job's output (data/logs/, out/): absent from a clean clone, and
not checked. The few other paths that name files on purpose absent are listed below with why.
usage: paths_test.py REPOSITORY_ROOT"""
import os, re, subprocess, sys

root = sys.argv[1] if len(sys.argv) > 1 else "."
ABSENT_ON_PURPOSE = {
    # docs/extending.md's worked examples: the files a reader would add
    "constructors/hexagonal_minus_two.cpp": "docs/extending.md's worked example of a new class",
    "sim/effects/target.hpp": "docs/extending.md's worked example of a new effect",
    # outputs of scripts, written where the user runs them, not kept in git
    "data/build-scan.csv": "scripts/analysis/build-scan.py's default output",
    # what a test shows to be missing
    "tests/data/atlas": "tests/checker/exact_checker_test.sh checks the checker without it",
}
files = subprocess.run(["git", "ls-files"], cwd=root, capture_output=True, text=True,
                       check=True).stdout.split()
tops = sorted({f.split("/")[0] for f in files if "/" in f} - {"data"}) + ["data"]
word = re.compile(r"(?<![\w/.-])((?:%s)/[A-Za-z0-9_./-]*[A-Za-z0-9_/])" % "|".join(map(re.escape, tops)))
placeholder = re.compile(r"(^|[/_.-])(LABEL|N|NAME|FORMAT|nN|cR)([/_.-]|$)")
stale = []
for f in files:
    if f.startswith("data/") or not f.endswith((".md", ".cpp", ".hpp", ".sh", ".py", ".cmake",
                                                 "CMakeLists.txt", ".yaml")):
        continue
    text = open(os.path.join(root, f), errors="replace").read()
    code = f.endswith((".cpp", ".hpp"))
    for m in word.finditer(text):
        p = m.group(1).rstrip("./") if not m.group(1).endswith("/") else m.group(1).rstrip("/")
        after = text[m.end():m.end() + 2]
        if after[:1] in ('"', "*", "{", "$", "<") or after == "-*" or placeholder.search(p):
            continue
        if p.endswith(("_", "-")) or p in ABSENT_ON_PURPOSE:
            continue
        if code:  # only comments
            line = text[:m.start()].rsplit("\n", 1)[-1]
            if "//" not in line and not line.lstrip().startswith("*"):
                continue
        if any(os.path.exists(os.path.join(root, p + e)) for e in ("", ".hpp", ".cpp", ".md")):
            continue
        lineno = text.count("\n", 0, m.start()) + 1
        stale.append(f"{f}:{lineno}: {p}")
# What .gitignore covers is written by the jobs, not kept (git check-ignore prints those it covers).
paths = sorted({s.rsplit(": ", 1)[1] for s in stale})
ignored = set(subprocess.run(["git", "check-ignore", "--no-index", *paths,
                              *[p + "/" for p in paths]], cwd=root, capture_output=True,
                             text=True).stdout.split()) if paths else set()
stale = [s for s in stale if not {s.rsplit(": ", 1)[1], s.rsplit(": ", 1)[1] + "/"} & ignored]
for s in stale:
    print("missing:", s)
print(f"paths named in docs and comments: {len(stale)} missing")
sys.exit(1 if stale else 0)
