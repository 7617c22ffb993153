#!/usr/bin/env python3
"""Draws frictionlab fit's plot: T^2 against the roller spacing l with each row's error bar, the
thick-plate line fitted through them with its 1-sigma band (from the slope's and intercept's
covariance), and the paper's thin formula (a line through the origin) for contrast; below, each
row's residual in units of its error for both.  Usage: plot_fit.py fit.json fit.png"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import atomic_png  # noqa: E402


def main(json_path, png_path):
    with open(json_path) as f:
        d = json.load(f)
    rows = d["rows"]
    l_mm = np.array([r["spacing_m"] for r in rows]) * 1e3
    dl_mm = np.array([(r["spacing_err_m"] or 0.0) for r in rows]) * 1e3
    t2 = np.array([r["period_s"] ** 2 for r in rows])
    sigma_period = np.array([2 * r["period_s"] * r["period_err_s"] for r in rows])
    sigma = np.array([r["period_squared_err_s2"] for r in rows])
    s, c = d["slope_s2_per_m"], d["intercept_s2"]
    var_s, var_c = d["slope_err_s2_per_m"] ** 2, d["intercept_err_s2"] ** 2
    cov = d["slope_intercept_covariance"]
    s0 = d["thin_slope_s2_per_m"]

    span = l_mm.max() - l_mm.min()
    x_mm = np.linspace(l_mm.min() - 0.08 * span, l_mm.max() + 0.08 * span, 300)
    x = x_mm * 1e-3
    y = s * x + c
    band = np.sqrt(var_s * x * x + 2 * cov * x + var_c)

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8.5, 7.5), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 1.3]})
    top.fill_between(x_mm, y - band, y + band, color="tab:red", alpha=0.2, lw=0,
                     label="1σ band of the fit")
    mu, h = d["mu_k"], d["h_c_m"]
    top.plot(x_mm, y, "-", color="tab:red",
             label=f"thick plate: μ_k = {mu:.4f} ± {d['mu_k_err']:.4f}, "
                   f"h_c = {1e3 * h:.2f} ± {1e3 * d['h_c_err_m']:.2f} mm")
    top.plot(x_mm, s0 * x, "--", color="grey",
             label=f"thin formula (through the origin): μ_k = {d['mu_k_thin_line']:.4f}")
    top.errorbar(l_mm, t2, yerr=sigma_period, xerr=dl_mm if dl_mm.any() else None, fmt="o",
                 color="k", ms=4, capsize=3, label="measured T² ± 2T dT")
    rig = d.get("through_rig")
    if rig:
        t2_corrected = np.array([r["period_corrected_s"] ** 2 for r in rows])
        top.plot(l_mm, t2_corrected, "x", color="tab:blue", ms=6,
                 label=f"corrected through the rig ({rig['scene']}): μ_k = {rig['mu_k']:.4f}")
    for r, xi, yi in zip(rows, l_mm, t2):
        if r["label"]:
            top.annotate(r["label"], (xi, yi), textcoords="offset points", xytext=(5, -10),
                         fontsize=7, color="dimgrey")
    chi = d["chi2_per_dof"]
    top.set_title(f"{d['file']}: T² against l ({len(rows)} rows"
                  + (f", χ²/dof = {chi:.2f}" if chi is not None else "") + ")", fontsize=10)
    top.set_ylabel("T² [s²]")
    top.grid(True, alpha=0.3)
    top.legend(fontsize=8, loc="upper left")

    bottom.axhline(0, color="k", lw=0.8)
    bottom.plot(l_mm, [r["residual_sigma"] for r in rows], "o", color="tab:red", label="thick")
    bottom.plot(l_mm, (t2 - s0 * l_mm * 1e-3) / sigma, "s", mfc="none", color="grey",
                label="thin")
    bottom.set_xlabel("roller spacing l [mm]")
    bottom.set_ylabel("residual [σ]")
    bottom.grid(True, alpha=0.3)
    bottom.legend(fontsize=8)
    fig.tight_layout()
    atomic_png.save(fig, png_path)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
