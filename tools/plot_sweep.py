#!/usr/bin/env python3
"""Draws a frictionlab sweep's plots from its results.csv and sweep.json, as the sweep calls for:

  period-vs-spacing.png  T +- dT against the roller spacing l, the analytic thin and thick curves
                         over it, and the error against the thick curve below (when l varies)
  mu-recovered.png       mu_k recovered (thin and thick formulas) against mu_k set (when mu_k varies)
  roller-speed.png       amplitude and period against the rollers' speed, coloured by regime, a
                         marker for each series of the other axes, with the analytic slip
                         threshold (when the roller speed varies across points by more than 1 %)
  runout.png             the highest jump, the share of the periods the rig's estimator discarded
                         and the period's error against the rollers' run-out, with theory's hop
                         threshold (when rollers.runout varies)
  tilt.png               the oscillation's centre against the rig's tilt with theory's line
                         x_eq = -(l - 2 mu_k h_c) tan(tilt) / (2 mu_k), and the period against the
                         thick plate's with g cos(tilt) (when world.tilt varies)
  skew.png               the plate's sideways drift against the rollers' skew with theory's line
                         v_r sin(skew / 2), and the period's error against the thick plate's on
                         parallel rollers (when rollers.skew varies)
  cycles.png             each cycle's period and amplitude against the rollers' speed during it,
                         the ramp's way down and way up apart, with theory's slip threshold
                         (when the sweep recorded cycles: OUTDIR/cycles/*.csv)
  map.png                the error against the thick curve over the first two axes, regimes marked
                         and named in a legend, values spanning decades evenly spaced (when two
                         axes have more than one value)
  axis.png               the period against the only axis with the thick-plate T of each point
                         (when none of the above applies: rollers.rolling_resistance, say)

Usage: plot_sweep.py results.csv sweep.json OUTDIR"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import atomic_png  # noqa: E402

# One colour for each regime a run can show (src/core/regime.cpp), so that no two share grey.
REGIME_COLOURS = {"oscillates": "tab:blue", "clipped": "tab:cyan", "stick-slip": "tab:olive",
                  "grows": "tab:pink", "decays": "tab:green", "sticks": "tab:orange",
                  "tips": "tab:red", "no restoring force": "tab:purple", "lost": "tab:brown",
                  "numerically failed": "black", "unknown": "grey"}
# One marker for each series of points (the values of the axes a plot does not show).
SERIES_MARKERS = ["o", "s", "^", "D", "v", "P", "X", "<", ">", "*"]


def number(row, key):
    v = row.get(key, "")
    try:
        return float(v) if v != "" else None
    except ValueError:
        return None


def distinct(rows, key):
    return sorted({number(r, key) for r in rows if number(r, key) is not None})


def group_key(row, axes, leave_out):
    return tuple(row[a["name"]] for a in axes if a["name"] not in leave_out)


def period_thin(l, mu, g):
    return math.pi * math.sqrt(2 * l / (mu * g))


def period_thick(l, mu, h, g):
    return math.pi * math.sqrt(2 * (l - 2 * mu * h) / (mu * g)) if l > 2 * mu * h else float("nan")


def plot_spacing(rows, meta, out):
    axes = meta["axes"]
    spacing_axes = [a["name"] for a in axes if a.get("key") == "rollers.spacing"]
    groups = {}
    for r in rows:
        groups.setdefault(group_key(r, axes, spacing_axes), []).append(r)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7.5), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 1.4]})
    for n, (key, members) in enumerate(sorted(groups.items())):
        colour = f"C{n % 10}"
        pts = sorted((number(r, "spacing_m"), number(r, "period_s"), number(r, "period_std_s"),
                      number(r, "error_vs_thick")) for r in members if number(r, "period_s"))
        label = ", ".join(key) if key else meta["sweep"]
        mu = number(members[0], "mu_k_set")
        h = number(members[0], "h_c_m")
        g = number(members[0], "gravity_m_s2") or 9.81
        if pts:
            top.errorbar([p[0] * 1e3 for p in pts], [p[1] for p in pts], yerr=[p[2] or 0 for p in pts],
                         fmt="o", ms=3.5, color=colour, label=f"{label} (mu_k {mu:g}): T +- dT")
            bottom.plot([p[0] * 1e3 for p in pts], [100 * p[3] for p in pts], "o", ms=3.5, color=colour)
        ls = sorted(distinct(members, "spacing_m"))
        if ls and mu:
            fine = [ls[0] + (ls[-1] - ls[0]) * i / 200 for i in range(201)]
            top.plot([l * 1e3 for l in fine], [period_thick(l, mu, h, g) for l in fine], "-",
                     color=colour, lw=1, alpha=0.8)
            top.plot([l * 1e3 for l in fine], [period_thin(l, mu, g) for l in fine], "--",
                     color=colour, lw=1, alpha=0.6)
    top.plot([], [], "k-", lw=1, label="thick plate: π √(2 (l − 2 μ h_c) / (μ g))")
    top.plot([], [], "k--", lw=1, label="thin plate (the paper): π √(2 l / (μ g))")
    top.set_ylabel("period T [s]")
    top.set_title(f"{meta['sweep']}: period against roller spacing")
    top.grid(True, alpha=0.3)
    top.legend(fontsize=8)
    bottom.axhspan(-0.05, 0.05, color="tab:green", alpha=0.12, label="±0.05 %")
    bottom.axhline(0, color="k", lw=0.8)
    bottom.set_xlabel("roller spacing l [mm]")
    bottom.set_ylabel("T / T_thick − 1 [%]")
    bottom.grid(True, alpha=0.3)
    bottom.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    atomic_png.save(fig, os.path.join(out, "period-vs-spacing.png"))


def plot_mu(rows, meta, out):
    pts = [(number(r, "mu_k_set"), number(r, "mu_k_recovered"), number(r, "mu_k_recovered_thick"),
            number(r, "mu_k_err_worst")) for r in rows if number(r, "mu_k_recovered")]
    fig, ax = plt.subplots(figsize=(6.5, 6))
    if pts:
        ax.errorbar([p[0] for p in pts], [p[1] for p in pts], yerr=[p[3] or 0 for p in pts], fmt="o",
                    ms=4, capsize=2, label="recovered, thin formula (the paper's) ± worst case")
        ax.plot([p[0] for p in pts], [p[2] for p in pts], "x", ms=6, color="k",
                label="recovered, thick formula with h_c")
    failed = [r for r in rows if not number(r, "mu_k_recovered") and number(r, "mu_k_set")]
    for r in failed:
        ax.axvline(number(r, "mu_k_set"), color=REGIME_COLOURS.get(r["regime"], "grey"), ls=":", lw=1)
    if failed:
        ax.plot([], [], ":", color="grey", label="no period (regime marked by colour)")
    values = [p[0] for p in pts] + [number(r, "mu_k_set") for r in failed]
    if values:
        lo, hi = min(values), max(values)
        ax.plot([lo, hi], [lo, hi], "k-", lw=0.8, alpha=0.6, label="recovered = set")
        if hi / lo > 8:
            ax.set_xscale("log")
            ax.set_yscale("log")
    ax.set_xlabel("μ_k set in the scene")
    ax.set_ylabel("μ_k recovered from the rig's estimator")
    ax.set_title(f"{meta['sweep']}: μ_k recovered against μ_k set")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    atomic_png.save(fig, os.path.join(out, "mu-recovered.png"))


def series_of(rows, axes, shown):
    """The rows split by the values of the axes a plot does not show: {label: rows}, and the
    legend's handles for the series (markers) and the regimes (colours) drawn after."""
    series = {}
    for r in rows:
        key = group_key(r, axes, shown)
        label = ", ".join(f"{a['name']} {r[a['name']]}" for a in axes if a["name"] not in shown)
        series.setdefault((key, label), []).append(r)
    return {label: members for (_, label), members in sorted(series.items())}


