"""Input no rig gives, refused by the module as `frictionlab` refuses it (InputError, its field,
the command's words): a log of noise, values beyond any bench, an accuracy the step rule cannot
honour, an output that would replace an input, a line no log has; and logs once misread (a 16-bit
ADC's values, a clock slower than the samples), held to a synthetic log's known period."""

import math

import pytest

import frictionlab as fl
from conftest import SCENES, cli

SERIES = SCENES.parent / "assets" / "examples" / "student-series.csv"


def uniform(seed):
    """Numbers in [0, 1), the same on every platform (tests/cli/input_refusals_test.cpp's)."""
    x = seed
    while True:
        x = (x * 6364136223846793005 + 1442695040888963407) % 2**64
        yield (x >> 11) / 2**53


def pulses_adc(pulses, duration_s):
    """Gaussian pulses (300 counts, sigma 10 ms) at the given times on 512 counts, at 1 kHz."""
    adc = [512.0] * int(duration_s * 1000)
    for p in pulses:
        for i in range(max(0, int((p - 0.08) * 1000)), min(len(adc), int((p + 0.08) * 1000) + 1)):
            adc[i] += 300.0 * math.exp(-0.5 * ((i * 1e-3 - p) / 0.01) ** 2)
    return [float(round(v)) for v in adc]


def rig_field(t, period=0.79, amplitude=0.02, offset=0.003, height=0.008, phase=0.4):
    """The paper's rig's magnet at the sensor (tests/estimator/synthetic_hall.hpp's dipole)."""
    x = amplitude * math.cos(2 * math.pi * t / period + phase)
    dx = x - (amplitude + offset)
    r2 = dx * dx + height * height
    return (3 * height * height - r2) / r2**2.5 * height**3 / 2


def message(error):
    """The words after the location."""
    return str(error).split("error: ", 1)[1]


def test_a_log_of_noise_is_refused_with_what_was_found(tmp_path):
    u = uniform(2)
    adc = pulses_adc([30 * next(u) for _ in range(60)], 30.0)
    t = [i * 1e-3 for i in range(len(adc))]
    with pytest.raises(fl.InputError) as caught:
        fl.estimate(t, adc)
    assert "accepted and" in str(caught.value)
    assert "discarded: more discarded than accepted" in str(caught.value)
    assert "plot='FILE.png' shows the pulses" in str(caught.value)
    log = tmp_path / "noise.csv"
    log.write_text("t_us,adc\n" + "".join(f"{i * 1000},{int(v)}\n" for i, v in enumerate(adc)))
    with pytest.raises(fl.InputError) as from_file:
        fl.estimate_file(log)
    printed = cli("estimate", log, status=2).stderr.strip()
    assert message(from_file.value) == message(printed).replace("--plot FILE.png", "plot='FILE.png'")


def test_a_period_beyond_any_rig_is_refused():
    with pytest.raises(fl.InputError) as caught:
        fl.analytic(period="790")
    assert caught.value.field == "period"
    printed = cli("analytic", "--period", "790", status=2).stderr.strip()
    assert message(caught.value) == message(printed)
    assert "write 790ms for milliseconds" in str(caught.value)
    # A rig's period at 2 m, none at 89 mm: its mu_k is no rig's.
    with pytest.raises(fl.InputError, match="gives a mu_k no rig has") as slow:
        fl.analytic(period=30.0)
    assert slow.value.field == "period"
    assert fl.analytic(period=30.0, spacing="2 m").mu_k == pytest.approx(
        2 * math.pi**2 * 2.0 / (9.81 * 30.0**2))


def test_an_amplitude_beyond_any_rig_is_refused():
    with pytest.raises(fl.InputError, match="expected the amplitude A from 0 to 2000 mm") as caught:
        fl.analytic(mu_k=0.3, amplitude="1e308 mm")
    assert caught.value.field == "amplitude"


def test_a_series_in_milliseconds_is_refused_at_its_cell(tmp_path):
    series = tmp_path / "ms.csv"
    series.write_text("label,spacing,period,period_err\na,60mm,648,5\nb,70mm,702,5\n")
    with pytest.raises(fl.InputError) as caught:
        fl.fit(series)
    assert str(caught.value) == cli("fit", series, status=2).stderr.strip()
    assert str(caught.value).startswith(f"{series}:2:8: error: period: expected the period T")


def test_a_measured_period_beyond_any_rig_is_refused_before_any_run(tmp_path):
    measured = tmp_path / "measured.csv"
    measured.write_text("label,period,period_err\nlego,790,0.03 s\n")
    with pytest.raises(fl.InputError) as caught:
        fl.compare(measured=measured, out=tmp_path / "cmp")
    assert str(caught.value).startswith(f"{measured}:2:6: error: period: expected the period T")
    assert not (tmp_path / "cmp").exists()


def test_an_accuracy_beyond_ten_percent_is_refused():
    with pytest.raises(fl.InputError, match="expected a period accuracy above 0 and at most 10 %") \
            as caught:
        fl.run(SCENES / "minimal.yaml", accuracy="200%", record=False)
    assert caught.value.field == "accuracy"


def test_an_output_that_would_replace_an_input_is_refused(tmp_path):
    series = tmp_path / "S.csv"
    series.write_bytes(SERIES.read_bytes())
    with pytest.raises(fl.InputError, match="which is the series this command reads") as caught:
        fl.fit(series, plot=series)
    assert caught.value.field == "plot"
    folder = tmp_path / "D"
    folder.mkdir()
    (folder / "fit.csv").write_bytes(SERIES.read_bytes())
    with pytest.raises(fl.InputError, match="fit.csv would replace the series") as caught:
        fl.fit(folder / "fit.csv", out=folder)
    assert caught.value.field == "out"
    assert series.read_bytes() == (folder / "fit.csv").read_bytes() == SERIES.read_bytes()


def test_values_of_a_sixteen_bit_adc_give_the_period():
    t = [i * 1e-3 for i in range(20000)]
    for baseline in (30000.0, 40000.0):
        adc = [float(round(baseline + 25000.0 * rig_field(x))) for x in t]
        assert max(adc) > 45000
        assert fl.estimate(t, adc).period == pytest.approx(0.79, rel=5e-4)


def test_the_rate_advised_gives_the_logs_period(tmp_path):
    # 500 samples a second, their millisecond times rounded down to 4 ms.
    log = tmp_path / "ticks.csv"
    log.write_text("t_ms,adc\n" + "".join(
        f"{4 * (2 * i // 4)},{round(512 + 300 * rig_field(i * 2e-3))}\n" for i in range(10000)))
    with pytest.raises(fl.InputError, match=r"the log reads with rate='500Hz': T = 0\.7900 s"):
        fl.estimate_file(log)
    assert fl.estimate_file(log, rate="500Hz").period == pytest.approx(0.79, rel=5e-4)


def test_a_line_no_log_has_is_refused(tmp_path):
    log = tmp_path / "digits.txt"
    log.write_text("7" * 100000)
    with pytest.raises(fl.InputError) as caught:
        fl.estimate_file(log)
    assert str(caught.value) == (f"{log}:1: error: line 1 of the log runs past 8192 bytes without a "
                                 "line end: expected a text of lines (a log's are a few dozen "
                                 "bytes: a time and a value), found a line longer than any such "
                                 "text has (a file without line ends, a number of megabytes): is "
                                 "it the file meant?")
