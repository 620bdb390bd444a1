#!/usr/bin/python3
"""Draws runs of Tu's artificial fish (kind "fish") from their HDF5 files, and renders the
POV-Ray scenes the skinned runs wrote beside them.

usage: /usr/bin/python3 analysis/plot_fish.py RUN_DIR [--out DIR]

Writes to RUN_DIR/figures/ (or --out), each when the run has what it needs:
  trajectories.png  top view of the centre of mass of every point (swim and turn sweeps), the
                    fish's outline (its 23 nodes) at the end of each.
  speed.png         speed in body lengths per second against the swim-MC rate, one line per
                    amplitude, and the stride against the gait frequency over the body's lowest
                    sideways mode (swim.toml, swim_rate.toml).
  stability.png     the largest stable step per scheme and per water / tail-mass switch, with the
                    stiffest vibration's 2 / w_max (stability.toml).
  school.png        fish-steps per second and the school's real-time factor against its size
                    (school.toml; wall time from the point files' wall_time_s attribute).
  air.png           sum m v and the centre of mass against time, and the blow-up step (air.toml).
  coupling.png      the 23 nodes and 91 units with the NURBS control net bound to them, undeformed
                    and at the last exported frame (the thesis's coupling figure, ch. 7).
  skin_cycle.png    the skinned fish over the exported swim cycle, rendered by POV-Ray (headless)
                    from the point's .pov scenes; skin_NNN.png each.
"""
import glob
import os
import shutil
import subprocess

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import style  # noqa: E402


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def attr(f, name, default=None):
    return f.attrs[name] if name in f.attrs else default


def label(f, axes):
    return ", ".join(f"{a}={text(attr(f, a))}" for a in axes)


def sweep_axes(run):
    import json
    with h5py.File(os.path.join(run, "index.h5"), "r") as index:
        return json.loads(text(index["sweep"].attrs["columns_json"]))


def metric(f, name):
    return float(f["metrics"][name][()]) if name in f["metrics"] else float("nan")


def trajectories(points, axes, out):
    fig, ax = plt.subplots(figsize=(8, 6))
    for f in points:
        if "com_x_m" not in f["timeseries"]:
            continue
        x, y = f["timeseries/com_x_m"][...], f["timeseries/com_y_m"][...]
        line, = ax.plot(x, y, lw=1, label=label(f, axes))
        nodes = f["lagrangian/nodes_m"]
        last = nodes[nodes.shape[0] - 1]
        ends = f["topology/unit_nodes"][...].reshape(-1, 2)
        for a, b in ends:
            ax.plot([last[a, 0], last[b, 0]], [last[a, 1], last[b, 1]], color=line.get_color(), lw=0.4, alpha=0.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m), left of the initial heading")
    ax.set_title("centre of mass, top view (fish outline at the end)")
    if len(points) > 1:
        ax.legend(fontsize=9, loc="best")
    style.save(fig, os.path.join(out, "trajectories.png"))


def speed(points, axes, out):
    def line(f):  # one line per value of every swept parameter but the rate (or the amplitude)
        return label(f, [a for a in axes if a != "swim_rate"]) or f"alpha = {float(attr(f, 'swim_amplitude')):g}"
    rows = [(line(f), float(attr(f, "swim_rate")), metric(f, "speed_body_lengths_per_s"),
             metric(f, "stride_body_lengths"), metric(f, "stroke_frequency_over_mode")) for f in points]
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4))
    for name in sorted({r[0] for r in rows}):
        pts = sorted(r[1:] for r in rows if r[0] == name)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=name)
        ax2.loglog([p[3] for p in pts], [p[2] for p in pts], "o-", label=name)
    ax.set_xlabel("swim-MC rate r (rest-length fraction per 0.055 s)")
    ax.set_ylabel("speed (body lengths / s)")
    ax.legend()
    ax.set_title("swim-MC: speed against amplitude and rate")
    ax2.axvline(1.0, color="grey", lw=0.8)
    ax2.set_xlabel("gait frequency / body's lowest sideways mode (ratio)")
    ax2.set_ylabel("stride (body lengths per swim cycle)")
    ax2.set_title("the body's inertia filters gaits faster than its modes", fontsize=9)
    style.save(fig, os.path.join(out, "speed.png"))


