#!/usr/bin/env python3
"""tools/check-layers on small trees of known verdict: a clean one passes; a lab file including
render, a core file including lab, and a CMakeLists.txt building a source from another folder
each fail, named by file and line."""

import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from tool_on_tree import run_on_tree  # noqa: E402

TOOL = pathlib.Path(sys.argv[1]) / "tools" / "check-layers"


def check(files):
    return run_on_tree(TOOL, files)


failures = []
clean = {"src/lab/run.cpp": '#include "scene/scene.hpp"\n#include "lab/run.hpp"\n',
         "src/render/draw.cpp": '#include "scene/scene.hpp"\n',
         "src/cli/main.cpp": '#include "render/draw.hpp"\n#include "serve/x.hpp"\n',
         "src/lab/CMakeLists.txt": "add_library(fl_lab STATIC run.cpp)\n"}
status, out = check(clean)
if status != 0:
    failures.append(f"a clean tree failed: {out}")
for name, text, expected in [
        ("src/lab/video.cpp", '#include "render/renderer.hpp"\n', "src/lab/video.cpp:1: lab includes render"),
        ("src/core/f.cpp", '\n#include "lab/run.hpp"\n', "src/core/f.cpp:2: core includes lab"),
        ("src/lab/CMakeLists.txt", "add_library(fl_lab STATIC ../serve/x.cpp)\n",
         "src/lab/CMakeLists.txt:1: builds ../serve/x.cpp")]:
    status, out = check({**clean, name: text})
    if status != 1 or expected not in out:
        failures.append(f"{name}: expected status 1 and '{expected}', got {status}: {out}")
for failure in failures:
    print(failure)
print(f"layers check: {4 - len(failures)} of 4 trees judged as expected")
sys.exit(1 if failures else 0)
