#!/usr/bin/env python3
"""One word per concept (docs/conventions.md, "Names"): in the code's names, JSON keys and options,
"exact" means algebraic d(n) only (the minimal polynomial of d and its proof, exact/), and
"search" basin hopping only (search/). The Q(sqrt3) check of the closed forms is "sqrt3", digits
beyond a long double "precise" or "decimal", a closed form of L "closed_form_L", the billiards
job "billiards runs". Comments and prose are free; names are read from the code with comments
and string literals removed, keys and options from the string literals that are one word.
usage: python3 tests/repository/vocabulary_test.py [ROOT]"""
import pathlib, re, sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
FOLDERS = ["analysis", "app", "bench", "checker", "commands", "constructors", "core", "exact",
           "formats", "fuzz", "jobs", "patterns", "pipeline", "polish", "python", "report", "runner",
           "scenes", "search", "sim", "store", "tests"]
# Where algebraic d(n) lives: any "exact" name is its own.
ALGEBRAIC = re.compile(r"^(exact/|checker/|pipeline/exact\.|jobs/exact_atlas\.|"
                       r"report/results/exact\.hpp|tests/unit/test_exact_algebraic\.cpp)")
# Algebraic names used outside those files: the commands, the exact atlas, its table and rows.
ALGEBRAIC_NAMES = {
    "exact", "Exact", "ExactAtlasCommand", "exact-atlas", "atlas-exact", "ExactRequest", "ExactRun", "ExactResult",
    "ExactSettings", "ExactAtlas", "ExactAtlasSettings", "ExactAtlasResult", "ExactAtlasRow",
    "ExactConfiguration", "run_exact", "build_exact_atlas", "read_exact_atlas",
    "exact_atlas_table_format", "exact_of_file", "exact_of_packing", "exact_cells",
    "exact_atlas", "exact_test", "exact_certificates", "exact_checker", "exact_row", "exact_call",
    # Retired, still read from files written before the rename (docs/conventions.md, "Names").
    "points_exact",
}
STRING = re.compile(r'"(?:[^"\\\n]|\\.)*"')
COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")

bad = []
count = 0
for folder in FOLDERS:
    for path in sorted((root / folder).rglob("*")):
        if path.suffix not in (".cpp", ".hpp", ".h") or not path.is_file():
            continue
        rel = path.relative_to(root).as_posix()
        count += 1
        text = COMMENT.sub(" ", path.read_text(errors="replace"))
        keys = [s[1:-1] for s in STRING.findall(text) if re.fullmatch(r'"-{0,2}[A-Za-z_][\w-]*"', s)]
        code = STRING.sub('""', text)
        for name in set(WORD.findall(code)) | {k.lstrip("-") for k in keys}:
            low = name.lower()
            if "exact" in low and not ALGEBRAIC.match(rel) and name not in ALGEBRAIC_NAMES \
                    and not name.startswith(("exactly", "inexact")):
                bad.append(f"{rel}: '{name}' (exact means algebraic d(n) only)")
            if re.search(r"billiards_?search|search_?billiards|segment_?search", low):
                bad.append(f"{rel}: '{name}' (search means basin hopping only)")
for line in sorted(set(bad)):
    print(line)
print(f"vocabulary: {count} files, {len(set(bad))} names off")
sys.exit(1 if bad else 0)
