#!/usr/bin/python3
"""Draws controller-in-the-fluid runs (kind `control_fluid`, experiments/control/block_flow.toml ...)
from their HDF5 alone (Lentine et al. 2010 Figs. 2, 8).

usage: /usr/bin/python3 analysis/plot_control_fluid.py RUN_DIR [--out DIR]

vorticity.png: the last recorded vorticity field with the bodies' outline markers, one panel per
point (Fig. 8 analogues). frames_<k>/frame_NNN.png: point k's recorded frames one per file (an
animation-friendly series; first two points only). angles.png: the controlled angle and the fluid
force along w against time, per point. convergence.txt: per point the final flow angle, its
deviation from flow-aligned (min) or perpendicular (max), and the converged frame beside the
paper's Fig. 2 (Navier-Stokes rows: 56 maximising, 50 minimising). parallel_dofs.txt: wall seconds
per frame against controlled joints and threads (Fig. 10), when the run has several thread counts.
Figures go to RUN_DIR/figures/.
"""
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402

from plot_control import timing_table  # noqa: E402
import plot_swimmer  # noqa: E402
import style  # noqa: E402

# Fig. 2, the Navier-Stokes rows: first converged frame by (objective, sense); drag_along is the
# drag the block feels along the stream.
PAPER_FRAME = {("drag", "max"): 56, ("drag", "min"): 50, ("effort", "min"): 30}


def text(f, name):
    v = f.attrs.get(name, "")
    return v.decode() if isinstance(v, bytes) else str(v)


def label(f):
    return text(f, "label") or f"{text(f, 'objectives')} {text(f, 'senses')}"


def metric(f, name):
    return float(f[f"metrics/{name}"][()])


def draw_field(ax, f, k, lim=None):
    w = f["fields/vorticity_per_s"]
    dx = float(f.attrs["domain_m"]) / w.shape[2]
    ox, oz = float(f.attrs["origin_x_m"]), float(f.attrs["origin_z_m"])
    ext = [ox, ox + w.shape[2] * dx, oz, oz + w.shape[1] * dx]
    lim = lim or (np.percentile(np.abs(w[k]), 99) or 1)
    im = ax.imshow(w[k], origin="lower", extent=ext, cmap="RdBu_r", vmin=-lim, vmax=lim)
    xy = f["lagrangian/markers_m"][min(k, f["lagrangian/markers_m"].shape[0] - 1)]
    ax.plot(xy[:, 0], xy[:, 1], "k.", ms=1.0)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("z (m)")
    return im, lim


def vorticity_figure(points, png):
    n = len(points)
    cols = min(n, 3)
    rows = (n + cols - 1) // cols
    fig, axes = style.subplots(rows, cols, width=min(style.WIDTH_IN, 4.2 * cols), height=4.0 * rows, squeeze=False)
    for ax in axes.flat[n:]:
        ax.axis("off")
    for ax, f in zip(axes.flat, points):
        last = f["fields/vorticity_per_s"].shape[0] - 1
        im, _ = draw_field(ax, f, last)
        ax.set_title(style.wrap(f"{label(f)}; flow angle {metric(f, 'flow_angle_deg'):.1f} deg, t = "
                                f"{f['fields/time_s'][last]:.2f} s", 36))
        fig.colorbar(im, ax=ax, shrink=0.8).set_label("vorticity (1/s)")
    fig.suptitle(style.wrap("vorticity (1/s) and the bodies' outline markers; stream from the left (Fig. 8)", 100))
    style.save(fig, png)


def frame_series(f, folder):
    os.makedirs(folder, exist_ok=True)
    w = f["fields/vorticity_per_s"]
    lim = np.percentile(np.abs(w[w.shape[0] - 1]), 99) or 1
    for k in range(w.shape[0]):
        fig, ax = style.subplots(width=5.5, height=5)
        im, _ = draw_field(ax, f, k, lim)
        fig.colorbar(im, ax=ax, shrink=0.8).set_label("vorticity (1/s)")
        ax.set_title(style.wrap(f"{label(f)}: t = {f['fields/time_s'][k]:.2f} s", 50))
        style.save(fig, os.path.join(folder, f"frame_{k:04d}.png"))


