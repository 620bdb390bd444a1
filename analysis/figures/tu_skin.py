"""Tu 1996, ch. 7 (NURBS skin): the skinned fish drawn from the run's HDF5 alone: the skin's mesh
(/lagrangian/skin_vertices_m, /topology/skin_triangles) at three of its stored frames over the
swim cycle, seen obliquely from above and shaded by each triangle's angle to a light, with the
dynamic model's 23 nodes beneath (ch. 7: the NURBS surfaces deform with the swimming fish).
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
from matplotlib.collections import PolyCollection  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import os  # noqa: E402

import style  # noqa: E402


def view(points, azimuth_deg=-60.0, elevation_deg=35.0):
    """Orthographic view: (screen x, screen y, depth) of 3-D points, camera at the given angles."""
    az, el = np.radians(azimuth_deg), np.radians(elevation_deg)
    right = np.array([-np.sin(az), np.cos(az), 0.0])
    toward = np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])
    up = np.cross(toward, right)
    return points @ right, points @ up, points @ toward


def shade(ax, verts, tris, light, cmap):
    sx, sy, depth = view(verts)
    a, b, c = verts[tris[:, 0]], verts[tris[:, 1]], verts[tris[:, 2]]
    n = np.cross(b - a, c - a)
    norm = np.linalg.norm(n, axis=1)
    keep = norm > 1e-12 * norm.max()
    n = n[keep] / norm[keep, None]
    t = tris[keep]
    brightness = 0.25 + 0.75 * np.abs(n @ light)  # two-sided: the fins are thin sheets
    order = np.argsort(depth[t].mean(axis=1))  # far first
    polys = np.stack([sx[t], sy[t]], axis=-1)[order]
    pc = PolyCollection(polys, array=brightness[order], cmap=cmap, clim=(0, 1), edgecolors="none")
    ax.add_collection(pc)
    return pc, sx, sy


def draw(run, out):
    points = [f for f in run.ok_points() if "lagrangian/skin_vertices_m" in f and "topology/skin_triangles" in f]
    if not points:
        return []
    f = points[0]
    verts_all = f["lagrangian/skin_vertices_m"]
    tris = f["topology/skin_triangles"][...].reshape(-1, 3)
    frames = f["topology/skin_frames"][...] if "topology/skin_frames" in f else np.arange(verts_all.shape[0])
    tall = f["lagrangian/time_s"][...]
    nodes = f["lagrangian/nodes_m"]
    n = verts_all.shape[0]
    picks = sorted({0, n // 2, n - 1})
    light = np.array([0.3, -0.4, 0.87])
    light /= np.linalg.norm(light)
    fig, axes = style.subplots(1, len(picks), height=3.6)
    axes = np.atleast_1d(axes)
    cmap = plt.get_cmap("Blues_r")
    pc = None
    for ax, k in zip(axes, picks):
        v = verts_all[k]
        centre = v.mean(axis=0)
        pc, sx, sy = shade(ax, v - centre, tris, light, cmap)
        frame = int(frames[k]) if k < len(frames) else -1
        nx, ny, _ = view(nodes[frame] - centre)
        ax.plot(nx, ny, "o", color="C3", ms=2.5, label="the dynamic model's 23 nodes")
        ax.set_xlim(sx.min() - 0.05, sx.max() + 0.05)
        ax.set_ylim(sy.min() - 0.05, sy.max() + 0.05)
        ax.set_aspect("equal")
        t = tall[frame] if frame >= 0 else float("nan")
        ax.set_title(f"t = {t:.2f} s")
        ax.set_xlabel("screen x (m)")
        ax.set_ylabel("screen y (m)")
    axes[0].legend(fontsize=9, loc="lower left")
    fig.colorbar(pc, ax=list(axes), label="shading |n . light| (1 = facing the light)", shrink=0.8)
    fig.suptitle(style.wrap(run.title, 110))
    return [style.save(fig, os.path.join(out, "tu_skin"))]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
