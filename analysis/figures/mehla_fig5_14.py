"""Mehla 2005 Figs. 5.7-5.14: the default orb web as built and settled: its parts by strand type
(frame, spokes, hub, spiral), the web in grey shades, and its settling curve (§5.1: 5-10 s).
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")

from figures import webs  # noqa: E402
import os  # noqa: E402

import style  # noqa: E402


def draw(run, out):
    pngs = []
    for k, f in enumerate(run.ok_points()):
        fig, (types, grey, energy) = style.subplots(1, 3, height=4.4, gridspec_kw={"width_ratios": [1, 1, 0.9]})
        webs.draw_web(f, types, by_type=True)
        types.set_title("strand types (Figs. 5.7-5.14)")
        webs.draw_web(f, grey)
        grey.set_title(f"settled, {int(f['metrics/particles'][()])} particles")
        webs.settling_curve(f, energy)
        energy.set_title("settling (dashed: settled)")
        fig.suptitle(style.wrap(run.title, 100))
        pngs.append(style.save(fig, os.path.join(out, "mehla_fig5_14" + (f"_{k}" if k else ""))))
    return pngs


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
