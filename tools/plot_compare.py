#!/usr/bin/env python3
"""Draws frictionlab compare's plot: simulated against measured periods for every row of the
measurements (the paper's Table I by default; with each row's dT and the simulated spread as error
bars), and mu_k refitted through the simulation against the mu_k the row reports.
Usage: plot_compare.py compare.json compare.png"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import atomic_png  # noqa: E402


def short(name):
    return name.replace("Polyurethane ", "PU ").replace(" blocks", "")


def main(json_path, png_path):
    with open(json_path) as f:
        data = json.load(f)
    rows = data["rows"]
    fig, (left, middle, right) = plt.subplots(1, 3, figsize=(16, 6.5),
                                              gridspec_kw={"width_ratios": [1.1, 0.9, 1.2]})
    # One marker and colour per temperature: 300 K red and 77 K blue as in the paper's table.
    styles = [("o", "tab:red"), ("s", "tab:blue"), ("^", "tab:green"), ("D", "tab:purple")]
    temperatures = sorted({r["temperature_k"] for r in rows}, key=lambda t: (t != 300.0, -t))
    markers = {t: styles[i % len(styles)] + (f"{t:g} K",) for i, t in enumerate(temperatures)}
    # Measured against simulated periods, with the row's dT and the simulated spread.
    for temperature, (marker, colour, label) in markers.items():
        sel = [r for r in rows if r["temperature_k"] == temperature and r["period_simulated_s"]]
        left.errorbar([r["period_measured_s"] for r in sel], [r["period_simulated_s"] for r in sel],
                      xerr=[r["period_measured_err_s"] for r in sel],
                      yerr=[r["period_simulated_std_s"] or 0 for r in sel], fmt=marker, color=colour,
                      ms=5, capsize=3, label=f"{label}: simulated")
    shown = [r["period_measured_s"] for r in rows if r["period_simulated_s"]]
    shown = shown or [r["period_measured_s"] for r in rows]
    lo, hi = 0.85 * min(shown), 1.1 * max(shown)
    left.plot([lo, hi], [lo, hi], "k-", lw=0.8, alpha=0.6, label="simulated = measured")
    left.set_xlim(lo, hi)
    left.set_ylim(lo, hi)
    left.set_xlabel("period measured, T ± dT [s]")
    left.set_ylabel("period simulated (the rig's estimator) [s]")
    left.set_title(f"scene {data['scene']}: simulated against measured")
    left.grid(True, which="both", alpha=0.3)
    left.legend(fontsize=8, loc="upper left")

    # One line per row of Table I, top to bottom.
    labels = [f"{short(r['label'])} {r['temperature_k']:g} K" for r in rows]
    ys = list(range(len(rows)))[::-1]
    for y, r in zip(ys, rows):
        colour = markers.get(r["temperature_k"], ("o", "grey", ""))[1]
        if r["residual_sigma"] is not None:
            middle.plot([r["residual_sigma"]], [y], "o", color=colour)
        else:
            middle.text(0, y, r["status"], ha="center", va="center", fontsize=8, color="grey")
        reported = r["mu_k_reported"]
        reported_err = [r["mu_k_reported_err"] or 0]
        if r["mu_k_refit"]:
            if reported is not None:
                right.errorbar([reported], [y + 0.15], xerr=reported_err, fmt="o", mfc="white",
                               color="grey", capsize=3)
            right.errorbar([r["mu_k_refit"]], [y - 0.15], xerr=[r["mu_k_refit_err_worst"]], fmt="o",
                           color=colour, capsize=3)
        else:
            at = reported if reported is not None else r["mu_k_simulated"]
            right.errorbar([at], [y], xerr=reported_err, fmt="x", color="grey", capsize=3)
            right.annotate("not fitted: " + r["status"], (at, y), textcoords="offset points",
                           xytext=(-8, 0), ha="right", va="center", fontsize=8, color="grey")
    middle.axvspan(-1, 1, color="tab:green", alpha=0.12, label="within the measured dT")
    middle.axvline(0, color="k", lw=0.8)
    worst = max([abs(r["residual_sigma"]) for r in rows if r["residual_sigma"] is not None] + [1.0])
    middle.set_xlim(-1.15 * worst, 1.15 * worst)
    middle.set_yticks(ys, labels, fontsize=8)
    middle.set_xlabel("residual (T_sim − T_measured) / dT")
    middle.set_title("residuals in units of the measured dT")
    middle.grid(True, axis="x", alpha=0.3)
    middle.legend(fontsize=8, loc="lower right")
    right.errorbar([], [], xerr=[], fmt="o", mfc="white", color="grey", label="reported (the paper's for Table I)")
    right.errorbar([], [], xerr=[], fmt="o", color="k", label="refitted through the simulation (± worst)")
    right.set_yticks(ys, labels, fontsize=8)
    right.set_xscale("log")
    right.set_xlabel("μ_k")
    right.set_title(f"μ_k refitted (h_c = {1e3 * data['h_c_m']:.2f} mm) against the reported")
    right.grid(True, which="both", axis="x", alpha=0.3)
    right.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    atomic_png.save(fig, png_path)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(*sys.argv[1:])
