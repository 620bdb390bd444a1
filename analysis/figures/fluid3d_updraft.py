"""Lentine et al. 2010 §7.1's fluid without the flyer: the updraft from the floor's source through the
open top, on the stored plane through the box's centre at the last frame: (a) the vertical velocity
with the in-plane velocity as arrows, (b) the vorticity magnitude (the wall layers), (c) the
Q-criterion. Drawn from the point files alone.
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
from figures.fluid3d_fields import plane  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import os  # noqa: E402

import numpy as np  # noqa: E402

import style  # noqa: E402

# The plane's column and row axes for each normal (the kind's slice_normal).
_AXES = {"x": ("y", "z"), "y": ("x", "z"), "z": ("x", "y")}
_COMPONENT = {"x": "u_m_per_s", "y": "v_m_per_s", "z": "w_m_per_s"}


def draw(run, out):
    pngs = []
    for k, f in enumerate(run.ok_points()):
        if "fields/w_m_per_s" not in f:
            continue
        normal = runs.text(f.attrs.get("slice_normal", "y"))
        across, up = _AXES[normal]
        dx = float(f["fields"].attrs.get("dx_m", 1.0))
        t = float(f["fields/time_s"][-1])
        along = plane(f, _COMPONENT[across])
        vertical = plane(f, _COMPONENT[up])
        rows, cols = vertical.shape
        extent = [0, cols * dx, 0, rows * dx]
        fig, axes = style.subplots(1, 3, height=4.4)
        panels = [(vertical, f"{up}-velocity (m/s)", "viridis", None),
                  (plane(f, "vorticity_magnitude_per_s"), "|vorticity| (1/s)", "magma", None),
                  (plane(f, "q_per_s2"), "Q (1/s^2)", "RdBu_r", "symmetric")]
        for ax, (field, label, cmap, scale) in zip(axes, panels):
            kw = {}
            if scale == "symmetric":
                lim = float(np.abs(field).max()) or 1.0
                kw = {"vmin": -lim, "vmax": lim}
            image = ax.imshow(field, origin="lower", extent=extent, cmap=cmap, **kw)
            fig.colorbar(image, ax=ax, label=label, shrink=0.8)
            ax.set_xlabel(f"{across} (m)")
            ax.set_ylabel(f"{up} (m)")
        step = max(1, cols // 12)
        xs = (np.arange(cols) + 0.5) * dx
        ys = (np.arange(rows) + 0.5) * dx
        axes[0].quiver(xs[::step], ys[::step], along[::step, ::step], vertical[::step, ::step], color="k", width=0.004)
        inflow = float(f["metrics/inflow_m3_per_s"][()])
        fig.suptitle(style.wrap(f"The centre plane normal to {normal} at t = {t:.3g} s (inflow {inflow:.3g} m^3/s): "
                                f"{run.title}", 110))
        pngs.append(style.save(fig, os.path.join(out, "fluid3d_updraft" + (f"_{k}" if k else ""))))
    return pngs


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
