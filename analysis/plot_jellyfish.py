#!/usr/bin/python3
"""Draws jellyfish runs (kind "jellyfish") from their HDF5 files alone.

usage: /usr/bin/python3 analysis/plot_jellyfish.py RUN_DIR [--out DIR] [--axis NAME] [--cycles N]

Writes to RUN_DIR/figures/ (or --out):
  trajectories.png  left: the centroid's axial displacement against time for every point
                    (Rudolf & Mould 2009 Fig. 5 left); right: the distance in the window at its
                    whole cycles' mean speed against the sweep axis (Fig. 5 right), a curve per
                    grid and step, when the run sweeps a numeric parameter, else a bar per point.
  morphology_<k>.png  bell outlines through one cycle after the warm-up, as a film strip
                    (Fig. 11): subumbrella (markers), exumbrella projected outward by the
                    thickness along the normals (§3.4), tentacles, muscle springs in grey.
  vorticity_<k>.png  when the point stored fields: vorticity with the bell and tracers (Fig. 6).
  wake.png, wake.txt  when points stored fields: the starting and stopping vortices' circulation
                    below the aperture per cycle (analysis/jellyfish_wake.py; stagger.toml).
  resonance.png     when a point was plucked (finite natural_hz): the pluck's free decay, and
                    stroke amplitude and distance per cycle of the driven points against the
                    driving frequency, with f_n marked.
  convergence.png   when the run sweeps `cells`: distance per cycle and stroke amplitude against
                    the cell size per setting, with the observed order and Richardson's estimate
                    (also printed, and written to convergence.txt, with the net fraction and the
                    cycle spread: the standard error of the window's mean distance per cycle).
                    A run that also varies the step draws a series per ratio dt / dx.
  step_convergence.png  when a grid runs at three or more steps: distance per cycle and stroke
                    against the step, with the order and Richardson's estimate in dt (and .txt).
  reynolds.png      when the run sweeps the viscosity: forward speed and distance per cycle in
                    diameters against Re = f D^2 / nu, Re = 10 marked (Herschlag & Miller 2011's
                    collapse of 2-D bells below it; studies/jellyfish/reynolds.toml), and reynolds.txt.
"""
import argparse
import glob
import os

import h5py
import jellyfish_wake
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import style  # noqa: E402


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def load(run_dir):
    import json
    index = h5py.File(os.path.join(run_dir, "index.h5"), "r")
    axes = json.loads(text(index["sweep"].attrs["columns_json"]))
    if "label" in index["sweep"] and any(text(v) for v in index["sweep/label"][...]):
        axes = ["label"] + [a for a in axes if a != "label"]
    # Row k of the sweep is point k; a point not (yet) written drops its row, so that the sweep
    # and the point files stay aligned (an unfinished or failed point must not relabel the rest).
    paths = sorted(glob.glob(os.path.join(run_dir, "point_*.h5")))
    rows = [int(os.path.basename(p)[len("point_"):-len(".h5")]) for p in paths]
    sweep = {k: index["sweep"][k][...][rows] for k in axes}
    missing = len(index["sweep"][axes[0]]) - len(rows) if axes else 0
    if missing:
        print(f"{run_dir}: {missing} point(s) not written; drawn without them")
    points = [h5py.File(p, "r") for p in paths]
    return sweep, points


def param(f, name):
    return f["params"].attrs[name] if "params" in f and name in f["params"].attrs else f.attrs.get(name)


def label_of(sweep, k):
    parts = []
    for name, values in sweep.items():
        v = values[k]
        if name == "label":
            parts.append(text(v))
        elif isinstance(v, (bytes, str)):
            parts.append(f"{name}={text(v)}")
        else:
            parts.append(f"{name}={float(v):g}")
    return ", ".join(parts) if parts else f"point {k}"


def short_label(sweep, k):
    """The case label and the columns a case does not fix (those that vary within a label)."""
    if "label" not in sweep:
        return label_of(sweep, k)
    labels = [text(v) for v in sweep["label"]]
    parts = [labels[k]]
    for name, values in sweep.items():
        if name == "label":
            continue
        same = [i for i in range(len(labels)) if labels[i] == labels[k]]
        if len({text(values[i]) if isinstance(values[i], bytes) else float(values[i]) for i in same}) > 1:
            v = values[k]
            parts.append(f"{name}={text(v)}" if isinstance(v, (bytes, str)) else f"{name}={float(v):g}")
    return ", ".join(parts)


