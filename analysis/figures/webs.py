"""Drawing orb webs for the Mehla figures: one web per panel from a point file's positions and
topology (analysis/draw_web.py's draw_web), a grid of the points of a sweep, settling curves."""
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from figures import runs  # noqa: E402
import style  # noqa: E402


def draw_web(f, ax, frame=-1, by_type=False):
    dw = runs.plotter("draw_web")
    k = frame if frame >= 0 else f["lagrangian/positions_m"].shape[0] + frame
    dw.draw_web(f, ax, k, by_type)


def settling_curve(f, ax, label=None, colour="k"):
    """Kinetic energy against time on a log scale, the settling time marked (thesis §5.1: webs
    settle in 5-10 s)."""
    t = f["timeseries/time_s"][...]
    ke = f["timeseries/kinetic_energy_j"][...]
    ax.semilogy(t, np.maximum(ke, 1e-300), color=colour, lw=0.8, label=label)
    if "metrics/settling_time_s" in f:
        s = float(f["metrics/settling_time_s"][()])
        if np.isfinite(s):
            ax.axvline(s, color=colour, lw=0.6, ls="--")
    # Ten decades below the largest peak drawn on these axes (the energy starts at 0).
    top = max(getattr(ax, "_ke_top", 0.0), float(ke.max()) * 3)
    ax._ke_top = top
    if top > 0:
        ax.set_ylim(top * 1e-10, top)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("kinetic energy (J)")


def sweep_grid(run, out, name, title, metrics=("particles", "spiral_segments", "hub_sag_m", "settling_time_s")):
    """One panel per point (the web at its last stored frame, grey shades), then the sweep's metrics
    per point, and the settling curves of every point."""
    points = run.points()
    labels = run.labels()
    n = len(points)
    cols = min(4, max(1, n))
    rows = math.ceil(n / cols)
    panel = style.WIDTH_IN / cols
    fig = style.figure(height=(panel + 0.4) * rows + 3.6)
    gs = fig.add_gridspec(rows + 1, cols, height_ratios=[panel + 0.4] * rows + [3.6])
    for k, f in enumerate(points):
        ax = fig.add_subplot(gs[k // cols, k % cols])
        if runs.text(f.attrs.get("status", "ok")) != "ok":
            ax.text(0.5, 0.5, runs.text(f.attrs.get("message", "failed")), ha="center", wrap=True, fontsize=9)
            ax.axis("off")
        else:
            draw_web(f, ax)
        ax.set_title(style.wrap(labels[k] if k < len(labels) else str(k), int(panel * 9)))
    bottom = gs[rows, :].subgridspec(1, 2, width_ratios=[1, 1])
    bars = fig.add_subplot(bottom[0, 0])
    x = np.arange(len(labels))
    shown = [m for m in metrics if m in run.sweep]
    for j, m in enumerate(shown):
        v = run.metric(m)
        ref = np.nanmax(np.abs(v)) or 1.0
        bars.plot(x, v / ref, "o-", ms=3, label=f"{m} (max {ref:.3g} {run.units.get(m, '')})")
    bars.set_xticks(x, labels, rotation=25, ha="right", fontsize=9)
    bars.set_ylabel("relative to the largest (ratio)")
    bars.set_xlabel("sweep point")
    bars.set_title("the sweep's measures")
    bars.legend(fontsize=9)
    curves = fig.add_subplot(bottom[0, 1])
    cmap = plt.get_cmap("viridis")
    for k, f in enumerate(points):
        if "timeseries/kinetic_energy_j" in f:
            settling_curve(f, curves, labels[k] if n <= 8 else None, cmap(k / max(1, n - 1)))
    if n <= 8:
        curves.legend(fontsize=9)
    curves.set_title("settling (dashed: settled)", fontsize=9)
    fig.suptitle(style.wrap(title, 100))
    return style.save(fig, os.path.join(out, name))
