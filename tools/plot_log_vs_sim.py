#!/usr/bin/env python3
"""Draws frictionlab compare --log's plot: the measured Hall signal and its simulation at the
refitted mu_k over each other (aligned on the first pulse), the residual below, and what the two
say differently.  Usage: plot_log_vs_sim.py compare-log-traces.json compare-log.png"""
import json
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import atomic_png  # noqa: E402


def main(json_path, png_path):
    with open(json_path) as f:
        d = json.load(f)
    t = d["t_s"]
    measured = d["adc_measured"]
    simulated = [float("nan") if v is None else v for v in d["adc_simulated"]]
    residual = [m - s for m, s in zip(measured, simulated)]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(13, 7.5), sharex=True,
                                      gridspec_kw={"height_ratios": [2.2, 1]})
    top.plot(t, measured, color="tab:blue", lw=0.9, label="the log (measured)")
    top.plot(t, simulated, color="tab:orange", lw=0.9, alpha=0.85,
             label=f"simulated at μ_k = {d['mu_k_simulated']:.4f} (scene {d['scene']})")
    top.set_ylabel("Hall sensor [ADC counts]")
    m, s = d["measured"], d["simulated"]
    top.set_title(f"{d['log']}: T = {m['period_s']:.5f} s measured, {s['period_s']:.5f} s simulated"
                  f" (aligned on the first pulse)")
    top.legend(loc="upper right", fontsize=9)
    top.grid(True, alpha=0.3)
    bottom.plot(t, residual, color="k", lw=0.7)
    bottom.axhline(0, color="grey", lw=0.8)
    bottom.set_ylabel("measured − simulated [counts]")
    bottom.set_xlabel("time on the log's clock [s]")
    bottom.set_title(f"residual: {d['residual_rms_counts']:.1f} counts rms", fontsize=10)
    bottom.grid(True, alpha=0.3)
    found = d["disagreements"] or ["the log and its simulation agree in every test"]
    text = "\n".join(textwrap.fill("• " + line, 150) for line in found)
    fig.text(0.01, 0.005, text, fontsize=8, va="bottom", ha="left", family="sans-serif")
    fig.tight_layout(rect=(0, 0.04 + 0.025 * text.count("\n"), 1, 1))
    atomic_png.save(fig, png_path)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(*sys.argv[1:])
