"""The contraction spline fitted to its data (Rudolf & Mould 2009 §3.3: a Hermite curve for the
rest length over a cycle): the samples against their phase with the fitted curve and its knots,
and the residuals. A thin wrapper over analysis/plot_fit.py's plot_spline() on FIT/spline_fit.h5.
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import style  # noqa: E402


def draw(run, out):
    import os

    pf = runs.plotter("plot_fit")
    path = os.path.join(run.folder, "spline_fit.h5")
    if not os.path.exists(path):
        return []
    png = os.path.join(out, "fit_spline.png")
    pf.plot_spline(path, png)
    return [png]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
