"""A run from Python gives what `frictionlab run --json` gives for the same scene and seed: every
field of the typed summary against the command's JSON, floats exactly."""

import functools
import json
import math

import pytest

import frictionlab as fl
from conftest import SCENES, TIMING_KEYS, cli, cli_json


def number(value):
    # JSON holds no infinity or NaN: the command writes null for them.
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def relative(value, reference):
    return None if value is None or reference is None else value / reference - 1.0


def label(regime):
    return None if regime is None else regime.label


def window_keys(w):
    return None if w is None else {"periods": w.periods, "period_s": w.period, "mu_k": w.mu_k}


def warming_keys(w):
    if w is None:
        return None
    return {
        "start_temperature_k": w.start_temperature,
        "room_temperature_k": w.room_temperature,
        "time_constant_s": w.time_constant,
        "hold_s": w.hold,
        "mu_k_start": w.mu_k_start,
        "mu_k_room": w.mu_k_room,
        "end_temperature_k": w.end_temperature,
        "mu_k_end": w.mu_k_end,
        "mu_k_cold_paper_formula": w.mu_k_cold_paper_formula,
        "first_10_periods": window_keys(w.first_10_periods),
        "first_30_s": window_keys(w.first_30_s),
        "whole_run": window_keys(w.whole_run),
    }


def summary_keys(r):
    """The typed summary under the keys of summary.json (docs/cli.md)."""
    e = r.estimator
    d = r.drive
    keys = {
        "scene": r.scene,
        "seed": r.seed,
        "regime": r.regime.label,
        "regime_since_s": r.regime_since,
        "regime_evidence": r.regime_evidence,
        "period_withheld": r.period_withheld,
        "failure": r.failure,
        "estimator_disagreement": r.estimator_disagreement,
        "condition_period": r.condition_period,
        "condition_spacing": r.condition_spacing,
        "condition_h_c": r.condition_h_c,
        "period_s": r.period,
        "period_std_s": e.period_std if e else None,
        "period_std_error_s": e.period_std_error if e else None,
        "periods_used": e.periods_used if e else None,
        "periods_discarded": e.periods_discarded if e else None,
        "period_trajectory_s": r.period_trajectory,
        "period_trajectory_err_s": r.period_trajectory_err,
        "oscillation_centre_m": r.oscillation_centre,
        "oscillation_centre_theory_m": r.oscillation_centre_theory,
        "drift_speed_m_s": r.drift_speed,
        "drift_speed_theory_m_s": r.drift_speed_theory,
        "tilt_rad": r.tilt,
        "period_thin_s": r.period_thin,
        "period_thick_s": r.period_thick,
        "error_vs_thin": relative(r.period, r.period_thin),
        "error_vs_thick": relative(r.period, r.period_thick),
        "trajectory_error_vs_thick": relative(r.period_trajectory, r.period_thick),
        "mu_k_set": r.mu_k_set,
        "mu_k_recovered": r.mu_k_recovered,
        "mu_k_recovered_thick": r.mu_k_recovered_thick,
        "mu_k_source": None
        if r.mu_k_source in (None, fl.PeriodSource.HALL_ESTIMATOR)
        else "trajectory: the scene has no sensor"
        if e is None
        else "trajectory: the rig's estimator accepted no period",
        "interrupted_at_s": r.interrupted_at,
        "mu_k_estimator": r.mu_k_estimator,
        "mu_k_err_worst": r.mu_k_err_worst,
        "mu_k_err_quadrature": r.mu_k_err_quadrature,
        "predicted_integrator_bias": r.predicted_integrator_bias,
        "sensor_clock_error": r.clock_error,
        "runout_m": r.runout,
        "runout_threshold_m": r.runout_threshold,
        "warming": warming_keys(r.warming),
        "clock_mu_k_bias": None if r.clock_error is None else (1 + r.clock_error) ** -2 - 1,
        "spacing_m": r.spacing,
        "h_c_m": r.h_c,
        "plate_mass_kg": r.plate_mass,
        "roller_speed_rad_s": r.roller_speed,
        "roller_speed_1_rad_s": r.roller_speed_1,
        "drive": None
        if d is None
        else {
            "motor_speed_rad_s": d.motor_speed,
            "motor_torque_n_m": d.motor_torque,
            "roller_speeds_rad_s": list(d.roller_speeds),
            "gearbox_ratio": d.gearbox_ratio,
            "turning_fraction": d.turning_fraction,
            "speed_ratio": d.speed_ratio,
            "speed_ratio_error": d.speed_ratio_error,
            "senses_opposite": d.senses_opposite,
            "load_torque_n_m": d.load_torque,
        },
        "plate_speed_max_m_s": r.plate_speed_max,
        "slip_margin": r.slip_margin,
        "amplitude_start_m": r.amplitude_start,
        "amplitude_end_m": r.amplitude_end,
        "amplitude_drift_per_period": r.amplitude_drift_per_period,
        "clip_time_s": r.clip_time,
        "amplitude_before_clip_m": r.amplitude_before_clip,
        "amplitude_clipped_m": r.amplitude_clipped,
        "stick_slip_period_s": r.stick_slip_period,
        "stick_slip_amplitude_m": r.stick_slip_amplitude,
        "stick_duration_s": r.stick_duration,
        "growth_rate_per_s": r.growth_rate,
        "e_folding_time_s": r.e_folding_time,
        "jumps": r.jumps,
        "first_jump_time_s": r.first_jump_time,
        "longest_jump_s": r.longest_jump,
        "highest_jump_m": r.highest_jump,
        "regime_theory": label(r.regime_theory),
        "amplitude_clipped_theory_m": r.amplitude_clipped_theory,
        "stick_slip_period_theory_s": r.stick_slip_period_theory,
        "stick_slip_amplitude_theory_m": r.stick_slip_amplitude_theory,
        "stick_duration_theory_s": r.stick_duration_theory,
        "growth_rate_theory_per_s": r.growth_rate_theory,
        "paper": None
        if r.paper_period is None
        else {
            "material": r.paper_material,
            "period_s": r.paper_period.value,
            "period_err_s": r.paper_period.uncertainty,
            "mu_k": r.paper_mu_k.value,
            "mu_k_err": r.paper_mu_k.uncertainty,
        },
        "min_normal_force_n": r.min_normal_force,
        "max_penetration_m": r.max_penetration,
        "time_step_s": r.time_step,
        "solver_iterations": r.solver_iterations,
        "solver_iterations_raised": r.solver_iterations_raised,
        "duration_s": r.duration,
        "steps": r.steps,
    }
    return {k: number(v) for k, v in keys.items()}



