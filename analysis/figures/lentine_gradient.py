"""The driven flyer's derivative (Lentine et al. 2010 §3.3, §4.3; studies/control/flyer_gradient.toml in 2-D,
flyer3d_gradient.toml in 3-D):
(a) the fluid's upward force on the creature held with both outer wing joints at each angle, (b) the
controller's central difference of that force for one wing at 20 deg against the settle of its
steady-state evaluation, beside the held poses' secant (one wing's share: half the two wings' slope)
and the check's window. Drawn from the point files alone.
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import json  # noqa: E402
import os  # noqa: E402
import re  # noqa: E402

import numpy as np  # noqa: E402

import style  # noqa: E402


def _setting(f):
    """(label, resolved parameters) of one point file."""
    config = json.loads(runs.text(f.attrs.get("config_json", "{}")) or "{}")
    return runs.text(f.attrs.get("label", "")), config.get("params", config)


def _angle_deg(initial):
    m = re.search(r"outer_r\s*=\s*([-0-9.]+)", str(initial))
    return float(m.group(1)) if m else np.nan


def _metric(f, names):
    """The first of `names` the point file has (the 2-D and 3-D kinds name their means differently)."""
    for name in names:
        if f"metrics/{name}" in f:
            return float(f[f"metrics/{name}"][()])
    raise KeyError(f"none of {names} in {f.filename}")


_FORCE = ("final_drag_along_n", "mean_up_force_n")
_DERIVATIVE = ("final_derivative_per_rad", "mean_derivative_per_rad")


def draw(run, out):
    held, derivative, depth = [], [], np.nan
    for f in run.ok_points():
        label, p = _setting(f)
        depth = float(p.get("depth_m", np.nan))
        if float(p.get("strength_rad_per_s", 0)) == 0:
            held.append((_angle_deg(p.get("initial_deg", "")), _metric(f, _FORCE)))
        else:
            step_s = float(p["frame_s"]) / float(p["substeps"])
            derivative.append((float(p["settle_steps"]) * step_s, _metric(f, _DERIVATIVE), label))
    if len(held) < 2 or not derivative:
        return []
    held.sort()
    derivative.sort()
    angles, force = np.array([h[0] for h in held]), np.array([h[1] for h in held])
    # One wing's share of the secant over the held poses (the static cases move both wings).
    secant = (force[-1] - force[0]) / np.radians(angles[-1] - angles[0]) / 2
    fig, (a, b) = style.subplots(1, 2, height=4.2)
    a.plot(angles, force, "o-", color="C0", label="held poses")
    a.set_xlabel("outer wing joints' angle (deg)")
    per_depth = f", over {depth:.3g} m of depth" if np.isfinite(depth) else ""  # 2-D forces act on a slab
    a.set_ylabel(f"upward force on the creature (N{per_depth})")
    a.set_title("(a) the steady force at held poses")
    a.legend()
    settle = np.array([d[0] for d in derivative])
    value = np.array([d[1] for d in derivative])
    b.semilogx(settle, value, "s-", color="C3", label="controller's central difference, one wing")
    b.axhline(secant, color="C0", ls="--", label=f"held poses' secant, one wing ({secant:.3g} N/rad)")
    # The checks' window, derivative / (F(last) - F(first)) in [low, high] /rad, drawn as derivatives.
    span = force[-1] - force[0]
    window = [re.search(r"in \[([-+0-9.e]+), ([-+0-9.e]+)\]", str(c.get("expected", ""))) for c in run.checks]
    low, high = next(((float(m.group(1)), float(m.group(2))) for m in window if m), (0.5, 3.0))
    lo, hi = sorted((low * span, high * span))
    b.axhspan(lo, hi, color="C0", alpha=0.12, label="the check's window")
    b.axhline(0, color="k", lw=0.6)
    b.set_xlabel("settle of the steady-state evaluation (s)")
    b.set_ylabel(f"dF_z / d(angle) (N/rad{per_depth})")
    b.set_title("(b) the derivative the controller descends on")
    b.legend(fontsize="small")
    fig.suptitle(style.wrap(run.title, 110))
    return [style.save(fig, os.path.join(out, "lentine_gradient"))]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
