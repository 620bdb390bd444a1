"""Rudolf & Mould 2009 Fig. 11: the morphology of a 4 cm bell through one contraction cycle at
0.7 Hz, as a film strip. A thin wrapper over analysis/plot_jellyfish.py's morphology().
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
        return runs.moved_outputs(out, "rm_fig11", lambda tmp: pj.morphology(sweep, points, tmp, 1.0))
    finally:
        for f in points:
            f.close()


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
