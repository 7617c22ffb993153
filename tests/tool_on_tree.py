"""Runs one of the repository's checks (tools/check-*) on a small tree written for the purpose:
the shared piece of the checks' own tests (layers_check_test.py, function_length_test.py)."""

import pathlib
import subprocess
import sys
import tempfile


def run_on_tree(tool, files):
    """The tool's exit status and output on a tree holding `files` ({path: text}), removed after."""
    with tempfile.TemporaryDirectory(prefix="tool-tree-") as folder:
        root = pathlib.Path(folder)
        for name, text in files.items():
            path = root / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
        done = subprocess.run([sys.executable, str(tool), str(root)], capture_output=True,
                              text=True, check=False)
    return done.returncode, done.stdout
