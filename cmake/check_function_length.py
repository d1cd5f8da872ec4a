#!/usr/bin/env python3
"""Fails when a function body in the given folders is longer than a limit (default 120 lines).

The rule, kept simple on purpose: comments, string and character literals (raw strings too) and
preprocessor lines are blanked; then braces are matched. A brace opened outside every function body
whose declaration head is not a namespace, class, struct, union, enum or extern block, and whose
head holds a '(', opens a function body (a free function, a member function, a constructor, an
operator, a lambda at namespace scope); a brace without '(' in its head (a table, an aggregate
initialiser) is not a function. A function's length is the number of lines from its opening brace
to its closing brace, both included; lambdas and local classes count in the function that holds
them.

Usage: check_function_length.py [--max N] DIR...   or   check_function_length.py --self-test
Prints every function over the limit (file:line: name, N lines) and exits 1 when there is one.
"""

import argparse
import pathlib
import re
import sys

SCOPE = re.compile(r"\b(namespace|class|struct|union|enum|extern)\b[^()]*$")


def blank_literals(text: str) -> str:
    """The text with comments, literals and preprocessor lines replaced by blanks (newlines kept)."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#":
            # A preprocessor line, with its continuations.
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
                i += 1
            continue
        if c == "/" and text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
            continue
        if c == "/" and text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            continue
        raw = re.match(r'(?:u8|u|U|L)?R"([^()\\\s]{0,16})\(', text[i:i + 24])
        if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            close = ")" + raw.group(1) + '"'
            end = text.find(close, i + raw.end())
            end = n if end < 0 else end + len(close)
            out.append('""' + re.sub(r"[^\n]", " ", text[i + 2:end]))
            i = end
            continue
        if c in "\"'":
            # A digit separator (1'000'000) is not a character literal.
            if c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum():
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else ""))
            i = j + 1
            continue
        out.append(c)
        line_start = c == "\n" or (line_start and c in " \t")
        i += 1
    return "".join(out)


def long_functions(path: pathlib.Path, limit: int):
    text = blank_literals(path.read_text(encoding="utf-8", errors="replace"))
    line = 1
    # Each open brace: (kind, line, head) with kind "scope" (namespace, class), "function" or "block".
    stack = []
    head = []
    own_head = []  # the head of each open function or block outside every function
    found = []

    def in_function():
        return any(kind != "scope" for kind, _, _ in stack)

    # After a brace closes outside every function, a ',' or '{' next continues a constructor's
    # initialiser list (x_{a}, y_{b} { ... }): the head is kept for the body that follows.
    closed_head = None
    for c in text:
        if c == "\n":
            line += 1
        if closed_head is not None and not c.isspace():
            if c in ",{":
                head = closed_head
            closed_head = None
        if in_function():
            if c == "{":
                stack.append(("inner", line, ""))
            elif c == "}":
                kind, opened, name = stack.pop()
                if kind == "function" and line - opened + 1 > limit:
                    found.append((opened, name, line - opened + 1))
                if kind != "inner":
                    closed_head = own_head.pop()
            continue
        if c == "{":
            h = " ".join("".join(head).split())
            if SCOPE.search(h):
                stack.append(("scope", line, h))
                head = []
            elif "(" in h:
                name = re.search(r"(operator\s*[^\s(]+|[~\w:]+)\s*\(", h)
                stack.append(("function", line, name.group(1) if name else h[-60:]))
                own_head.append(list(head))
            else:
                stack.append(("block", line, h))
                own_head.append(list(head))
            head = []
        elif c == "}":
            if stack:
                stack.pop()
            head = []
        elif c == ";":
            head = []
        else:
            head.append(c)
    return found


SELF_TEST = r"""
namespace a {
struct S {
    S(int x) : x_{x}, y_(x) {
        // a { in a comment
        f("}", '{');
    }
    int x_, y_;
};
const int kTable[] = {
    1, 2, 3,
    4,
};
auto raw() { return R"x( } { )x"; }
template <class T> T twice(T v) {
    auto g = [&](int k) {
        return k;
    };
    return v + v;
}
extern "C" {
int c_side(void) {
    return 1'000;
}
}
}  // namespace a
"""


def self_test() -> int:
    """The rule on a text of known answers: each function's length at a limit of 1 line."""
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        p = pathlib.Path(d) / "sample.cpp"
        p.write_text(SELF_TEST)
        got = sorted((name, n) for _, name, n in long_functions(p, 1))
    want = sorted([("S", 4), ("raw", 1), ("twice", 6), ("c_side", 3)])
    want = [w for w in want if w[1] > 1]
    if got != want:
        print(f"check_function_length --self-test: found {got}, expected {want}")
        return 1
    print("check_function_length --self-test: constructor with an initialiser list, literals, a table, "
          "a template with a lambda and an extern block counted as expected")
    return 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--max", type=int, default=120, help="longest function allowed [lines]")
    ap.add_argument("--self-test", action="store_true", help="check the rule on a sample of known answers")
    ap.add_argument("dirs", nargs="*", type=pathlib.Path)
    a = ap.parse_args()
    if a.self_test:
        return self_test()
    if not a.dirs:
        ap.error("name at least one folder")
    bad = 0
    files = 0
    for d in a.dirs:
        for f in sorted(list(d.rglob("*.cpp")) + list(d.rglob("*.hpp"))):
            files += 1
            for opened, name, n in long_functions(f, a.max):
                print(f"{f}:{opened}: {name}: {n} lines (more than {a.max})")
                bad += 1
    if bad:
        print(f"check_function_length: {bad} function(s) over {a.max} lines; split them into named steps")
        return 1
    print(f"check_function_length: {files} files, no function over {a.max} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
