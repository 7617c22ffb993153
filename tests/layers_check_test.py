#!/usr/bin/env python3
"""tools/check-layers on small trees of known verdict: a clean one passes; a lab file including
render, a core file including lab, a room including a room it does not link, a CMakeLists.txt
building a source from another folder, a source no target builds and a tests/ folder that mirrors
no folder of src/ each fail, named by file (and line)."""

import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from tool_on_tree import run_on_tree  # noqa: E402

TOOL = pathlib.Path(sys.argv[1]) / "tools" / "check-layers"


def check(files):
    return run_on_tree(TOOL, files)


failures = []
clean = {"src/lab/run/run.cpp": '#include "scene/scene.hpp"\n#include "lab/run/run.hpp"\n'
                                '#include "lab/logs/log.hpp"\n',
         "src/lab/run/CMakeLists.txt": "add_library(fl_lab_run STATIC run.cpp)\n"
                                       "target_link_libraries(fl_lab_run PUBLIC fl_lab_logs)\n",
         "src/lab/logs/log.cpp": '#include "lab/logs/log.hpp"\n',
         "src/lab/logs/CMakeLists.txt": "# builds log.cpp\nadd_library(fl_lab_logs STATIC log.cpp)\n",
         "src/render/draw.cpp": '#include "scene/scene.hpp"\n',
         "src/render/CMakeLists.txt": "add_library(fl_render STATIC draw.cpp)\n",
         "src/cli/main.cpp": '#include "render/draw.hpp"\n#include "serve/x.hpp"\n',
         "src/cli/CMakeLists.txt": "add_executable(frictionlab main.cpp)\n",
         "tests/lab/run/CMakeLists.txt": "fl_add_gtest(NAME run_test SOURCES run_test.cpp)\n",
         "tests/support/CMakeLists.txt": "\n"}
status, out = check(clean)
if status != 0:
    failures.append(f"a clean tree failed: {out}")
cases = [
    ("src/lab/run/video.cpp", '#include "render/gl/renderer.hpp"\n',
     "src/lab/run/video.cpp:1: lab includes render"),
    ("src/core/f.cpp", '\n#include "lab/run.hpp"\n', "src/core/f.cpp:2: core includes lab"),
    ("src/lab/run/run.cpp", '#include "lab/studies/study.hpp"\n',
     "src/lab/run/run.cpp:1: lab/run includes lab/studies, a room its CMakeLists.txt does not "
     "link (fl_lab_studies)"),
    ("src/lab/run/CMakeLists.txt", "add_library(fl_lab_run STATIC run.cpp ../logs/log.cpp)\n"
                                   "target_link_libraries(fl_lab_run PUBLIC fl_lab_logs)\n",
     "src/lab/run/CMakeLists.txt:1: builds ../logs/log.cpp"),
    ("src/lab/logs/extra.cpp", "\n",
     "src/lab/logs/extra.cpp: built by no target of its own folder's CMakeLists.txt"),
    ("tests/sweep/CMakeLists.txt", "\n", "tests/sweep mirrors no folder of src/")]
for name, text, expected in cases:
    status, out = check({**clean, name: text})
    if status != 1 or expected not in out:
        failures.append(f"{name}: expected status 1 and '{expected}', got {status}: {out}")
for failure in failures:
    print(failure)
print(f"layers check: {len(cases) + 1 - len(failures)} of {len(cases) + 1} trees judged as expected")
sys.exit(1 if failures else 0)