# (scene, overrides, seed): the harmonic oscillation, the whole rig with its drive and the
# paper's material, a clipped cycle, a stick-slip cycle, a growing amplitude.
CASES = {
    "minimal": ("minimal.yaml", {}, None),
    "minimal-seed-3": ("minimal.yaml", {"friction.mu_k": 0.35}, 3),
    "paper-rig-seed-7": ("paper-rig.yaml", {}, 7),
    "clipped": ("minimal.yaml", {"rollers.speed": "200rpm", "plate.offset": "30mm"}, None),
    "stick-slip": (
        "minimal.yaml",
        {"friction.mu_s": 0.348, "rollers.speed": "200rpm", "plate.offset": "30mm"},
        None,
    ),
    "grows": ("minimal.yaml", {"friction.law": "stribeck", "friction.beta": "-0.01s/m"}, None),
    "runout-jumps": ("paper-rig.yaml", {"rollers.runout": "0.3mm"}, None),
    # Jumps so violent that the estimator accepts no period.
    "runout-no-period": ("paper-rig.yaml", {"rollers.runout": "1mm"}, None),
    "warming": ("paper-rig-77K-warming.yaml", {"world.duration": "40s"}, None),
}


@functools.lru_cache(maxsize=None)
def case_runs(case):
    """The command's JSON (without its cost) and the module's result for a case, run once."""
    file, overrides, seed = CASES[case]
    args = ["run", SCENES / file]
    for key, value in overrides.items():
        args += ["--set", f"{key}={value}"]
    if seed is not None:
        args += ["--set", f"world.seed={seed}"]
    expected = {k: v for k, v in cli_json(*args).items() if k not in TIMING_KEYS}
    return expected, fl.run(fl.load_scene(SCENES / file, set=overrides), seed=seed)


# The regimes beyond the plain oscillation, run-out and warming: the slow set.
FAST_CASES = {"minimal", "minimal-seed-3", "paper-rig-seed-7"}


@pytest.mark.parametrize(
    "case", [c if c in FAST_CASES else pytest.param(c, marks=pytest.mark.slow) for c in sorted(CASES)])
def test_summary_equals_the_commands_json(case):
    expected, result = case_runs(case)
    found = summary_keys(result)
    unmapped = set(expected) - set(found)
    assert not unmapped, f"summary.json keys the typed summary does not give: {unmapped}"
    for key in sorted(found):
        assert found[key] == expected.get(key), key
    if case == "runout-no-period":
        # Neither gives a number the run did not measure.
        assert result.estimator.periods_used == 0 and expected.get("mu_k_estimator") is None
        assert expected["mu_k_source"] == "trajectory: the rig's estimator accepted no period"
    # And the module's own JSON is the command's, key for key.
    assert {k: v for k, v in result.json().items() if k not in TIMING_KEYS} == expected
    assert set(result.json()) - set(expected) == TIMING_KEYS


@pytest.mark.slow
def test_the_cases_show_their_regimes():
    regimes = {case: case_runs(case)[1].regime for case in CASES}
    assert regimes["clipped"] == fl.Regime.CLIPPED
    assert regimes["stick-slip"] == fl.Regime.STICK_SLIP
    assert regimes["grows"] == fl.Regime.GROWS
    assert regimes["paper-rig-seed-7"] == fl.Regime.OSCILLATES
    # ... and the run-out and warming cases have the numbers they are there for.
    jumping = case_runs("runout-jumps")[1]
    assert jumping.jumps > 0 and jumping.highest_jump > 0
    assert len(jumping.jump_list) >= jumping.jumps
    assert jumping.jump_list["height_m"].max() == jumping.highest_jump
    warming = case_runs("warming")[1]
    assert warming.warming.start_temperature == 77.0
    assert warming.warming.mu_k_start < warming.warming.mu_k_end < warming.warming.mu_k_room


