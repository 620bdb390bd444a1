"""Mehla 2005 §5.3.7-5.3.8, Figs. 5.39-5.44: the settled default web against different
backgrounds (Fig. 5.39), without and with alpha blending (Figs. 5.40-5.43), and with shading by
strand type (Fig. 5.44: brighter frames, fainter spiral), drawn from the run's positions alone.
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
import os  # noqa: E402

import style  # noqa: E402

# Fig. 5.44: frames brightest, spiral faintest (the same shades as analysis/draw_web.py).
SHADES = [0.95, 0.9, 0.85, 0.85, 0.8, 0.75]


def segments(f, frame=-1):
    pos = f["lagrangian/positions_m"][frame]
    a, b = f["topology/spring_a"][...], f["topology/spring_b"][...]
    return np.stack([pos[a, :2], pos[b, :2]], axis=1), f["topology/spring_type"][...]


def background(ax, kind, extent):
    x0, x1, y0, y1 = extent
    if kind == "sky":  # a dusk gradient, like the photographs behind Fig. 5.39
        g = np.linspace(0, 1, 256)[:, None]
        img = np.dstack([0.10 + 0.5 * g, 0.12 + 0.3 * g, 0.25 + 0.2 * g]) * np.ones((1, 4, 1))
        ax.imshow(img, extent=extent, origin="lower", aspect="auto", zorder=0)
    elif kind == "foliage":  # seeded green noise
        rng = np.random.default_rng(5)
        n = rng.random((24, 24))
        img = np.dstack([0.05 + 0.15 * n, 0.2 + 0.35 * n, 0.05 + 0.1 * n])
        ax.imshow(img, extent=extent, origin="lower", interpolation="bicubic", aspect="auto", zorder=0)
    else:
        ax.set_facecolor(kind)


def panel(ax, segs, types, bg, alpha, shaded, colour="white"):
    lo, hi = segs.reshape(-1, 2).min(axis=0), segs.reshape(-1, 2).max(axis=0)
    pad = 0.03 * (hi - lo).max()
    extent = (lo[0] - pad, hi[0] + pad, lo[1] - pad, hi[1] + pad)
    background(ax, bg, extent)
    if shaded:
        cols = [(s, s, s) for s in np.array(SHADES)[types]]
    else:
        cols = colour
    ax.add_collection(LineCollection(segs, colors=cols, linewidths=0.5, alpha=alpha, zorder=1))
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])


def draw(run, out):
    f = run.ok_points()[0]
    segs, types = segments(f)
    fig, axes = style.subplots(2, 3, height=7.6)
    panel(axes[0, 0], segs, types, "black", 1.0, False)
    axes[0, 0].set_title("black background (Fig. 5.39)", fontsize=9)
    panel(axes[0, 1], segs, types, "sky", 0.6, True)
    axes[0, 1].set_title("dusk sky, shaded, alpha 0.6 (Fig. 5.39)", fontsize=9)
    panel(axes[0, 2], segs, types, "foliage", 0.6, True)
    axes[0, 2].set_title("foliage, shaded, alpha 0.6 (Fig. 5.39)", fontsize=9)
    panel(axes[1, 0], segs, types, "#1a1a1a", 1.0, False)
    axes[1, 0].set_title("no alpha blending (Figs. 5.40, 5.42)", fontsize=9)
    panel(axes[1, 1], segs, types, "#1a1a1a", 0.4, False)
    axes[1, 1].set_title("alpha blending 0.4 (Figs. 5.41, 5.43)", fontsize=9)
    panel(axes[1, 2], segs, types, "#1a1a1a", 0.55, True)
    axes[1, 2].set_title("shading by strand type + alpha (Fig. 5.44)", fontsize=9)
    fig.suptitle(run.title, fontsize=9)
    return [style.save(fig, os.path.join(out, "mehla_fig5_44"))]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
