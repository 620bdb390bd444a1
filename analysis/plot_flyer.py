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
flyer_phase.png and flyer_phase.txt: per point of six flaps or more, the force window's mean
over the flap's phase (eight bins from the inner pattern's zero) of the inner and outer angles, the
upward force and the force's magnitude |F| (F_d, what the controller descends on), the upward force,
|F| and its horizontal part over the down-strokes and the up-strokes (the sense the controller
followed), how often a controlled joint turns back between frames, and the derivative of F_d the
controller stepped on (dF_d/d(angle), N/rad, the controlled joints' mean): where the controller gains
on and loses to the held wings, whether the |F| it gains is lift, and which way its derivative pushed
the wing in each part of the flap.
flyer_vorticity.png: per point the vorticity with the bodies at the last flap's lowest and highest
wing (Fig. 12 (a), (b) analogues; Fig. 11's animation is plot_control_fluid.py's frame series).
The vorticity with the bodies and the frame series are plot_control_fluid.py's.
Figures go to RUN_DIR/figures/.
"""
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from plot_control_fluid import draw_field, text  # noqa: E402
import style  # noqa: E402


def is_flyer(f):
    return float(f.attrs.get("flap_period_s", 0)) > 0 and "timeseries/force_z_n_bodies" in f


def resolution(f):
    n = int(f.attrs["cells"])
    if "domain_y_m" in f.attrs:  # the 3-D box: cells along x, the other axes in the box's proportions
        dx = float(f.attrs["domain_x_m"]) / n
        grid = "x".join(str(round(float(f.attrs[f"domain_{a}_m"]) / dx)) for a in "xyz") + " cells"
    else:
        grid = f"{n}^2"
    return f"{grid}, {int(f.attrs['substeps'])} steps/frame, {text(f, 'advection')}"


def legend_columns(labels):
    """Two columns of legend entries, or one when the labels are too long to stand side by side."""
    return 2 if max((len(x) for x in labels), default=0) <= 60 else 1


def panels(n, labels, height_in):
    """n panels sharing the x axis over an axis for a legend of `labels` (style.legend_key)."""
    rows = -(-len(labels) // legend_columns(labels))
    legend_in = 0.22 * rows + 0.3  # 9-point entries
    fig, axes = style.subplots(n + 1, 1, height=height_in + legend_in,
                               gridspec_kw={"height_ratios": [height_in / n] * n + [legend_in]})
    for ax in axes[1:n]:
        ax.sharex(axes[0])
    for ax in axes[:n - 1]:
        ax.tick_params(labelbottom=False)
    return fig, axes


def angles_figure(points, png):
    # One setting for all points goes in the title; a point has one colour in the three panels.
    settings = {resolution(f) for f in points}
    shared = settings.pop() if len(settings) == 1 else None
    names = [text(f, "label") if shared else f"{text(f, 'label')} ({resolution(f)})" for f in points]
    labels = [f"{name}: mean {float(f['metrics/mean_up_force_n'][()]):.2f} N" for name, f in zip(names, points)]
    fig, axes = panels(3, labels, 9)
    for i, (f, label) in enumerate(zip(points, labels)):
        ts, colour = f["timeseries"], f"C{i % 10}"
        t = ts["time_s"][...]
        for k in ts:
            if k.startswith("pd_angle_deg_"):
                axes[0].plot(t, ts[k][...], lw=0.8, ls=":", color=colour)
        for j in [j.strip() for j in text(f, "controlled").split(",")]:
            axes[0].plot(t, ts[f"angle_deg_{j}"][...], lw=1, color=colour)
            axes[1].plot(t, ts[f"sense_{j}"][...], lw=0.8, color=colour)
        axes[2].plot(t, ts["force_z_n_bodies"][...], lw=0.8, color=colour, label=label)
    axes[0].set_ylabel("joint angle (deg; + wing down)\ninner (PD) dotted, outer solid")
    axes[1].set_ylabel("sense (+1 max, -1 min)")
    axes[2].set_ylabel("fluid's upward force on all bodies (N)")
    axes[2].set_xlabel("time (s)")
    style.legend_key(axes[3], [axes[2]], ncol=legend_columns(labels))
    if shared:
        fig.suptitle(f"the driven flyer's joints and upward force ({shared})")
    style.save(fig, png)


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
    fig, axes = style.subplots(len(points), 2, width=9, height=4.4 * len(points), squeeze=False)
    for row, f in zip(axes, points):
        for ax, k, when in zip(row, extreme_frames(f), ("wing furthest down", "wing furthest up")):
            im, _ = draw_field(ax, f, k)
            ax.set_title(style.wrap(f"{text(f, 'label')} ({resolution(f)}): {when}, t = {f['fields/time_s'][k]:.2f} s", 45))
            fig.colorbar(im, ax=ax, shrink=0.8).set_label("vorticity (1/s)")
    fig.suptitle(style.wrap("the driven flyer: vorticity (1/s) and the bodies' outline markers; source at the floor, "
                            "open top (§7.1, Figs. 11, 12)", 90))
    style.save(fig, png)


def window(f):
    """The setting a held point is the reference for: grid, step, scheme, the flaps averaged and the
    projected forcing's tolerance and preconditioner (points before it was a parameter: mass)."""
    preconditioner = text(f, "forcing_preconditioner") or "mass"
    return (f"{resolution(f)}, {int(f.attrs['force_cycles'])} flaps, "
            f"forcing {float(f.attrs.get('forcing_tolerance', 0)):g} {preconditioner}")


def reading(f):
    """How the controller's evaluations read F_d (control_fluid's perturbation and objective_bodies)."""
    return f"{text(f, 'perturbation') or 'moved'}, {text(f, 'objective_bodies') or 'moved'}"


def force_window(f):
    """The last force_cycles flaps of the series (the metric's window), or None if too short."""
    per = int(round(float(f.attrs["flap_period_s"]) / float(f.attrs["frame_s"])))
    n = per * int(f.attrs["force_cycles"])
    length = len(f["timeseries/time_s"])
    return slice(length - n, length) if 0 < n <= length else None


def held_references(points):
    """The held point (strength 0) of each window: the reference of the points sharing it."""
    return {window(f): f for f in points if float(f.attrs["strength_rad_per_s"]) == 0}


def flap_means(f):
    """The mean upward force of each of the last force_cycles flaps (the metric's window)."""
    w = force_window(f)
    if w is None:
        return np.array([])
    return f["timeseries/force_z_n_bodies"][w].reshape(int(f.attrs["force_cycles"]), -1).mean(axis=1)


def standard_error(means):
    """Standard error of the mean of the per-flap means (flaps taken as independent), NaN below 2."""
    return float(np.std(means, ddof=1) / np.sqrt(len(means))) if len(means) > 1 else float("nan")


def force_table(points, path):
    """Per point the mean upward force, the spread of its per-flap means, and its ratio to the held
    point (strength 0) of its window with the ratio's standard error from both points' flaps."""
    held = held_references(points)
    with open(path, "w") as out:
        out.write("The standard errors treat the flaps as independent samples; the ratio's combines both "
                  "points' relative errors.\n")
        out.write(f"{'label':36s} {'setting':71s} {'reading':18s} mean_up_force_n  flaps  flap_sd  flap_se  "
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
            out.write(f"{text(f, 'label'):36s} {window(f):71s} {reading(f):18s} {force:15.4f}  {len(means):5d}  "
                      f"{sd:7.3f}  {se:7.3f}  {ratio_se:>8s}  {ratio}\n")


PHASE_BINS = 8


def force_parts(ts, w):
    """The fluid's force on all bodies over the window: upward, magnitude, and horizontal magnitude
    (x, and y in 3-D)."""
    up = ts["force_z_n_bodies"][w]
    horizontal = np.hypot(ts["force_x_n_bodies"][w],
                          ts["force_y_n_bodies"][w] if "force_y_n_bodies" in ts else 0.0)
    return up, np.hypot(up, horizontal), horizontal


def phase_profile(f):
    """Phase bins' means over the force window: inner angle, outer angle (the controlled joints'
    mean), upward force, |F|; and the upward force, |F| and its horizontal part over down- and
    up-strokes (sense > 0: down); the controlled joints' mean derivative of F_d (N/rad)."""
    ts, w = f["timeseries"], force_window(f)
    joints = [j.strip() for j in text(f, "controlled").split(",")]
    inner = next(k for k in ts if k.startswith("pd_angle_deg_"))
    t = ts["time_s"][w]
    phase = np.floor((t % float(f.attrs["flap_period_s"])) / float(f.attrs["flap_period_s"]) * PHASE_BINS)
    phase = np.minimum(phase.astype(int), PHASE_BINS - 1)
    outer = np.mean([ts[f"angle_deg_{j}"][w] for j in joints], axis=0)
    derivative = np.mean([ts[f"derivative_per_rad_{j}"][w] for j in joints], axis=0)
    force, magnitude, horizontal = force_parts(ts, w)
    down = ts[f"sense_{joints[0]}"][w] > 0
    bins = [phase == b for b in range(PHASE_BINS)]
    # How often a controlled joint turns back from one frame to the next (the sign-only strength step).
    steps = np.diff(ts[f"angle_deg_{joints[0]}"][w])
    moving = steps[np.abs(steps) > 0]
    reversals = float(np.mean(np.sign(moving[1:]) != np.sign(moving[:-1]))) if len(moving) > 1 else 0.0
    return {"reversals": reversals, "inner": [ts[inner][w][m].mean() for m in bins],
            "outer": [outer[m].mean() for m in bins], "force": [force[m].mean() for m in bins],
            "magnitude": [magnitude[m].mean() for m in bins], "derivative": [derivative[m].mean() for m in bins],
            "down": force[down].mean(), "up": force[~down].mean(),
            "down_abs": magnitude[down].mean(), "up_abs": magnitude[~down].mean(),
            "down_horizontal": horizontal[down].mean(), "up_horizontal": horizontal[~down].mean()}


def phase_outputs(points, png, path):
    """flyer_phase.png and .txt (the module's docstring) for the points of six flaps or more."""
    # six flaps: the 3-D claims' window; a QUICK run's two are too few for phase means
    long = [f for f in points if int(f.attrs["force_cycles"]) >= 6 and force_window(f) is not None]
    if not long:
        return
    held = held_references(long)
    centres = (np.arange(PHASE_BINS) + 0.5) / PHASE_BINS
    # one legend for the four panels (a point's colour is the same in each), below them
    names = [f"{text(f, 'label')} ({resolution(f)})" for f in long]
    fig, axes = panels(4, names + ["inner (PD), first point"], 12)
    with open(path, "w") as out:
        out.write("Phase means over each point's force window (phase 0: the inner pattern's zero, rising = "
                  "turning the wings down); the stroke split follows the sense the controller followed.\n")
        out.write(f"{'label':36s} {'setting':71s} down_force_n  up_force_n  (held: down, up)  "
                  f"down_abs_n  up_abs_n  (held: down, up)  down_horizontal_n  up_horizontal_n  reversals  "
                  f"outer_deg by phase bin / force_n by phase bin / dF_d/d(angle) N/rad by phase bin\n")
        for f, name in zip(long, names):
            prof = phase_profile(f)
            ref = held.get(window(f))
            ref_prof = phase_profile(ref) if ref is not None else None
            versus = f"({ref_prof['down']:6.2f}, {ref_prof['up']:6.2f})" if ref_prof else "(-, -)"
            versus_abs = f"({ref_prof['down_abs']:6.2f}, {ref_prof['up_abs']:6.2f})" if ref_prof else "(-, -)"
            out.write(f"{text(f, 'label'):36s} {window(f):71s} {prof['down']:12.3f}  {prof['up']:10.3f}  "
                      f"{versus:16s}  {prof['down_abs']:10.3f}  {prof['up_abs']:8.3f}  {versus_abs:16s}  "
                      f"{prof['down_horizontal']:17.3f}  {prof['up_horizontal']:15.3f}  "
                      f"{prof['reversals']:9.2f}  " + " ".join(f"{a:6.1f}" for a in prof["outer"])
                      + " / " + " ".join(f"{x:6.2f}" for x in prof["force"])
                      + " / " + " ".join(f"{x:6.1f}" for x in prof["derivative"]) + "\n")
            line, = axes[1].plot(centres, prof["force"], marker="o", ms=3, lw=1, label=name)
            axes[0].plot(centres, prof["outer"], marker="o", ms=3, lw=1, color=line.get_color())
            axes[2].plot(centres, prof["magnitude"], marker="o", ms=3, lw=1, color=line.get_color())
            axes[3].plot(centres, prof["derivative"], marker="o", ms=3, lw=1, color=line.get_color())
    inner = phase_profile(long[0])["inner"]
    axes[0].plot(centres, inner, color="k", ls=":", lw=1, label="inner (PD), first point")
    axes[0].set_ylabel("angle (deg; + turns the wing down)")
    axes[1].set_ylabel("fluid's upward force on all bodies (N)")
    axes[2].set_ylabel("|F| on all bodies (N; F_d, the objective)")
    axes[3].axhline(0.0, color="k", lw=0.5)
    axes[3].set_ylabel("dF_d / d(outer angle)\n(N/rad, what the controller steps on)")
    axes[3].set_xlabel("phase of the flap")
    style.legend_key(axes[4], [axes[1], axes[0]], ncol=legend_columns(names))
    fig.suptitle("the driven flyer over a flap: phase means over the force window (§7.1); outer angles solid")
    style.save(fig, png)


def draw(run, out):
    """Every figure of the run folder `run`, as PNGs (and tables) in folder `out`."""
    os.makedirs(out, exist_ok=True)
    points = [h5py.File(p, "r") for p in sorted(glob.glob(os.path.join(run, "point_*.h5")))]
    flyers = [f for f in points if is_flyer(f)]
    if flyers:
        angles_figure(flyers, os.path.join(out, "flyer_angles.png"))
        force_table(flyers, os.path.join(out, "flyer_force.txt"))
        phase_outputs(flyers, os.path.join(out, "flyer_phase.png"), os.path.join(out, "flyer_phase.txt"))
        with_fields = [f for f in flyers if "fields/vorticity_per_s" in f]
        if with_fields:
            vorticity_figure(with_fields, os.path.join(out, "flyer_vorticity.png"))
    for f in points:
        f.close()


def figures(run):
    """(name, Figure) of every figure of the run folder `run`."""
    return style.collect(draw, run)


def main():
    style.main(draw, __doc__)


if __name__ == "__main__":
    main()