def test_values_the_run_did_not_measure_are_none():
    # 2 s: the estimator sees a single pulse and accepts no period (the command's JSON says null
    # for the estimator's mu_k and spreads there, as the module says None).
    r = fl.run(SCENES / "minimal.yaml", duration="2s")
    assert r.regime == fl.Regime.OSCILLATES
    assert r.estimator.periods_used == 0
    assert r.period is None and r.period_withheld
    for value in (r.estimator.period, r.estimator.period_std, r.estimator.mu_k,
                  r.estimator.mu_k_err_worst, r.mu_k_estimator, r.mu_k_err_worst,
                  r.mu_k_err_quadrature):
        assert value is None
    # mu_k then comes from the trajectory's own period.
    assert r.mu_k_source == fl.PeriodSource.TRAJECTORY and r.mu_k_recovered is not None
    # A scene without a drive, a clock error, jumps or the paper's material.
    q = fl.run(SCENES / "minimal.yaml", duration="2s", record=False)
    assert q.drive is None and q.clock_error is None and q.jumps is None
    assert q.trajectory is None and q.hall is None and q.cycles is None
    s = fl.run(fl.load_scene(SCENES / "minimal.yaml", set={"friction.mu_k": 0.3}), duration=2.0)
    assert s.paper_material is None and s.paper_period is None and s.paper_mu_k is None


def test_duration_and_seed_are_the_commands_options():
    a = fl.run(SCENES / "minimal.yaml", duration="3 s", seed=5, record=False)
    b = fl.run(SCENES / "minimal.yaml", duration=3.0, seed=5, record=False)
    expected = {k: v for k, v in cli_json("run", SCENES / "minimal.yaml", "--duration", "3s",
                                          "--set", "world.seed=5").items()
                if k not in TIMING_KEYS}
    for r in (a, b):
        assert r.duration == 3.0 and r.seed == 5
        assert {k: v for k, v in r.json().items() if k not in TIMING_KEYS} == expected


def test_accuracy_picks_the_commands_step():
    expected = cli_json("run", SCENES / "minimal.yaml", "--accuracy", "0.001%", "--duration", "1s")
    r = fl.run(SCENES / "minimal.yaml", duration="1s", accuracy="0.001%", record=False)
    assert r.time_step == expected["time_step_s"] and r.steps == expected["steps"]


def test_an_accuracy_the_sensor_cannot_meet_is_refused_as_the_command_refuses_it():
    # The rig's estimator cannot time 10 s of the minimal plate to 0.001 %: both front ends refuse
    # it before the run, with the same words, each spelling the field its own way.
    err = cli("run", SCENES / "minimal.yaml", "--accuracy", "0.001%", status=2).stderr
    assert "the rig's estimator times each turning point" in err
    with pytest.raises(fl.InputError) as caught:
        fl.run(SCENES / "minimal.yaml", accuracy="0.001%", record=False)
    said = str(caught.value)
    assert said.startswith("accuracy='0.001%': error: the rig's estimator times each turning point")
    assert "ask for a duration of at least 79 s" in said and "--duration of at least 79 s" in err


def test_str_is_the_commands_summary():
    text = cli("run", SCENES / "minimal.yaml", "--duration", "3s").stdout
    r = fl.run(SCENES / "minimal.yaml", duration="3s", record=False)
    # The command's text but for the run's cost (its last line: wall time), which differs.
    def without_cost(s):
        return [line for line in s.splitlines() if not line.startswith("  run ")]

    assert without_cost(str(r)) == without_cost(text)
    assert len(without_cost(text)) == len(text.splitlines()) - 1


def test_a_run_too_short_for_a_turning_point_measures_no_amplitude():
    # minimal.yaml starts at rest 20 mm off centre: its first turning point is half a period,
    # T / 2 = 0.39 s, later. Before it there is no amplitude to report: None, null, never 0.
    short = fl.run(SCENES / "minimal.yaml", duration="0.3s", record=False)
    assert short.amplitude_start is None and short.amplitude_end is None
    assert short.json()["amplitude_start_m"] is None
    assert "none measured" in str(short)
    longer = fl.run(SCENES / "minimal.yaml", duration="0.5s", record=False)
    assert longer.amplitude_start == pytest.approx(0.020, rel=1e-3)


def test_every_key_of_summary_json_is_an_item_of_the_summary(tmp_path):
    # A field added to the one table (lab/run/summary_fields.cpp) reaches Python without a
    # binding of its own: summary[key] is summary.json's value.
    r = fl.run(SCENES / "minimal.yaml", duration="2s", out=tmp_path, record=False)
    written = json.loads((tmp_path / "summary.json").read_text())
    for key, value in written.items():
        assert r[key] == value, key
    with pytest.raises(KeyError, match="no key"):
        r["no_such_key"]