def numeric_axis(sweep, wanted):
    # The frequency first (Fig. 5's axis), when the run varies it.
    names = [wanted] if wanted else ["contraction_hz"] + [n for n in sweep if n not in ("label", "contraction_hz")]
    for n in names:
        if n in sweep and np.issubdtype(sweep[n].dtype, np.number) and len(np.unique(sweep[n])) > 1:
            return n
    return None


def metric(f, name):
    return float(f["metrics/" + name][()]) if "metrics/" + name in f else np.nan


def plucked(f):
    return np.isfinite(metric(f, "natural_hz"))


def window_distance(f):
    """Distance in the window at the mean speed of its whole cycles: a window that ends part way
    through a cycle (0.65 Hz over 10 s) would add that part's surge to distance_m. Files written
    before cycle_speed_m_per_s existed give distance_m."""
    speed = metric(f, "cycle_speed_m_per_s")
    return speed * float(param(f, "duration_s")) if np.isfinite(speed) else metric(f, "distance_m")


def has_tentacles(f):
    value = param(f, "tentacles")
    return True if value is None else bool(value)


def settings(points, indices):
    """The points grouped by grid, step, advection scheme and tentacles (the bell with them or alone), so that
    a run of several settings draws one curve each."""
    groups = {}
    for k in indices:
        f = points[k]
        cell_mm = 1e3 * float(param(f, "domain_m")) / float(param(f, "cells"))
        key = (not has_tentacles(f), round(cell_mm, 6), float(param(f, "dt_s")), text(param(f, "advection")))
        groups.setdefault(key, []).append(k)
    schemes = {key[3] for key in groups}
    grids = {key[1:3] for key in groups}
    bodies = {key[0] for key in groups}
    def name(alone, c, dt, scheme):
        parts = (["bell alone" if alone else "with tentacles"] if len(bodies) > 1 else []) + \
            ([f"{c:g} mm, dt {dt:g} s"] if len(grids) > 1 else []) + ([scheme] if len(schemes) > 1 else [])
        return ", ".join(parts)
    return [(name(*key) if len(groups) > 1 else None, ks) for key, ks in sorted(groups.items())]


def trajectories(sweep, points, out, axis_name):
    fig, (left, right) = style.subplots(1, 2, height=4.4)
    axis = numeric_axis(sweep, axis_name)
    cmap = plt.get_cmap("viridis")
    n = len(points)
    mixed = len({has_tentacles(f) for f in points}) > 1
    # Colour by the swept value, with a colour bar, when a numeric axis varies; else a legend.
    values = np.asarray(sweep[axis], dtype=float) if axis else None
    norm = plt.Normalize(np.nanmin(values), np.nanmax(values)) if axis else None
    for k, f in enumerate(points):
        if text(f["metrics"].attrs.get("status", b"ok")) not in ("ok",) and "timeseries" not in f:
            continue
        t = f["timeseries/time_s"][...]
        y = f["timeseries/centroid_y_m"][...]
        colour = cmap(norm(values[k])) if axis else cmap(k / max(1, n - 1))
        left.plot(t, (y - y[0]) * 1e3, color=colour, lw=0.9,
                  ls=":" if plucked(f) else "--" if mixed and not has_tentacles(f) else "-",
                  label=None if axis else label_of(sweep, k))
    left.set_xlabel("time (s)")
    left.set_ylabel("centroid displacement (mm)")
    left.set_title(style.wrap("trajectories (Fig. 5 left)" + ("; dotted: pluck" if any(plucked(f) for f in points) else "") +
                              ("; dashed: bell alone" if mixed else ""), 50))
    if axis:
        bar = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=left)
        bar.set_label(style.label(axis))
    else:
        left.legend()
    dist = np.array([window_distance(f) for f in points])
    driven = np.array([not plucked(f) for f in points])
    if axis:
        x = sweep[axis]
        ranked = [i for i in np.argsort(x, kind="stable") if driven[i]] or list(np.argsort(x, kind="stable"))
        for g, (name, ks) in enumerate(settings(points, ranked)):
            colour = f"C{g}" if name else "k"
            right.plot(x[ks], dist[ks] * 1e3, "o-", color=colour, ms=3, label=name)
            best = ks[int(np.nanargmax(dist[ks]))]
            right.axvline(x[best], color=colour, lw=0.8, ls="--", label=f"largest at {style.value_label(axis, float(x[best]))}")
        plucks = [k for k, f in enumerate(points) if plucked(f)]
        if plucks and axis == "contraction_hz":
            for g, (name, ks) in enumerate(settings(points, plucks)):
                fn = np.mean([metric(points[k], "natural_hz") for k in ks])
                right.axvline(fn, color=f"C{g}" if name else "tab:blue", lw=0.8, ls=":",
                              label=f"natural frequency {fn:.3g} Hz (pluck{', ' + name if name else ''})")
        right.set_xlabel(style.label(axis))
        right.legend()
    else:
        right.bar(range(n), dist * 1e3, color="0.4")
        right.set_xticks(range(n), [label_of(sweep, k) for k in range(n)], rotation=20)
        right.set_xlabel("sweep point")
    right.axhline(0, color="0.7", lw=0.6)
    right.set_ylabel("distance in the window (mm)")
    right.set_title(style.wrap("distance at the whole cycles' mean speed (Fig. 5 right)", 50))
    style.save(fig, os.path.join(out, "trajectories.png"))


