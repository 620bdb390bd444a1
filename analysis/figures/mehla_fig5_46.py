"""Mehla 2005 §5.3.9, Figs. 5.45-5.47: the web billowing in wind: frames of the animation
(shaded, the rest shape faint behind) and the hub's displacement against time.
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import numpy as np  # noqa: E402

from figures import webs  # noqa: E402
import os  # noqa: E402

import style  # noqa: E402


def draw(run, out):
    pngs = []
    for k, f in enumerate(run.ok_points()):
        pos = f["lagrangian/positions_m"]
        t = f["lagrangian/time_s"][...]
        picks = np.linspace(0, len(t) - 1, 5).round().astype(int)
        fig = style.figure(height=6.0)
        gs = fig.add_gridspec(2, 5, height_ratios=[2.2, 2])
        for col, fr in enumerate(picks):
            ax = fig.add_subplot(gs[0, col])
            webs.draw_web(f, ax, int(fr))
            ax.set_title(f"t = {t[fr]:.2f} s")
        hub = fig.add_subplot(gs[1, :])
        hubs = f["topology/hub_particles"][...] if "topology/hub_particles" in f else None
        if hubs is not None and len(hubs):
            p = pos[...][:, np.sort(hubs), :].mean(axis=1)
            d = p - p[0]
            for j, axis in enumerate("xyz"[: d.shape[1]]):
                hub.plot(t, d[:, j] * 1e3, lw=0.8, label=f"hub {axis}")
            hub.set_xlabel("time (s)")
            hub.set_ylabel("hub displacement (mm)")
            hub.legend(loc="upper left")
        # What the run holds, read from its file: the stored frames, their span and rate.
        rate = (len(t) - 1) / (t[-1] - t[0]) if len(t) > 1 and t[-1] > t[0] else float("nan")
        fig.suptitle(style.wrap(f"Mehla Figs. 5.46-5.47, the web in wind: {len(t)} stored frames over "
                                f"{t[-1] - t[0]:.3g} s ({rate:.3g} frames/s), five of them above; "
                                f"{runs.text(f.attrs.get('label', '')) or run.title}", 110))
        pngs.append(style.save(fig, os.path.join(out, "mehla_fig5_46" + (f"_{k}" if k else ""))))
    return pngs

def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
