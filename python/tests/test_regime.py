"""frictionlab.Regime mirrors core/regime.hpp's Regime, value for value."""

import re

import frictionlab as fl
from conftest import SOURCE_DIR


def regimes_in_the_header():
    text = (SOURCE_DIR / "src" / "core" / "regime.hpp").read_text()
    body = re.search(r"enum class Regime \{(.*?)\};", text, re.S).group(1)
    return re.findall(r"^\s*k(\w+),", body, re.M)


def upper_snake(camel):
    return re.sub(r"(?<!^)(?=[A-Z])", "_", camel).upper()


def test_every_regime_of_the_header_in_its_order():
    names = [upper_snake(n) for n in regimes_in_the_header()]
    assert len(names) >= 10
    members = fl.Regime.__members__
    assert list(members) == names
    for value, name in enumerate(names):
        assert int(members[name]) == value


def test_labels_are_the_commands_names():
    for regime in fl.Regime.__members__.values():
        assert fl.Regime.from_label(regime.label) == regime
    assert fl.Regime.STICK_SLIP.label == "stick-slip"
    assert fl.Regime.NO_RESTORING_FORCE.label == "no restoring force"
    harmonic = {r for r in fl.Regime.__members__.values() if r.harmonic}
    assert harmonic == {fl.Regime.OSCILLATES, fl.Regime.CLIPPED, fl.Regime.GROWS,
                        fl.Regime.DECAYS}
