"""frictionlab.report: the lab report a student hands in, from a run's folder and a phone's
measurement: its marked numbers are the run's summary.json's, exactly; a measurement's T and mu_k
are estimate_file's; bad input is refused."""
import json
import pathlib
import re

import pytest

import frictionlab

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "assets" / "examples" / "instruments"
MINIMAL = pathlib.Path(__file__).resolve().parents[2] / "scenes" / "minimal.yaml"


def test_a_runs_report_holds_its_summarys_numbers(tmp_path):
    frictionlab.run(MINIMAL, out=tmp_path / "run", duration="5 s")
    said = frictionlab.report([tmp_path / "run"], out=tmp_path / "report.html",
                              student="Smith, J.", stopwatch=[(10, 7.9, 7.76)])
    assert said["written"] == str(tmp_path / "report.html")
    html = (tmp_path / "report.html").read_text()
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    marks = re.findall(r'data-field="([a-z_]+)" data-value="([^"]*)"', html)
    assert len(marks) >= 10
    for field, value in marks:
        assert json.loads(value) == summary[field], field
    assert said["parts"][0]["period_s"] == summary["period_s"]
    assert "Smith, J." in html and "Timed by hand" in html


def test_a_measurements_report_gives_estimate_files_numbers(tmp_path):
    phone = EXAMPLES / "phone-magnetometer.csv"
    said = frictionlab.report([phone], out=tmp_path / "report.html", material="lego")
    estimate = frictionlab.estimate_file(phone)
    assert said["parts"][0]["period_s"] == pytest.approx(estimate.period, rel=1e-12)
    assert said["parts"][0]["mu_k"] == pytest.approx(estimate.mu_k, rel=1e-12)
    assert "LEGO blocks, 300 K" in (tmp_path / "report.html").read_text()


def test_bad_input_is_refused(tmp_path):
    junk = tmp_path / "junk.csv"
    junk.write_text("hello\nworld\n")
    with pytest.raises(frictionlab.InputError):
        frictionlab.report([junk], out=tmp_path / "report.html")
    with pytest.raises(frictionlab.InputError):
        frictionlab.report([], out=tmp_path / "report.html")
    assert not (tmp_path / "report.html").exists()


def test_a_report_in_french(tmp_path):
    phone = EXAMPLES / "phone-magnetometer.csv"
    frictionlab.report([phone], out=tmp_path / "rapport.html", material="lego", language="fr")
    html = (tmp_path / "rapport.html").read_text()
    assert '<html lang="fr">' in html and "Compte rendu" in html
    with pytest.raises(frictionlab.InputError):
        frictionlab.report([phone], out=tmp_path / "x.html", language="xx")