def angles_figure(points, png):
    fig, (ax_angle, ax_force) = style.subplots(1, 2, height=4.6)
    for f in points:
        t = f["timeseries/time_s"][...]
        joints = [k[len("angle_deg_"):] for k in f["timeseries"] if k.startswith("angle_deg_")]
        for j in joints:
            line, = ax_angle.plot(t, f[f"timeseries/angle_deg_{j}"][...], lw=1, label=f"{label(f)}: {j}")
            ax_force.plot(t, f[f"timeseries/drag_along_n_{j}"][...], lw=0.6, color=line.get_color())
    ax_angle.set_xlabel("time (s)")
    ax_angle.set_ylabel("joint angle (deg; 0 along the stream)")
    ax_force.set_xlabel("time (s)")
    ax_force.set_ylabel("fluid force on the joint's bodies along w (N)")
    ax_force.set_yscale("symlog", linthresh=100)
    ax_angle.legend(ncol=1 if len(ax_angle.get_lines()) < 6 else 2)
    style.save(fig, png)


def converged(angles, tol_deg, tail):
    """The first frame from which the angle stays within tol_deg of its mean over the last `tail`."""
    mean = angles[-tail:].mean()
    first = len(angles)
    while first > 0 and abs(angles[first - 1] - mean) <= tol_deg:
        first -= 1
    return first + 1


def convergence_table(points, path):
    """converged_frame is the run's metric (its convergence_tolerance_deg); at_2.5deg the same at
    2.5 degrees: the fluid's unsteadiness moves the optimum by about two strength steps."""
    with open(path, "w") as out:
        out.write("point                      sense  flow_angle_deg  deviation_deg  converged_frame  at_2.5deg  paper_frame\n")
        for f in points:
            sense = text(f, "senses").split(",")[0].strip()
            objective = text(f, "objectives").split(",")[0].strip().replace("drag_along", "drag")
            angle = metric(f, "flow_angle_deg")
            deviation = angle if sense == "min" else 90 - angle
            a = f["timeseries/angle_deg_" + text(f, "controlled").split(",")[0].strip()][...]
            tail = int(f.attrs["average_frames"])
            out.write(f"{label(f):26s} {sense:5s}  {angle:14.2f}  {deviation:13.2f}  "
                      f"{int(metric(f, 'converged_frame')):15d}  {converged(a, 2.5, tail):9d}  "
                      f"{PAPER_FRAME.get((objective, sense), 0):11d}\n")


def draw(run, out):
    """Every figure of the run folder `run`, as PNGs (and tables) in folder `out`."""
    os.makedirs(out, exist_ok=True)
    points = [h5py.File(p, "r") for p in sorted(glob.glob(os.path.join(run, "point_*.h5")))]
    if not points:
        raise SystemExit(f"{run}: no points")
    with_fields = [f for f in points if "fields/vorticity_per_s" in f]
    if with_fields:
        vorticity_figure(with_fields, os.path.join(out, "vorticity.png"))
        for k, f in enumerate(with_fields[:2]):
            frame_series(f, os.path.join(out, f"frames_{k}"))
    angles_figure(points, os.path.join(out, "angles.png"))
    convergence_table(points, os.path.join(out, "convergence.txt"))
    if len({(int(f.attrs["threads"]), int(f.attrs.get("fluid_threads", 1))) for f in points}) > 1:
        timing_table(points, os.path.join(out, "parallel_dofs.txt"))
    plot_swimmer.draw(points, out, draw_field)  # the swimmer's rise (§7.2), when the run tracks one
    for f in points:
        f.close()


def figures(run):
    """(name, Figure) of every figure of the run folder `run`."""
    return style.collect(draw, run)


def main():
    style.main(draw, __doc__)


if __name__ == "__main__":
    main()
