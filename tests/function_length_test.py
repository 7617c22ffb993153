#!/usr/bin/env python3
"""tools/check-function-length on small trees of known verdict: functions of 120 lines pass, one
of 121 fails by name and line, braces in strings and comments do not count, a listed function may
not grow and must leave the list once split."""

import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from tool_on_tree import run_on_tree  # noqa: E402

TOOL = pathlib.Path(sys.argv[1]) / "tools" / "check-function-length"


def function(name, lines):
    body = ["  int x = 0;"] * (lines - 2)
    return "\n".join([f"int {name}(int a) {{"] + body + ["}"]) + "\n"


def check(files):
    return run_on_tree(TOOL, files)


cases = [
    ("two of 120 lines and a string with braces",
     {"src/a.cpp": function("f", 120) + 'const char* s = "{{{";\n// }}}\n' + function("g", 120)},
     0, ""),
    ("one of 121 lines", {"src/core/b.cpp": "\n" + function("longer", 121)}, 1,
     "src/core/b.cpp:2: longer is 121 lines"),
    ("a listed one that grew",
     {"src/c.cpp": function("h", 130), "tools/long-functions.txt": "src/c.cpp:h 125\n"}, 1,
     "h grew to 130 lines"),
    ("a listed one that was split",
     {"src/c.cpp": function("h", 40), "tools/long-functions.txt": "src/c.cpp:h 125\n"}, 1,
     "src/c.cpp:h is no longer over 120 lines"),
    ("a listed one as long as listed",
     {"src/c.cpp": function("h", 125), "tools/long-functions.txt": "src/c.cpp:h 125\n"}, 0, ""),
]
failures = []
for what, files, status, expected in cases:
    got, out = check(files)
    if got != status or expected not in out:
        failures.append(f"{what}: expected status {status} and '{expected}', got {got}: {out}")
for failure in failures:
    print(failure)
print(f"function length check: {len(cases) - len(failures)} of {len(cases)} trees judged as expected")
sys.exit(1 if failures else 0)
