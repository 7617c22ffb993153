"""sweep: a sweep file's points run in parallel, as `frictionlab sweep` runs them, the rows
returned as columns."""

import csv
import math

import numpy as np
import pytest

import frictionlab as fl
from conftest import SCENES, cli_json

pytestmark = pytest.mark.slow

SWEEP = """format: 1
name: tiny
scene: {scene}
set:
  world.duration: 3 s
axes:
  - material: [lego, cardboard]
  - key: rollers.spacing
    values: [5 mm, 80 mm, 100 mm]
"""


@pytest.fixture(scope="module")
def sweeps(tmp_path_factory):
    folder = tmp_path_factory.mktemp("sweep")
    file = folder / "tiny.yaml"
    file.write_text(SWEEP.format(scene=SCENES / "minimal.yaml"))
    # Exit status 3: points without a result (the invalid ones).
    command = cli_json("sweep", file, "-j", "2", "--out", folder / "command", status=3)
    columns = fl.sweep(file, jobs=2, out=folder / "module")
    return folder, command, columns


def test_same_files_as_the_command(sweeps):
    folder, command, _ = sweeps
    assert command["complete"] and command["points"] == 6
    for name in ("results.csv", "sweep.json", "plan.json"):
        assert (folder / "module" / name).read_bytes() == (folder / "command" / name).read_bytes()


def test_columns_are_results_csv(sweeps):
    folder, _, columns = sweeps
    with open(folder / "command" / "results.csv", newline="") as f:
        header, *rows = list(csv.reader(f))
    assert list(columns) == header
    for c, name in enumerate(header):
        cells = [row[c] for row in rows]
        values = columns[name]
        if isinstance(values, list):  # text; an empty cell is no value
            assert values == [cell or None for cell in cells], name
            continue
        assert isinstance(values, np.ma.MaskedArray) and values.shape == (6,), name
        assert list(np.ma.getmaskarray(values)) == [cell == "" for cell in cells], name
        for value, cell in zip(values.tolist(), cells):  # masked entries come back as None
            if cell:
                assert value == float(cell), name  # the shortest text that reads back exactly
    # The axes' columns are each point's labels.
    assert columns["material"] == ["lego"] * 3 + ["cardboard"] * 3
    assert columns["rollers.spacing"] == ["5 mm", "80 mm", "100 mm"] * 2


def test_points_without_a_value_are_masked_not_zero(sweeps):
    _, _, columns = sweeps
    status = columns["status"]
    # 5 mm is narrower than the rollers: the loader refuses those points.
    assert status == ["invalid", "ok", "ok", "invalid", "ok", "ok"]
    period = columns["period_trajectory_s"]
    assert period.dtype == np.float64
    assert list(period.mask) == [True, False, False, True, False, False]
    assert all(math.isnan(v) for v in period.data[period.mask])  # never 0
    assert columns["index"].dtype == np.int64 and not columns["index"].mask.any()
    assert columns["error"][0] and columns["error"][1] is None
    # Wider rollers, longer period; lower mu_k (cardboard), longer period.
    assert period[2] > period[1] and period[4] > period[1]


def test_a_finished_sweep_is_not_run_again(sweeps):
    folder, _, columns = sweeps
    seen = []
    again = fl.sweep(folder / "tiny.yaml", out=folder / "module", progress=seen.append)
    assert all(p["resumed"] == 6 for p in seen)
    for name in columns:
        assert np.ma.allequal(again[name], columns[name]) if not isinstance(columns[name], list) \
            else again[name] == columns[name]


def test_progress_counts_invalid_points_apart_from_failed(sweeps):
    folder, _, _ = sweeps
    seen = []
    fl.sweep(folder / "tiny.yaml", jobs=2, out=folder / "progress", progress=seen.append)
    last = seen[-1]
    assert last["done"] == last["total"] == 6
    # The two 5 mm points: the scene refuses a spacing shorter than the rollers' diameter.
    assert last["invalid"] == 2 and last["failed"] == 0


def test_a_sweep_at_an_accuracy_is_the_commands(tmp_path):
    """accuracy= picks each point's step as `sweep --accuracy` does: the same files, each row with
    the step it took and what sized it."""
    file = tmp_path / "tiny.yaml"
    file.write_text(SWEEP.format(scene=SCENES / "minimal.yaml"))
    cli_json("sweep", file, "--accuracy", "0.01%", "--out", tmp_path / "command", status=3)
    columns = fl.sweep(file, accuracy="0.01%", out=tmp_path / "module")
    for name in ("results.csv", "sweep.json", "plan.json"):
        assert (tmp_path / "module" / name).read_bytes() == (tmp_path / "command" / name).read_bytes()
    ok = [i for i, s in enumerate(columns["status"]) if s == "ok"]
    assert ok and all(columns["time_step_basis"][i] == "integrator bias" for i in ok)
    for i in ok:  # each step 1/N s, its predicted bias within 90 % of the accuracy
        dt = float(columns["time_step_s"][i])
        omega = 2 * math.pi / float(columns["period_thick_s"][i])
        assert (omega * dt) ** 2 / 24 <= 0.9e-4
        assert abs(1 / dt - round(1 / dt)) < 1e-6
