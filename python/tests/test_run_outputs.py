"""run(..., out=DIR) writes what `frictionlab run --out DIR` writes, byte for byte."""

import pytest

import frictionlab as fl
from conftest import SCENES, cli

# What a run cost on this machine: written, never reproducible.
COST = {"timing.json"}


def same_files(a, b):
    names = sorted(p.name for p in a.iterdir())
    assert names == sorted(p.name for p in b.iterdir())
    for name in set(names) - COST:
        assert (a / name).read_bytes() == (b / name).read_bytes(), name
    return names


@pytest.mark.parametrize("file, overrides", [
    ("minimal.yaml", []),
    ("paper-rig.yaml", []),
    # The plate jumps: jumps.csv too.
    pytest.param("paper-rig.yaml", ["rollers.runout=1mm"], marks=pytest.mark.slow),
])
def test_out_writes_the_commands_files(tmp_path, file, overrides):
    args = [a for o in overrides for a in ("--set", o)]
    cli("run", SCENES / file, *args, "--out", tmp_path / "command")
    result = fl.run(fl.load_scene(SCENES / file, set=overrides), out=tmp_path / "module")
    names = same_files(tmp_path / "module", tmp_path / "command")
    assert {"summary.json", "timing.json", "trajectory.csv", "hall.csv", "cycles.csv"} <= set(names)
    # The arrays hold what the files hold.
    module = tmp_path / "module"
    assert len((module / "trajectory.csv").read_text().splitlines()) - 1 == len(result.trajectory)
    hall = (module / "hall.csv").read_text().splitlines()
    assert len(hall) - 1 == len(result.hall)
    last = hall[-1].split(",")
    assert int(last[0]) == result.hall["t_us"][-1] and int(last[1]) == result.hall["adc"][-1]
    assert len((module / "cycles.csv").read_text().splitlines()) - 1 == len(result.cycles)
    if "periods.csv" in names:
        assert len((module / "periods.csv").read_text().splitlines()) - 1 == len(result.periods)
    if "jumps.csv" in names:
        assert len((module / "jumps.csv").read_text().splitlines()) - 1 == len(result.jump_list)


def test_out_without_recording_still_writes_the_files(tmp_path):
    fl.run(SCENES / "minimal.yaml", duration="2s", out=tmp_path / "a", record=False)
    cli("run", SCENES / "minimal.yaml", "--duration", "2s", "--out", tmp_path / "b")
    same_files(tmp_path / "a", tmp_path / "b")
