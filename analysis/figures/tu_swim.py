"""Tu 1996, ch. 5 (swim): the swim motor controller's speed against its rate, one line per
amplitude (left), and against its amplitude, one line per rate (right), in body lengths per second,
from the swim run's sweep table (the thesis: speed grows roughly in proportion to both).
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import os  # noqa: E402

import style  # noqa: E402

R_MAX = 0.075  # the [reimpl] largest rate (the kind's default r_max)


def draw(run, out):
    alpha, rate = run.metric("swim_amplitude"), run.metric("swim_rate")
    speed = run.metric("speed_body_lengths_per_s")
    if len(speed) == 0 or np.all(np.isnan(alpha)) or np.all(np.isnan(rate)):
        return []
    fig, (left, right) = style.subplots(1, 2, height=4.4)
    for k, a in enumerate(np.unique(alpha)):
        sel = alpha == a
        order = np.argsort(rate[sel])
        left.plot(rate[sel][order] / R_MAX, speed[sel][order], "o-", color=f"C{k}", label=f"amplitude alpha = {a:g}")
    for k, r in enumerate(np.unique(rate)):
        sel = rate == r
        order = np.argsort(alpha[sel])
        right.plot(alpha[sel][order], speed[sel][order], "s-", color=f"C{k}", label=f"rate r = {r / R_MAX:g} r_max")
    for ax in (left, right):
        ax.axhline(0.5, color="0.6", lw=0.8, ls=":")
        ax.set_ylabel("speed (body lengths per second)")
        ax.set_ylim(bottom=0)
        ax.legend(fontsize=9, loc="upper left")
    left.set_xlabel("swim-MC rate r (fraction of r_max = 0.075)")
    left.set_title("speed against the rate (dotted: 0.5 body lengths/s)")
    right.set_xlabel("swim-MC amplitude alpha (fraction of full contraction)")
    right.set_title("speed against the amplitude")
    right.set_xlim(0, 1.05)
    left.set_xlim(0, 1.05)
    fig.suptitle(style.wrap(run.title, 110))
    return [style.save(fig, os.path.join(out, "tu_swim"))]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
