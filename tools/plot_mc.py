#!/usr/bin/env python3
"""Draws frictionlab analytic --mc's histogram: mu_k from the Monte Carlo's draws (the thick-plate
formula on T, l and h_c drawn from Gaussians), its mean and 95 % interval, beside the Gaussian of
the quadrature rule and the paper's worst-case interval.  Usage: plot_mc.py mc.json mc.png"""
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import atomic_png  # noqa: E402


def main(json_path, png_path):
    with open(json_path) as f:
        data = json.load(f)
    samples = np.asarray(data["samples"], dtype=float)
    fig, ax = plt.subplots(figsize=(8.5, 5.2))
    if samples.size:
        ax.hist(samples, bins=min(120, max(10, int(math.sqrt(samples.size)))), density=True,
                color="tab:blue", alpha=0.55, label=f"{data['accepted']} draws (seed {data['seed']})")
    mu = data["mu_k_thick"]
    quad = data["mu_k_err_quadrature"]
    worst = data["mu_k_err_worst"]
    if quad > 0:
        x = np.linspace(mu - 4.5 * quad, mu + 4.5 * quad, 400)
        ax.plot(x, np.exp(-0.5 * ((x - mu) / quad) ** 2) / (quad * math.sqrt(2 * math.pi)), "k-",
                lw=1.2, label=f"quadrature rule: {mu:.4f} ± {quad:.4f}")
    ax.axvspan(mu - worst, mu + worst, color="grey", alpha=0.12,
               label=f"worst case (the paper's): ± {worst:.4f}")
    if data["mu_k_mean"] is not None:
        ax.axvline(data["mu_k_mean"], color="tab:red", lw=1.5,
                   label=f"Monte Carlo mean {data['mu_k_mean']:.4f}, sd {data['mu_k_sd'] or 0:.4f}")
        for q in ("mu_k_quantile_025", "mu_k_quantile_975"):
            ax.axvline(data[q], color="tab:red", ls="--", lw=1)
        ax.plot([], [], "--", color="tab:red",
                label=f"95 % interval [{data['mu_k_quantile_025']:.4f}, "
                      f"{data['mu_k_quantile_975']:.4f}]")
    title = (f"T = {data['period_s']:.4g} ± {data['period_err_s']:.2g} s, "
             f"l = {1e3 * data['spacing_m']:.1f} ± {1e3 * data['spacing_err_m']:.1f} mm, "
             f"h_c = {1e3 * data['h_c_m']:.2f} ± {1e3 * data['h_c_err_m']:.2f} mm")
    if data["skipped"]:
        title += f" ({data['skipped']} draws outside the formula's domain skipped)"
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("μ_k (thick-plate formula)")
    ax.set_ylabel("probability density")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    atomic_png.save(fig, png_path)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
