#!/usr/bin/env python3
"""opcount.py FILE.c [BODY...] -- the operations of each body's material function in
sphc's generated C: every arithmetic operator (+ - * /, a unary minus), comparison,
conditional (?:) and call (sqrt, pow, log, sph_* helpers) counted once, in the lines
between the function's opening and closing braces (comments and the assignments to S,
psi and the state, which compute nothing, excluded)."""
import re
import sys

OPS = re.compile(r"(\?|<=|>=|==|!=|&&|\|\||(?<![eE])[-+*/<>])")
CALL = re.compile(r"\b([A-Za-z_][A-Za-z_0-9]*)\s*\(")


def functions(code):
    """name -> body text of every '<body>_material' function."""
    out = {}
    for m in re.finditer(r"SPH_FN void (\w+)_material\(", code):
        start = code.index("{", m.end())
        end = code.index("\n}\n", start)
        out[m.group(1)] = code[start + 1:end]
    return out


def count(body):
    n = 0
    for line in body.splitlines():
        line = re.sub(r"/\*.*?\*/", "", line).strip()
        if not line or line.startswith("(void)"):
            continue
        rhs = line.split("=", 1)[1] if "=" in line else line
        rhs = re.sub(r"([(,]\s*)-(?=\d)", r"\1", rhs)  # a negative constant
        rhs = re.sub(r"\b\d+(\.\d*)?([eE][-+]?\d+)?", "c", rhs)  # numbers
        n += len(OPS.findall(rhs)) + len(CALL.findall(rhs))
    return n


def main():
    code = open(sys.argv[1]).read()
    fns = functions(code)
    names = sys.argv[2:] or sorted(fns)
    for name in names:
        print(f"{name} {count(fns[name])}")


if __name__ == "__main__":
    main()