def stability(points, axes, out):
    names = [label(f, [a for a in axes if a != "scheme"]) for f in points]
    dts = [metric(f, "max_stable_dt_s") for f in points]
    limit = [metric(f, "spring_limit_dt_s") for f in points]
    schemes = sorted({text(attr(f, "scheme")) for f in points})
    colors = dict(zip(schemes, ["#c54", "#4a7", "#58c", "#a6c"]))
    groups = sorted(set(names), key=names.index)
    fig, ax = style.subplots(width=min(style.WIDTH_IN, max(6, 1.6 * len(groups))), height=4.5)
    width = 0.8 / max(1, len(schemes))
    for k, sc in enumerate(schemes):
        for f, n, v in zip(points, names, dts):
            if text(attr(f, "scheme")) != sc:
                continue
            x = groups.index(n) + (k - (len(schemes) - 1) / 2) * width
            ax.bar(x, v, width, color=colors[sc], label=sc if n == groups[0] else None)
            ax.text(x, v, f"{v:.3g}", ha="center", va="bottom", fontsize=9)
    for g in groups:
        lim = limit[names.index(g)]
        i = groups.index(g)
        ax.plot([i - 0.45, i + 0.45], [lim, lim], "k--", lw=0.8, label="2 / w_max" if i == 0 else None)
    ax.set_xticks(range(len(groups)))
    ax.set_xticklabels([g or "-" for g in groups], fontsize=9, rotation=15)
    ax.set_yscale("log")
    ax.set_xlabel("setting")
    ax.set_ylabel("largest stable step (s)")
    ax.set_title(style.wrap("largest stable step per scheme; dashed: the stiffest vibration's 2 / w_max", 60))
    ax.legend(fontsize=9)
    style.save(fig, os.path.join(out, "stability.png"))


def air(points, axes, out):
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for f in points:
        t = f["timeseries/time_s"][...]
        p = np.sqrt(sum(f[f"timeseries/momentum_{c}_kg_m_per_s"][...] ** 2 for c in "xyz"))
        com = np.sqrt(sum((f[f"timeseries/com_{c}_m"][...] - f[f"timeseries/com_{c}_m"][0]) ** 2 for c in "xyz"))
        lab = label(f, axes)
        step = metric(f, "blowup_step")
        if step > 0:
            lab += f" (blows up at step {int(step)})"
        a1.plot(t, p + 1e-300, label=lab)
        a2.plot(t, com + 1e-300, label=lab)
    a1.set_yscale("log")
    a2.set_yscale("log")
    a1.set_ylabel("|sum m v| (kg m/s)")
    a2.set_ylabel("centre-of-mass travel (m)")
    a2.set_xlabel("time (s)")
    a1.legend(fontsize=9)
    a1.set_title("fish in air (mu = 0): momentum and centre of mass stay at round-off")
    style.save(fig, os.path.join(out, "air.png"))


def coupling(f, out):
    nodes = f["lagrangian/nodes_m"]
    ends = f["topology/unit_nodes"][...].reshape(-1, 2)
    cls = f["topology/unit_class"][...]
    colours = {0: "#888", 1: "#d22", 2: "#26c"}
    net = f["lagrangian/skin_control_points_m"]
    times = f["lagrangian/time_s"][...]
    last = net.shape[0] - 1
    i_last = int(f["topology/skin_frames"][last])  # the recorded frame of the last exported one
    net_t = float(times[i_last])
    views = [(nodes[0], f["lagrangian/skin_rest_control_points_m"][0], "undeformed"),
             (nodes[i_last], net[last], "last exported frame" + (f" (t = {net_t:.2f} s)" if net_t is not None else ""))]
    fig = plt.figure(figsize=(12, 5))
    for k, (x, c, title) in enumerate(views):
        ax = fig.add_subplot(1, 2, k + 1, projection="3d")
        for (a, b), kind in zip(ends, cls):
            ax.plot(*[[x[a, d], x[b, d]] for d in range(3)], color=colours[int(kind)], lw=1)
        ax.scatter(x[:, 0], x[:, 1], x[:, 2], color="k", s=8)
        body = 9 * 21
        for half in range(2):
            g = c[half * body:(half + 1) * body].reshape(9, 21, 3)
            for i in range(9):
                ax.plot(g[i, :, 0], g[i, :, 1], g[i, :, 2], color="#3a3", lw=0.4)
            for j in range(21):
                ax.plot(g[:, j, 0], g[:, j, 1], g[:, j, 2], color="#3a3", lw=0.4)
        ax.set_title(title + "\nunits: red muscle, grey cross, blue other; green: NURBS control net", fontsize=9)
        span = np.ptp(c, axis=0)
        ax.set_box_aspect(tuple(max(v, 0.05 * span.max()) for v in span))
        ax.view_init(elev=25, azim=-60)
        ax.set_axis_off()
    style.save(fig, os.path.join(out, "coupling.png"))


