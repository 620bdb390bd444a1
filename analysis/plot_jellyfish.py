#!/usr/bin/python3
"""Draws jellyfish runs (kind "jellyfish") from their HDF5 files alone.

usage: /usr/bin/python3 analysis/plot_jellyfish.py RUN_DIR [--out DIR] [--axis NAME] [--cycles N]

Writes to RUN_DIR/figures/ (or --out):
  trajectories.png  left: the centroid's axial displacement against time for every point
                    (Rudolf & Mould 2009 Fig. 5 left); right: distance_m against the sweep axis
                    (Fig. 5 right) when the run sweeps a numeric parameter, else a bar per point.
  morphology_<k>.png  bell outlines through one cycle after the warm-up, as a film strip
                    (Fig. 11): subumbrella (markers), exumbrella projected outward by the
                    thickness along the normals (§3.4), tentacles, muscle springs in grey.
  vorticity_<k>.png  when the point stored fields: vorticity with the bell and tracers (Fig. 6).
"""
import argparse
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def load(run_dir):
    import json
    index = h5py.File(os.path.join(run_dir, "index.h5"), "r")
    axes = json.loads(text(index["sweep"].attrs["columns_json"]))
    if "label" in index["sweep"] and any(text(v) for v in index["sweep/label"][...]):
        axes = ["label"] + [a for a in axes if a != "label"]
    sweep = {k: index["sweep"][k][...] for k in axes}
    points = []
    for path in sorted(glob.glob(os.path.join(run_dir, "point_*.h5"))):
        points.append(h5py.File(path, "r"))
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


def numeric_axis(sweep, wanted):
    names = [wanted] if wanted else [n for n in sweep if n != "label"]
    for n in names:
        if n in sweep and np.issubdtype(sweep[n].dtype, np.number) and len(np.unique(sweep[n])) > 1:
            return n
    return None


def trajectories(sweep, points, out, axis_name):
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    axis = numeric_axis(sweep, axis_name)
    cmap = plt.get_cmap("viridis")
    n = len(points)
    for k, f in enumerate(points):
        if text(f["metrics"].attrs.get("status", b"ok")) not in ("ok",) and "timeseries" not in f:
            continue
        t = f["timeseries/time_s"][...]
        y = f["timeseries/centroid_y_m"][...]
        left.plot(t, (y - y[0]) * 1e3, color=cmap(k / max(1, n - 1)), lw=0.8, label=label_of(sweep, k) if n <= 8 else None)
    left.set_xlabel("time (s)")
    left.set_ylabel("centroid displacement (mm)")
    left.set_title("trajectories (Fig. 5 left)")
    if n <= 8:
        left.legend(fontsize=7)
    dist = np.array([float(f["metrics/distance_m"][()]) if "metrics/distance_m" in f else np.nan for f in points])
    if axis:
        x = sweep[axis]
        order = np.argsort(x)
        right.plot(x[order], dist[order] * 1e3, "ko-", ms=3)
        best = int(np.nanargmax(dist))
        right.axvline(x[best], color="tab:red", lw=0.8, ls="--", label=f"max at {axis} = {x[best]:g}")
        right.set_xlabel(axis)
        right.legend(fontsize=8)
    else:
        right.bar(range(n), dist * 1e3, color="0.4")
        right.set_xticks(range(n), [label_of(sweep, k) for k in range(n)], rotation=20, fontsize=7)
    right.axhline(0, color="0.7", lw=0.6)
    right.set_ylabel("distance travelled in the window (mm)")
    right.set_title("distance (Fig. 5 right)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "trajectories.png"), dpi=110)
    plt.close(fig)


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
        fig, ax = plt.subplots(figsize=(14, 3.4))
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
            ax.text(col * spacing * 1e3, -35, f"t = {t[fr] - warm:.2f} s", ha="center", fontsize=7)
        ax.set_aspect("equal")
        ax.set_xlabel("mm (frames offset sideways; height relative to the first frame)")
        ax.set_title(f"bell through {cycles:g} cycle(s) at {hz:g} Hz (Fig. 11): {label_of(sweep, k)}", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"morphology_{k}.png"), dpi=110)
        plt.close(fig)


def vorticity(sweep, points, out):
    for k, f in enumerate(points):
        if "fields/vorticity_per_s" not in f:
            continue
        w = f["fields/vorticity_per_s"]
        tf = f["fields/time_s"][...]
        dx = float(f["fields"].attrs.get("dx_m", 0)) or float(param(f, "domain_m")) / w.shape[2]
        xy = f["lagrangian/markers_m"][...]
        tm = f["lagrangian/time_s"][...]
        picks = np.linspace(0, len(tf) - 1, 4).astype(int)
        fig, axes = plt.subplots(1, 4, figsize=(14, 4))
        for ax, fr in zip(axes, picks):
            m = np.searchsorted(tm, tf[fr])
            m = min(m, len(tm) - 1)
            c = xy[m, :, :].mean(axis=0)
            half = 0.06
            ext = [0, w.shape[2] * dx, 0, w.shape[1] * dx]
            lim = np.percentile(np.abs(w[fr]), 99.5) or 1
            ax.imshow(w[fr], origin="lower", extent=ext, cmap="RdBu_r", vmin=-lim, vmax=lim)
            ax.plot(xy[m, :, 0], xy[m, :, 1], "k.", ms=1.5)
            if "lagrangian/tracers_m" in f and f["lagrangian/tracers_m"].shape[0] > 0:
                tr = f["lagrangian/tracers_m"][min(m, f["lagrangian/tracers_m"].shape[0] - 1)]
                ax.plot(tr[:, 0], tr[:, 1], ".", color="0.3", ms=0.8)
            ax.set_xlim(c[0] - half, c[0] + half)
            ax.set_ylim(c[1] - half, c[1] + half)
            ax.set_title(f"t = {tf[fr]:.2f} s", fontsize=8)
            ax.set_xticks([])
            ax.set_yticks([])
        fig.suptitle(f"vorticity (1/s) and tracers (Fig. 6): {label_of(sweep, k)}", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"vorticity_{k}.png"), dpi=110)
        plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run_dir")
    ap.add_argument("--out")
    ap.add_argument("--axis", help="sweep axis for the distance plot (default: the first numeric one)")
    ap.add_argument("--cycles", type=float, default=1.0, help="cycles drawn in the morphology strip")
    ap.add_argument("--no-morphology", action="store_true", help="skip the per-point film strips")
    a = ap.parse_args()
    out = a.out or os.path.join(a.run_dir, "figures")
    os.makedirs(out, exist_ok=True)
    sweep, points = load(a.run_dir)
    trajectories(sweep, points, out, a.axis)
    if not a.no_morphology:
        morphology(sweep, points, out, a.cycles)
    vorticity(sweep, points, out)
    print(f"figures in {out}")


if __name__ == "__main__":
    main()
