"""analytic: the analytic model, as `frictionlab analytic` computes it."""

import math

import pytest

import frictionlab as fl
from conftest import cli, cli_json

# The command's options and the module's arguments for the same set-ups.
CASES = {
    "mu_k": (["--mu-k", "0.29", "--h-c", "3.6mm"], {"mu_k": 0.29, "h_c": "3.6mm"}),
    "period": (["--period", "0.79s", "--period-err", "0.03s", "--h-c", "2.58mm"],
               {"period": "0.79s", "period_err": "0.03s", "h_c": "2.58mm"}),
    "material-77K": (["--material", "polished-wood", "--temperature", "77K"],
                     {"material": "polished-wood", "temperature": "77K"}),
    "stick-slip": (["--mu-k", "0.29", "--h-c", "2.58mm", "--roller-speed", "200rpm",
                    "--amplitude", "30mm", "--mu-s", "0.348"],
                   {"mu_k": 0.29, "h_c": "2.58mm", "roller_speed": "200rpm", "amplitude": "30mm",
                    "mu_s": 0.348}),
    "stribeck": (["--mu-k", "0.29", "--law", "stribeck", "--beta", "-0.01s/m"],
                 {"mu_k": 0.29, "law": "stribeck", "beta": "-0.01s/m"}),
    "no-restoring-force": (["--mu-k", "10", "--h-c", "30mm"], {"mu_k": 10, "h_c": "30mm"}),
    "si-numbers": (["--mu-k", "0.3", "--spacing", "0.1", "--h-c", "0.004", "--roller-speed", "100"],
                   {"mu_k": 0.3, "spacing": 0.1, "h_c": 0.004, "roller_speed": 100.0}),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_report_equals_the_commands_json(case):
    options, arguments = CASES[case]
    expected = cli_json("analytic", *options)
    report = fl.analytic(**arguments)
    assert report.json() == expected
    # The typed report holds the same numbers.
    assert report.period_thin == expected["period_thin_s"]
    assert report.period_thick == expected["period_thick_s"]
    assert report.mu_k == expected["mu_k"]
    assert report.restoring_force == expected["restoring_force"]
    assert report.tipping_amplitude == expected["tipping_amplitude_m"]
    assert report.slip_margin == expected["slip_margin"]
    if report.friction_law is not None:
        law = expected["friction_law"]
        assert report.friction_law.law.mu_s == law["mu_s"]
        assert report.friction_law.prediction.regime.label == law["regime"]
        cycle = report.friction_law.cycle
        assert (cycle is None) == (law["stick_slip_cycle"] is None)
        if cycle is not None:
            assert cycle.period == law["stick_slip_cycle"]["period_s"]
    if report.period_measured is not None:
        assert report.mu_k_thick.mu_k == expected["mu_k_thick"]


def test_the_thin_formula():
    # T = pi sqrt(2 l / (mu_k g)), independently.
    report = fl.analytic(mu_k=0.29, spacing=0.089, gravity=9.81)
    assert report.period_thin == pytest.approx(math.pi * math.sqrt(2 * 0.089 / (0.29 * 9.81)),
                                               rel=1e-15)
    assert report.period_thick == pytest.approx(report.period_thin, rel=1e-15)  # h_c = 0
    assert report.mu_k_thin is None and report.material is None  # made from mu_k


def test_bad_arguments_are_the_commands_errors():
    with pytest.raises(fl.InputError) as caught:
        fl.analytic(mu_k=0.29, spacing="89xx")
    expected = cli("analytic", "--mu-k", "0.29", "--spacing", "89xx", status=2).stderr.strip()
    assert str(caught.value) == expected.replace("--spacing", "spacing")
    with pytest.raises(fl.InputError, match="give exactly one of mu_k, period or material"):
        fl.analytic(mu_k=0.29, period="0.79s")
    with pytest.raises(fl.InputError, match="unknown material \"legoo\""):
        fl.analytic(material="legoo")
    with pytest.raises(fl.InputError, match="the paper measured Brass at 300 K only"):
        fl.analytic(material="brass", temperature="77K")
