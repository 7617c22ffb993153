#!/usr/bin/env python3
"""What the lab costs from Python, against the frictionlab command; a benchmark, not a test.

  PYTHONPATH=build/release/python /usr/bin/python3 python/bench/bench_python.py [--repeat N]

1. The minimal scene's 10 s: a call of frictionlab.run (the scene read from its file, as the
   command reads it) against a whole `frictionlab run` process, interleaved. Target: the call
   costs at most 5 % more. wall_s is the run's own time (world built, stepped, diagnosed), so
   call - wall_s is everything else: the scene's loading and compiling, and the binding.
2. A Python loop of 1000 short runs (50 ms of simulated time each): how much of the loop is
   spent outside the runs themselves (an upper bound on the binding's share).
3. Four runs of the minimal scene's 10 s in four threads against one after another: the GIL is
   released while a world steps, so the threads use every core.
"""

import argparse
import json
import os
import pathlib
import statistics
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor

import frictionlab as fl

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]
MINIMAL = SOURCE_DIR / "scenes" / "minimal.yaml"


def median_ms(values):
    return 1e3 * statistics.median(values)


def spread_ms(values):
    return f"{1e3 * min(values):.1f} to {1e3 * max(values):.1f}"


def against_the_command(cli, repeat):
    process, process_run, call, call_run, call_recorded = [], [], [], [], []
    for i in range(repeat):
        order = ("cli", "python") if i % 2 == 0 else ("python", "cli")
        for who in order:
            if who == "cli":
                start = time.perf_counter()
                out = subprocess.run([cli, "run", str(MINIMAL), "--json"], check=True,
                                     capture_output=True, text=True).stdout
                process.append(time.perf_counter() - start)
                process_run.append(json.loads(out)["wall_s"])
            else:
                start = time.perf_counter()
                r = fl.run(MINIMAL, record=False)
                call.append(time.perf_counter() - start)
                call_run.append(r.wall_s)
                start = time.perf_counter()
                fl.run(MINIMAL)
                call_recorded.append(time.perf_counter() - start)
    ratio = statistics.median(call) / statistics.median(process)
    print("1. minimal scene, 10 s simulated (medians of %d, interleaved)" % repeat)
    print(f"   frictionlab run (whole process)        {median_ms(process):7.1f} ms"
          f"  ({spread_ms(process)}); the run itself {median_ms(process_run):.1f} ms")
    print(f"   frictionlab.run(path, record=False)    {median_ms(call):7.1f} ms"
          f"  ({spread_ms(call)}); the run itself {median_ms(call_run):.1f} ms")
    print(f"   frictionlab.run(path) with the arrays  {median_ms(call_recorded):7.1f} ms"
          f"  ({spread_ms(call_recorded)})")
    outside = [c - w for c, w in zip(call, call_run)]
    outside_process = [c - w for c, w in zip(process, process_run)]
    print(f"   outside the run: the call {median_ms(outside):.2f} ms, the process "
          f"{median_ms(outside_process):.2f} ms")
    verdict = "met" if ratio <= 1.05 else "NOT met"
    print(f"   call / process: {ratio:.3f} (target <= 1.05: {verdict})")
    return {"process_ms": median_ms(process), "call_ms": median_ms(call),
            "call_recorded_ms": median_ms(call_recorded), "ratio": ratio,
            "outside_call_ms": median_ms(outside), "outside_process_ms": median_ms(outside_process)}


def short_runs(count):
    scene = fl.load_scene(MINIMAL, set={"world.duration": "50ms"})
    fl.run(scene, record=False)  # the first run reads the paper's table
    inside = 0.0
    start = time.perf_counter()
    for _ in range(count):
        inside += fl.run(scene, record=False).wall_s
    total = time.perf_counter() - start
    start = time.perf_counter()
    for _ in range(count):
        fl.run(scene)
    recorded = time.perf_counter() - start
    start = time.perf_counter()
    for _ in range(count):
        fl.run(MINIMAL, duration="50ms", record=False)
    loading = time.perf_counter() - start
    share = 1.0 - inside / total
    print(f"2. {count} short runs (50 steps each) in a Python loop")
    print(f"   a loaded scene, record=False: {1e3 * total:.0f} ms, {1e6 * total / count:.0f} us a run;"
          f" the runs themselves {1e3 * inside:.0f} ms; outside them {100 * share:.1f} %"
          " (compiling the rig, the binding)")
    print(f"   with the arrays (record=True): {1e6 * recorded / count:.0f} us a run")
    print(f"   the scene read from its file each time: {1e6 * loading / count:.0f} us a run")
    return {"per_run_us": 1e6 * total / count, "outside_share": share,
            "per_run_recorded_us": 1e6 * recorded / count, "per_run_loading_us": 1e6 * loading / count}


def threads(repeat):
    scene = fl.load_scene(MINIMAL)
    serial, parallel = [], []
    for _ in range(repeat):
        start = time.perf_counter()
        for _ in range(4):
            fl.run(scene, record=False)
        serial.append(time.perf_counter() - start)
        start = time.perf_counter()
        with ThreadPoolExecutor(4) as pool:
            list(pool.map(lambda _: fl.run(scene, record=False), range(4)))
        parallel.append(time.perf_counter() - start)
    speedup = statistics.median(serial) / statistics.median(parallel)
    print(f"3. four runs of 10 s on {os.cpu_count()} cores (medians of {repeat})")
    print(f"   one after another {median_ms(serial):.0f} ms, four threads {median_ms(parallel):.0f} ms:"
          f" speed-up {speedup:.2f}")
    return {"serial_ms": median_ms(serial), "threads_ms": median_ms(parallel), "speedup": speedup}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(SOURCE_DIR / "build/release/src/cli/frictionlab"))
    parser.add_argument("--repeat", type=int, default=20)
    parser.add_argument("--short-runs", type=int, default=1000)
    parser.add_argument("--json", help="also write the figures to this file")
    args = parser.parse_args()
    print(f"frictionlab {fl.__version__}, {os.cpu_count()} cores, load average "
          + " ".join(f"{v:.2f}" for v in os.getloadavg()))
    results = {
        "command": against_the_command(args.cli, args.repeat),
        "short_runs": short_runs(args.short_runs),
        "threads": threads(max(3, args.repeat // 4)),
        "load_average": os.getloadavg(),
    }
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(results, indent=2) + "\n")


if __name__ == "__main__":
    main()
