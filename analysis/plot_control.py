#!/usr/bin/python3
"""Draws creature-controller runs (kind `control`, experiments/control/*.toml) from their HDF5 alone.

usage: /usr/bin/python3 analysis/plot_control.py RUN_DIR [--out DIR]

frames.png: the creature in the x-z plane (geom_frames_m: centre and axis tips at the half-extents) at
a few frames (light to dark, last frame bold), one panel per point (Lentine et al. 2010 Figs. 3, 4,
6, 9, 5): boxes as their 12 edges, capsules as thick segments, spheres as circles, the wind as an
arrow; frames_top.png the same seen from above (x-y) when the creature moves out of the x-z plane
(ball joints, block_ball.toml). angles.png: every controlled DOF's angle (a ball joint's three:
its rotation vector's components) against time, and every controlled joint's objective (per
point). Figures go to RUN_DIR/figures/ as PNG.
"""
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import style  # noqa: E402

BOX, SPHERE, CAPSULE, ELLIPSOID, CYLINDER = 6, 2, 3, 4, 5


def text(f, name):
    v = f.attrs.get(name, "")
    return v.decode() if isinstance(v, bytes) else str(v)


def title(f):
    parts = [text(f, "label")] if text(f, "label") else []
    parts.append(f"{text(f, 'objectives')} {text(f, 'senses')}")
    parts.append(f"strength {float(f.attrs['strength_rad_per_s']):g} rad/s")
    return ", ".join(p for p in parts if p)


def draw_pose(ax, frames, types, k, alpha, lw, plane=(0, 2)):
    """Frame k of geom_frames_m (points: centre, then the x, y, z axis tips scaled by half-sizes),
    projected on the plane of world axes `plane`."""
    u, v = plane
    g = frames[k].reshape(-1, 4, 3)
    for j, t in enumerate(types):
        c, ex, ey, ez = g[j, 0], g[j, 1] - g[j, 0], g[j, 2] - g[j, 0], g[j, 3] - g[j, 0]
        colour = "0.5" if t == BOX and np.allclose(frames[0].reshape(-1, 4, 3)[j], g[j]) and k > 0 else "tab:blue"
        if t == BOX:
            signs = [(a, b, d) for a in (-1, 1) for b in (-1, 1) for d in (-1, 1)]
            corner = {s: c + s[0] * ex + s[1] * ey + s[2] * ez for s in signs}
            for s in signs:
                for axis in range(3):
                    if s[axis] < 0:
                        other = tuple(-x if i == axis else x for i, x in enumerate(s))
                        p, q = corner[s], corner[other]
                        ax.plot([p[u], q[u]], [p[v], q[v]], color=colour, alpha=alpha, lw=lw)
        elif t in (CAPSULE, CYLINDER):
            a, b = c - ez, c + ez
            radius = np.linalg.norm(ex)
            ax.plot([a[u], b[u]], [a[v], b[v]], color="tab:blue", alpha=alpha, lw=max(lw, 400 * radius / 10))
        elif t in (SPHERE, ELLIPSOID):
            ax.add_patch(plt.Circle((c[u], c[v]), np.linalg.norm(ex), color="tab:blue", alpha=alpha * 0.6, fill=True))


def has_ball(f):
    """A controlled ball joint: its three angle series beside its one objective."""
    ts = f["timeseries"]
    return any(f"angle_deg_{k[len('objective_'):]}_x" in ts for k in ts if k.startswith("objective_"))


def frames_figure(points, png, plane=(0, 2)):
    n = len(points)
    cols = min(n, 3)
    rows = (n + cols - 1) // cols
    fig, axes = style.subplots(rows, cols, width=min(style.WIDTH_IN, 3.8 * cols), height=3.9 * rows, squeeze=False)
    for ax in axes.flat[n:]:
        ax.axis("off")
    for ax, f in zip(axes.flat, points):
        frames = f["lagrangian/geom_frames_m"][...]
        types = f["topology/geom_type"][...]
        count = frames.shape[0]
        # Denser early, where the creature moves; the last frame bold.
        for i, k in enumerate(np.unique(np.round(np.linspace(0, 1, 6) ** 2 * (count - 1)).astype(int))):
            last = k == count - 1
            draw_pose(ax, frames, types, k, 0.25 + 0.75 * i / 5, 2.0 if last else 0.8, plane)
        wind = np.array([float(f.attrs[f"wind_{a}_m_per_s"]) for a in "xyz"])
        if np.linalg.norm(wind) > 0 and float(f.attrs["density_kg_per_m3"]) > 0:
            # The wind as an arrow in the axes' lower left corner (axes fractions), clear of the title.
            w2 = wind[list(plane)]
            direction = w2 / np.linalg.norm(w2) if np.linalg.norm(w2) > 0 else np.zeros(2)
            start = np.array([0.05, 0.08])
            ax.annotate("", xy=start + 0.2 * direction, xytext=start, xycoords="axes fraction",
                        arrowprops=dict(arrowstyle="->", color="tab:red"))
            ax.text(0.05, 0.1, f"wind {np.linalg.norm(wind):g} m/s", color="tab:red", transform=ax.transAxes,
                    va="bottom")
        m = f["metrics"]
        ax.set_title(style.wrap(f"{title(f)}; final {float(m['final_angle_deg'][()]):.1f} deg, converged at frame "
                                f"{int(m['converged_frame'][()])}", 34))
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel(f"{'xyz'[plane[0]]} (m)")
        ax.set_ylabel(f"{'xyz'[plane[1]]} (m)")
    style.save(fig, png)


