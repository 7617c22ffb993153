"""Ctrl-C in the module's long calls: run, compare, accuracy and stability stop as the command
does (nothing more started, what was finished kept and written) and raise KeyboardInterrupt.
Each job here takes far longer than the second after which the signal comes."""

import csv
import os
import signal
import threading

import pytest

import frictionlab as fl
from conftest import SCENES


def interrupt_after(seconds, call):
    """Calls `call` with a SIGINT to this process `seconds` after the start; expects it to raise
    KeyboardInterrupt."""
    timer = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
    finally:
        timer.cancel()
        timer.join()


def test_run_stops_writes_its_files_and_raises(tmp_path):
    interrupt_after(1.0, lambda: fl.run(SCENES / "minimal.yaml", duration="5000s", out=tmp_path))
    summary = (tmp_path / "summary.json").read_text()
    assert '"interrupted_at_s"' in summary


def test_accuracy_keeps_its_finished_points_and_raises(tmp_path):
    interrupt_after(1.0, lambda: fl.accuracy(SCENES / "minimal.yaml", periods=1000, out=tmp_path))
    with open(tmp_path / "accuracy.csv") as f:
        points = list(csv.DictReader(f))
    assert len(points) < 28
    assert all(p["valid"] == "1" for p in points)


def test_compare_keeps_the_rows_done_and_raises(tmp_path):
    interrupt_after(1.0, lambda: fl.compare(duration="60s", jobs=1, out=tmp_path))
    with open(tmp_path / "compare.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 15
    assert rows[-1]["status"] == "interrupted"


def test_stability_raises(tmp_path):
    catalogue = tmp_path / "catalogue"
    catalogue.mkdir()
    scene = (SCENES / "extreme" / "stribeck-drop.yaml").read_text()
    for i in range(20):
        (catalogue / f"case-{i}.yaml").write_text(scene)
    interrupt_after(1.0, lambda: fl.stability(dir=catalogue, jobs=1, out=tmp_path / "out"))
