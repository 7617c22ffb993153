"""estimate and estimate_file: the rig's estimator on a Hall signal, as `frictionlab estimate`
runs it."""

import numpy as np
import pytest

import frictionlab as fl
from conftest import SCENES, cli, cli_json


@pytest.fixture(scope="module")
def run_with_log(tmp_path_factory):
    out = tmp_path_factory.mktemp("run")
    return fl.run(SCENES / "minimal.yaml", out=out), out / "hall.csv"


def test_the_papers_value_for_the_material_as_the_command_gives_it(run_with_log):
    _, log = run_with_log
    expected = cli_json("estimate", log, "--material", "iron")
    found = fl.estimate_file(log, material="iron").json()
    assert found["paper"] == expected["paper"]
    assert found["paper"]["mu_k"] == 0.42
    assert fl.estimate_file(log).json()["paper"] is None


def test_a_log_file_reads_as_the_command_reads_it(run_with_log):
    _, log = run_with_log
    expected = cli_json("estimate", log)
    # What only the command draws: the plot and the Monte Carlo (--plot, --mc).
    assert expected.pop("plot") is None
    assert expected.pop("monte_carlo") is None
    found = fl.estimate_file(log)
    assert found.json() == expected
    assert found.period == expected["period_s"] and found.mu_k == expected["mu_k"]
    assert found.period_std == expected["period_std_s"]
    assert found.period_std_error == expected["period_sem_s"]
    assert found.mu_k_err_worst == expected["mu_k_err_worst"]
    assert found.periods_used == expected["periods_used"]
    assert found.geometry == expected["geometry"]
    assert found.duration == expected["duration_s"]
    np.testing.assert_array_equal(found.periods["period_s"],
                                  [p["period_s"] for p in expected["periods"]])
    statuses = {"accepted": 0, "outlier": 1, "broken": 2}
    np.testing.assert_array_equal(found.periods["status"],
                                  [statuses[p["status"]] for p in expected["periods"]])


def test_arrays_give_what_the_run_itself_measured(run_with_log):
    result, log = run_with_log
    hall = result.hall
    found = fl.estimate(hall["t_us"] * 1e-6, hall["adc"])
    # The run fed the same samples to the same estimator.
    assert found.period == result.estimator.period
    assert found.periods_used == result.estimator.periods_used
    assert found.mu_k == result.estimator.mu_k
    assert found.mu_k_err_worst == result.estimator.mu_k_err_worst
    # ... and the file of them reads the same.
    from_file = fl.estimate_file(log).json()
    from_arrays = found.json()
    # (How each was read differs: a file's header, encoding and lines; the arrays' none.)
    for key in ("log", "format", "time_column", "adc_column", "file", "encoding", "columns_from",
                "time_unit", "time_unit_from", "header_line"):
        del from_file[key], from_arrays[key]
    assert from_arrays == from_file


def test_spacing_and_gravity_carry_into_mu_k(run_with_log):
    result, _ = run_with_log
    t, adc = result.hall["t_us"] * 1e-6, result.hall["adc"]
    base = fl.estimate(t, adc)
    other = fl.estimate(t, adc, spacing="100mm", gravity=9.80)
    assert other.period == base.period
    # mu_k = 2 pi^2 l / (g T^2), in the estimator's single precision.
    assert other.mu_k == pytest.approx(base.mu_k * (0.100 / 0.089) * (9.81 / 9.80), rel=1e-6)
    assert fl.estimate(t, adc, spacing=0.1, gravity="9.8 m/s^2").mu_k == other.mu_k


def test_a_signal_without_periods_raises_the_commands_error(tmp_path):
    flat = tmp_path / "flat.csv"
    flat.write_text("t_s,adc\n0,500\n0.001,500\n0.002,500\n")
    with pytest.raises(fl.InputError) as caught:
        fl.estimate_file(flat)
    assert str(caught.value) == cli("estimate", flat, status=2).stderr.strip()
    # From arrays: the sample's index stands for the line.
    with pytest.raises(fl.InputError, match=r"^samples:1: error: no pulse in 3 samples"):
        fl.estimate([0.0, 0.001, 0.002], [500, 500, 500])


def test_bad_samples_are_located():
    with pytest.raises(fl.InputError, match=r"^samples:3: error: sample 3: time 0.001 s is not after"):
        fl.estimate([0.0, 0.001, 0.001], [500, 500, 500])
    with pytest.raises(fl.InputError, match=r"^log:2: error: sample 2: expected an ADC value from 0 to 65535"):
        fl.estimate([0.0, 0.001], [500, 70000], name="log")
    with pytest.raises(fl.InputError, match="as many ADC values as times"):
        fl.estimate([0.0, 0.001], [500])
    with pytest.raises(fl.InputError, match="geometry='three': error: expected auto, one or pair"):
        fl.estimate([0.0, 0.001], [500, 500], geometry="three")
    with pytest.raises(fl.InputError, match="spacing: error: expected the roller spacing as a finite positive length"):
        fl.estimate([0.0, 0.001], [500, 500], spacing=-1)


INSTRUMENTS = SCENES.parent / "assets" / "examples" / "instruments"


# The files are the paper's rig simulated at mu_k 0.29 (assets/examples/make-instrument-examples):
# its plate's centre of mass 3.58 mm above the rollers' contact line, 14.29 mm with the 180 g phone
# lying on its bricks (each run's summary says so).
@pytest.mark.parametrize("name,h_c", [("phone-magnetometer.csv", "3.58mm"),
                                      ("phone-accelerometer.csv", "14.29mm"),
                                      ("tracker-plate.txt", "3.58mm")])
def test_another_instrument_reads_as_the_command_reads_it(name, h_c):
    path = INSTRUMENTS / name
    expected = cli_json("estimate", path, "--h-c", h_c)
    assert expected.pop("plot") is None
    assert expected.pop("monte_carlo") is None
    found = fl.estimate_file(path, h_c=h_c.replace("mm", " mm"))
    assert found.json() == expected
    assert found.instrument == expected["instrument"] != "Hall sensor"
    assert found.channel == expected["channel"]
    assert found.baseline is None
    # The thick formula with that h_c gives mu_k back, within what the periods' standard error
    # allows (d mu / mu = 2 dT / T, three of them); the paper's thin one cannot.
    allowed = 3 * 2 * found.period_std_error / found.period * 0.29
    assert abs(found.mu_k_thick - 0.29) < allowed
    assert abs(found.mu_k - 0.29) > allowed
