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
    ax.set_title("spring network: chain (grey), muscles aperture → apex (dark → light)", fontsize=8)


def muscle_curves(points, labels, ax):
    """Each muscle element's activation over the cycle after the warm-up (/lagrangian/muscle_activation,
    frames x muscles x 1), coloured aperture -> apex as in the network panel: Fig. 4 right's family of
    staggered curves. Solid: the first point (staggered); dashed: the second (unison)."""
    cmap = plt.get_cmap("plasma")
    for k, f in enumerate(points[:2]):
        t = f["lagrangian/time_s"][...]
        act = f["lagrangian/muscle_activation"][...][:, :, 0]
        hz = float(attr(f, "contraction_hz", 1.0))
        warm = float(attr(f, "warmup_cycles", 0.0)) / hz
        sel = (t >= warm) & (t <= warm + 1.0 / hz)
        xy = f["lagrangian/markers_m"][0]
        muscles = f["topology/muscles"][...].reshape(-1, 2)
        height = np.array([xy[[a, b], 1].mean() for a, b in muscles])
        order = np.argsort(np.argsort(height))
        for m in range(act.shape[1]):
            ax.plot((t[sel] - warm) * hz, act[sel, m], color=cmap(order[m] / max(1, act.shape[1] - 1)),
                    lw=0.8, ls="-" if k == 0 else "--", label=labels[k] if m == 0 else None)
    ax.set_xlabel("phase in the cycle after the warm-up")
    ax.set_ylabel("muscle activation a(t)")
    ax.set_title("each muscle's activation, aperture → apex (dark → light)", fontsize=8)
    ax.legend(fontsize=7)


def draw(run, out):
    points = run.ok_points()
    if not points or "topology/muscles" not in points[0]:
        return []
    labels = run.labels()
    has_curves = "lagrangian/muscle_activation" in points[0]
    if has_curves:
        fig, (left, middle, right) = plt.subplots(1, 3, figsize=(17, 4.6), gridspec_kw={"width_ratios": [1, 1.2, 1.3]})
        muscle_curves(points, labels, middle)
    else:
        fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6), gridspec_kw={"width_ratios": [1, 1.3]})
    network(points[0], left)
    for k, f in enumerate(points):
        t = f["timeseries/time_s"][...]
        hz = float(attr(f, "contraction_hz", 1.0))
        warm = float(attr(f, "warmup_cycles", 0.0)) / hz
        sel = (t >= warm) & (t <= warm + 1.0 / hz)
        phase = (t[sel] - warm) * hz
        line = right.plot(phase, f["timeseries/aperture_muscle_factor"][sel], lw=1.2,
                          label=f"{labels[k]}: aperture muscle curve")[0]
        right.plot(phase, f["timeseries/diameter_ratio"][sel], ls="--", color=line.get_color(), lw=1,
                   label=f"{labels[k]}: diameter ratio")
    right.axhline(0.56, color="0.6", lw=0.6, ls=":")
    right.set_xlabel("phase in the cycle after the warm-up")
    right.set_ylabel("factor / ratio")
    right.set_title("the aperture muscle's curve (aperture_muscle_factor) and the diameter it gives (0.56: Fig. 3)", fontsize=8)
    right.legend(fontsize=7)
    fig.suptitle(run.title, fontsize=9)
    fig.tight_layout()
    return [runs.savefig(fig, out, "rm_fig4")]


if __name__ == "__main__":
    runs.main(draw, __doc__)
