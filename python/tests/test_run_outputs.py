"""run(..., out=DIR) writes what `frictionlab run --out DIR` writes, byte for byte."""

import pytest

import frictionlab as fl
from conftest import SCENES, cli

DETERMINISTIC = ["summary.json", "trajectory.csv", "hall.csv", "cycles.csv"]


@pytest.mark.parametrize("file", ["minimal.yaml", "paper-rig.yaml"])
def test_out_writes_the_commands_files(tmp_path, file):
    cli("run", SCENES / file, "--out", tmp_path / "command")
    result = fl.run(SCENES / file, out=tmp_path / "module")
    for name in DETERMINISTIC:
        assert (tmp_path / "module" / name).read_bytes() == (
            tmp_path / "command" / name
        ).read_bytes(), name
    assert (tmp_path / "module" / "timing.json").is_file()
    # The arrays hold what the files hold.
    rows = (tmp_path / "module" / "trajectory.csv").read_text().splitlines()
    assert len(rows) - 1 == len(result.trajectory)
    hall = (tmp_path / "module" / "hall.csv").read_text().splitlines()
    assert len(hall) - 1 == len(result.hall)
    last = hall[-1].split(",")
    assert int(last[0]) == result.hall["t_us"][-1] and int(last[1]) == result.hall["adc"][-1]


def test_out_without_recording_still_writes_the_files(tmp_path):
    fl.run(SCENES / "minimal.yaml", duration="2s", out=tmp_path / "a", record=False)
    cli("run", SCENES / "minimal.yaml", "--duration", "2s", "--out", tmp_path / "b")
    for name in DETERMINISTIC:
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes(), name
