#!/usr/bin/python3
"""Draws a strand or oscillator run from its HDF5 files alone.

usage: /usr/bin/python3 analysis/plot_run.py RUN_DIR [--out DIR]

For every point file: a strand run gives its settled shape (and the shapes stored along the way)
and its kinetic-energy curve on a log scale with the settling time marked; an oscillator run gives
every integrator and step in one figure (displacement, error,
error against the step). Figures go to RUN_DIR/figures/ as PNG.
"""
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import style  # noqa: E402


def text(attr):
    return attr.decode() if isinstance(attr, bytes) else str(attr)


def plot_strand(f, title, out_png):
    fig, (shape, energy) = style.subplots(1, 2, height=4.0)
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
    shape.legend(loc="lower right")

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
    energy.legend()
    fig.suptitle(title)
    style.save(fig, out_png)


INTEGRATOR_WORDS = {"euler": "explicit Euler", "symplectic_euler": "symplectic Euler", "rk4": "RK4",
                    "implicit_euler": "implicit Euler"}


def step(f):
    """The step a point ran with in s: the metric dt_used_s (dt_s may be "auto"), else dt_s."""
    if "metrics/dt_used_s" in f:
        return float(f["metrics/dt_used_s"][()])
    return float(f.attrs["dt_s"])


def plot_oscillators(points, title, out_png):
    """Every integrator and step of an oscillator sweep in one figure: the displacement and the
    error against time at the largest step (a colour per integrator), and the largest error
    against the step on log axes (thesis §4.1-4.2)."""
    fig, (xs, err, order) = style.subplots(1, 3, height=4.0)
    integrators = list(dict.fromkeys(text(f.attrs["integrator"]) for f in points))
    colour = {name: f"C{k}" for k, name in enumerate(integrators)}
    dts = sorted({step(f) for f in points})
    coarse = [f for f in points if step(f) == dts[-1]]
    t = coarse[0]["timeseries/time_s"][...]
    xs.plot(t, coarse[0]["timeseries/x_exact_m"][...] * 1e3, "k", lw=2, label="exact")
    for f in coarse:
        name = text(f.attrs["integrator"])
        tf = f["timeseries/time_s"][...]
        xs.plot(tf, f["timeseries/x_m"][...] * 1e3, color=colour[name], lw=0.9, label=INTEGRATOR_WORDS.get(name, name))
        err.semilogy(tf, np.abs(f["timeseries/error_m"][...]) + 1e-300, color=colour[name], lw=0.9)
    xs.set_xlabel("time (s)")
    xs.set_ylabel("displacement (mm)")
    xs.set_title(f"step {dts[-1]:g} s")
    xs.legend(loc="lower left")
    err.set_xlabel("time (s)")
    err.set_ylabel("|x - exact| (m)")
    err.set_title(f"error, step {dts[-1]:g} s")
    for name in integrators:
        mine = sorted((step(f), float(f["metrics/max_abs_error_m"][()])) for f in points
                      if text(f.attrs["integrator"]) == name)
        order.loglog([d for d, _ in mine], [e for _, e in mine], "o-", color=colour[name], ms=4,
                     label=INTEGRATOR_WORDS.get(name, name))
    order.set_xlabel("time step (s)")
    order.set_ylabel("largest |x - exact| (m)")
    order.set_title("error against the step")
    order.legend()
    fig.suptitle(style.wrap(title, 100))
    style.save(fig, out_png)


def draw(run, out):
    """Every figure of a strand or oscillator run, as PNGs in folder `out`."""
    os.makedirs(out, exist_ok=True)
    drawn = 0
    oscillators, title = [], ""
    for path in sorted(glob.glob(os.path.join(run, "point_*.h5"))):
        f = h5py.File(path, "r")
        kind = text(f.attrs["kind"])
        label = text(f.attrs["label"])
        status = text(f.attrs["status"])
        name = os.path.splitext(os.path.basename(path))[0]
        png = os.path.join(out, name + ".png")
        if status != "ok":
            print(f"{name}: {status}: {text(f.attrs['message'])}")
            f.close()
            continue
        if kind == "oscillator":
            oscillators.append(f)
            title = text(f.attrs["title"])
            continue
        if kind == "strand":
            plot_strand(f, style.wrap(f"{text(f.attrs['title'])}: {label}", 100), png)
            drawn += 1
        else:
            print(f"{name}: kind {kind} is not drawn by this script")
        f.close()
    if oscillators:
        plot_oscillators(oscillators, title, os.path.join(out, "integrators.png"))
        drawn += 1
        for f in oscillators:
            f.close()
    if drawn == 0:
        raise SystemExit(f"{run}: nothing drawn")


def figures(run):
    """(name, Figure) of every figure of the run folder `run`."""
    return style.collect(draw, run)


def main():
    style.main(draw, __doc__)


if __name__ == "__main__":
    main()
