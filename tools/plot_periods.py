#!/usr/bin/env python3
"""Draws the rig's estimator's periods over a run (frictionlab run --out DIR --plot).

    plot_periods.py DIR OUT.png

DIR holds the run's periods.csv (each period the estimator judged: start_s, end_s, period_s,
status) and summary.json. Top: every period against the time it ended, the accepted ones and the
rejected ones apart, with the thick-plate period for the scene's mu_k; for rollers that warm, the
thick-plate period at the rollers' mu_k(t) instead (the temperature on a second axis), and the
windows a student averages over (the first 10 periods, the first 30 s). Bottom: mu_k from each
accepted period by the paper's formula mu_k = 2 pi^2 l / (g T^2), with the warming rollers' mu_k(t)
and what the paper's formula gives on rollers that stay cold.
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import atomic_png  # noqa: E402

ACCEPTED = "#1f77b4"
REJECTED = "#d62728"


def thick_period(l, mu, h, g):
    return math.pi * math.sqrt(2 * (l - 2 * mu * h) / (mu * g))


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: plot_periods.py DIR OUT.png\n")
        return 2
    folder, out = argv[1], argv[2]
    with open(os.path.join(folder, "periods.csv"), newline="") as f:
        periods = list(csv.DictReader(f))
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    l, h = summary["spacing_m"], summary["h_c_m"]
    # g from the paper's formula's period for the scene's mu_k: T_thin = pi sqrt(2 l / (mu_k g)).
    g = 2 * math.pi ** 2 * l / (summary["mu_k_set"] * summary["period_thin_s"] ** 2)
    duration = summary["duration_s"]
    accepted = [p for p in periods if p["status"] == "accepted"]
    rejected = [p for p in periods if p["status"] != "accepted"]

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 7.5), sharex=True)
    top.plot([float(p["end_s"]) for p in accepted], [float(p["period_s"]) for p in accepted], "o",
             ms=3, color=ACCEPTED, label=f"accepted ({len(accepted)})")
    if rejected:
        top.plot([float(p["end_s"]) for p in rejected], [float(p["period_s"]) for p in rejected],
                 "x", ms=5, color=REJECTED, label=f"discarded ({len(rejected)})")
    mu_of_t = None
    warming = summary.get("warming")
    if warming:
        t0, room = warming["start_temperature_k"], warming["room_temperature_k"]
        tau, hold = warming["time_constant_s"], warming["hold_s"]
        mu0, mu_room = warming["mu_k_start"], warming["mu_k_room"]

        def temperature(t):
            return t0 if t <= hold else room - (room - t0) * math.exp(-(t - hold) / tau)

        def mu_of_t(t):
            return mu0 + (temperature(t) - t0) / (room - t0) * (mu_room - mu0)

        ts = [duration * i / 400 for i in range(401)]
        top.plot(ts, [thick_period(l, mu_of_t(t), h, g) for t in ts], "k-", lw=1,
                 label="thick-plate T at the rollers' mu_k(t)")
        hot = top.twinx()
        hot.plot(ts, [temperature(t) for t in ts], color="tab:orange", lw=1, alpha=0.7)
        hot.set_ylabel("rollers' temperature [K]", color="tab:orange")
        if len(accepted) >= 10:
            tenth = float(accepted[9]["end_s"])
            for ax in (top, bottom):
                ax.axvspan(0, tenth, color="tab:green", alpha=0.12)
            top.plot([], [], color="tab:green", alpha=0.3, lw=6, label="the first 10 periods")
        for ax in (top, bottom):
            ax.axvline(30, color="tab:green", ls="--", lw=1)
        top.plot([], [], color="tab:green", ls="--", lw=1, label="30 s")
    elif summary.get("period_thick_s"):
        top.axhline(summary["period_thick_s"], color="k", lw=1, label="thick-plate T")
    top.set_ylabel("period [s]")
    top.set_title(f"{summary['scene']}: the rig's estimator's periods over the run")
    top.grid(True, alpha=0.3)
    top.legend(fontsize=8, loc="upper right")

    mus = [2 * math.pi ** 2 * l / (g * float(p["period_s"]) ** 2) for p in accepted]
    bottom.plot([float(p["end_s"]) for p in accepted], mus, "o", ms=3, color=ACCEPTED,
                label="mu_k from each period (the paper's formula)")
    if mu_of_t:
        ts = [duration * i / 400 for i in range(401)]
        bottom.plot(ts, [mu_of_t(t) for t in ts], "k-", lw=1, label="the rollers' mu_k(t)")
        bottom.axhline(warming["mu_k_cold_paper_formula"], color="tab:blue", ls=":", lw=1,
                       label=f"rollers that stay at {warming['start_temperature_k']:.0f} K "
                             "(the paper's formula)")
    bottom.set_xlabel("time [s]")
    bottom.set_ylabel("mu_k")
    bottom.grid(True, alpha=0.3)
    bottom.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    atomic_png.save(fig, out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