def outline(xy, bell, thickness):
    """Subumbrella (the markers) and the exumbrella: each point moved outward by the thickness
    along the normal of the chain (Rudolf & Mould §3.4)."""
    sub = xy[:bell]
    tangent = np.gradient(sub, axis=0)
    normal = np.stack([-tangent[:, 1], tangent[:, 0]], axis=1)
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    centre = sub.mean(axis=0)
    if np.mean(np.sum((sub - centre) * normal, axis=1)) < 0:
        normal = -normal
    return sub, sub + thickness * normal


def morphology(sweep, points, out, cycles):
    for k, f in enumerate(points):
        if "lagrangian/markers_m" not in f:
            continue
        xy = f["lagrangian/markers_m"][...]
        t = f["lagrangian/time_s"][...]
        hz = float(param(f, "contraction_hz"))
        warm = float(param(f, "warmup_cycles")) / hz
        thickness = float(param(f, "bell_thickness_m"))
        bell = int(f["topology/bell_markers"][0])
        muscles = f["topology/muscles"][...].reshape(-1, 2)
        frames = np.searchsorted(t, warm + np.linspace(0, cycles / hz, 9)[:-1])
        frames = frames[frames < len(t)]
        fig, ax = style.subplots(height=3.0)
        spacing = 0.06
        for col, fr in enumerate(frames):
            p = xy[fr].copy()
            p[:, 0] += col * spacing - xy[fr, :bell, 0].mean()
            p[:, 1] -= xy[frames[0], :bell, 1].mean()
            sub, exu = outline(p, bell, thickness)
            ax.fill(np.r_[sub[:, 0], exu[::-1, 0]] * 1e3, np.r_[sub[:, 1], exu[::-1, 1]] * 1e3, color="0.85", lw=0)
            ax.plot(sub[:, 0] * 1e3, sub[:, 1] * 1e3, "k", lw=1)
            ax.plot(exu[:, 0] * 1e3, exu[:, 1] * 1e3, "0.3", lw=0.8)
            for a, b in muscles:
                ax.plot(p[[a, b], 0] * 1e3, p[[a, b], 1] * 1e3, color="tab:red", lw=0.4, alpha=0.5)
            tent = p[bell:]
            half = len(tent) // 2
            for chain, root in ((tent[:half], p[0]), (tent[half:], p[bell - 1])):
                c = np.vstack([root, chain])
                ax.plot(c[:, 0] * 1e3, c[:, 1] * 1e3, "k", lw=0.5)
            ax.text(col * spacing * 1e3, -35, f"t = {t[fr] - warm:.2f} s", ha="center", fontsize=9)
        ax.set_aspect("equal")
        ax.set_xlabel("x, each frame offset sideways; height from the first frame (mm)")
        ax.set_ylabel("height (mm)")
        ax.set_title(style.wrap(f"bell through {cycles:g} cycle(s) at {hz:g} Hz (Fig. 11): {short_label(sweep, k)}", 110))
        style.save(fig, os.path.join(out, f"morphology_{k}.png"))


