"""Mehla 2005 Fig. 5.17, orb webs of varying sizes: every web of the sweep as settled, the sweep's measures
per point and the settling curves, from the run's HDF5 alone.
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import style  # noqa: E402
from figures import webs  # noqa: E402

METRICS = ("spokes", "spiral_segments", "particles", "hub_sag_m", "settling_time_s")


def draw(run, out):
    return [webs.sweep_grid(run, out, "mehla_fig5_17", f"Mehla Fig. 5.17: {run.title}", METRICS)]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
