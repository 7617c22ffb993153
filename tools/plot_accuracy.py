#!/usr/bin/env python3
"""Draws frictionlab's work-precision study: period error against wall time per simulated
second (one line per solver-iteration count), and error against omega*dt with the fitted and the
theoretical law.  Usage: plot_accuracy.py accuracy.csv accuracy.json accuracy.png"""
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import atomic_png  # noqa: E402


def main(csv_path, json_path, png_path):
    with open(csv_path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["valid"] == "1"]
    with open(json_path) as f:
        meta = json.load(f)
    omega = meta["omega_rad_s"]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    for iters in sorted({int(r["solver_iterations"]) for r in rows}):
        pts = sorted((float(r["wall_per_simulated_second_s"]), abs(float(r["period_error"])),
                      float(r["time_step_s"])) for r in rows if int(r["solver_iterations"]) == iters)
        left.loglog([p[0] * 1e3 for p in pts], [max(p[1], 1e-12) for p in pts], "o-",
                    label=f"{iters} iterations")
        pts_dt = sorted((omega * float(r["time_step_s"]), abs(float(r["period_error"])))
                        for r in rows if int(r["solver_iterations"]) == iters)
        right.loglog([p[0] for p in pts_dt], [max(p[1], 1e-12) for p in pts_dt], "o", label=f"{iters} it.")
    xs = sorted({omega * float(r["time_step_s"]) for r in rows})
    right.loglog(xs, [x * x / 24 for x in xs], "k--", label="theory (ω dt)²/24")
    if "law" in meta:
        c, p = meta["law"]["coefficient"], meta["law"]["exponent"]
        right.loglog(xs, [c * x ** p for x in xs], "r:", label=f"fit {c:.4f} (ω dt)^{p:.2f}")
    left.set_xlabel("wall time per simulated second [ms]")
    left.set_ylabel("|period error| against the thick-plate formula")
    left.set_title(f"{meta['scene']}: error against run time")
    left.grid(True, which="both", alpha=0.3)
    left.legend()
    right.set_xlabel("ω dt")
    right.set_ylabel("|period error|")
    right.set_title("the integrator's error law")
    right.grid(True, which="both", alpha=0.3)
    right.legend(fontsize=8)
    fig.tight_layout()
    atomic_png.save(fig, png_path)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
