"""Rudolf & Mould 2009 Fig. 6: a contraction cycle, trace particles showing the flow around the
bell (here over the vorticity). A thin wrapper over analysis/plot_jellyfish.py's vorticity().
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
        return runs.moved_outputs(out, "rm_fig6", lambda tmp: pj.vorticity(sweep, points, tmp))
    finally:
        for f in points:
            f.close()


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