def angles_figure(points, png):
    """Every controlled DOF's angle and every controlled joint's objective against time; the legend
    in a row of its own below both panels (a sweep has tens of lines)."""
    entries = sum(1 for f in points for k in f["timeseries"] if k.startswith("angle_deg_"))
    ncol = 1 if entries < 4 else 2
    legend_rows = -(-entries // ncol)
    fig = style.figure(height=4.2 + 0.22 * legend_rows)
    grid = fig.add_gridspec(2, 2, height_ratios=[4.2, 0.22 * legend_rows])
    ax_angle, ax_obj = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1])
    key = fig.add_subplot(grid[1, :])
    for f in points:
        t = f["timeseries/time_s"][...]
        dofs = [k[len("angle_deg_"):] for k in f["timeseries"] if k.startswith("angle_deg_")]
        joints = [k[len("objective_"):] for k in f["timeseries"] if k.startswith("objective_")]
        colour = {}
        name = text(f, "label") or title(f)
        for d in dofs:
            line, = ax_angle.plot(t, f[f"timeseries/angle_deg_{d}"][...], lw=1, label=f"{name}: {d}")
            colour.setdefault(d, line.get_color())
        for j in joints:
            ax_obj.plot(t, f[f"timeseries/objective_{j}"][...], lw=1, color=colour.get(j, colour.get(j + "_x")))
    ax_angle.set_xlabel("time (s)")
    ax_angle.set_ylabel("joint angle (deg)")
    ax_obj.set_xlabel("time (s)")
    ax_obj.set_ylabel("objective J_i (effort N m s, drag N)")
    ax_obj.set_yscale("symlog", linthresh=1e-3)
    ax_angle.set_title("controlled angles")
    ax_obj.set_title("objectives J_i (colours as the angles)")
    style.legend_key(key, [ax_angle], ncol=ncol, loc="upper center")
    style.save(fig, png)


def timing_table(points, path):
    """Fig. 10's table: wall seconds per frame against controlled joints, per count of evaluation
    threads and (control_fluid) fluid threads (from each point's wall_time_s attribute: provenance,
    not a dataset)."""
    rows = {}
    for f in points:
        joints = sum(1 for k in f["timeseries"] if k.startswith("objective_"))
        per_frame = float(f.attrs["wall_time_s"]) / float(f.attrs["frames"])
        rows.setdefault(joints, {})[(int(f.attrs["threads"]), int(f.attrs.get("fluid_threads", 1)))] = per_frame
    columns = sorted({c for r in rows.values() for c in r})
    fluid = any(c[1] > 1 for c in columns)
    names = [f"{t} thread(s)" + (f", {ft} fluid" if fluid else "") + " s/frame" for t, ft in columns]
    with open(path, "w") as out:
        out.write("joints  " + "  ".join(f"{n:>19s}" for n in names) + "\n")
        for j in sorted(rows):
            out.write(f"{j:6d}  " + "  ".join(f"{rows[j].get(c, float('nan')):{max(19, len(n))}.6f}"
                                             for c, n in zip(columns, names)) + "\n")


def draw(run, out):
    """Every figure of a control run folder, as PNGs (and the timing table) in folder `out`."""
    os.makedirs(out, exist_ok=True)
    files = [h5py.File(p, "r") for p in sorted(glob.glob(os.path.join(run, "point_*.h5")))]
    points = [f for f in files if "lagrangian/geom_frames_m" in f]
    if not points:
        raise SystemExit(f"{run}: no control points with geom frames")
    frames_figure(points, os.path.join(out, "frames.png"))
    if any(has_ball(f) for f in points):
        frames_figure(points, os.path.join(out, "frames_top.png"), plane=(0, 1))
    angles_figure(points, os.path.join(out, "angles.png"))
    if len({(int(f.attrs["threads"]), int(f.attrs.get("fluid_threads", 1))) for f in points}) > 1:
        timing_table(points, os.path.join(out, "parallel_dofs.txt"))
    for f in files:
        f.close()


def figures(run):
    """(name, Figure) of every figure of the run folder `run`."""
    return style.collect(draw, run)


def main():
    style.main(draw, __doc__)


if __name__ == "__main__":
    main()
