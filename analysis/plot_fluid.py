#!/usr/bin/python3
"""Draws fluid runs from their HDF5 files alone.

usage: /usr/bin/python3 analysis/plot_fluid.py RUN_DIR [--out DIR]

For every point: vorticity snapshots (with tracers when stored) and the kinetic-energy curve.
For a sweep over cells (Taylor-Green), also the error against cells per advection scheme on log
axes. Figures go to RUN_DIR/figures/ as PNG.
"""
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402
import style  # noqa: E402


def snapshots(f, title, png, count=4):
    fields = f["fields"]
    t = fields["time_s"][...]
    w = fields["vorticity_per_s"]
    dx = float(fields.attrs["dx_m"])
    ny, nx = w.shape[1], w.shape[2]
    frames = np.linspace(0, len(t) - 1, count).round().astype(int)
    lim = np.abs(w[0]).max() or 1.0
    fig, axes = style.subplots(1, count + 1, height=3.3)
    for ax, k in zip(axes, frames):
        image = ax.imshow(w[k], origin="lower", cmap="RdBu_r", vmin=-lim, vmax=lim, extent=[0, nx * dx, 0, ny * dx])
        if "lagrangian/tracers_m" in f:
            p = f["lagrangian/tracers_m"][k]
            ax.plot(p[:, 0], p[:, 1], ",", color="k", alpha=0.5)
        ax.set_title(f"t = {t[k]:.2f} s")
        ax.set_xticks([])
        ax.set_yticks([])
    ts = f["timeseries/time_s"][...]
    axes[-1].plot(ts, f["timeseries/kinetic_energy_j_per_m"][...], "k")
    axes[-1].set_xlabel("time (s)")
    axes[-1].set_ylabel("kinetic energy (J/m)")
    bar = fig.colorbar(image, ax=list(axes[:-1]), shrink=0.8)
    bar.set_label("vorticity (1/s)")
    fig.suptitle(style.wrap(title, 110))
    style.save(fig, png)


def convergence(run, out):
    with h5py.File(os.path.join(run, "index.h5"), "r") as idx:
        s = idx["sweep"]
        if "cells" not in s or "advection" not in s or np.all(np.isnan(s["velocity_error_rms_m_per_s"][...])):
            return None
        cells = s["cells"][...]
        scheme = s["advection"].asstr()[...]
        err = s["velocity_error_rms_m_per_s"][...]
        title = idx.attrs["title"]
    fig, ax = style.subplots(width=7.0, height=4.6)
    for name in sorted(set(scheme)):
        sel = scheme == name
        order = np.argsort(cells[sel])
        ax.loglog(cells[sel][order], err[sel][order], "o-", label=f"advection {name}")
    ref = np.unique(cells.astype(float))
    ax.loglog(ref, err.max() * (ref.min() / ref), "k:", label="first order (slope -1)")
    ax.loglog(ref, err.max() * (ref.min() / ref) ** 2, "k--", lw=0.8, label="second order (slope -2)")
    # The grids themselves as the x ticks, plain numbers (log minor tick labels overlap).
    ax.set_xticks(ref, [f"{c:g}" for c in ref])
    ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xlabel("fluid cells per side (count)")
    ax.set_ylabel("rms velocity error (m/s)")
    ax.set_title(style.wrap(title, 70))
    ax.legend()
    png = os.path.join(out, "convergence.png")
    style.save(fig, png)
    return png


def draw(run, out):
    """Every figure of the run folder `run`, as PNGs (and tables) in folder `out`."""
    os.makedirs(out, exist_ok=True)
    for path in sorted(glob.glob(os.path.join(run, "point_*.h5"))):
        with h5py.File(path, "r") as f:
            name = os.path.splitext(os.path.basename(path))[0]
            if f.attrs["status"] != "ok" or "fields" not in f:
                print(f"{name}: {f.attrs['status']} {f.attrs['message']}")
                continue
            png = os.path.join(out, name + ".png")
            snapshots(f, f"{f.attrs['title']}\n{name}: advection {f.attrs['advection']}, {f.attrs['cells']} cells", png)
            print(png)
    png = convergence(run, out)
    if png:
        print(png)


def figures(run):
    """(name, Figure) of every figure of the run folder `run`."""
    return style.collect(draw, run)


def main():
    style.main(draw, __doc__)


if __name__ == "__main__":
    main()