def school(points, out):
    rows = sorted((int(attr(f, "school_size")), metric(f, "school_fish_steps") / float(attr(f, "wall_time_s")))
                  for f in points)
    n = np.array([r[0] for r in rows])
    rate = np.array([r[1] for r in rows])
    # real-time factor: simulated seconds of the whole school per wall second
    realtime = rate * float(attr(points[0], "dt_s")) / n
    fig, ax = style.subplots(width=7.5, height=4.5)
    ax.loglog(n, rate, "o-", label="fish-steps per second")
    ax.loglog(n, realtime, "s--", label="real-time factor of the school (sim s / wall s)")
    ax.axhline(1.0, color="grey", lw=0.8)
    for x, y, z in zip(n, rate, realtime):
        ax.annotate(f"{y:.3g}/s, x{z:.3g}", (x, y), fontsize=9, textcoords="offset points", xytext=(4, 4))
    ax.set_xlabel("fish in the school (count)")
    ax.set_ylabel("rate (1/s) or real-time factor (ratio)")
    ax.legend(fontsize=9)
    ax.set_title(style.wrap("school: one core, 0.055 s steps (wall time from the point files' wall_time_s)", 70))
    style.save(fig, os.path.join(out, "school.png"))


def render_skin(run, out):
    scenes = sorted(glob.glob(os.path.join(run, "point_*_skin_*.pov")))
    if not scenes:
        return
    povray = shutil.which("povray")
    if povray is None:
        raise SystemExit("povray is not installed (scripts/deps.sh installs it): cannot render " + scenes[0])
    images = []
    for scene in scenes:
        name = os.path.basename(scene).replace(".pov", ".png").split("_", 2)[-1]
        png = os.path.join(out, name)
        subprocess.run([povray, "+I" + scene, "+O" + png, "+W800", "+H450", "-D", "+A0.3", "+FN", "-V", "+WT1"],
                       check=True, capture_output=True)
        images.append(png)
    fig, axes = style.subplots(1, len(images), height=style.WIDTH_IN / len(images) * 0.6 + 0.8)
    axes = np.atleast_1d(axes)
    for ax, png in zip(axes, images):
        ax.imshow(plt.imread(png))
        ax.set_axis_off()
        ax.set_title(os.path.basename(png), fontsize=9)
    fig.suptitle("the skinned fish over one tail-beat cycle (POV-Ray)")
    style.save(fig, os.path.join(out, "skin_cycle.png"))


def draw(run, out):
    """Every figure of the run folder `run`, as PNGs (and tables) in folder `out`."""
    os.makedirs(out, exist_ok=True)
    axes = sweep_axes(run)
    points = [h5py.File(p, "r") for p in sorted(glob.glob(os.path.join(run, "point_*.h5")))]
    if not points:
        raise SystemExit("no point files in " + run)
    task = text(attr(points[0], "task", "simulate"))
    if task == "stable_step":
        stability(points, axes, out)
        return
    if all("lagrangian/nodes_m" in f for f in points):
        trajectories(points, axes, out)
    if "school_size" in axes:
        school(points, out)
        return
    if "swim_rate" in axes:
        speed(points, axes, out)
    if float(attr(points[0], "water_mu", 1.0)) == 0.0:
        air(points, axes, out)
    for f in points:
        if "lagrangian/skin_control_points_m" in f:
            coupling(f, out)
            break
    render_skin(run, out)


def figures(run):
    """(name, Figure) of every figure of the run folder `run`."""
    return style.collect(draw, run)


def main():
    style.main(draw, __doc__)


if __name__ == "__main__":
    main()
