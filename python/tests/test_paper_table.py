"""paper_table: the paper's Table I, as `frictionlab table` reads it."""

import frictionlab as fl
from conftest import cli_json


def test_table_equals_the_commands():
    expected = cli_json("table")
    table = fl.paper_table()
    assert table.source == expected["source"]
    assert table.spacing.value == expected["spacing_m"]
    assert table.spacing.uncertainty == expected["spacing_err_m"]
    rows = [(m, row) for m in table.materials for row in m.measurements]
    assert len(rows) == len(expected["rows"]) == 15
    for (material, row), want in zip(rows, expected["rows"]):
        assert material.key == want["material"] and material.name == want["name"]
        assert row.temperature == want["temperature_k"]
        assert row.period.value == want["period_s"]
        assert row.period.uncertainty == want["period_err_s"]
        assert row.mu_k.value == want["mu_k_paper"]
        assert row.mu_k.uncertainty == want["mu_k_paper_err"]
        if "literature" in want:
            assert [material.literature.low, material.literature.high] == want["literature"]


def test_find():
    table = fl.paper_table()
    assert table.find("lego").room.period.value == 0.79
    assert table.find("brass").cold is None and table.find("lego").cold.temperature == 77.0
    assert table.find("unobtainium") is None