def drawn_cycle(f, times):
    """(start, end) in s of the contraction cycle a figure of the point shows: the first cycle after
    the warm-up when `times` reach it, else the last whole cycle of `times`."""
    period = 1.0 / float(param(f, "contraction_hz"))
    start = float(param(f, "warmup_cycles") or 0.0) * period
    if start + period > times[-1] + 1e-9 or start < times[0] - 1e-9:
        start = max(times[0], times[-1] - period)
    return start, start + period


def vorticity(sweep, points, out):
    """Rudolf & Mould Fig. 6: the vorticity around the bell at four phases of one contraction cycle,
    with the trace particles' paths over the cycle before each frame (/lagrangian/tracers_m, stored
    at the markers' frames: they move a few mm per cycle, so a dot per frame would hide the flow)."""
    for k, f in enumerate(points):
        if "fields/vorticity_per_s" not in f:
            continue
        w = f["fields/vorticity_per_s"]
        tf = f["fields/time_s"][...]
        dx = float(f["fields"].attrs.get("dx_m", 0)) or float(param(f, "domain_m")) / w.shape[2]
        xy = f["lagrangian/markers_m"][...]
        tm = f["lagrangian/time_s"][...]
        bell = int(f["topology/bell_markers"][0]) if "topology/bell_markers" in f else xy.shape[1]
        tracers = f["lagrangian/tracers_m"] if "lagrangian/tracers_m" in f and f["lagrangian/tracers_m"].shape[0] else None
        start, end = drawn_cycle(f, tf)
        hz = float(param(f, "contraction_hz"))
        picks = [int(np.argmin(np.abs(tf - (start + q * (end - start))))) for q in (0.0, 0.25, 0.5, 0.75)]
        lim = max(np.percentile(np.abs(w[fr]), 99.5) for fr in picks) or 1.0
        trail = int(round(1.0 / hz / np.median(np.diff(tm)))) if len(tm) > 1 else 0  # marker frames per cycle
        if tracers is not None:  # every other row and column of the n x n lattice, so that paths stay apart
            side = int(round(np.sqrt(tracers.shape[1])))
            idx = np.arange(tracers.shape[1])
            keep = idx[((idx // side) % 2 == 0) & ((idx % side) % 2 == 0)] if side * side == len(idx) else idx
        fig, axes = style.subplots(1, 4, height=3.9, sharey=True)
        half = 0.05  # m: the window around the bell's centre
        ext = [0, w.shape[2] * dx * 1e3, 0, w.shape[1] * dx * 1e3]
        for ax, fr in zip(axes, picks):
            m = min(int(np.searchsorted(tm, tf[fr])), len(tm) - 1)
            c = xy[m, :bell, :].mean(axis=0)
            image = ax.imshow(w[fr], origin="lower", extent=ext, cmap="RdBu_r", vmin=-lim, vmax=lim)
            if tracers is not None:
                path = tracers[max(0, m - trail):m + 1][:, keep]  # the last cycle's frames x tracers x 2
                near = np.all(np.abs(path[-1] - c) < half, axis=1)
                ax.plot(path[:, near, 0] * 1e3, path[:, near, 1] * 1e3, color="0.1", lw=0.8)
                ax.plot(path[-1, near, 0] * 1e3, path[-1, near, 1] * 1e3, ".", color="0.1", ms=1.5)
            ax.plot(xy[m, :, 0] * 1e3, xy[m, :, 1] * 1e3, ".", color="tab:green", ms=2)
            ax.set_xlim((c[0] - half) * 1e3, (c[0] + half) * 1e3)
            ax.set_ylim((c[1] - half) * 1e3, (c[1] + half) * 1e3)
            ax.set_title(f"t = {tf[fr]:.2f} s (phase {(tf[fr] - start) * hz:.2f})")
            ax.set_xlabel("x (mm)")
        axes[0].set_ylabel("y (mm)")
        bar = fig.colorbar(image, ax=list(axes), shrink=0.9)
        bar.set_label("vorticity (1/s)")
        warm = float(param(f, "warmup_cycles") or 0.0)
        fig.suptitle(style.wrap(f"Fig. 6: the flow through one contraction cycle at {hz:g} Hz, t = {start:.2f}-{end:.2f} s"
                                f" (after {warm:g} warm-up cycles); green: the bell; black: trace particles and their"
                                f" paths over the last cycle; {label_of(sweep, k)}", 110))
        style.save(fig, os.path.join(out, f"vorticity_{k}.png"))


def resonance(sweep, points, out):
    """The pluck's free decay and the driven response against frequency, f_n marked."""
    plucks = [k for k, f in enumerate(points) if plucked(f)]
    several_sizes = len({float(param(f, "bell_diameter_m")) for f in points}) > 1
    if not plucks or (several_sizes and len(plucks) < len(points)):
        return  # several sizes driven: size_scaling() draws them
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    for k in plucks:
        f = points[k]
        t = f["timeseries/time_s"][...]
        left.plot(t, f["timeseries/diameter_ratio"][...], lw=0.9,
                  label=f"{short_label(sweep, k)}: f_n {metric(f, 'natural_hz'):.3g} Hz, zeta {metric(f, 'damping_ratio'):.2f}")
    left.axhline(1, color="0.7", lw=0.6)
    left.set_xlabel("time (s)")
    left.set_ylabel("aperture width / rest width")
    left.set_title("pluck: free decay of the diameter")
    left.legend(fontsize=9)
    driven = [k for k, f in enumerate(points) if not plucked(f)]
    if driven and "contraction_hz" in sweep:
        hz = {k: float(sweep["contraction_hz"][k]) for k in driven}
        twin = right.twinx()
        for g, (name, ks) in enumerate(settings(points, sorted(driven, key=lambda k: hz[k]))):
            x = [hz[k] for k in ks]
            amp = [metric(points[k], "stroke_amplitude") for k in ks]
            dpc = [metric(points[k], "distance_per_cycle_m") * 1e3 for k in ks]
            right.plot(x, amp, "o-" if g == 0 else "^-.", color="k", alpha=1 - 0.3 * g, ms=3,
                       label="stroke amplitude" + (f" ({name})" if name else ""))
            twin.plot(x, dpc, "s--" if g == 0 else "v:", color="tab:green", alpha=1 - 0.3 * g, ms=3,
                      label="distance per cycle" + (f" ({name})" if name else ""))
        twin.set_ylabel("distance per cycle (mm)", color="tab:green")
        for k in plucks:
            right.axvline(metric(points[k], "natural_hz"), color="tab:blue", ls=":", lw=1)
        right.axvline(np.nan, color="tab:blue", ls=":", label="f_n (pluck)")
        right.set_xlabel("driving frequency (Hz)")
        right.set_ylabel("stroke amplitude (diameter ratio)")
        right.set_title("driven at fixed peak tension")
        lines, labels = right.get_legend_handles_labels()
        more, more_labels = twin.get_legend_handles_labels()
        twin.legend(lines + more, labels + more_labels, fontsize=9, loc="best")  # the twin is drawn over right
    else:
        right.axis("off")
    style.save(fig, os.path.join(out, "resonance.png"))


def size_scaling(sweep, points, out):
    """Several bell sizes, each with a pluck: distance travelled in the window against the driving
    frequency per size with its f_n marked, and the frequency of the largest distance against f_n.
    A size run on several grids (cells across its own box: size_scaling.toml's 300
    and 150) draws a curve and a peak per grid, the coarser dashed and open."""
    sizes = sorted({round(float(param(f, "bell_diameter_m")), 9) for f in points})
    if len(sizes) < 2:
        return
    grids = sorted({int(param(f, "cells")) for f in points}, reverse=True)
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    peaks = {g: ([], []) for g in grids}
    for i, d in enumerate(sizes):
        for g_index, g in enumerate(grids):
            mine = [f for f in points
                    if round(float(param(f, "bell_diameter_m")), 9) == d and int(param(f, "cells")) == g]
            plucks = [f for f in mine if plucked(f)]
            driven = sorted((f for f in mine if not plucked(f)), key=lambda f: float(param(f, "contraction_hz")))
            if not plucks or not driven:
                continue
            fn = metric(plucks[0], "natural_hz")
            hz = np.array([float(param(f, "contraction_hz")) for f in driven])
            dist = np.array([window_distance(f) for f in driven]) * 1e3
            colour = f"C{i}"
            grid = f", {g} cells" if len(grids) > 1 else ""
            # Normalised by f_n and by the size's largest distance, so that the peaks of bells whose
            # distances differ 20-fold compare on one axis.
            left.plot(hz / fn, dist / np.nanmax(dist), "o-" if g_index == 0 else "o--", color=colour, ms=3,
                      mfc=colour if g_index == 0 else "none",
                      label=f"{d * 100:g} cm{grid} (f_n {fn:.3g} Hz, largest {np.nanmax(dist):.3g} mm)")
            peaks[g][0].append(fn)
            peaks[g][1].append(hz[int(np.nanargmax(dist))])
    left.axvspan(0.8, 1.2, color="0.93", zorder=0)
    left.axvline(1.0, color="0.5", ls=":", lw=1)
    left.set_xlabel("driving frequency / f_n")
    left.set_ylabel("distance in the window at its whole cycles' rate / largest")
    left.set_title("distance against frequency per size (grey: within 20% of f_n)")
    left.legend(fontsize=9)
    fn_all = [fn for fns, _ in peaks.values() for fn in fns]
    if fn_all:
        line = np.array([0.8 * min(fn_all), 1.25 * max(fn_all)])
        right.fill_between(line, 0.8 * line, 1.2 * line, color="0.9", label="within 20% of f_n")
        right.plot(line, line, color="0.5", lw=0.8)
        for g_index, g in enumerate(grids):
            fns, pk = peaks[g]
            grid = f" ({g} cells across the box)" if len(grids) > 1 else ""
            right.plot(fns, pk, "ko" if g_index == 0 else "ks", mfc="k" if g_index == 0 else "none",
                       label="frequency of the largest distance" + grid)
        right.set_xscale("log")
        right.set_yscale("log")
    right.set_xlabel("natural frequency f_n from the pluck (Hz)")
    right.set_ylabel("distance peak (Hz)")
    right.set_title("peak against f_n across sizes")
    right.legend(fontsize=9)
    style.save(fig, os.path.join(out, "size_scaling.png"))


def richardson(h, q):
    """Observed order and extrapolated value from three grids h, h/2, h/4 (Roache 1998)."""
    if len(q) != 3 or not np.all(np.isfinite(q)):
        return np.nan, np.nan
    d1, d2 = q[0] - q[1], q[1] - q[2]
    if d2 == 0 or d1 / d2 <= 0:
        return np.nan, np.nan
    ratio = h[0] / h[1]
    p = np.log(d1 / d2) / np.log(ratio)
    if p <= 0:  # the differences grow as the grid is refined: no estimate
        return p, np.nan
    return p, q[2] + (q[2] - q[1]) / (ratio ** p - 1)


def group_by_setting(sweep, points, skip):
    """The sweep's points grouped by every column outside `skip`: (column names, {values: [indices]})."""
    keys = [n for n in sweep if n not in skip]
    groups = {}
    for k, f in enumerate(points):
        g = tuple(text(sweep[n][k]) if isinstance(sweep[n][k], bytes) else float(sweep[n][k]) for n in keys)
        groups.setdefault(g, []).append(k)
    return keys, groups


def setting_name(keys, values):
    def one(n, v):
        if n == "tentacles":
            return "with tentacles" if v else "bell alone"
        return f"{n}={v:g}" if isinstance(v, float) else f"{n}={v}"
    return ", ".join(one(n, v) for n, v in zip(keys, values))


def save_study(fig, lines, out, stem):
    """Writes a convergence study's figure STEM.png and table STEM.txt, and prints the table."""
    style.save(fig, os.path.join(out, stem + ".png"))
    with open(os.path.join(out, stem + ".txt"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines))


def step_convergence(sweep, points, out):
    """Distance per cycle and stroke against the step on one grid (convergence_step_scheme.toml; in a
    grid study such as convergence_default.toml, each grid run at three or more steps): observed order
    and Richardson estimate in dt from the three smallest steps halving."""
    if "dt_s" not in sweep or len(np.unique(sweep["dt_s"])) < 3:
        return
    skip = {"dt_s", "label"}
    keys, groups = group_by_setting(sweep, points, skip)
    groups = {g: ks for g, ks in groups.items() if len({float(sweep["dt_s"][k]) for k in ks}) >= 3}
    if not groups:
        return
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    lines = ["setting | dt (s) | distance per cycle (mm) | stroke amplitude | cycle growth | observed order in dt | "
             "Richardson (mm) | finest / Richardson"]
    for g, ks in sorted(groups.items()):
        ks = sorted(ks, key=lambda k: -float(sweep["dt_s"][k]))
        dt = np.array([float(sweep["dt_s"][k]) for k in ks])
        d = np.array([metric(points[k], "distance_per_cycle_m") * 1e3 for k in ks])
        a = np.array([metric(points[k], "stroke_amplitude") for k in ks])
        growth = [metric(points[k], "cycle_distance_growth") for k in ks]
        name = setting_name(keys, g) or "default"
        p, rich = richardson(dt[-3:], d[-3:]) if len(d) >= 3 else (np.nan, np.nan)
        left.plot(dt, d, "o-", ms=3, label=f"{name} (p = {p:.2g})")
        if np.isfinite(rich):
            left.plot([0.0], [rich], "x", color=left.lines[-1].get_color())
        right.plot(dt, a, "o-", ms=3, label=name)
        for ti, di, ai, gi in zip(dt, d, a, growth):
            lines.append(f"{name} | {ti:g} | {di:.4g} | {ai:.4g} | {gi:.3g} | {p:.3g} | {rich:.4g} | {d[-1] / rich:.4f}")
    for ax, what in ((left, "distance per cycle (mm); x: Richardson estimate"), (right, "stroke amplitude")):
        ax.set_xlim(left=0)
        ax.set_xlabel("coupled step dt (s), one grid")
        ax.set_ylabel(what)
        ax.legend(fontsize=9)
    left.set_title("step convergence")
    save_study(fig, lines, out, "step_convergence")


def convergence(sweep, points, out):
    if "cells" not in sweep or len(np.unique(sweep["cells"])) < 2:
        return
    skip = {"cells", "dt_s", "label", "bell_segments", "domain_m"}
    keys, groups = group_by_setting(sweep, points, skip)
    cell_mm = lambda k: float(param(points[k], "domain_m")) / float(sweep["cells"][k]) * 1e3  # noqa: E731
    # A study that also varies the step on a grid (convergence_default.toml) draws one series per ratio
    # dt / dx, so that each line is a refinement with dt ∝ dx and its order is computed on that alone.
    series = {}
    for g, ks in groups.items():
        ratios = {}
        for k in ks:
            r = float(sweep["dt_s"][k]) / cell_mm(k) if "dt_s" in sweep else 0.0
            ratios.setdefault(float(f"{r:.6g}"), []).append(k)
        for r, rks in ratios.items():
            series[(g, r if len(ratios) > 1 else None)] = rks
    fig, (left, right) = plt.subplots(1, 2, figsize=(16, 4.5))
    lines = ["setting | cell (mm) | distance per cycle (mm) | stroke amplitude | net fraction | cycle spread | "
             "cycle growth | observed order | Richardson (mm)"]
    for (g, r), ks in sorted(series.items(), key=lambda item: (item[0][0], item[0][1] or 0.0)):
        ks = sorted(ks, key=lambda k: -cell_mm(k))
        h = np.array([cell_mm(k) for k in ks])
        d = np.array([metric(points[k], "distance_per_cycle_m") * 1e3 for k in ks])
        a = np.array([metric(points[k], "stroke_amplitude") for k in ks])
        name = setting_name(keys, g) + ("" if r is None else f", dt = {r * 1e3:g} ms per mm of cell")
        p, rich = richardson(h, d)
        style = "o-" if len(ks) > 1 else "s"
        # The observed order needs three grids halving the cell (richardson); otherwise the name alone.
        left.plot(h, d, style, ms=3, label=name if not np.isfinite(p) else f"{name} (p = {p:.2g})")
        right.plot(h, a, style, ms=3, label=name)
        net = [metric(points[k], "net_fraction") for k in ks]
        spread = [metric(points[k], "cycle_distance_spread") for k in ks]
        growth = [metric(points[k], "cycle_distance_growth") for k in ks]
        for hi, di, ai, ni, si, gi in zip(h, d, a, net, spread, growth):
            lines.append(f"{name} | {hi:g} | {di:.4g} | {ai:.4g} | {ni:.3g} | {si:.3g} | {gi:.3g} | {p:.3g} | {rich:.4g}")
    for ax, what in ((left, "distance per cycle (mm)"), (right, "stroke amplitude")):
        ax.set_xscale("log", base=2)
        ax.invert_xaxis()
        ax.set_xlabel("cell size (mm), dt ∝ dx, markers ≤ half a cell apart")
        ax.set_ylabel(what)
    # One legend, beside the right panel, for both (the same colours): inside, it hid points.
    right.legend(*left.get_legend_handles_labels(), fontsize=9, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    left.set_title("grid convergence")
    save_study(fig, lines, out, "convergence")


def reynolds(sweep, points, out):
    """Forward speed against Re = f D^2 / nu when the run sweeps the viscosity (driven points only)."""
    name = "kinematic_viscosity_m2_per_s"
    if name not in sweep or len(np.unique(sweep[name])) < 2:
        return
    rows = []
    for f in points:
        if plucked(f):
            continue
        hz, d, nu = (float(param(f, n)) for n in ("contraction_hz", "bell_diameter_m", name))
        speed = metric(f, "cycle_speed_m_per_s")
        rows.append((hz * d * d / nu, speed, metric(f, "distance_per_cycle_m") / d, speed * d / nu, nu))
    if len(rows) < 2:
        return
    rows.sort()
    re, speed, per_d, swim_re, nu = (np.array(c) for c in zip(*rows))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.semilogx(re, speed * 1e3, "o-", color="k", label="whole cycles' mean speed")
    ax.axvline(10, color="tab:red", ls=":", label="Re = 10 (Herschlag & Miller 2011)")
    ax.axhline(0, color="0.7", lw=0.6)
    ax.set_xlabel("Re = f D^2 / nu")
    ax.set_ylabel("forward speed (mm/s)")
    twin = ax.twinx()
    twin.semilogx(re, per_d, "s--", color="tab:green", ms=3)
    twin.set_ylabel("distance per cycle (diameters)", color="tab:green")
    ax.set_ylim(bottom=min(0.0, 1e3 * speed.min() * 1.1))
    twin.set_ylim(bottom=min(0.0, per_d.min() * 1.1))
    ax.set_title("the bell's speed against the Reynolds number")
    ax.legend(fontsize=9, loc="upper left")
    style.save(fig, os.path.join(out, "reynolds.png"))
    lines = ["nu_m2_per_s  Re  speed_mm_per_s  per_cycle_diameters  swimming_Re"]
    lines += [f"{n:.3g}  {r:.3g}  {1e3 * v:.4g}  {p:.4g}  {w:.3g}" for r, v, p, w, n in rows]
    with open(os.path.join(out, "reynolds.txt"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines))


def draw(run, out, axis=None, cycles=1.0, no_morphology=False):
    """Every figure of the run folder `run`, as PNGs (and tables) in folder `out`."""
    os.makedirs(out, exist_ok=True)
    sweep, points = load(run)
    trajectories(sweep, points, out, axis)
    if not no_morphology:
        morphology(sweep, points, out, cycles)
    vorticity(sweep, points, out)
    jellyfish_wake.wake(points, [label_of(sweep, k) for k in range(len(points))], param, out)
    resonance(sweep, points, out)
    size_scaling(sweep, points, out)
    convergence(sweep, points, out)
    step_convergence(sweep, points, out)
    reynolds(sweep, points, out)
    print(f"figures in {out}")


def figures(run):
    """(name, Figure) of every figure of the run folder `run`."""
    return style.collect(draw, run)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run_dir")
    ap.add_argument("--out")
    ap.add_argument("--axis", help="sweep axis for the distance plot (default: the first numeric one)")
    ap.add_argument("--cycles", type=float, default=1.0, help="cycles drawn in the morphology strip")
    ap.add_argument("--no-morphology", action="store_true", help="skip the per-point film strips")
    a = ap.parse_args()
    draw(a.run_dir, a.out or os.path.join(a.run_dir, "figures"), axis=a.axis, cycles=a.cycles, no_morphology=a.no_morphology)


if __name__ == "__main__":
    main()
