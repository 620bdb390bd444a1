#!/usr/bin/python3
"""Draws the driven flyer (experiments/control/flyer.toml; Lentine et al. 2010 §7.1, Figs. 11-13)
from its HDF5 alone; points without a flap period (other control_fluid runs) are skipped.

usage: /usr/bin/python3 analysis/plot_flyer.py RUN_DIR [--out DIR]

flyer_angles.png: per point the PD-driven inner angles, the controlled outer angles and the sense
each followed (+1 max on the down-stroke, -1 min on the up-stroke), and the fluid's upward force
on all bodies against time. flyer_force.txt: per point the mean upward force over the last
force_cycles flap cycles, the standard deviation and standard error of its per-flap means, and its
ratio to the held point of the same grid, step, advection, flaps and forcing tolerance (the
experiment's check) with that ratio's standard error, and the reading of F_d its evaluations used.
flyer_vorticity.png: per point the vorticity with the bodies at the last flap's lowest and highest
wing (Fig. 12 (a), (b) analogues; Fig. 11's animation is plot_control_fluid.py's frame series).
The vorticity with the bodies and the frame series are plot_control_fluid.py's.
Figures go to RUN_DIR/figures/.
"""
import argparse
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import numpy as np  # noqa: E402

from plot_control_fluid import draw_field, text  # noqa: E402


def is_flyer(f):
    return float(f.attrs.get("flap_period_s", 0)) > 0 and "timeseries/force_z_n_bodies" in f


def resolution(f):
    return f"{int(f.attrs['cells'])}^2, {int(f.attrs['substeps'])} steps/frame, {text(f, 'advection')}"


def angles_figure(points, png):
    fig, axes = plt.subplots(3, 1, figsize=(10, 9), sharex=True)
    for f in points:
        ts = f["timeseries"]
        t = ts["time_s"][...]
        name = f"{text(f, 'label')} ({resolution(f)})"
        for k in ts:
            if k.startswith("pd_angle_deg_"):
                axes[0].plot(t, ts[k][...], lw=0.8, ls=":", label=f"{name}: {k[len('pd_angle_deg_'):]} (PD)")
        for j in [j.strip() for j in text(f, "controlled").split(",")]:
            line, = axes[0].plot(t, ts[f"angle_deg_{j}"][...], lw=1, label=f"{name}: {j}")
            axes[1].plot(t, ts[f"sense_{j}"][...], lw=0.8, color=line.get_color(), label=f"{name}: {j}")
        axes[2].plot(t, ts["force_z_n_bodies"][...], lw=0.8,
                     label=f"{name}: mean {float(f['metrics/mean_up_force_n'][()]):.2f} N")
    axes[0].set_ylabel("joint angle (deg; + turns the wing down)")
    axes[1].set_ylabel("sense (+1 max, -1 min)")
    axes[2].set_ylabel("fluid's upward force on all bodies (N)")
    axes[2].set_xlabel("time (s)")
    for ax in axes:
        ax.legend(fontsize=5, ncol=2)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def extreme_frames(f):
    """Field frames nearest the last flap's lowest and highest inner angle (Fig. 12 (a), (b))."""
    ts = f["timeseries"]
    inner = next(k for k in ts if k.startswith("pd_angle_deg_"))
    per = int(round(float(f.attrs["flap_period_s"]) / float(f.attrs["frame_s"])))
    t, a = ts["time_s"][-per:], ts[inner][-per:]
    field_t = f["fields/time_s"][...]
    # a positive inner angle is the wing down (models/flyer.xml)
    return [int(np.argmin(np.abs(field_t - t[np.argmax(a)]))), int(np.argmin(np.abs(field_t - t[np.argmin(a)])))]


