#!/usr/bin/python3
"""Draws fluid runs from their HDF5 files alone.

usage: /usr/bin/python3 analysis/plot_fluid.py RUN_DIR [--out DIR]

For every point: vorticity snapshots (with tracers when stored) and the kinetic-energy curve.
For a sweep over cells (Taylor-Green), also the error against cells per advection scheme on log
axes. Figures go to RUN_DIR/figures/ as PNG.
"""
import argparse
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def snapshots(f, title, png, count=4):
    fields = f["fields"]
    t = fields["time_s"][...]
    w = fields["vorticity_per_s"]
    dx = float(fields.attrs["dx_m"])
    ny, nx = w.shape[1], w.shape[2]
    frames = np.linspace(0, len(t) - 1, count).round().astype(int)
    lim = np.abs(w[0]).max() or 1.0
    fig, axes = plt.subplots(1, count + 1, figsize=(3.2 * (count + 1), 3.3))
    for ax, k in zip(axes, frames):
        ax.imshow(w[k], origin="lower", cmap="RdBu_r", vmin=-lim, vmax=lim, extent=[0, nx * dx, 0, ny * dx])
        if "lagrangian/tracers_m" in f:
            p = f["lagrangian/tracers_m"][k]
            ax.plot(p[:, 0], p[:, 1], ",", color="k", alpha=0.5)
        ax.set_title(f"vorticity, t = {t[k]:.2f} s", fontsize=9)
        ax.set_xticks([])
        ax.set_yticks([])
    ts = f["timeseries/time_s"][...]
    axes[-1].plot(ts, f["timeseries/kinetic_energy_j_per_m"][...], "k")
    axes[-1].set_xlabel("time (s)")
    axes[-1].set_ylabel("kinetic energy (J/m)")
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    plt.close(fig)


def convergence(run, out):
    with h5py.File(os.path.join(run, "index.h5"), "r") as idx:
        s = idx["sweep"]
        if "cells" not in s or "advection" not in s or np.all(np.isnan(s["velocity_error_rms_m_per_s"][...])):
            return None
        cells = s["cells"][...]
        scheme = s["advection"].asstr()[...]
        err = s["velocity_error_rms_m_per_s"][...]
        title = idx.attrs["title"]
    fig, ax = plt.subplots(figsize=(5, 4))
    for name in sorted(set(scheme)):
        sel = scheme == name
        order = np.argsort(cells[sel])
        ax.loglog(cells[sel][order], err[sel][order], "o-", label=name)
    ref = cells.astype(float)
    ax.loglog(np.sort(ref), err.max() * (ref.min() / np.sort(ref)), "k:", label="first order")
    ax.set_xlabel("cells per side")
    ax.set_ylabel("rms velocity error (m/s)")
    ax.set_title(title, fontsize=8)
    ax.legend(fontsize=8)
    fig.tight_layout()
    png = os.path.join(out, "convergence.png")
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return png


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run")
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    out = args.out or os.path.join(args.run, "figures")
    os.makedirs(out, exist_ok=True)
    for path in sorted(glob.glob(os.path.join(args.run, "point_*.h5"))):
        with h5py.File(path, "r") as f:
            name = os.path.splitext(os.path.basename(path))[0]
            if f.attrs["status"] != "ok" or "fields" not in f:
                print(f"{name}: {f.attrs['status']} {f.attrs['message']}")
                continue
            png = os.path.join(out, name + ".png")
            snapshots(f, f"{f.attrs['title']}\n{name}: advection {f.attrs['advection']}, {f.attrs['cells']} cells", png)
            print(png)
    png = convergence(args.run, out)
    if png:
        print(png)


if __name__ == "__main__":
    main()
