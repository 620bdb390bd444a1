"""Fluid solver (Rudolf & Mould 2009 §3.2, Stam's stable fluids): the Taylor-Green vortex's rms
velocity error against the cells per side for each advection scheme, on log axes. A thin wrapper
over analysis/plot_fluid.py's convergence().
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import style  # noqa: E402


def draw(run, out):
    pf = runs.plotter("plot_fluid")
    return runs.moved_outputs(out, "fluid_taylor_green", lambda tmp: pf.convergence(run.folder, tmp))


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
