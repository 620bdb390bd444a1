"""Rudolf & Mould 2009 Fig. 5: trajectories for several contraction frequencies (left) and the
distance travelled against frequency (right), with the bell's natural frequency from the pluck
(resonance panel). A thin wrapper: the drawing is analysis/plot_jellyfish.py's trajectories() and
resonance(), called on the run's HDF5.
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import style  # noqa: E402


def draw(run, out):
    pj = runs.plotter("plot_jellyfish")
    sweep, points = pj.load(run.folder)
    try:
        return runs.moved_outputs(out, "rm_fig5", lambda tmp: (pj.trajectories(sweep, points, tmp, "contraction_hz"),
                                                               pj.resonance(sweep, points, tmp)))
    finally:
        for f in points:
            f.close()


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
