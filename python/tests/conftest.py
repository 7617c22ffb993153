"""Shared by the module's tests: the source tree, the frictionlab command to hold the module
against, and a way to run it.

ctest sets FRICTIONLAB_SOURCE_DIR, FRICTIONLAB_CLI and PYTHONPATH (the build's module folder);
by hand: PYTHONPATH=build/release/python /usr/bin/python3 -m pytest python/tests
"""

import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(
    os.environ.get("FRICTIONLAB_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2])
)
CLI = pathlib.Path(
    os.environ.get("FRICTIONLAB_CLI", SOURCE_DIR / "build" / "release" / "src" / "cli" / "frictionlab")
)
SCENES = SOURCE_DIR / "scenes"

# What a run cost on this machine: in `run --json` beside the summary, never reproducible.
TIMING_KEYS = {"wall_s", "real_time_factor", "steps_per_second"}


def cli(*args, status=0):
    """Runs the frictionlab command; checks its exit status; returns the finished process."""
    done = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True)
    assert done.returncode == status, done.stderr
    return done


def cli_json(*args, status=0):
    """The object `frictionlab ... --json` prints."""
    return json.loads(cli(*args, "--json", status=status).stdout)


def pytest_configure(config):
    # ctest runs the fast set as python_module_test (-m "not slow") and the rest as
    # python_module_slow_test (-m slow), as the suite's labels split the C++ tests.
    config.addinivalue_line("markers", "slow: runs many or long simulations (ctest label slow)")


@pytest.fixture(scope="session", autouse=True)
def command_line_built():
    if not CLI.is_file():
        pytest.fail(f"the frictionlab command is not built at {CLI} (set FRICTIONLAB_CLI)")
