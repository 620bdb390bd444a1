"""The swimmer's figures (experiments/control/swimmer*.toml; Lentine et al. 2010 §7.2, Fig. 7), from
the HDF5 alone; plot_control_fluid.py calls these for runs that track a rise (timeseries rise_z_m).

rise.png: the creature's centre of mass height against time per point, the phases shaded (from the
recorded phase series), and the mouth flux beneath. swimmer_angles.png: the five controlled leg
angles of each point. rise.txt: per point its grid, step, rise per cycle and total rise, and the
ratio of each point's rise per cycle to the mouth-only point's of the same grid and step, and the
rise per cycle split into the phases with the legs' power stroke (1, 2: minimise the downward force)
and the recovery (3: maximise it), over the same last rise_cycles cycles. swimmer_vorticity.png:
vorticity with the bodies at six moments of the controller's last cycle (a Fig. 7 analogue).
"""
import os

import numpy as np
import style  # noqa: E402


PHASE_COLOURS = ["#d8e8f8", "#f8e0d0", "#e8e8e8"]


def _text(f, name):
    v = f.attrs.get(name, "")
    return v.decode() if isinstance(v, bytes) else str(v)


def _label(f):
    return (f"{_text(f, 'label')} {int(f.attrs['cells'])}^2 x{int(f.attrs['substeps'])}"
            f" {_text(f, 'advection')}")


def is_swimmer(f):
    return "timeseries/rise_z_m" in f


def _shade_phases(ax, t, phase):
    start = 0
    for k in range(1, len(t) + 1):
        if k == len(t) or phase[k] != phase[start]:
            t0 = t[start - 1] if start > 0 else 0.0
            ax.axvspan(t0, t[k - 1], color=PHASE_COLOURS[int(phase[start]) % 3], lw=0)
            start = k


def rise_figure(points, png):
    fig, (ax, axf) = style.subplots(2, 1, height=6, sharex=True, gridspec_kw={"height_ratios": [3, 1]})
    first = points[0]
    t = first["timeseries/time_s"][...]
    _shade_phases(ax, t, first["timeseries/phase"][...])
    for f in points:
        tt = f["timeseries/time_s"][...]
        z = f["timeseries/rise_z_m"][...]
        ax.plot(tt, (z - z[0]) * 100, lw=1.2,
                label=f"{_label(f)}: {100 * float(f['metrics/rise_per_cycle_m'][()]):+.2f} cm/cycle")
        axf.plot(tt, f["timeseries/mouth_flux_m_per_s"][...], lw=1)
    ax.set_ylabel("centre of mass height - first frame's (cm)")
    ax.set_title(style.wrap("swimmer: phases 1 draw in + min drag (blue), 2 expel + min (orange), 3 max drag (grey)", 100))
    ax.legend()
    axf.set_ylabel("mouth flux (m/s)")
    axf.set_xlabel("time (s)")
    style.save(fig, png)


def angles_figure(points, png):
    n = len(points)
    fig, axes = style.subplots(n, 1, height=2.6 * n, sharex=True, squeeze=False)
    for ax, f in zip(axes[:, 0], points):
        t = f["timeseries/time_s"][...]
        _shade_phases(ax, t, f["timeseries/phase"][...])
        for name in [k for k in f["timeseries"] if k.startswith("angle_deg_")]:
            ax.plot(t, f[f"timeseries/{name}"][...], lw=1, label=name[len("angle_deg_"):])
        ax.set_ylabel("leg angle (deg)")
        ax.set_title(_label(f))
        ax.legend(ncol=5)
    axes[-1, 0].set_xlabel("time (s)")
    style.save(fig, png)


def phase_split(f):
    """Rise per cycle (m) while in phases 1-2 and while in phase 3, over the last rise_cycles cycles."""
    t = f["timeseries/time_s"][...]
    z = f["timeseries/rise_z_m"][...]
    phase = f["timeseries/phase"][...]
    cycles = int(f.attrs["rise_cycles"])
    first = len(t) - int(round(cycles * float(f.attrs["cycle_s"]) / float(f.attrs["frame_s"])))
    dz = np.diff(z[first - 1:])
    ph = phase[first:]
    return dz[ph < 2].sum() / cycles, dz[ph == 2].sum() / cycles


def rise_table(points, path):
    def key(f):
        return (int(f.attrs["cells"]), int(f.attrs["substeps"]), _text(f, "advection"))

    off = {key(f): float(f["metrics/rise_per_cycle_m"][()]) for f in points
           if _text(f, "label").startswith("mouth_only")}
    with open(path, "w") as out:
        out.write("label                  cells  substeps  advection        rise_per_cycle_m  rise_total_m  "
                  "ratio_to_mouth_only  in_phases_1_2_m  in_phase_3_m\n")
        for f in points:
            r = float(f["metrics/rise_per_cycle_m"][()])
            base = off.get(key(f))
            ratio = f"{r / base:19.3f}" if base else " " * 18 + "-"
            power, recovery = phase_split(f)
            out.write(f"{_text(f, 'label'):22s} {key(f)[0]:5d}  {key(f)[1]:8d}  {key(f)[2]:15s}  {r:16.5f}  "
                      f"{float(f['metrics/rise_total_m'][()]):12.5f}  {ratio}  {power:15.5f}  {recovery:12.5f}\n")


def vorticity_strip(f, draw_field, png):
    """Six recorded fields of the last cycle with the bodies, one shared colour scale."""
    times = f["fields/time_s"][...]
    last = np.nonzero(times >= times[-1] - float(f.attrs["cycle_s"]) + 1e-9)[0]
    picks = last[np.linspace(0, len(last) - 1, min(6, len(last))).round().astype(int)]
    fig, axes = style.subplots(1, len(picks), height=style.WIDTH_IN / len(picks) + 0.9, squeeze=False)
    lim = None
    for j, (ax, k) in enumerate(zip(axes[0], picks)):
        im, lim = draw_field(ax, f, int(k), lim)
        ax.set_xlim(-1.0, 1.0)
        ax.set_title(f"t = {times[k]:.2f} s")
        if j:  # one y axis for the strip
            ax.set_ylabel("")
            ax.set_yticklabels([])
    fig.colorbar(im, ax=list(axes[0]), shrink=0.8).set_label("vorticity (1/s)")
    fig.suptitle(style.wrap(f"{_label(f)}: vorticity, the last cycle", 100))
    style.save(fig, png)


def draw(points, out_dir, draw_field):
    swimmers = [f for f in points if is_swimmer(f)]
    if not swimmers:
        return
    with_fields = [f for f in swimmers if "fields/vorticity_per_s" in f]
    if with_fields:
        vorticity_strip(with_fields[0], draw_field, os.path.join(out_dir, "swimmer_vorticity.png"))
    rise_figure(swimmers, os.path.join(out_dir, "rise.png"))
    angles_figure(swimmers[:4], os.path.join(out_dir, "swimmer_angles.png"))
    rise_table(swimmers, os.path.join(out_dir, "rise.txt"))
