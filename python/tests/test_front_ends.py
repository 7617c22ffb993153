"""The command and the module are two spellings of the same requests (lab/request): the same
request gives the same files, the same numbers, the same error (the field it is about and the
message) and the same ending (exit status 2 is InputError, 3 a summary that failed)."""

import json
import shutil

import pytest

import frictionlab as fl
from conftest import SCENES, TIMING_KEYS, cli

LOGS = SCENES.parent / "tests" / "data" / "logs"


def message(text):
    """A located diagnostic without its location: the text after "error: "."""
    return text.strip().split("error: ", 1)[1]


def located_field(text):
    """The location before ": error: " on the command line."""
    return text.strip().split(": error: ", 1)[0]


@pytest.mark.parametrize("scene", ["minimal.yaml", "paper-rig.yaml"])
def test_a_run_writes_the_same_bytes(tmp_path, scene):
    cli("run", SCENES / scene, "--duration", "3s", "--out", tmp_path / "cli")
    fl.run(SCENES / scene, duration="3s", out=tmp_path / "py", record=False)
    for name in ["summary.json", "trajectory.csv", "hall.csv", "periods.csv", "cycles.csv"]:
        cli_file, py_file = tmp_path / "cli" / name, tmp_path / "py" / name
        assert cli_file.exists() == py_file.exists(), name
        if cli_file.exists():
            assert cli_file.read_bytes() == py_file.read_bytes(), name


def test_a_run_prints_the_same_summary():
    printed = json.loads(cli("run", SCENES / "minimal.yaml", "--duration", "2s", "--json").stdout)
    returned = fl.run(SCENES / "minimal.yaml", duration="2s", record=False).json()
    for key in TIMING_KEYS:
        printed.pop(key), returned.pop(key)
    assert printed == returned


# Bad requests, as each front end spells them: the command's options, the module's arguments,
# the field both name, and how each spells a field its message mentions (None: none).
BAD_RUNS = [
    (["--size", "640x480"], {"size": "640x480"}, "size", ("--video", "video")),
    (["--fps", "10"], {"fps": 10}, "fps", ("--still", "still")),
    (["--accuracy", "0.01%", "--set", "world.time_step=2ms"],
     {"accuracy": "0.01%", "set": ["world.time_step=2ms"]}, "accuracy",
     ("--set world.time_step=2ms", "set={'world.time_step': '2ms'}")),
    (["--duration", "5kg"], {"duration": "5kg"}, "duration", None),
    (["--plot"], {"plot": True}, "plot", ("--out", "out")),
    (["--video", "clip.avi"], {"video": "clip.avi"}, "video", None),
]


@pytest.mark.parametrize("options,arguments,field,mention", BAD_RUNS,
                         ids=[b[2] for b in BAD_RUNS])
def test_a_bad_run_is_the_same_error(options, arguments, field, mention):
    done = cli("run", SCENES / "minimal.yaml", *options, status=2)
    arguments = dict(arguments)
    scene = fl.load_scene(SCENES / "minimal.yaml", set=arguments.pop("set", None))
    with pytest.raises(fl.InputError) as caught:
        fl.run(scene, record=False, **arguments)
    assert caught.value.field == field
    assert located_field(done.stderr).startswith("--" + field.replace("_", "-"))
    assert located_field(str(caught.value)).startswith(field)
    printed, raised = message(done.stderr), message(str(caught.value))
    if mention:
        assert mention[0] in printed and mention[1] in raised
        printed, raised = printed.replace(mention[0], "FIELD"), raised.replace(mention[1], "FIELD")
    # The same words, each front end's spelling of the fields inside them aside.
    assert raised == printed.replace("--", "")


def test_an_output_that_cannot_be_written_is_bad_input_in_both(tmp_path):
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    done = cli("run", SCENES / "minimal.yaml", "--out", blocker, status=2)
    with pytest.raises(fl.InputError) as caught:
        fl.run(SCENES / "minimal.yaml", out=blocker, record=False)
    assert caught.value.field == "out"
    assert message(done.stderr) == message(str(caught.value))


def test_a_run_a_guard_stopped_fails_in_both():
    done = cli("run", SCENES / "extreme" / "rollers-outward.yaml", "--json", status=3)
    result = fl.run(SCENES / "extreme" / "rollers-outward.yaml", record=False)
    assert result.failure is not None
    assert json.loads(done.stdout)["failure"] == result.failure


