"""The jellyfish's wake circulation, from a point's stored vorticity fields (the
mechanism of a claim the converged model misses, stagger.toml).

Per field frame, on the right half of the box (x > the box's axis) and below the bell's lowest
marker (the aperture), the positive and the negative circulation, sum of w dA over the cells of each
sign. On that half a downward jet's starting vortex turns counter-clockwise (w > 0) and the
re-expansion's stopping vortex clockwise (w < 0). Per whole cycle of the window, the peak of each;
their means over the cycles are what wake.txt lists, and wake.png draws the two series.
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import style  # noqa: E402


def circulation_series(f, param):
    """(time_s, positive, negative) circulation below the aperture on the right half, m^2/s. param(f, name)
    reads a point's parameter (plot_jellyfish.param)."""
    w = f["fields/vorticity_per_s"]
    tf = f["fields/time_s"][...]
    ny, nx = w.shape[1], w.shape[2]
    dx = float(param(f, "domain_m")) / int(param(f, "cells"))
    x = (np.arange(nx) + 0.5) * dx - 0.5 * nx * dx
    y = (np.arange(ny) + 0.5) * dx
    tm = f["lagrangian/time_s"][...]
    markers = f["lagrangian/markers_m"]
    bell = int(f["topology/bell_markers"][0])
    pos, neg = np.zeros(len(tf)), np.zeros(len(tf))
    for k in range(len(tf)):
        aperture_y = float(np.min(markers[int(np.argmin(abs(tm - tf[k])))][:bell, 1]))
        half = w[k][y < aperture_y, :][:, x > 0]
        pos[k] = half[half > 0].sum() * dx * dx
        neg[k] = half[half < 0].sum() * dx * dx
    return tf, pos, neg


def cycle_peaks(f, param, tf, pos, neg):
    """Mean over the window's whole cycles of each cycle's peak starting and stopping circulation."""
    hz = float(param(f, "contraction_hz"))
    warm = float(param(f, "warmup_cycles")) / hz
    cycles = int(np.floor(float(param(f, "duration_s")) * hz + 1e-9))
    spans = [(tf >= warm + c / hz) & (tf < warm + (c + 1) / hz) for c in range(cycles)]
    spans = [m for m in spans if m.any()]
    return float(np.mean([pos[m].max() for m in spans])), float(np.mean([neg[m].min() for m in spans])), len(spans)


def wake(points, labels, param, out):
    """wake.txt and wake.png for the points that stored fields; nothing when none did."""
    rows, series = [], []
    for k, f in enumerate(points):
        if "fields/vorticity_per_s" not in f:
            continue
        tf, pos, neg = circulation_series(f, param)
        start, stop, n = cycle_peaks(f, param, tf, pos, neg)
        rows.append(f"{labels[k]}: starting {start:.4e} m^2/s, stopping {stop:.4e}, difference {start + stop:.4e} "
                    f"(means of each of {n} cycles' peaks)")
        series.append((labels[k], tf, pos, neg))
    if not rows:
        return
    with open(os.path.join(out, "wake.txt"), "w") as fh:
        fh.write("wake circulation below the aperture, right half (jellyfish_wake.py)\n" + "\n".join(rows) + "\n")
    print("\n".join(rows))
    fig, ax = plt.subplots(figsize=(9, 4))
    for label, tf, pos, neg in series:
        line = ax.plot(tf, pos * 1e4, lw=1, label=f"{label}: w > 0 (starting vortex)")[0]
        ax.plot(tf, neg * 1e4, lw=1, ls="--", color=line.get_color(), label=f"{label}: w < 0 (stopping vortex)")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("circulation below the aperture, right half (cm^2/s)")
    ax.legend(fontsize=9)
    style.save(fig, os.path.join(out, "wake.png"))
