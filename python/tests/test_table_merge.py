"""The paper's table and a sweep's shards joined, from Python as from the command: the same
request (lab/request), so the same JSON."""

import frictionlab as fl
from conftest import SCENES, cli, cli_json


def test_table_is_the_commands():
    assert fl.table(h_c="3.6mm") == cli_json("table", "--h-c", "3.6mm")
    assert fl.table() == cli_json("table")


def test_a_table_at_an_implausible_gravity_is_refused_as_the_command_refuses_it():
    err = cli("table", "--gravity", "981", status=2).stderr
    assert "gravity" in err
    try:
        fl.table(gravity=981)
    except fl.InputError as e:
        assert e.field == "gravity"
    else:
        raise AssertionError("g = 981 m/s^2 was taken")


def test_merge_joins_shards_as_the_command_does(tmp_path):
    sweep = SCENES / "sweeps" / "materials.yaml"
    for k in (1, 2):
        cli("sweep", sweep, "--shard", f"{k}/2", "--out", tmp_path / f"part{k}", "-j", "1")
    by_python = fl.merge([tmp_path / "part1", tmp_path / "part2"], out=tmp_path / "py")
    by_command = cli_json(
        "merge", tmp_path / "part1", tmp_path / "part2", "--out", tmp_path / "cli"
    )
    assert by_python["points"] == by_command["points"] == 15
    assert by_python["status"] == by_command["status"]
    assert (tmp_path / "py" / "results.csv").read_bytes() == (
        tmp_path / "cli" / "results.csv"
    ).read_bytes()
