#!/usr/bin/env python3
"""Draws what the rig's period estimator saw in a Hall-sensor log (frictionlab estimate --plot).

    plot_hall.py DATA.json OUT.png

DATA.json is written by `frictionlab estimate`: the samples (t_s, adc), the estimator's baseline
and timing level per sample (null while it was still learning the signal), the pulses (time,
rise, fall, peak, distorted) and the periods between turning points (start, end, period,
status: accepted, outlier or broken), plus the summary (period_s, period_std_s, mu_k, ...).

Top: the signal, the baseline and the timing level, each pulse marked at its time with its rise
and fall crossings, the turning points the periods run between, distorted pulses and rejected
periods in red.
Bottom: every period against the time it ended, accepted ones with the mean and +-dT band,
rejected ones marked with why.
"""
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
PULSE = "#2ca02c"


def none_to_nan(values):
    return [math.nan if v is None else v for v in values]


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: plot_hall.py DATA.json OUT.png\n")
        return 2
    with open(argv[1], encoding="utf-8") as f:
        d = json.load(f)
    out = argv[2]

    t = d["t_s"]
    fig, (top, bottom) = plt.subplots(
        2, 1, figsize=(12, 7.5), gridspec_kw={"height_ratios": [3, 2]}, constrained_layout=True
    )

    # The signal as the estimator saw it.
    top.plot(t, d["adc"], color="0.25", linewidth=0.7, label="ADC value")
    top.plot(t, none_to_nan(d["baseline"]), color="0.55", linewidth=1.0, linestyle="--",
             label="baseline")
    top.plot(t, none_to_nan(d["timing_level"]), color="#ff7f0e", linewidth=1.0, linestyle=":",
             label="timing level")
    # Before the estimator knew the signal's baseline and polarity (no levels yet).
    learned = next((i for i, v in enumerate(d["baseline"]) if v is not None), None)
    if t and (learned is None or learned > 0):
        end = t[-1] if learned is None else t[learned]
        top.axvspan(t[0], end, color="0.5", alpha=0.08, label="learning the signal")
    rejected_spans = [p for p in d["periods"] if p["status"] != "accepted"]
    for k, p in enumerate(rejected_spans):
        top.axvspan(p["start_s"], p["end_s"], color=REJECTED, alpha=0.12,
                    label="rejected period" if k == 0 else None)
        # Neighbouring labels alternate in height so that they do not overlap.
        top.annotate(p["status"], xy=((p["start_s"] + p["end_s"]) / 2, 0.87 - 0.05 * (k % 2)),
                     xycoords=("data", "axes fraction"), ha="center", va="top",
                     color=REJECTED, fontsize=8)
    ymin = min(d["adc"]) if d["adc"] else 0
    ymax = max(d["adc"]) if d["adc"] else 1
    span = max(ymax - ymin, 1)
    good = [p for p in d["pulses"] if not p["distorted"]]
    bad = [p for p in d["pulses"] if p["distorted"]]
    for group, colour, label in ((good, PULSE, "pulse (its time)"),
                                 (bad, REJECTED, "distorted pulse")):
        if not group:
            continue
        top.vlines([p["time_s"] for p in group], ymin - 0.04 * span, ymax + 0.04 * span,
                   colors=colour, linewidth=0.7, alpha=0.6, label=label)
        # The rise and fall crossings of the timing level, whose midpoint is the pulse's time.
        crossings = [p["rise_s"] for p in group] + [p["fall_s"] for p in group]
        top.plot(crossings, [ymin - 0.04 * span] * len(crossings), linestyle="none",
                 marker="|", markersize=8, color=colour)
    # The turning points the periods run between (for a pair: the middle of the pair).
    turns = sorted({p["start_s"] for p in d["periods"]} | {p["end_s"] for p in d["periods"]})
    if turns:
        top.plot(turns, [ymax + 0.07 * span] * len(turns), linestyle="none", marker="v",
                 markersize=5, color=ACCEPTED, label="turning point")
    top.set_ylim(ymin - 0.08 * span, ymax + 0.16 * span)
    top.set_xlabel("time [s]")
    top.set_ylabel("Hall sensor [ADC counts]")
    top.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), fontsize=8, ncol=8,
               frameon=False)

    n_used = d.get("periods_used", 0)
    title = os.path.basename(d.get("log", ""))
    if n_used and d.get("period_s"):
        title += (
            f": T = {d['period_s']:.5f} ± {d['period_std_s']:.5f} s over {n_used} periods "
            f"({d.get('periods_discarded', 0)} discarded), "
            f"μk = {d['mu_k']:.4f} ± {d['mu_k_err_worst']:.4f} "
            f"(l = {1000 * d['spacing_m']:.1f} mm, {d.get('geometry', '')})"
        )
    else:
        title += f": {len(d['pulses'])} pulses, no period"
    top.set_title(title, fontsize=10)

    # The periods.
    accepted = [p for p in d["periods"] if p["status"] == "accepted"]
    rejected = [p for p in d["periods"] if p["status"] != "accepted"]
    if accepted and n_used:
        mean = d["period_s"]
        sd = d["period_std_s"]
        bottom.axhspan(mean - sd, mean + sd, color=ACCEPTED, alpha=0.12, label="mean ± dT")
        bottom.axhline(mean, color=ACCEPTED, linewidth=1.0)
    bottom.plot([p["end_s"] for p in accepted], [p["period_s"] for p in accepted], "o",
                color=ACCEPTED, markersize=4, label="accepted period")
    for p in rejected:
        bottom.plot(p["end_s"], p["period_s"], "x", color=REJECTED, markersize=7)
        bottom.annotate(p["status"], (p["end_s"], p["period_s"]), textcoords="offset points",
                        xytext=(4, 4), fontsize=8, color=REJECTED)
    if rejected:
        bottom.plot([], [], "x", color=REJECTED, label="rejected period")
    if accepted:
        values = [p["period_s"] for p in accepted]
        lo, hi = min(values), max(values)
        pad = max(hi - lo, 1e-4 * max(hi, 1e-9)) * 0.6
        # Keep the accepted ones readable; rejected ones far off are drawn at the edge.
        bottom.set_ylim(lo - pad, hi + pad)
        for p in rejected:
            if p["period_s"] > hi + pad or p["period_s"] < lo - pad:
                y = hi + 0.85 * pad if p["period_s"] > hi else lo - 0.85 * pad
                bottom.annotate(f"{p['period_s']:.3f} s ({p['status']})", (p["end_s"], y),
                                fontsize=8, color=REJECTED, ha="center")
    bottom.set_xlim(top.get_xlim())
    bottom.set_xlabel("time the period ended [s]")
    bottom.set_ylabel("period [s]")
    bottom.legend(loc="upper right", fontsize=8, ncol=3, framealpha=0.85)
    bottom.grid(True, alpha=0.3)

    atomic_png.save(fig, out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
