#!/usr/bin/python3
"""Draws a strand or oscillator run from its HDF5 files alone.

usage: /usr/bin/python3 analysis/plot_run.py RUN_DIR [--out DIR]

For every point file: a strand run gives its settled shape (and the shapes stored along the way)
and its kinetic-energy curve on a log scale with the settling time marked; an oscillator run gives
the numeric and exact displacement and the error. Figures go to RUN_DIR/figures/ as PNG.
"""
import argparse
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def text(attr):
    return attr.decode() if isinstance(attr, bytes) else str(attr)


def plot_strand(f, title, out_png):
    fig, (shape, energy) = plt.subplots(1, 2, figsize=(11, 4))
    pos = f["lagrangian/positions_m"][...]  # (frames, particles, 2)
    times = f["lagrangian/time_s"][...]
    for k in range(pos.shape[0]):
        last = k == pos.shape[0] - 1
        shape.plot(pos[k, :, 0] * 1e3, pos[k, :, 1] * 1e3, color="k" if last else "0.6",
                   lw=1.5 if last else 0.6, alpha=1.0 if last else 0.4,
                   label=f"t = {times[k]:.1f} s" if last else None)
    shape.plot(pos[-1, [0, -1], 0] * 1e3, pos[-1, [0, -1], 1] * 1e3, "ks", ms=5)
    shape.set_xlabel("x (mm)")
    shape.set_ylabel("y (mm)")
    shape.set_aspect("equal", adjustable="datalim")
    shape.set_title("shape (grey: earlier frames)")
    shape.legend(loc="lower right", fontsize=8)

    t = f["timeseries/time_s"][...]
    ke = f["timeseries/kinetic_energy_j"][...]
    energy.semilogy(t, np.maximum(ke, 1e-300), "k", lw=1)
    settle = float(f["metrics/settling_time_s"][()])
    frac = float(f.attrs["settling_fraction"])
    energy.axhline(ke.max() * frac, color="tab:red", lw=0.8, ls="--", label=f"{frac:g} of peak")
    if np.isfinite(settle):
        energy.axvline(settle, color="tab:red", lw=0.8, label=f"settled at {settle:.2f} s")
    energy.set_ylim(max(ke.max() * 1e-8, 1e-300), ke.max() * 3)
    energy.set_xlabel("time (s)")
    energy.set_ylabel("kinetic energy (J)")
    energy.set_title("settling")
    energy.legend(fontsize=8)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)


def plot_oscillator(f, title, out_png):
    fig, (xs, err) = plt.subplots(1, 2, figsize=(11, 4))
    t = f["timeseries/time_s"][...]
    xs.plot(t, f["timeseries/x_exact_m"][...], "k", lw=2, label="exact")
    xs.plot(t, f["timeseries/x_m"][...], "tab:orange", lw=1, label=text(f.attrs["integrator"]))
    xs.set_xlabel("time (s)")
    xs.set_ylabel("displacement (m)")
    xs.legend(fontsize=8)
    err.semilogy(t, np.abs(f["timeseries/error_m"][...]) + 1e-300, "tab:orange", lw=1)
    err.set_xlabel("time (s)")
    err.set_ylabel("|x - x_exact| (m)")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run")
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    out = args.out or os.path.join(args.run, "figures")
    os.makedirs(out, exist_ok=True)
    drawn = 0
    for path in sorted(glob.glob(os.path.join(args.run, "point_*.h5"))):
        with h5py.File(path, "r") as f:
            kind = text(f.attrs["kind"])
            label = text(f.attrs["label"])
            status = text(f.attrs["status"])
            name = os.path.splitext(os.path.basename(path))[0]
            title = f"{text(f.attrs['title'])}\n{name} {label} ({status})"
            png = os.path.join(out, name + ".png")
            if status != "ok":
                print(f"{name}: {status}: {text(f.attrs['message'])}")
                continue
            if kind == "strand":
                plot_strand(f, title, png)
            elif kind == "oscillator":
                plot_oscillator(f, title, png)
            else:
                print(f"{name}: kind {kind} is not drawn by this script")
                continue
            drawn += 1
            print(png)
    if drawn == 0:
        raise SystemExit(f"{args.run}: nothing drawn")


if __name__ == "__main__":
    main()