def test_a_logs_sidecar_sets_the_rig_in_both(tmp_path):
    log = tmp_path / "lego-l075.csv"
    shutil.copy(LOGS / "clean.csv", log)
    (tmp_path / "lego-l075.yaml").write_text("spacing: 75 mm\n")
    printed = json.loads(cli("estimate", log, "--json").stdout)
    returned = fl.estimate_file(log)
    assert printed["spacing_m"] == pytest.approx(0.075)
    assert returned.spacing == pytest.approx(0.075)
    assert returned.mu_k == pytest.approx(printed["mu_k"])


SERIES = SCENES.parent / "assets" / "examples" / "student-series.csv"


def test_a_fit_is_the_commands_fit(tmp_path):
    printed = json.loads(cli("fit", SERIES, "--mc", "2000", "--json").stdout)
    returned = fl.fit(SERIES, mc=2000)
    printed.pop("plot")
    assert returned.json() == printed
    assert returned.mu_k == printed["mu_k"] and returned.h_c == printed["h_c_m"]
    cli("fit", SERIES, "--out", tmp_path / "cli")
    fl.fit(SERIES, out=tmp_path / "py")
    for name in ["fit.json", "fit.csv"]:
        assert (tmp_path / "cli" / name).read_bytes() == (tmp_path / "py" / name).read_bytes()
    assert returned.paper is None
    printed = json.loads(cli("fit", SERIES, "--material", "lego", "--json").stdout)
    returned = fl.fit(SERIES, material="lego")
    assert returned.paper == printed["paper"] == returned.json()["paper"]
    assert printed["paper"]["key"] == "lego"


def test_a_bad_fit_is_the_same_error():
    done = cli("fit", SERIES, "--mc", "0", status=2)
    with pytest.raises(fl.InputError) as caught:
        fl.fit(SERIES, mc=0)
    assert caught.value.field == "monte_carlo.draws"
    assert located_field(done.stderr) == "--mc 0"
    assert located_field(str(caught.value)) == "mc='0'"
    done = cli("fit", SERIES, "--scene", SCENES / "minimal.yaml", status=2)
    with pytest.raises(fl.InputError) as caught:
        fl.fit(SERIES, scene=SCENES / "minimal.yaml")
    assert caught.value.field == "scene"
    assert "--through-rig" in done.stderr and "through_rig" in str(caught.value)


def test_an_analytic_report_is_the_commands():
    printed = json.loads(cli("analytic", "--period", "0.79s", "--period-err", "0.03s",
                             "--h-c", "3mm", "--json").stdout)
    assert fl.analytic(period="0.79s", period_err="0.03s", h_c="3mm").json() == printed
    # The defaults are the request's, the same in both: the paper's rig.
    assert fl.analytic(mu_k=0.29).json() == json.loads(cli("analytic", "--mu-k", "0.29",
                                                           "--json").stdout)


@pytest.mark.parametrize("options,arguments,field", [
    (["--mu-k", "0.3", "--mu-s", "0.2"], {"mu_k": 0.3, "mu_s": 0.2}, "mu_s"),
    (["--mu-k", "0.3", "--period-err", "0.01s"], {"mu_k": 0.3, "period_err": "0.01s"},
     "period_err"),
    (["--mu-k", "0.3", "--temperature", "77K"], {"mu_k": 0.3, "temperature": "77K"},
     "temperature"),
    (["--material", "plexiglass"], {"material": "plexiglass"}, "material"),
])
def test_a_bad_analytic_request_is_the_same_error(options, arguments, field):
    done = cli("analytic", *options, status=2)
    with pytest.raises(fl.InputError) as caught:
        fl.analytic(**arguments)
    assert caught.value.field == field
    assert located_field(done.stderr).startswith("--" + field.replace("_", "-"))
    assert located_field(str(caught.value)).startswith(field)


def test_a_log_read_by_its_fields_is_the_commands_estimate():
    log = LOGS / "no-time-column.csv"
    printed = json.loads(cli("estimate", log, "--rate", "500Hz", "--json").stdout)
    returned = fl.estimate_file(log, rate="500Hz").json()
    printed.pop("plot"), printed.pop("monte_carlo")
    assert returned == printed
    # Without the rate, both ask for it, each in its own spelling.
    done = cli("estimate", log, status=2)
    with pytest.raises(fl.InputError) as caught:
        fl.estimate_file(log)
    assert "--rate 1kHz" in done.stderr and "rate='1kHz'" in str(caught.value)


