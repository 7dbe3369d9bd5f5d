#!/usr/bin/env python3
"""Lists the C++ functions longer than a limit (default 150 lines) in the repository's source
folders and exits 1 if there is any. A function's length runs from the line of its opening brace
to the line of its closing brace, both counted. A scan of brace depth, with comments, strings,
character literals and preprocessor lines blanked first: a `{` at file, namespace or class level
that follows a parameter list (`)`, maybe then `const`, `noexcept`, `override`, `final`, a
trailing return type or a constructor's initializer list) opens a function; everything inside it
(blocks, lambdas, local classes) counts toward that function. A TEST(...) body is a function too.
usage: function-lengths.py [--limit N] [--root DIR] [--all]
  --all prints every function with its length (longest first), not only those over the limit."""
import argparse, os, re, subprocess, sys

FOLDERS = ["analysis", "app", "bench", "checker", "commands", "constructors", "core", "exact",
           "formats", "jobs", "patterns", "pipeline", "polish", "report", "runner", "scenes",
           "search", "sim", "store", "tests", "fuzz"]


def blank(text):
    """The text with comments, string and character literals and preprocessor lines replaced by
    spaces (newlines kept, so that line numbers stay right)."""
    out = []
    i, n = 0, len(text)
    line_start = True  # only whitespace since the last newline

    def keep_newlines(s):
        return "".join(c if c == "\n" else " " for c in s)

    while i < n:
        c = text[i]
        if line_start and c == "#":
            # A preprocessor directive, with its backslash-continued lines.
            j = i
            while j < n:
                k = text.find("\n", j)
                if k < 0:
                    k = n
                if k > 0 and text[k - 1] == "\\":
                    j = k + 1
                    continue
                break
            out.append(keep_newlines(text[i:k]))
            i = k
            continue
        if c == "/" and text.startswith("//", i):
            k = text.find("\n", i)
            k = n if k < 0 else k
            out.append(" " * (k - i))
            i = k
            continue
        if c == "/" and text.startswith("/*", i):
            k = text.find("*/", i + 2)
            k = n if k < 0 else k + 2
            out.append(keep_newlines(text[i:k]))
            i = k
            continue
        m = re.compile(r'(?:u8|u|U|L)?R"([^ ()\\\t\n]{0,16})\(').match(text, i)
        if m and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            end = text.find(")" + m.group(1) + '"', m.end())
            end = n if end < 0 else end + len(m.group(1)) + 2
            out.append('""' + keep_newlines(text[i + 2:end]))
            i = end
            continue
        if c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum())):
            # A string or a character literal (a ' after a digit or letter is a digit separator).
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(c + keep_newlines(text[i + 1:j - 1]) + c if j - i >= 2 else c)
            i = j
            line_start = False
            continue
        out.append(c)
        if c == "\n":
            line_start = True
        elif not c.isspace():
            line_start = False
        i += 1
    return "".join(out)


# After a parameter list's `)`: qualifiers, then maybe a trailing return type, or a constructor's
# initializer list (`: a_(x), b_(y)`), then the body's `{`.
QUALIFIERS = r"(?:\s*(?:const|volatile|noexcept(?:\s*\([^()]*\))?|override|final|mutable|&&|&|" \
             r"throw\s*\(\s*\)|requires\b[^{;]*))*"
FUNCTION_TAIL = re.compile(r"\)" + QUALIFIERS + r"\s*(?:->[^{;]*)?$", re.S)
INIT_LIST_TAIL = re.compile(r"\)" + QUALIFIERS + r"\s*:\s*[^;]*$", re.S)


def name_of(header):
    """The function's name: what stands before the parameter list's `(` (with a macro's
    arguments, as in TEST(Suite, Name))."""
    h = " ".join(header.split())
    # The parameter list: the first `(` at angle-bracket depth 0 after the name.
    m = re.search(r"((?:[\w~]+::)*(?:operator\s*(?:\(\)|[^\s(]+)|[\w~]+))\s*\(", h)
    if not m:
        return h[:60]
    name = m.group(1)
    if re.fullmatch(r"[A-Z_0-9]+", name):  # a macro such as TEST(Suite, Name): keep its arguments
        depth, j = 0, m.end() - 1
        for j in range(m.end() - 1, len(h)):
            depth += {"(": 1, ")": -1}.get(h[j], 0)
            if depth == 0:
                break
        return h[m.start():j + 1]
    return name