def legend_by_regime_and_series(ax, regimes, series_labels, extra=()):
    """A legend with a colour for each regime and a marker for each series."""
    handles = [plt.Line2D([], [], ls="", marker="o", color=REGIME_COLOURS.get(g, "grey"), label=g)
               for g in regimes]
    if len(series_labels) > 1:
        handles += [plt.Line2D([], [], ls="", marker=SERIES_MARKERS[n % len(SERIES_MARKERS)],
                               color="k", mfc="none", label=label)
                    for n, label in enumerate(series_labels)]
    ax.legend(handles=handles + list(extra), fontsize=7)


def plot_roller_speed(rows, meta, out):
    rpm = 60 / (2 * math.pi)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    speed_axes = [a["name"] for a in meta["axes"] if a.get("key") == "rollers.speed"]
    series = series_of(rows, meta["axes"], speed_axes)
    for n, members in enumerate(series.values()):
        marker = SERIES_MARKERS[n % len(SERIES_MARKERS)]
        for r in members:
            colour = REGIME_COLOURS.get(r["regime"], "grey")
            x = number(r, "roller_speed_rad_s") * rpm
            top.plot([x], [1e3 * (number(r, "amplitude_end_m") or float("nan"))], marker, ms=5,
                     color=colour)
            if number(r, "period_s"):
                bottom.plot([x], [number(r, "period_s")], marker, ms=5, color=colour)
        # Each series' points joined, so a series reads as one line across the regimes.
        ordered = sorted(members, key=lambda r: number(r, "roller_speed_rad_s"))
        top.plot([number(r, "roller_speed_rad_s") * rpm for r in ordered],
                 [1e3 * (number(r, "amplitude_end_m") or float("nan")) for r in ordered], "-",
                 color="grey", lw=0.6, alpha=0.6)
    regimes = sorted({r["regime"] for r in rows if r["regime"]})
    thresholds = sorted(t for t in (number(r, "slip_threshold_rad_s") for r in rows) if t)
    if thresholds:
        t = thresholds[len(thresholds) // 2] * rpm
        for ax in (top, bottom):
            ax.axvline(t, color="k", ls="--", lw=1)
    thick = sorted(t for t in (number(r, "period_thick_s") for r in rows) if t)
    if thick:
        bottom.axhline(thick[len(thick) // 2], color="k", lw=0.8, alpha=0.6, label="thick-plate T")
    axis = next((a for a in meta["axes"] if a.get("key") == "rollers.speed"), None)
    if axis and axis.get("scale") == "log":
        top.set_xscale("log")
    top.set_ylabel("amplitude at the end [mm]")
    top.set_title(f"{meta['sweep']}: the slip threshold (colour: regime; marker: series)")
    top.grid(True, which="both", alpha=0.3)
    slip = [plt.Line2D([], [], color="k", ls="--", lw=1, label=f"slip condition a ω_r = A ω: {t:.0f} rpm")] \
        if thresholds else []
    legend_by_regime_and_series(top, regimes, list(series), slip)
    bottom.set_xlabel("roller speed [rpm]")
    bottom.set_ylabel("period T [s] (oscillating runs)")
    bottom.grid(True, which="both", alpha=0.3)
    if thick:
        bottom.legend(fontsize=8)
    fig.tight_layout()
    atomic_png.save(fig, os.path.join(out, "roller-speed.png"))


def plot_runout(rows, meta, out):
    axis = next(a for a in meta["axes"] if a.get("key") == "rollers.runout" and len(a["values"]) > 1)
    pos, numeric = axis_positions(axis)
    unit = axis.get("unit") or "m"
    ok = [r for r in rows if r["status"] == "ok"]
    ideal = next((r for r in ok if numeric and pos[r[axis["name"]]] == 0), None)
    fig, (top, middle, bottom) = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    xs = [pos[r[axis["name"]]] for r in ok]
    top.plot(xs, [1e3 * (number(r, "highest_jump_m") or 0) for r in ok], "o-", ms=4, color="C3")
    share = []
    for r in ok:
        used, dropped = number(r, "periods_used") or 0, number(r, "periods_discarded") or 0
        share.append(100 * dropped / (used + dropped) if used + dropped else float("nan"))
    middle.plot(xs, share, "o-", ms=4, color="C1")
    reference = number(ideal, "period_trajectory_s") if ideal else None
    for key, label, colour in (("period_s", "the rig's estimator (periods kept)", "C0"),
                               ("period_trajectory_s", "the trajectory", "k")):
        pts = [(pos[r[axis["name"]]], number(r, key)) for r in ok if number(r, key)]
        base = reference or number(ok[0], "period_thick_s")
        bottom.plot([p[0] for p in pts], [100 * (p[1] / base - 1) for p in pts], "o-", ms=4,
                    color=colour, label=label)
    thresholds = sorted(t for t in (number(r, "runout_threshold_m") for r in ok) if t)
    if thresholds and numeric:
        scale = {"m": 1, "mm": 1e3, "um": 1e6}.get(unit, 1)
        t = thresholds[len(thresholds) // 2] * scale
        for ax in (top, middle, bottom):
            ax.axvline(t, color="k", ls="--", lw=1)
        top.plot([], [], "k--", lw=1, label=f"hop threshold from theory: {t:.3g} {unit}")
        top.legend(fontsize=8)
    top.set_ylabel("highest jump [mm]")
    top.set_title(f"{meta['sweep']}: rollers off their shafts")
    middle.set_ylabel("periods discarded [%]")
    bottom.set_ylabel("period against true rollers [%]" if reference else "T / T_thick − 1 [%]")
    bottom.set_xlabel(axis["name"] + (f" [{unit}]" if numeric else ""))
    bottom.legend(fontsize=8)
    for ax in (top, middle, bottom):
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    atomic_png.save(fig, os.path.join(out, "runout.png"))


def by_regime(rows):
    """Each regime (or status, for a point without one) of the rows, its rows and its colour."""
    for regime in sorted({r["regime"] or r["status"] for r in rows}):
        yield (regime, [r for r in rows if (r["regime"] or r["status"]) == regime],
               REGIME_COLOURS.get(regime, "grey"))


def theory_line(ax, rows, pos, axis, key, label):
    """Theory's value of each point (in thousandths: mm, mm/s) as a black line over the axis."""
    theory = sorted((pos[r[axis["name"]]], number(r, key)) for r in rows
                    if number(r, key) is not None)
    ax.plot([t[0] for t in theory], [1e3 * t[1] for t in theory], "k-", lw=1, label=label)


def finish_two_panels(fig, top, bottom, axis, numeric, out, name, title, top_label, bottom_label):
    """Labels, grids and legends of a plot of two panels over one axis, saved as `name`."""
    unit = axis.get("unit") or "rad"
    top.set_ylabel(top_label)
    top.set_title(title)
    bottom.set_ylabel(bottom_label)
    bottom.set_xlabel(axis["name"] + (f" [{unit}]" if numeric else ""))
    for ax in (top, bottom):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    atomic_png.save(fig, os.path.join(out, name))


def plot_tilt(rows, meta, out):
    axis = next(a for a in meta["axes"] if a.get("key") == "world.tilt" and len(a["values"]) > 1)
    pos, numeric = axis_positions(axis)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    theory_line(top, rows, pos, axis, "oscillation_centre_theory_m",
                "theory: x_eq = -(l - 2 mu_k h_c) tan(tilt) / (2 mu_k)")
    for regime, members, colour in by_regime(rows):
        centred = [r for r in members if number(r, "oscillation_centre_m") is not None]
        top.plot([pos[r[axis["name"]]] for r in centred],
                 [1e3 * number(r, "oscillation_centre_m") for r in centred], "o", ms=5,
                 color=colour, label=f"measured ({regime})")
        if not centred:  # a regime without a centre (tips): marked on the axis
            top.plot([pos[r[axis["name"]]] for r in members], [0] * len(members), "x", ms=8,
                     color=colour, label=f"{regime}: no oscillation")
        timed = [r for r in members if number(r, "period_trajectory_s")]
        bottom.plot([pos[r[axis["name"]]] for r in timed],
                    [number(r, "period_trajectory_s") for r in timed], "o", ms=5, color=colour,
                    label=f"the trajectory ({regime})")
    thick = sorted((pos[r[axis["name"]]], number(r, "period_thick_s")) for r in rows
                   if number(r, "period_thick_s"))
    bottom.plot([t[0] for t in thick], [t[1] for t in thick], "k-", lw=1,
                label="thick plate with g cos(tilt)")
    finish_two_panels(fig, top, bottom, axis, numeric, out, "tilt.png",
                      f"{meta['sweep']}: a rig that is not level", "oscillation centre [mm]",
                      "period T [s]")


def plot_skew(rows, meta, out):
    axis = next(a for a in meta["axes"] if a.get("key") == "rollers.skew" and len(a["values"]) > 1)
    pos, numeric = axis_positions(axis)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    theory_line(top, rows, pos, axis, "drift_speed_theory_m_s", "theory: v_r sin(skew / 2)")
    for regime, members, colour in by_regime(rows):
        drifting = [r for r in members if number(r, "drift_speed_m_s") is not None]
        top.plot([pos[r[axis["name"]]] for r in drifting],
                 [1e3 * number(r, "drift_speed_m_s") for r in drifting], "o", ms=5, color=colour,
                 label=f"measured ({regime})")
        timed = [r for r in members
                 if number(r, "period_trajectory_s") and number(r, "period_thick_s")]
        bottom.plot([pos[r[axis["name"]]] for r in timed],
                    [100 * (number(r, "period_trajectory_s") / number(r, "period_thick_s") - 1)
                     for r in timed], "o", ms=5, color=colour, label=f"the trajectory ({regime})")
    bottom.axhline(0.0, color="k", lw=1, label="thick plate on parallel rollers")
    bottom.axhspan(-0.01, 0.01, color="0.85", label="+-0.01 %")
    finish_two_panels(fig, top, bottom, axis, numeric, out, "skew.png",
                      f"{meta['sweep']}: roller axes not quite parallel", "sideways drift [mm/s]",
                      "T / T_thick - 1 [%]")


def read_cycles(out, index):
    path = os.path.join(out, "cycles", f"{int(index):08d}.csv")
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def plot_cycles(rows, meta, out):
    """Period and amplitude of every cycle against the rollers' speed during it; the ramp's way
    down (filled) and way up (open) apart; theory's slip threshold A = v_r / Omega (dashed), the
    stick-slip cycle where it has a closed form (dotted), the thick-plate period."""
    label_axis = meta["axes"][0]["name"] if meta["axes"] else None
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 8.5), sharex=True)
    styles = {"down": dict(marker="o", mfc=None), "up": dict(marker="^", mfc="none"),
              "hold": dict(marker="x", mfc=None)}
    drew_limit = False
    for n, r in enumerate(rows):
        cycles = read_cycles(out, r["index"])
        if not cycles:
            continue
        colour = f"C{n % 10}"
        name = r.get(label_axis, "") if label_axis else meta["sweep"]
        name = name.strip("{}")
        for direction, style in styles.items():
            members = [c for c in cycles if c["ramp"] == direction]
            if not members:
                continue
            rpm = [number(c, "roller_speed_rpm") for c in members]
            kw = dict(ls="none", ms=3.2, color=colour, marker=style["marker"], alpha=0.8)
            if style["mfc"] is not None:
                kw["mfc"] = style["mfc"]
            top.plot(rpm, [number(c, "period_s") for c in members], **kw)
            bottom.plot(rpm, [1e3 * number(c, "amplitude_m") for c in members], **kw)
        bottom.plot([], [], "s", color=colour, label=f"{name} ({r['regime'] or r['status']})")
        # Theory at each cycle's speed, along the speeds the ramp went through.
        by_speed = sorted(cycles, key=lambda c: number(c, "roller_speed_rpm"))
        limit = [(number(c, "roller_speed_rpm"), number(c, "slip_limit_amplitude_m")) for c in by_speed
                 if number(c, "slip_limit_amplitude_m") is not None]
        # Theory is drawn over the measured cycles (it lies on them where it holds).
        if limit and not drew_limit:
            bottom.plot([p[0] for p in limit], [1e3 * p[1] for p in limit], "k--", lw=1, zorder=5)
            drew_limit = True
        stick = [(number(c, "roller_speed_rpm"), number(c, "stick_slip_amplitude_m"),
                  number(c, "stick_slip_period_s")) for c in by_speed
                 if number(c, "stick_slip_amplitude_m") is not None]
        clipped = all(abs(p[1] - number(c, "slip_limit_amplitude_m")) < 1e-9 * p[1]
                      for p, c in zip(stick, [c for c in by_speed
                                              if number(c, "stick_slip_amplitude_m") is not None]))
        if stick and not clipped:
            bottom.plot([p[0] for p in stick], [1e3 * p[1] for p in stick], ":", color="k", lw=1.3,
                        zorder=5)
            top.plot([p[0] for p in stick], [p[2] for p in stick], ":", color="k", lw=1.3, zorder=5)
    thick = sorted(t for t in (number(r, "period_thick_s") for r in rows) if t)
    if thick:
        top.axhline(thick[len(thick) // 2], color="k", lw=0.8, alpha=0.6,
                    label=f"thick-plate period {thick[len(thick) // 2]:.4f} s")
    thresholds = sorted(t for t in (number(r, "slip_threshold_rad_s") for r in rows) if t)
    amplitudes = sorted(a for a in (number(r, "amplitude_start_m") for r in rows) if a)
    if thresholds:
        t = thresholds[len(thresholds) // 2] * 60 / (2 * math.pi)
        for ax in (top, bottom):
            ax.axvline(t, color="grey", ls="-.", lw=0.8)
        start = f" for A = {1e3 * amplitudes[len(amplitudes) // 2]:.1f} mm" if amplitudes else ""
        top.plot([], [], "-.", color="grey", lw=0.8, label=f"slip threshold{start}: {t:.0f} rpm")
    bottom.plot([], [], "k--", lw=1, label="slip threshold: A Ω = a ω_r (above: the plate reaches "
                "a roller's speed)")
    bottom.plot([], [], "k:", lw=1.2, label="stick-slip cycle (closed form, μ_s > μ_k)")
    top.plot([], [], "ko", ms=3.2, ls="none", label="ramp going down")
    top.plot([], [], "k^", ms=3.2, mfc="none", ls="none", label="ramp going up")
    top.plot([], [], "k:", lw=1.2, label="stick-slip period (closed form)")
    for ax in (top, bottom):
        ax.set_xscale("log")
        ax.grid(True, which="both", alpha=0.3)
    top.set_ylabel("period of the cycle [s]")
    top.set_title(f"{meta['sweep']}: each cycle against the rollers' speed during it")
    top.legend(fontsize=7.5, loc="upper right")
    bottom.set_xlabel("roller speed, mean over the cycle [rpm]")
    bottom.set_ylabel("amplitude of the cycle [mm]")
    bottom.set_yscale("log")
    bottom.legend(fontsize=7.5, loc="upper left")
    fig.tight_layout()
    atomic_png.save(fig, os.path.join(out, "cycles.png"))


def axis_positions(axis, even_over_decades=False):
    """Each value's place on the plot's axis: its number, or (for texts, and with
    even_over_decades for numbers spanning more than a factor 10 on a linear axis, which would
    crowd all but the largest into a corner) its index, evenly spaced. Returns the places and
    whether they are the numbers."""
    numbers = axis.get("numbers") or []
    if numbers and all(n is not None for n in numbers):
        positive = [n for n in numbers if n > 0]
        spread = (len(positive) == len(numbers) and max(positive) > 10 * min(positive))
        if not (even_over_decades and spread and axis.get("scale") != "log"):
            return {v: n for v, n in zip(axis["values"], numbers)}, True
    return {v: i for i, v in enumerate(axis["values"])}, False


def plot_map(rows, meta, out, a, b):
    # A map is a grid of the axes' values: evenly spaced where the values span decades.
    xa, xnum = axis_positions(a, even_over_decades=True)
    ya, ynum = axis_positions(b, even_over_decades=True)
    fig, ax = plt.subplots(figsize=(9, 5.5))
    xs = [xa[r[a["name"]]] for r in rows]
    ys = [ya[r[b["name"]]] for r in rows]
    errs = [100 * (number(r, "error_vs_thick") if number(r, "error_vs_thick") is not None else float("nan"))
            for r in rows]
    finite = [abs(e) for e in errs if not math.isnan(e)]
    if finite:
        lim = max(finite)
        sc = ax.scatter(xs, ys, c=errs, cmap="coolwarm", vmin=-lim, vmax=lim, s=90, marker="s")
        fig.colorbar(sc, ax=ax, label="T / T_thick − 1 [%]")
    else:  # no point gave a period (all failed, invalid, or too short): the points alone
        ax.scatter(xs, ys, s=90, marker="s", color="lightgrey")
    others = set()
    for x, y, e, r in zip(xs, ys, errs, rows):
        if math.isnan(e) and r["regime"] == "oscillates" and r["status"] == "ok":
            # Oscillating, with no error to colour (no period, or no thick-plate theory).
            ax.scatter([x], [y], s=90, marker="s", color="lightgrey")
            ax.annotate("?", (x, y), ha="center", va="center", fontsize=7, color="k")
            others.add("oscillates, no error measured")
            continue
        if r["regime"] != "oscillates" or r["status"] != "ok":
            mark = r["regime"] or r["status"]
            others.add(mark)
            ax.scatter([x], [y], s=90, marker="s", color=REGIME_COLOURS.get(mark, "lightgrey"))
            ax.annotate(mark[:1], (x, y), ha="center", va="center", fontsize=7, color="white")
    if others:
        ax.legend(handles=[plt.Line2D([], [], ls="", marker="s", color=REGIME_COLOURS.get(m, "lightgrey"),
                                      label=("?" if m.startswith("oscillates") else m[:1]) + f": {m}")
                           for m in sorted(others)],
                  fontsize=7, loc="upper left", bbox_to_anchor=(1.18, 1.0))
    ax.set_xlabel(a["name"] + (f" [{a['unit']}]" if xnum and a.get("unit") else ""))
    ax.set_ylabel(b["name"] + (f" [{b['unit']}]" if ynum and b.get("unit") else ""))
    if not xnum:
        ax.set_xticks(list(xa.values()), list(xa.keys()), rotation=30, ha="right", fontsize=8)
    if not ynum:
        ax.set_yticks(list(ya.values()), list(ya.keys()), fontsize=8)
    if xnum and a.get("scale") == "log":
        ax.set_xscale("log")
    if ynum and b.get("scale") == "log":
        ax.set_yscale("log")
    ax.margins(0.08)
    ax.set_title(f"{meta['sweep']}: error against the thick-plate formula "
                 "(letters: regimes other than oscillating)")
    fig.tight_layout()
    atomic_png.save(fig, os.path.join(out, "map.png"))


def plot_axis(rows, meta, out, a):
    pos, numeric = axis_positions(a)
    fig, ax = plt.subplots(figsize=(8, 5))
    for regime in sorted({r["regime"] or r["status"] for r in rows}):
        members = [r for r in rows if (r["regime"] or r["status"]) == regime and number(r, "period_s")]
        ax.errorbar([pos[r[a["name"]]] for r in members], [number(r, "period_s") for r in members],
                    yerr=[number(r, "period_std_s") or 0 for r in members], fmt="o", ms=4,
                    color=REGIME_COLOURS.get(regime, "grey"), label=regime)
    thick = [(pos[r[a["name"]]], number(r, "period_thick_s")) for r in rows if number(r, "period_thick_s")]
    ax.plot([t[0] for t in thick], [t[1] for t in thick], "k_", ms=12, label="thick-plate T")
    if not numeric:
        ax.set_xticks(list(pos.values()), list(pos.keys()), rotation=30, ha="right", fontsize=8)
    if a.get("scale") == "log":
        ax.set_xscale("log")
    ax.set_xlabel(a["name"] + (f" [{a['unit']}]" if numeric and a.get("unit") else ""))
    ax.set_ylabel("period T [s]")
    ax.set_title(f"{meta['sweep']}: period against {a['name']}")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    atomic_png.save(fig, os.path.join(out, "axis.png"))


def main(csv_path, json_path, out):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    with open(json_path) as f:
        meta = json.load(f)
    drawn = 0
    has_cycles = os.path.isdir(os.path.join(out, "cycles")) and any(
        read_cycles(out, r["index"]) for r in rows)
    if has_cycles:
        plot_cycles(rows, meta, out)
        drawn += 1
    if len(distinct(rows, "spacing_m")) > 1:
        plot_spacing(rows, meta, out)
        drawn += 1
    if len(distinct(rows, "mu_k_set")) > 1:
        plot_mu(rows, meta, out)
        drawn += 1
    speeds = distinct(rows, "roller_speed_rad_s")
    if len(speeds) > 1 and speeds[-1] > 1.01 * speeds[0] and not has_cycles:
        plot_roller_speed(rows, meta, out)
        drawn += 1
    if any(a.get("key") == "rollers.runout" and len(a["values"]) > 1 for a in meta["axes"]):
        plot_runout(rows, meta, out)
        drawn += 1
    if any(a.get("key") == "world.tilt" and len(a["values"]) > 1 for a in meta["axes"]):
        plot_tilt(rows, meta, out)
        drawn += 1
    if any(a.get("key") == "rollers.skew" and len(a["values"]) > 1 for a in meta["axes"]):
        plot_skew(rows, meta, out)
        drawn += 1
    varied = [a for a in meta["axes"] if len(a["values"]) > 1]
    if len(varied) >= 2:
        plot_map(rows, meta, out, varied[0], varied[1])
        drawn += 1
    if drawn == 0 and varied:
        plot_axis(rows, meta, out, varied[0])


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