def test_fit_reads_a_sweeps_own_results(tmp_path):
    # Three spacings of minimal.yaml (mu_k 0.29, h_c 2.58 mm): the fit of the sweep's own
    # results.csv finds the scene's mu_k and h_c, from either front end.
    sweep = tmp_path / "spacing.yaml"
    sweep.write_text(f"format: 1\nname: three\nscene: {SCENES / 'minimal.yaml'}\n"
                     "set:\n  world.duration: 6 s\n"
                     "axes:\n  - key: rollers.spacing\n    values: [80 mm, 89 mm, 100 mm]\n")
    fl.sweep(sweep, out=tmp_path / "out")
    results = tmp_path / "out" / "results.csv"
    printed = json.loads(cli("fit", results, "--json").stdout)
    returned = fl.fit(results)
    printed.pop("plot")
    assert returned.json() == printed
    assert returned.mu_k == pytest.approx(0.29, abs=3 * returned.mu_k_err)
    assert returned.mu_k == pytest.approx(0.29, rel=5e-3)
    assert returned.h_c == pytest.approx(2.58e-3, abs=3 * returned.h_c_err)


def test_a_sweep_that_varies_more_than_the_spacing_is_no_series(tmp_path):
    results = tmp_path / "results.csv"
    results.write_text("index,plate.material,rollers.spacing,seed,status,spacing_m,period_s,"
                       "period_std_error_s\n0,lego,80 mm,1,ok,0.08,0.74,0.0001\n")
    done = cli("fit", results, status=2)
    assert "varies plate.material besides the roller spacing" in done.stderr


def test_every_mu_k_from_a_measured_period_carries_dl(tmp_path):
    # compare --log refits mu_k from the log's period on the rig's l +- dl (the estimate's
    # default dl, the paper's 2 mm): its uncertainty is at least dl / l (mu_k ~ l for the thin
    # formula, about so for the thick), not the period's 0.007 % alone.
    done = json.loads(cli("compare", "--log", LOGS / "clean.csv", "--out", tmp_path,
                          "--json").stdout)
    assert done["spacing_err_m"] == pytest.approx(0.002)
    dl_over_l = done["spacing_err_m"] / done["spacing_m"]
    assert done["mu_k_refit_err_quadrature"] / done["mu_k_refit"] >= 0.95 * dl_over_l


def test_a_bad_sweep_request_is_bad_input_in_both(tmp_path):
    sweep = SCENES / "sweeps" / "spacing.yaml"
    with pytest.raises(fl.InputError) as caught:
        fl.sweep(sweep, jobs=0, out=tmp_path)
    assert caught.value.field == "jobs"
    done = cli("sweep", sweep, "--shard", "4/3", "--out", tmp_path, status=2)
    with pytest.raises(fl.InputError) as caught:
        fl.sweep(sweep, shard="4/3", out=tmp_path)
    assert caught.value.field == "shard"
    assert message(done.stderr) == message(str(caught.value))
    assert located_field(done.stderr) == "--shard 4/3"
    assert located_field(str(caught.value)) == "shard='4/3'"


def test_a_comparison_and_the_studies_are_the_commands(tmp_path):
    # compare --log and stability --only are quick; accuracy at its fewest periods.
    printed = json.loads(cli("compare", "--log", LOGS / "clean.csv", "--out", tmp_path / "c",
                             "--json").stdout)
    returned = fl.compare(log=LOGS / "clean.csv", out=tmp_path / "p")
    assert returned["mu_k_refit"] == printed["mu_k_refit"]
    assert returned["period_measured_s"] == printed["period_measured_s"]
    assert returned["paper"] is printed["paper"] is None
    printed = json.loads(cli("compare", "--log", LOGS / "clean.csv", "--material", "iron",
                             "--out", tmp_path / "c", "--json").stdout)
    returned = fl.compare(log=LOGS / "clean.csv", material="iron", out=tmp_path / "p")
    assert returned["paper"] == printed["paper"] and printed["paper"]["key"] == "iron"
    printed = json.loads(cli("stability", "--only", "mu-1", "--json").stdout)
    returned = fl.stability(only="mu-1")
    assert [c["found"] for c in returned["cases"]] == [c["found"] for c in printed["cases"]]
    assert returned["unexpected"] == printed["unexpected"] == 0
    with pytest.raises(fl.InputError) as caught:
        fl.accuracy(SCENES / "minimal.yaml", periods=2, out=tmp_path / "a")
    assert caught.value.field == "periods"
    done = cli("accuracy", SCENES / "minimal.yaml", "--periods", "2", "--out", tmp_path / "a",
               status=2)
    assert message(done.stderr) == message(str(caught.value))
