#!/usr/bin/env python3
"""No message of the lab names a command-line flag: the layers below the front ends (lab, core,
scene, io, hall_log, estimator, physics, sensor) name a request's field with io/field_ref.hpp, and each front end
spells it (--geometry, geometry=). Reads every string literal of those folders' C++ sources and
fails on one that holds a flag ("--geometry", "-j"), printing where it is."""

import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parents[2])
LAYERS = ["lab", "core", "scene", "io", "hall_log", "estimator", "physics", "sensor"]
# A string literal (with escapes), outside comments.
LITERAL = re.compile(r'"(?:[^"\\\n]|\\.)*"')
# "--geometry", or a short flag standing alone ("-j 2"); "12-tooth" is no flag.
FLAG = re.compile(r"(?:^|[\s(\"'`])(?:--[a-z][a-z-]*|-[a-zA-Z](?=\s|$))")


def code_lines(text):
    """Each line without its // comment and without what /* */ covers (literals kept)."""
    in_block = False
    for number, line in enumerate(text.splitlines(), 1):
        out = ""
        i = 0
        while i < len(line):
            if in_block:
                end = line.find("*/", i)
                if end < 0:
                    i = len(line)
                    continue
                in_block = False
                i = end + 2
                continue
            if line.startswith("/*", i):
                in_block = True
                i += 2
                continue
            if line.startswith("//", i):
                break
            if line[i] == '"':
                m = LITERAL.match(line, i)
                if m:
                    out += m.group(0)
                    i = m.end()
                    continue
            out += line[i]
            i += 1
        yield number, out


found = []
for layer in LAYERS:
    for path in sorted((ROOT / "src" / layer).rglob("*")):
        if path.suffix not in {".cpp", ".hpp", ".h"}:
            continue
        for number, line in code_lines(path.read_text(encoding="utf-8")):
            for literal in LITERAL.findall(line):
                body = literal[1:-1]
                if FLAG.search(body) and not re.fullmatch(r"-+", body):
                    found.append(f"{path.relative_to(ROOT)}:{number}: {literal}")

if found:
    print("strings below the front ends that name a command-line flag "
          "(name the field with field_ref instead):")
    print("\n".join(found))
    sys.exit(1)
print(f"no flag named in the string literals of src/{{{','.join(LAYERS)}}}")
