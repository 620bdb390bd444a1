"""Lentine et al. 2010 Figs. 11 and 13 in 3-D: the driven flyer (control_fluid3d, stored_fields =
"volume") in a strip of frames over its last flap, each the isosurface of the Q-criterion
(Q = (|Omega|^2 - |S|^2) / 2 > 0 where rotation outweighs strain: the vortices the wings shed)
coloured by the vertical velocity there, with the creature's geoms (or its flesh, when recorded) at
that frame. The level is a stated fraction of the largest Q in the drawn frames outside the bodies
(Q inside and next to a turning rigid body is its own rotation, not a vortex). Drawn from the point
files alone: the geoms from their recorded type, size and pose, the surface by marching tetrahedra
(figures/creature3d.py).
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import creature3d, runs  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import os  # noqa: E402

import numpy as np  # noqa: E402
from matplotlib import cm, colors  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

import style  # noqa: E402

Q_FRACTION = 0.1  # the isosurface's level: this fraction of the largest Q outside the bodies
PANELS = 4  # frames in the strip, spread over the last flap period
GEOM_RGBA = (0.55, 0.55, 0.58, 1.0)
FLESH_RGBA = (0.85, 0.75, 0.35, 1.0)  # a gold apart from the colour map's reds and blues


def drawn_frames(times, period_s, panels=PANELS):
    """Indices of the stored field frames nearest to `panels` times spread over the last flap
    period (all frames when fewer), increasing and distinct."""
    times = np.asarray(times)
    if len(times) <= panels:
        return list(range(len(times)))
    start = max(times[0], times[-1] - period_s * (1 - 1.0 / panels))
    wanted = np.linspace(start, times[-1], panels)
    return sorted({int(np.argmin(np.abs(times - t))) for t in wanted})


def body_mask(point, frame, axes, cells=1.5):
    """Cells whose centre lies in a geom's bounding box grown by `cells` cell sizes at lagrangian frame
    `frame`: (nz, ny, nx) booleans."""
    dx = axes[0][1] - axes[0][0]
    gz, gy, gx = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    centres = np.stack([gx, gy, gz], axis=-1)
    mask = np.zeros(gx.shape, dtype=bool)
    pos = point["lagrangian/geom_position_m"][frame]
    rot = point["lagrangian/geom_rotation"][frame].reshape(-1, 3, 3)
    size = point["lagrangian/geom_size_m"][frame]
    types = point["topology/geom_type"][()]
    for g in range(len(pos)):
        local = (centres - pos[g]) @ rot[g]  # the cell centres in the geom's frame
        half = creature3d.half_extents(int(types[g]), size[g]) + cells * dx
        mask |= np.all(np.abs(local) <= half, axis=-1)
    return mask


def lagrangian_frame(point, t):
    """The pose frame recorded at time t (the nearest)."""
    return int(np.argmin(np.abs(point["lagrangian/time_s"][()] - t)))


def draw_point(f, title, out_path):
    times = f["fields/time_s"][()]
    period = float(f.attrs.get("flap_period_s", times[-1] - times[0]))
    frames = drawn_frames(times, period)
    axes = creature3d.cell_centres(f)
    dx = float(f["fields"].attrs["dx_m"])
    poses = [lagrangian_frame(f, times[k]) for k in frames]
    q = [f["fields/q_per_s2"][k] for k in frames]
    w = [f["fields/w_m_per_s"][k] for k in frames]
    masks = [body_mask(f, p, axes) for p in poses]
    q_max = max(float(np.where(m, -np.inf, qk).max()) for m, qk in zip(masks, q))
    free = [np.where(m, 0.0, qk) for m, qk in zip(masks, q)]
    level = Q_FRACTION * q_max if q_max > 0 else np.inf
    surfaces = [creature3d.isosurface(qk, level, axes, wk) for qk, wk in zip(free, w)]
    w_lim = max([float(np.abs(c).max()) for _, c in surfaces if len(c)] + [1e-12])
    norm = colors.Normalize(-w_lim, w_lim)
    cmap = matplotlib.colormaps["RdBu_r"]
    lo = [a[0] - dx / 2 for a in axes]
    hi = [a[-1] + dx / 2 for a in axes]
    fig = style.figure(height=4.6)
    fig.get_layout_engine().set(rect=(0, 0.06, 1, 0.94))  # room for the legend below the panels
    skipped, panels = 0, []
    for n, (k, p, (tris, c)) in enumerate(zip(frames, poses, surfaces)):
        ax = fig.add_subplot(1, len(frames), n + 1, projection="3d")
        panels.append(ax)
        body, s = creature3d.creature_triangles(f, p)
        skin = creature3d.flesh_triangles(f, p)
        if skin is not None:  # the flesh wraps the geoms
            body = skin
        skipped = max(skipped, s)
        allt = np.concatenate([tris, body])
        if len(allt):
            look = GEOM_RGBA if skin is None else FLESH_RGBA
            rgba = np.concatenate([cmap(norm(c)).reshape(-1, 4), np.tile(look, (len(body), 1))])
            ax.add_collection3d(Poly3DCollection(allt, facecolors=creature3d.shade(allt, rgba), edgecolors="none"))
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[1], hi[1])
        ax.set_zlim(lo[2], hi[2])
        ax.set_box_aspect([h - l for l, h in zip(lo, hi)], zoom=1.15)
        ax.view_init(elev=18, azim=-60)
        ax.set_xlabel("x (m)", labelpad=-4)
        ax.set_ylabel("y (m)", labelpad=-4)
        ax.set_zlabel("z (m)", labelpad=-4)
        ax.tick_params(labelsize=9, pad=-2)
        ax.set_title(f"t = {times[k]:.2f} s")
    fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=panels, shrink=0.7,
                 label="vertical velocity w on the Q surface (m/s)")
    creature = (Patch(color=FLESH_RGBA, label="the flyer's flesh") if creature3d.flesh_triangles(f, 0) is not None else
                Patch(color=GEOM_RGBA, label="the flyer's geoms" + (f" ({skipped} mesh geoms not drawn)" if skipped else "")))
    handles = [creature,
               Patch(color=cmap(0.7), label=f"the surface Q = {level:.3g} 1/s^2, coloured by w")]
    fig.legend(handles=handles, loc="lower center", ncols=2, frameon=False)
    fig.suptitle(style.wrap(f"{title}: Q-criterion isosurface at {Q_FRACTION:g} x the largest Q outside the bodies "
                            f"in these frames ({q_max:.3g} 1/s^2), fluid cells of {dx:.3g} m", 120))
    return style.save(fig, out_path)


def draw(run, out):
    pngs = []
    labels = run.labels()
    for n, f in enumerate(run.ok_points()):
        if "fields/q_per_s2" not in f or f["fields/q_per_s2"].ndim != 4 or "lagrangian/geom_position_m" not in f:
            continue
        k = int(f.attrs.get("point_index", n))
        label = labels[k] if k < len(labels) else str(k)
        pngs.append(draw_point(f, f"{run.title} ({label})",
                               os.path.join(out, "lentine_q3d" + (f"_{k}" if k else ""))))
    if not pngs:  # say so in the report rather than leave the figure out
        fig = style.figure(height=1.2)
        fig.text(0.5, 0.5, style.wrap(f"{run.title}: no point stored the fluid's volume with the geoms' poses, so "
                                      "there is no Q-criterion render; rerun it with params.stored_fields=volume "
                                      "(control_fluid3d).", 110), ha="center", va="center")
        pngs.append(style.save(fig, os.path.join(out, "lentine_q3d")))
    return pngs


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
