"""The 3-D fluid (Lentine et al. 2010 §4.1's solver, Stam's stable fluids in 3-D) against the decaying
Taylor-Green vortex in the Stokes limit: (a) the decay-rate and velocity errors against the cells per
side on log axes, with the discrete Laplacian's rate error and a slope of two; (b) the kinetic
energy's relative error against exp(-6 nu k^2 t) over time, per grid; (c) the Q-criterion on the
stored plane of the finest grid at the last frame. Drawn from the point files alone.
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


def _metric(f, name):
    return float(f["metrics/" + name][()]) if "metrics/" + name in f else float("nan")


def draw(run, out):
    points = sorted((f for f in run.ok_points() if "metrics/decay_rate_error" in f), key=lambda f: int(f.attrs["cells"]))
    if not points:
        return []
    cells = np.array([int(f.attrs["cells"]) for f in points])
    amplitude = np.array([float(f.attrs["amplitude_m_per_s"]) for f in points])
    rate = np.array([_metric(f, "decay_rate_error") for f in points])
    velocity = np.array([_metric(f, "velocity_error_rms_m_per_s") for f in points]) / amplitude
    fig, (conv, energy, q_axes) = style.subplots(1, 3, height=4.0)

    # (a) errors against the grid, the discrete Laplacian's rate error 1 - (sin(k dx/2) / (k dx/2))^2
    # (one wavelength across the box: k dx = 2 pi / cells) and a slope of two through the finest point.
    n = np.geomspace(cells.min(), cells.max(), 50)
    half = np.pi / n
    conv.loglog(cells, rate, "o-", label="decay-rate error |nu_eff - nu| / nu")
    conv.loglog(cells, velocity, "s-", label="velocity error rms / A")
    conv.loglog(n, 1 - (np.sin(half) / half) ** 2, "k:", lw=1, label="discrete Laplacian's rate error")
    conv.loglog(n, velocity[-1] * (cells[-1] / n) ** 2, "k--", lw=0.8, label="slope -2")
    conv.set_xticks(cells, [str(c) for c in cells])
    conv.minorticks_off()
    conv.set_xlabel("cells per side")
    conv.set_ylabel("relative error")
    conv.set_title("(a) convergence")
    conv.legend(fontsize="small", loc="lower left")

    # (b) kinetic energy against the exact exp(-6 nu k^2 t), per grid.
    for f, c in zip(points, cells):
        t = f["timeseries/time_s"][()]
        energy.plot(t, f["timeseries/kinetic_energy_error_rel"][()], label=f"{c}^3")
    energy.set_xlabel("time (s)")
    energy.set_ylabel("KE / KE_exact - 1")
    energy.set_title("(b) kinetic energy")
    energy.legend(fontsize="small")

    # (c) Q on the stored plane of the finest grid, last frame.
    finest = points[-1]
    q = plane(finest, "q_per_s2")
    dx = float(finest["fields"].attrs.get("dx_m", 1.0))
    extent = [0, q.shape[1] * dx, 0, q.shape[0] * dx]
    lim = float(np.abs(q).max()) or 1.0
    image = q_axes.imshow(q, origin="lower", extent=extent, cmap="RdBu_r", vmin=-lim, vmax=lim)
    fig.colorbar(image, ax=q_axes, label="Q (1/s^2)", shrink=0.8)
    t_last = float(finest["fields/time_s"][-1])
    normal = runs.text(finest.attrs.get("slice_normal", "z"))
    axes = {"x": ("y", "z"), "y": ("x", "z"), "z": ("x", "y")}[normal]
    q_axes.set_xlabel(f"{axes[0]} (m)")
    q_axes.set_ylabel(f"{axes[1]} (m)")
    q_axes.set_title(f"(c) Q, {cells[-1]}^3, t = {t_last:.3g} s")

    nu = float(points[0].attrs["kinematic_viscosity_m2_per_s"])
    k = 2 * np.pi / float(points[0].attrs["domain_x_m"])
    fig.suptitle(style.wrap(f"3-D Taylor-Green vortex, Stokes limit (Re = A / (nu k) = {amplitude[0] / (nu * k):.3g}): "
                            f"{run.title}", 110))
    return [style.save(fig, os.path.join(out, "fluid3d_taylor_green"))]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
