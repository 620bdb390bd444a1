#!/usr/bin/python3
"""Draws orb-web runs from their HDF5 files alone.

usage: /usr/bin/python3 analysis/draw_web.py RUN_DIR [--by-type] [--frame K] [--out DIR]

For every point: the web as a line drawing in the thesis's grey shades with alpha (Mehla 2005
Fig. 5.44: light strands over a dark background), or coloured by strand type with --by-type, at
stored frame K (default: the last), plus its settling curve (kinetic energy, log scale).
For a sweep, a plot of each metric of the sweep table against the point labels.
Figures go to RUN_DIR/figures/.
"""
import argparse
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
import style  # noqa: E402

TYPES = ["outer_frame", "inner_frame", "primary_spoke", "hub", "secondary_spoke", "spiral"]
COLOURS = ["#8c564b", "#d62728", "#1f77b4", "#9467bd", "#2ca02c", "#ff7f0e"]
GREYS = [0.95, 0.9, 0.85, 0.85, 0.8, 0.75]  # frames brightest, spiral faintest (Fig. 5.44)


def draw_web(f, ax, frame, by_type):
    pos = f["lagrangian/positions_m"][frame]  # (particles, 3)
    a = f["topology/spring_a"][...]
    b = f["topology/spring_b"][...]
    kind = f["topology/spring_type"][...]
    for t, name in enumerate(TYPES):
        sel = kind == t
        if not sel.any():
            continue
        segs = np.stack([pos[a[sel], :2], pos[b[sel], :2]], axis=1)
        colour = COLOURS[t] if by_type else str(GREYS[t])
        ax.add_collection(LineCollection(segs, colors=colour, linewidths=0.4, alpha=0.8 if by_type else 0.55,
                                         label=name if by_type else None))
    anchors = f["topology/attachment_particles"][...]
    ax.plot(pos[anchors, 0], pos[anchors, 1], "s", color="k" if by_type else "w", ms=3)
    ax.set_aspect("equal")
    ax.autoscale()
    ax.set_xticks([])
    ax.set_yticks([])
    if not by_type:
        ax.set_facecolor("#1a1a1a")
    else:
        ax.legend(fontsize=9, loc="lower right")


def draw_point(path, out, frame, by_type):
    with h5py.File(path, "r") as f:
        name = os.path.splitext(os.path.basename(path))[0]
        if f.attrs["status"] != "ok":
            print(f"{name}: {f.attrs['status']}: {f.attrs['message']}")
            return None
        fig, (web_ax, ke_ax) = style.subplots(1, 2, height=5.0, gridspec_kw={"width_ratios": [1.3, 1]})
        k = frame if frame is not None else f["lagrangian/positions_m"].shape[0] - 1
        draw_web(f, web_ax, k, by_type)
        t = f["lagrangian/time_s"][k]
        web_ax.set_title(style.wrap(f"{f.attrs['label'] or name}: t = {t:.1f} s, "
                                    f"{int(f['metrics/particles'][()])} particles", 60))
        if "timeseries/kinetic_energy_j" in f:
            ts = f["timeseries/time_s"][...]
            ke = f["timeseries/kinetic_energy_j"][...]
            ke_ax.semilogy(ts, np.maximum(ke, 1e-300), "k", lw=0.8)
            settle = float(f["metrics/settling_time_s"][()])
            if np.isfinite(settle):
                ke_ax.axvline(settle, color="tab:red", lw=0.8, label=f"settled at {settle:.2f} s")
                ke_ax.legend()
            ke_ax.set_ylim(max(ke.max() * 1e-9, 1e-300), ke.max() * 3)
            ke_ax.set_xlabel("time (s)")
            ke_ax.set_ylabel("kinetic energy (J)")
        fig.suptitle(style.wrap(f.attrs["title"], 100))
        png = os.path.join(out, name + (".types" if by_type else "") + ".png")
        style.save(fig, png)
        return png


def sweep_plot(run, out):
    path = os.path.join(run, "index.h5")
    if not os.path.exists(path):
        return None
    with h5py.File(path, "r") as idx:
        s = idx["sweep"]
        if len(s["point_index"]) < 2:
            return None
        labels = [lab or str(i) for lab, i in zip(s["label"].asstr()[...], s["point_index"][...])]
        metrics = ["particles", "spokes", "spiral_segments", "silk_length_m", "hub_sag_m", "settling_time_s"]
        fig, axes = style.subplots(2, 3, height=6.4, sharex=True)
        for ax, m in zip(axes.flat, metrics):
            unit = s[m].attrs["unit"]
            unit = unit.decode() if isinstance(unit, bytes) else str(unit)
            ax.plot(range(len(labels)), s[m][...], "o-")
            ax.set_ylabel(style.label(m, unit if m not in ("particles", "spokes", "spiral_segments") else "count"))
            ax.set_xticks(range(len(labels)))
            ax.set_xticklabels(labels, rotation=30, ha="right")
        for ax in axes[-1]:
            ax.set_xlabel("sweep point")
        fig.suptitle(style.wrap(idx.attrs["title"], 100))
        png = os.path.join(out, "sweep.png")
        style.save(fig, png)
        return png


def draw(run, out, by_type=False, frame=None):
    """Every figure of the run folder `run`, as PNGs (and tables) in folder `out`."""
    os.makedirs(out, exist_ok=True)
    for path in sorted(glob.glob(os.path.join(run, "point_*.h5"))):
        png = draw_point(path, out, frame, by_type)
        if png:
            print(png)
    png = sweep_plot(run, out)
    if png:
        print(png)


def figures(run):
    """(name, Figure) of every figure of the run folder `run`."""
    return style.collect(draw, run)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run")
    ap.add_argument("--by-type", action="store_true", help="colour strands by type instead of grey")
    ap.add_argument("--frame", type=int, default=None, help="stored frame to draw (default: last)")
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    draw(args.run, args.out or os.path.join(args.run, "figures"), by_type=args.by_type, frame=args.frame)


if __name__ == "__main__":
    main()
