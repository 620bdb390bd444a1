"""Rudolf & Mould 2009 Fig. 4: the spring-mass network of the bell slice (left; the muscle springs
coloured from the aperture to the apex) and the contraction curves (right): the aperture muscle's
rest-length factor over one cycle after the warm-up and the diameter ratio it produces, for each
point of the run (staggered and unison expansion, §3.3), and, when the run recorded them
(/lagrangian/muscle_activation), every muscle element's activation curve. The run records the aperture muscle's
curve only; with staggered expansion the springs toward the apex finish their expansion sooner
(src/jellyfish/contraction_curve.hpp).
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import os  # noqa: E402

import style  # noqa: E402


def attr(f, name, default=None):
    return f.attrs[name] if name in f.attrs else default


def network(f, ax):
    xy = f["lagrangian/markers_m"][0]
    springs = f["topology/springs"][...].reshape(-1, 2)
    muscles = f["topology/muscles"][...].reshape(-1, 2)
    for a, b in springs:
        ax.plot(xy[[a, b], 0] * 1e3, xy[[a, b], 1] * 1e3, color="0.3", lw=0.8)
    cmap = plt.get_cmap("plasma")
    # Muscles ordered by their height: the aperture (lowest) to the apex.
    height = np.array([xy[[a, b], 1].mean() for a, b in muscles])
    order = np.argsort(np.argsort(height))
    for k, (a, b) in enumerate(muscles):
        ax.plot(xy[[a, b], 0] * 1e3, xy[[a, b], 1] * 1e3, color=cmap(order[k] / max(1, len(muscles) - 1)), lw=1.2)
    bell = int(f["topology/bell_markers"][0])
    ax.plot(xy[:bell, 0] * 1e3, xy[:bell, 1] * 1e3, "k.", ms=2)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title("spring network: chain (grey), muscles by height (colour bar)")


def release(f):
    """The point's expansion in words: staggered (apex first, pulse_stagger > 0) or unison."""
    stagger = float(attr(f, "pulse_stagger", 0.0))
    return f"staggered release (pulse stagger {stagger:g})" if stagger > 0 else "unison release (pulse stagger 0)"


def drawn_cycle(f, t):
    """Times and phases of the first cycle after the warm-up (the cycle the figure compares)."""
    hz = float(attr(f, "contraction_hz", 1.0))
    warm = float(attr(f, "warmup_cycles", 0.0)) / hz
    sel = (t >= warm) & (t <= warm + 1.0 / hz)
    return sel, (t[sel] - warm) * hz


def muscle_curves(points, ax):
    """Each muscle element's activation over the cycle after the warm-up (/lagrangian/muscle_activation,
    frames x muscles x 1), coloured aperture -> apex by a colour bar as in the network panel: Fig. 4
    right's family of staggered curves. Solid: the staggered point; dashed: the unison one."""
    cmap = plt.get_cmap("plasma")
    for k, f in enumerate(points[:2]):
        t = f["lagrangian/time_s"][...]
        act = f["lagrangian/muscle_activation"][...][:, :, 0]
        sel, phase = drawn_cycle(f, t)
        xy = f["lagrangian/markers_m"][0]
        muscles = f["topology/muscles"][...].reshape(-1, 2)
        height = np.array([xy[[a, b], 1].mean() for a, b in muscles])
        order = np.argsort(np.argsort(height))
        for m in range(0, act.shape[1], max(1, act.shape[1] // 24)):
            ax.plot(phase, act[sel, m], color=cmap(order[m] / max(1, act.shape[1] - 1)),
                    lw=0.8, ls="-" if k == 0 else "--", label=release(f) if m == 0 else None)
    ax.set_xlabel("phase in the cycle after the warm-up (cycles)")
    ax.set_ylabel("muscle activation a(t) (0 to 1)")
    ax.set_xlim(0, 0.3)
    ax.set_title("the pulse: each muscle's activation (solid: staggered, dashed: unison)")


def draw(run, out):
    points = run.ok_points()
    if not points or "topology/muscles" not in points[0]:
        return []
    has_curves = "lagrangian/muscle_activation" in points[0]
    fig = style.figure(height=7.6)
    grid = fig.add_gridspec(2, 2)
    left = fig.add_subplot(grid[0, 0])
    network(points[0], left)
    if has_curves:
        middle = fig.add_subplot(grid[0, 1])
        muscle_curves(points, middle)
        bar = fig.colorbar(plt.cm.ScalarMappable(cmap="plasma"), ax=middle)
        bar.set_label("muscle height, aperture (0) to apex (1) (fraction)")
    right = fig.add_subplot(grid[1, 0])
    diff = fig.add_subplot(grid[1, 1])
    ratios = []
    for k, f in enumerate(points):
        t = f["timeseries/time_s"][...]
        sel, phase = drawn_cycle(f, t)
        ratio = f["timeseries/diameter_ratio"][sel]
        ratios.append((release(f), phase, ratio))
        right.plot(phase, f["timeseries/aperture_muscle_factor"][sel], lw=1.0, color=f"C{k}")
        right.plot(phase, ratio, ls="--", color=f"C{k}", lw=1.6, label=release(f))
    right.axhline(0.56, color="0.6", lw=0.6, ls=":")
    right.plot([], [], color="0.3", lw=1.0, label="solid: aperture muscle's rest-length factor")
    right.plot([], [], color="0.3", lw=1.6, ls="--", label="dashed: diameter ratio (dotted 0.56: Fig. 3)")
    right.set_xlabel("phase in the cycle after the warm-up (cycles)")
    right.set_ylabel("factor or diameter ratio (fraction of rest)")
    right.set_title("aperture muscle's curve and the diameter it gives")
    right.legend(fontsize=9, loc="lower right")
    if len(ratios) >= 2:
        (name_a, pa, ra), (name_b, pb, rb) = ratios[0], ratios[1]
        d = ra - np.interp(pa, pb, rb)
        diff.plot(pa, d * 100, color="k", lw=1.2)
        diff.axhline(0, color="0.6", lw=0.6)
        diff.set_title(style.wrap(f"diameter ratio: {name_a.split(' (')[0]} minus {name_b.split(' (')[0]}", 55))
        diff.set_xlabel("phase in the cycle after the warm-up (cycles)")
        diff.set_ylabel("difference (% of the rest diameter)")
    else:
        diff.axis("off")
    fig.suptitle(style.wrap(run.title, 110))
    return [style.save(fig, os.path.join(out, "rm_fig4"))]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