def functions(path):
    """(first line, last line, name) of each function in the file."""
    text = blank(open(path, errors="replace").read())
    found = []
    # A stack of open scopes: "ns" (file, namespace, extern, class), "fn" (a function's body) or
    # "other" (an initializer, an enum, a block inside a function).
    stack = []
    header_start = 0  # where the text before the next `{` began (after the last ; { or })
    line = 1
    fn_start = None
    i = 0
    skip_to = -1  # a member's brace initializer inside a constructor's initializer list
    for i, c in enumerate(text):
        if c == "\n":
            line += 1
            continue
        if i < skip_to:
            continue
        if c not in "{};":
            continue
        in_function = any(kind == "fn" for kind, _, _ in stack)
        if c == ";":
            if not in_function:
                header_start = i + 1
            continue
        if c == "}":
            if stack:
                kind, start, name = stack.pop()
                if kind == "fn" and not any(k == "fn" for k, _, _ in stack):
                    found.append((start, line, name))
            if not any(k == "fn" for k, _, _ in stack):
                header_start = i + 1
            continue
        # c == "{"
        if in_function or (stack and stack[-1][0] == "other"):
            stack.append(("other", line, ""))
            continue
        header = text[header_start:i]
        # An access specifier or a label before the declaration is not part of it.
        h = re.sub(r"^(?:\s*(?:public|private|protected)\s*:(?!:))+", "", header).strip()
        words = re.findall(r"[A-Za-z_]\w*", h)
        if words[:1] == ["namespace"] or words[:2] == ["inline", "namespace"] or \
                re.fullmatch(r'extern\s*""', h):
            stack.append(("ns", line, ""))
            header_start = i + 1
            continue
        if "(" in h and (FUNCTION_TAIL.search(h) or INIT_LIST_TAIL.search(h)) and \
                not re.match(r"(?:template\s*<[^{]*>\s*)?(?:class|struct|union|enum)\b", h):
            tail = INIT_LIST_TAIL.search(h)
            if tail and not FUNCTION_TAIL.search(h) and re.search(r"[\w>]\s*$", h):
                # `{` right after a member's name in an initializer list: that member's brace
                # initializer, not the body; skip to its matching `}`.
                depth, j = 0, i
                while j < len(text):
                    depth += {"{": 1, "}": -1}.get(text[j], 0)
                    if depth == 0:
                        break
                    j += 1
                skip_to = j + 1
                continue
            stack.append(("fn", line, name_of(h)))
            continue
        if re.match(r"(?:template\s*<[^{]*>\s*)?(?:class|struct|union)\b", h) and "=" not in h:
            stack.append(("ns", line, ""))
            header_start = i + 1
            continue
        stack.append(("other", line, ""))  # an initializer, an enum, an array
    return found


def source_files(root):
    try:
        listed = subprocess.run(["git", "ls-files", "--", *FOLDERS], cwd=root,
                                capture_output=True, text=True, check=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        listed = [os.path.relpath(os.path.join(d, f), root)
                  for top in FOLDERS for d, _, fs in os.walk(os.path.join(root, top)) for f in fs]
    return sorted(f for f in listed if f.endswith((".cpp", ".hpp")) and
                  os.path.exists(os.path.join(root, f)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--limit", type=int, default=150)
    parser.add_argument("--root", default=os.path.join(os.path.dirname(__file__), ".."))
    parser.add_argument("--all", action="store_true")
    args = parser.parse_args()
    rows = []
    files = source_files(args.root)
    for f in files:
        for first, last, name in functions(os.path.join(args.root, f)):
            rows.append((last - first + 1, f, first, name))
    rows.sort(key=lambda r: (-r[0], r[1], r[2]))
    long = [r for r in rows if r[0] > args.limit]
    for length, f, first, name in (rows if args.all else long):
        print(f"{f}:{first}: {name}: {length} lines")
    print(f"functions longer than {args.limit} lines: {len(long)} "
          f"({len(rows)} functions in {len(files)} files)")
    return 1 if long else 0


if __name__ == "__main__":
    sys.exit(main())
