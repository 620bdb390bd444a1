"""Rudolf & Mould 2009 §3.3, "the resonant frequency of the system depends on the diameter of its
umbrella": the distance in a given time against the driving frequency for 2, 4 and 8 cm bells with
each size's natural frequency from its pluck, and the frequency of the largest distance against f_n
(issue 13 §3). A thin wrapper: the drawing is analysis/plot_jellyfish.py's size_scaling(), called on
the run's HDF5.
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402


def draw(run, out):
    pj = runs.plotter("plot_jellyfish")
    sweep, points = pj.load(run.folder)
    try:
        return runs.moved_outputs(out, "rm_size_scaling", lambda tmp: pj.size_scaling(sweep, points, tmp))
    finally:
        for f in points:
            f.close()


if __name__ == "__main__":
    runs.main(draw, __doc__)
