"""Tu 1996, ch. 5 (turn): the fish's heading over time through a left turn from its fastest gait,
one line per turn amplitude at the run's fastest turn rate (left), and the top view of the same
swim-turn-swim sequences: the centre of mass's path with the fish's outline (its 23 nodes seen from
above) at the start of the turn and at the end of the run (right). From the turn run's point files.
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

# The outline seen from above: snout, the left nodes of rings 1-5, the tail tip, the right nodes back.
OUTLINE = [0, 1, 5, 9, 13, 17, 21, 20, 16, 12, 8, 4, 0]


def turn_window(f):
    """(start, end) of the schedule's first turn item, seconds, from the point's schedule attribute."""
    text = runs.text(f.attrs.get("schedule", ""))
    t = 0.0
    for item in text.split(";"):
        parts = item.split()
        if len(parts) != 2:
            continue
        if parts[0] in ("left", "right"):
            return t, t + float(parts[1])
        t += float(parts[1])
    return None


def draw(run, out):
    points = [f for f in run.ok_points() if "timeseries/heading_rad" in f and turn_window(f)]
    if not points:
        return []
    rates = np.array([float(f.attrs.get("turn_rate", np.nan)) for f in points])
    top = np.nanmax(rates)
    chosen = [f for f, r in zip(points, rates) if r == top]
    chosen.sort(key=lambda f: float(f.attrs.get("turn_amplitude", 0)))
    fig, (left, right) = style.subplots(1, 2, height=4.8)
    for k, f in enumerate(chosen):
        t = f["timeseries/time_s"][...]
        h = np.degrees(f["timeseries/heading_rad"][...])
        start, end = turn_window(f)
        h0 = np.interp(start, t, h)
        amp = float(f.attrs.get("turn_amplitude", np.nan))
        lab = f"turn amplitude {amp:g}"
        left.plot(t - start, h - h0, color=f"C{k}", lw=1.2, label=lab)
        x, y = f["timeseries/com_x_m"][...], f["timeseries/com_y_m"][...]
        L = float(f["metrics/fish_length_m"][()])
        right.plot(x / L, y / L, color=f"C{k}", lw=1.2, label=lab)
        nodes = f["lagrangian/nodes_m"]
        for frame, ls in ((int(np.searchsorted(t, start)), ":"), (len(t) - 1, "-")):
            xy = nodes[frame][:, :2] / L
            right.plot(xy[OUTLINE, 0], xy[OUTLINE, 1], color=f"C{k}", lw=0.8, ls=ls)
    start, end = turn_window(chosen[0])
    left.axvspan(0, end - start, color="0.9", zorder=0, label="turn item (left turn-MC on)")
    left.axhline(90, color="0.5", lw=0.8, ls="--", label="90 degrees")
    left.set_xlabel("time since the turn began (s)")
    left.set_ylabel("heading change of the body axis (degrees)")
    left.set_title(style.wrap(f"heading through a turn (turn rate r = {top:g})", 60))
    left.legend(fontsize=9, loc="lower right")
    right.set_aspect("equal", adjustable="datalim")
    right.set_xlabel("x (body lengths)")
    right.set_ylabel("y (body lengths)")
    right.set_title(style.wrap("top view: swim, turn, swim (outline dotted at the turn's start, solid at the end)", 60))
    right.legend(fontsize=9, loc="upper left")
    fig.suptitle(style.wrap(run.title, 110))
    return [style.save(fig, os.path.join(out, "tu_turn"))]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
