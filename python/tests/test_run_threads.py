"""Runs in Python threads: the GIL is released while a world steps, and each run gives exactly
the result it gives on its own."""

import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

import frictionlab as fl
from conftest import SCENES, TIMING_KEYS


def same_bits(a, b):
    """Structured arrays equal bit for bit (the bytes between fields are zeroes)."""
    return a.dtype == b.dtype and a.tobytes() == b.tobytes()


def deterministic(result):
    return {k: v for k, v in result.json().items() if k not in TIMING_KEYS}


@pytest.mark.slow
def test_four_threads_give_the_serial_results_bit_for_bit():
    scenes = [fl.load_scene(SCENES / "minimal.yaml", set={"world.seed": seed}) for seed in (1, 2)]
    scenes += [fl.load_scene(SCENES / "paper-rig.yaml", set={"world.seed": seed}) for seed in (1, 2)]
    serial = [fl.run(scene) for scene in scenes]
    with ThreadPoolExecutor(4) as pool:
        threaded = list(pool.map(fl.run, scenes))
    for alone, together in zip(serial, threaded):
        assert deterministic(together) == deterministic(alone)
        assert same_bits(together.trajectory, alone.trajectory)
        assert same_bits(together.hall, alone.hall)
        assert same_bits(together.cycles, alone.cycles)
    # The seeds made different runs: the comparison above could tell them apart.
    assert not same_bits(serial[0].hall, serial[1].hall)


@pytest.mark.slow
def test_one_scene_in_four_threads_at_once():
    scene = fl.load_scene(SCENES / "minimal.yaml")
    alone = fl.run(scene)
    with ThreadPoolExecutor(4) as pool:
        results = list(pool.map(lambda _: fl.run(scene), range(4)))
    for r in results:
        assert deterministic(r) == deterministic(alone)
        assert same_bits(r.trajectory, alone.trajectory)


def test_python_runs_while_a_world_steps():
    # With the GIL held through the run, this thread could not count while the run stepped.
    window = {}

    def run():
        window["start"] = time.perf_counter()
        fl.run(SCENES / "minimal.yaml", duration="20s", record=False)
        window["end"] = time.perf_counter()

    worker = threading.Thread(target=run)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    start, end = window["start"], window["end"]
    # The middle half of the run, where the world steps (the scene is loaded and the results
    # are made before and after it).
    lo, hi = start + 0.25 * (end - start), start + 0.75 * (end - start)
    during = sum(1 for t in ticks if lo < t < hi)
    assert during >= 10, f"{during} ticks in the middle {1e3 * (hi - lo):.0f} ms of the run"
