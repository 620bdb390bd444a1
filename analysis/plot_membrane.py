#!/usr/bin/python3
"""Draws membrane runs (kind `membrane`, experiments/jellyfish/membrane.toml) from their HDF5 files alone.

usage: /usr/bin/python3 analysis/plot_membrane.py RUN_DIR [--out DIR]

area_loss.png: enclosed-area loss (percent of the initial area) and aspect ratio against time, one
curve per point (kernel x cells). outlines.png: the markers' outline at a few times per point, with
the circle of the final area dashed. Figures go to RUN_DIR/figures/ as PNG.
"""
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import style  # noqa: E402


def label(f):
    return f"{f.attrs['kernel']}, {f.attrs['cells']} cells"


def line_style(f):
    """Colour by kernel, line by grid, so the four runs of membrane.toml read at a glance."""
    colour = {"bilinear": "tab:blue", "peskin4": "tab:orange"}.get(str(f.attrs["kernel"]), "k")
    line = "-" if int(f.attrs["cells"]) >= 100 else "--"
    return colour, line


def area_loss(points, title, png):
    fig, (ax_loss, ax_aspect) = style.subplots(1, 2, height=4.0)
    for f in points:
        t = f["timeseries/time_s"][...]
        colour, line = line_style(f)
        ax_loss.plot(t, 100 * f["timeseries/area_loss_fraction"][...], line, color=colour, label=label(f))
        ax_aspect.plot(t, f["timeseries/aspect_ratio"][...], line, color=colour, label=label(f))
    ax_loss.set_xlabel("time (s)")
    ax_loss.set_ylabel("enclosed-area loss (% of initial)")
    ax_loss.axhline(0, color="k", lw=0.5)
    ax_loss.legend(fontsize=9)
    ax_aspect.set_xlabel("time (s)")
    ax_aspect.set_ylabel("aspect ratio (principal second moments)")
    ax_aspect.axhline(1, color="k", lw=0.5)
    ax_aspect.axhline(1.05, color="k", lw=0.5, ls=":")
    ax_aspect.legend(fontsize=9)
    fig.suptitle(title, fontsize=9)
    style.save(fig, png)


def outlines(points, png):
    fig, axes = style.subplots(1, len(points), height=min(3.8, style.WIDTH_IN / len(points)) + 1.2, squeeze=False)
    for ax, f in zip(axes[0], points):
        x = f["lagrangian/markers_m"]
        t = f["lagrangian/time_s"][...] if "lagrangian/time_s" in f else f["timeseries/time_s"][...]
        # Start, mid-relaxation, about the first round crossing and the overshoot (for membrane.toml's
        # 10 s: 0.8, 1.6, 2.5 s), and the end.
        wanted = t[-1] * np.array([0.0, 0.08, 0.16, 0.25, 1.0])
        frames = np.unique([int(np.argmin(np.abs(t - w))) for w in wanted])
        colours = plt.cm.viridis(np.linspace(0, 0.9, len(frames)))
        for k, c in zip(frames, colours):
            p = x[k]
            ax.plot(np.r_[p[:, 0], p[0, 0]], np.r_[p[:, 1], p[0, 1]], "-", color=c, lw=1, label=f"t = {t[k]:.1f} s")
        # The circle of the final area about the final centroid: where the membrane should end.
        p = x[-1]
        r = np.sqrt(f["timeseries/area_m2"][-1] / np.pi)
        a = np.linspace(0, 2 * np.pi, 200)
        ax.plot(p[:, 0].mean() + r * np.cos(a), p[:, 1].mean() + r * np.sin(a), "k:", lw=1, label="equal-area circle")
        loss = 100 * f["metrics/area_loss_fraction"][()]
        ax.set_title(f"{label(f)}\narea loss {loss:.3f}%", fontsize=9)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
    handles, names = axes[0][0].get_legend_handles_labels()
    axes[0][-1].legend(handles, names, loc="lower right", fontsize=9)
    style.save(fig, png)


def draw(run, out):
    """Every figure of the run folder `run`, as PNGs (and tables) in folder `out`."""
    os.makedirs(out, exist_ok=True)
    files = []
    for path in sorted(glob.glob(os.path.join(run, "point_*.h5"))):
        f = h5py.File(path, "r")
        if f.attrs["status"] != "ok" or "lagrangian/markers_m" not in f:
            print(f"{os.path.basename(path)}: {f.attrs['status']} {f.attrs['message']}")
            f.close()
            continue
        files.append(f)
    if not files:
        raise SystemExit(f"{run}: no finished membrane points")
    files.sort(key=lambda f: (str(f.attrs["kernel"]), int(f.attrs["cells"])))
    title = files[0].attrs["title"]
    png = os.path.join(out, "area_loss.png")
    area_loss(files, title, png)
    print(png)
    png = os.path.join(out, "outlines.png")
    outlines(files, png)
    print(png)
    for f in files:
        f.close()


def figures(run):
    """(name, Figure) of every figure of the run folder `run`."""
    return style.collect(draw, run)


def main():
    style.main(draw, __doc__)


if __name__ == "__main__":
    main()
