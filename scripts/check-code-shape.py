#!/usr/bin/env python3
"""The code's shape, as CONTRIBUTING asks: no source file over 400 lines, no C++ function over 60.

Usage: check-code-shape.py [--debt FILE] [SOURCE_DIR]. Prints each file or function over its
limit with its length. Without --debt it exits 1 if there is any. With --debt (the recorded
offenders, one `path [function] lines` per line) it exits 1 only when a file or function is over
its limit and not recorded, or has grown past its recorded length, and when a recorded one has
shrunk or gone (lower its line): the list stays exact, and the debt can only shrink.

A C++ function is found by its body: a line that ends a signature with `{` (a `)` before it, or
a constructor's initialiser list) at brace depth 0 outside types, or inside a class or struct body
for members defined there; its length runs from its first signature line to its closing brace.
Lambdas and blocks inside a function count as its lines.
"""
import pathlib
import re
import subprocess
import sys

MAX_FILE_LINES = 400
MAX_FUNCTION_LINES = 60
ACCESS = re.compile(r"^(public|private|protected)\s*:$")
SOURCE_SUFFIXES = (".cpp", ".h", ".py", ".sh", ".cmake")
NOT_A_FUNCTION = re.compile(r"^\s*(namespace|struct|class|enum|union|extern|if|for|while|switch|do|else|try|catch)\b")


def tracked_files(root):
    """The files git tracks; outside a git checkout (a source tarball), every source file but
    those under a build or output folder."""
    listed = subprocess.run(["git", "-C", str(root), "ls-files"], capture_output=True, text=True)
    if listed.returncode == 0:
        names = listed.stdout.split()
    else:
        names = [str(f.relative_to(root)) for f in root.rglob("*") if f.is_file()
                 and f.relative_to(root).parts[0] not in ("build", "out", ".git")]
    return [root / f for f in names if f.endswith(SOURCE_SUFFIXES) or f.endswith("CMakeLists.txt")]


def strip_code(line, in_comment):
    """The line without comments, strings and character literals; whether a /* */ is still open."""
    out, i = [], 0
    while i < len(line):
        if in_comment:
            end = line.find("*/", i)
            if end < 0:
                return "".join(out), True
            in_comment, i = False, end + 2
        elif line.startswith("//", i):
            break
        elif line.startswith("/*", i):
            in_comment, i = True, i + 2
        elif line[i] in "\"'":
            quote, i = line[i], i + 1
            while i < len(line) and line[i] != quote:
                i += 2 if line[i] == "\\" else 1
            i += 1
            out.append(quote * 2)
        else:
            out.append(line[i])
            i += 1
    return "".join(out), in_comment


def signature_start(code_lines, k):
    """The first line of the signature that ends on line k (back to a blank, ;, } or { line)."""
    j = k
    while j > 0:
        prev = code_lines[j - 1].strip()
        if not prev or prev.endswith((";", "}", "{")) or prev.startswith("#") or ACCESS.match(prev):
            break
        j -= 1
    return j


def function_name(signature):
    """The name a signature defines (`Class::name`, `name`, or a TEST's `Suite.Name`)."""
    test = re.match(r"\s*(?:TEST|TEST_F|TEST_P)\(\s*(\w+)\s*,\s*(\w+)", signature)
    if test:
        return f"{test.group(1)}.{test.group(2)}"
    name = re.search(r"([~\w:]+)\s*\(", signature)
    return name.group(1) if name else signature.strip()[:40]


def not_a_function(stripped):
    """Whether a line opening a brace opens a type, namespace, control block or initialiser."""
    return bool(NOT_A_FUNCTION.match(stripped)
                or re.search(r"\b(struct|class|enum|union)\b[^()]*\{", stripped)
                or "=" in stripped.split("{")[0] and ")" not in stripped)


def long_functions(path):
    text = path.read_text(errors="replace")
    if "R\"(" in text:  # raw strings would fool the brace count; none of our long code has them
        text = re.sub(r'R"\((.|\n)*?\)"', '""', text)
    code_lines, in_comment = [], False
    for line in text.split("\n"):
        code, in_comment = strip_code(line, in_comment)
        code_lines.append(code)
    found, opens = [], []  # opens: for each open brace, whether it opened a function body
    start = opening = None
    for k, code in enumerate(code_lines):
        for ch in code:
            if ch == "{":
                if any(opens) or not_a_function(code.strip()):
                    opens.append(False)
                    continue
                first = signature_start(code_lines, k)
                is_function = ")" in "".join(code_lines[first:k + 1]) or code.strip().startswith(":")
                opens.append(is_function)
                if is_function:
                    start, opening = first, k
            elif ch == "}" and opens:
                if opens.pop() and not any(opens):
                    length = k - start + 1
                    if length > MAX_FUNCTION_LINES:
                        signature = " ".join(code_lines[start:opening + 1])
                        found.append((start + 1, length, function_name(signature)))
    return found


def read_debt(path):
    """The recorded offenders: `path lines` for a file, `path name lines` for a function."""
    debt = {}
    for line in path.read_text().splitlines():
        fields = line.split("#")[0].split()
        if fields:
            debt[tuple(fields[:-1])] = int(fields[-1])
    return debt


def offenders(root):
    """Every file and function over its limit: {(path,) or (path, name): lines}, and where."""
    found, where = {}, {}
    for path in tracked_files(root):
        rel = str(path.relative_to(root))
        lines = path.read_text(errors="replace").count("\n")
        if lines > MAX_FILE_LINES:
            found[(rel,)] = lines
            where[(rel,)] = f"{rel}: {lines} lines (at most {MAX_FILE_LINES})"
        if path.suffix in (".cpp", ".h"):
            for line, length, name in long_functions(path):
                key = (rel, name)
                found[key] = max(length, found.get(key, 0))
                where[key] = (f"{rel}:{line}: {name} is {length} lines (at most "
                              f"{MAX_FUNCTION_LINES})")
    return found, where


def main():
    args = sys.argv[1:]
    debt_path = None
    if args and args[0] == "--debt":
        debt_path, args = pathlib.Path(args[1]), args[2:]
    root = pathlib.Path(args[0] if args else ".").resolve()
    found, where = offenders(root)
    debt = read_debt(debt_path) if debt_path else {}
    new = [k for k in found if k not in debt or found[k] > debt[k]]
    paid = [k for k in debt if k not in found or found[k] < debt[k]]
    for k in sorted(found):
        recorded = f" (recorded debt: {debt[k]})" if k in debt else " (new)"
        print(where[k] + (recorded if debt_path else ""))
    for k in sorted(paid):
        now = found.get(k, "within the limit")
        print(f"paid off: {' '.join(k)} was {debt[k]}, now {now}: lower it in {debt_path}")
    if debt_path:
        print(f"code shape: {len(found)} over the limits, {len(new)} new or grown beyond "
              f"{debt_path}, {len(paid)} paid off but still listed")
        return 1 if new or paid else 0
    if not found:
        print(f"code shape: every file <= {MAX_FILE_LINES} lines, every C++ function <= "
              f"{MAX_FUNCTION_LINES}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