def vorticity_figure(points, png):
    fig, axes = plt.subplots(len(points), 2, figsize=(8, 3.9 * len(points)), squeeze=False)
    for row, f in zip(axes, points):
        for ax, k, when in zip(row, extreme_frames(f), ("wing furthest down", "wing furthest up")):
            im, _ = draw_field(ax, f, k)
            ax.set_title(f"{text(f, 'label')} ({resolution(f)}): {when}, t = {f['fields/time_s'][k]:.2f} s", fontsize=7)
            ax.tick_params(labelsize=6)
            fig.colorbar(im, ax=ax, shrink=0.7).ax.tick_params(labelsize=6)
    fig.suptitle("the driven flyer: vorticity (1/s) and the bodies' outline markers; source at the floor, "
                 "open top (§7.1, Figs. 11, 12)", fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def window(f):
    """The setting a held point is the reference for: grid, step, scheme, the flaps averaged and the
    projected forcing's tolerance."""
    return (f"{resolution(f)}, {int(f.attrs['force_cycles'])} flaps, "
            f"forcing {float(f.attrs.get('forcing_tolerance', 0)):g}")


def reading(f):
    """How the controller's evaluations read F_d (control_fluid's perturbation and objective_bodies)."""
    return f"{text(f, 'perturbation') or 'moved'}, {text(f, 'objective_bodies') or 'moved'}"


def flap_means(f):
    """The mean upward force of each of the last force_cycles flaps (the metric's window)."""
    per = int(round(float(f.attrs["flap_period_s"]) / float(f.attrs["frame_s"])))
    cycles = int(f.attrs["force_cycles"])
    force = f["timeseries/force_z_n_bodies"][...]
    if cycles < 1 or per * cycles > len(force):
        return np.array([])
    return force[len(force) - per * cycles:].reshape(cycles, per).mean(axis=1)


def standard_error(means):
    """Standard error of the mean of the per-flap means (flaps taken as independent), NaN below 2."""
    return float(np.std(means, ddof=1) / np.sqrt(len(means))) if len(means) > 1 else float("nan")


def force_table(points, path):
    """Per point the mean upward force, the spread of its per-flap means, and its ratio to the held
    point (strength 0) of its window with the ratio's standard error from both points' flaps."""
    held = {window(f): f for f in points if float(f.attrs["strength_rad_per_s"]) == 0}
    with open(path, "w") as out:
        out.write("The standard errors treat the flaps as independent samples; the ratio's combines both "
                  "points' relative errors.\n")
        out.write(f"{'label':36s} {'setting':66s} {'reading':18s} mean_up_force_n  flaps  flap_sd  flap_se  "
                  f"ratio_se  / held\n")
        for f in points:
            force = float(f["metrics/mean_up_force_n"][()])
            means = flap_means(f)
            se = standard_error(means)
            ref = held.get(window(f))
            ratio, ratio_se = "-", "-"
            if ref is f:
                ratio = "1.0000"
            elif ref is not None:
                ref_force = float(ref["metrics/mean_up_force_n"][()])
                ratio = f"{force / ref_force:.4f}"
                ref_se = standard_error(flap_means(ref))
                ratio_se = f"{force / ref_force * np.hypot(se / force, ref_se / ref_force):8.4f}"
            sd = float(np.std(means, ddof=1)) if len(means) > 1 else float("nan")
            out.write(f"{text(f, 'label'):36s} {window(f):66s} {reading(f):18s} {force:15.4f}  {len(means):5d}  "
                      f"{sd:7.3f}  {se:7.3f}  {ratio_se:>8s}  {ratio}\n")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run")
    parser.add_argument("--out")
    args = parser.parse_args()
    out = args.out or os.path.join(args.run, "figures")
    points = [h5py.File(p, "r") for p in sorted(glob.glob(os.path.join(args.run, "point_*.h5")))]
    flyers = [f for f in points if is_flyer(f)]
    if flyers:
        os.makedirs(out, exist_ok=True)
        angles_figure(flyers, os.path.join(out, "flyer_angles.png"))
        force_table(flyers, os.path.join(out, "flyer_force.txt"))
        with_fields = [f for f in flyers if "fields/vorticity_per_s" in f]
        if with_fields:
            vorticity_figure(with_fields, os.path.join(out, "flyer_vorticity.png"))
    for f in points:
        f.close()


if __name__ == "__main__":
    main()
