#!/usr/bin/env python3
"""Draws frictionlab compare's plot: simulated against measured periods for every row of the
paper's Table I (with the paper's dT and the simulated spread as error bars), and mu_k refitted
through the simulation against the paper's mu_k.  Usage: plot_compare.py compare.json compare.png"""
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
    markers = {300.0: ("o", "tab:red", "300 K"), 77.0: ("s", "tab:blue", "77 K")}
    # Measured against simulated periods, with the paper's dT and the simulated spread.
    for temperature, (marker, colour, label) in markers.items():
        sel = [r for r in rows if r["temperature_k"] == temperature and r["period_simulated_s"]]
        left.errorbar([r["period_measured_s"] for r in sel], [r["period_simulated_s"] for r in sel],
                      xerr=[r["period_measured_err_s"] for r in sel],
                      yerr=[r["period_simulated_std_s"] or 0 for r in sel], fmt=marker, color=colour,
                      ms=5, capsize=3, label=f"{label}: the paper's μ_k simulated")
    shown = [r["period_measured_s"] for r in rows if r["period_simulated_s"]]
    lo, hi = 0.85 * min(shown), 1.1 * max(shown)
    left.plot([lo, hi], [lo, hi], "k-", lw=0.8, alpha=0.6, label="simulated = measured")
    left.set_xlim(lo, hi)
    left.set_ylim(lo, hi)
    left.set_xlabel("period measured by the paper, T ± dT [s]")
    left.set_ylabel("period simulated (the rig's estimator) [s]")
    left.set_title(f"scene {data['scene']}: simulated against measured")
    left.grid(True, which="both", alpha=0.3)
    left.legend(fontsize=8, loc="upper left")

    # One line per row of Table I, top to bottom.
    labels = [f"{short(r['name'])} {r['temperature_k']:g} K" for r in rows]
    ys = list(range(len(rows)))[::-1]
    for y, r in zip(ys, rows):
        colour = markers.get(r["temperature_k"], ("o", "grey", ""))[1]
        if r["residual_sigma"] is not None:
            middle.plot([r["residual_sigma"]], [y], "o", color=colour)
        else:
            middle.text(0, y, r["status"], ha="center", va="center", fontsize=8, color="grey")
        if r["mu_k_refit"]:
            right.errorbar([r["mu_k_paper"]], [y + 0.15], xerr=[r["mu_k_paper_err"]], fmt="o",
                           mfc="white", color="grey", capsize=3)
            right.errorbar([r["mu_k_refit"]], [y - 0.15], xerr=[r["mu_k_refit_err_worst"]], fmt="o",
                           color=colour, capsize=3)
        else:
            right.errorbar([r["mu_k_paper"]], [y], xerr=[r["mu_k_paper_err"]], fmt="x", color="grey",
                           capsize=3)
            right.annotate("not fitted: " + r["status"], (r["mu_k_paper"], y), textcoords="offset points",
                           xytext=(-8, 0), ha="right", va="center", fontsize=8, color="grey")
    middle.axvspan(-1, 1, color="tab:green", alpha=0.12, label="within the paper's dT")
    middle.axvline(0, color="k", lw=0.8)
    worst = max([abs(r["residual_sigma"]) for r in rows if r["residual_sigma"] is not None] + [1.0])
    middle.set_xlim(-1.15 * worst, 1.15 * worst)
    middle.set_yticks(ys, labels, fontsize=8)
    middle.set_xlabel("residual (T_sim − T_measured) / dT")
    middle.set_title("residuals in units of the paper's dT")
    middle.grid(True, axis="x", alpha=0.3)
    middle.legend(fontsize=8, loc="lower right")
    right.errorbar([], [], xerr=[], fmt="o", mfc="white", color="grey", label="printed in the paper")
    right.errorbar([], [], xerr=[], fmt="o", color="k", label="refitted through the simulation (± worst)")
    right.set_yticks(ys, labels, fontsize=8)
    right.set_xscale("log")
    right.set_xlabel("μ_k")
    right.set_title(f"μ_k refitted (h_c = {1e3 * data['h_c_m']:.2f} mm) against the paper's")
    right.grid(True, which="both", axis="x", alpha=0.3)
    right.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    atomic_png.save(fig, png_path)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(*sys.argv[1:])
