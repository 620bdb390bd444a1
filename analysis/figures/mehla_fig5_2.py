"""Mehla 2005 Figs. 5.1-5.2: a strand laid at rest length sags, over-extended strands stay taut,
Provot's strain limit caps the stretch; beside them the settling curves (§5.1: webs settle in
5-10 s). Every point of the strand_layouts run, settled shape and kinetic energy, from its HDF5.
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from figures import webs  # noqa: E402
import os  # noqa: E402

import style  # noqa: E402


def draw(run, out):
    fig, (shape, energy) = plt.subplots(1, 2, figsize=(12, 4.5))
    cmap = plt.get_cmap("viridis")
    labels = run.labels()
    n = len(run.points())
    for k, f in enumerate(run.points()):
        if runs.text(f.attrs.get("status", "ok")) != "ok":
            continue
        c = cmap(k / max(1, n - 1))
        pos = f["lagrangian/positions_m"][-1]
        shape.plot(pos[:, 0] * 1e3, pos[:, 1] * 1e3, color=c, lw=1.2, label=labels[k])
        webs.settling_curve(f, energy, labels[k], c)
    shape.set_xlabel("x (mm)")
    shape.set_ylabel("y (mm)")
    shape.set_title("settled strands (Fig. 5.1: rest layout sags; Fig. 5.2: Provot)", fontsize=9)
    shape.legend(fontsize=9)
    energy.set_title("settling: kinetic energy (dashed: settled, 1e-4 of peak)", fontsize=9)
    energy.legend(fontsize=9)
    fig.suptitle(run.title, fontsize=9)
    return [style.save(fig, os.path.join(out, "mehla_fig5_2"))]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
