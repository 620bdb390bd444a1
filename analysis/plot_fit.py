#!/usr/bin/python3
"""Draws the results of `creaturelab fit` from their HDF5 files alone.

usage: /usr/bin/python3 analysis/plot_fit.py FIT_DIR [--out DIR]

FIT_DIR holds spline_fit.h5 (`fit spline`) or controller_fit.h5 (`fit controller`), or both.
Writes to FIT_DIR/figures/ (or --out):
  spline_fit.png       left: the samples against their phase in the period with the fitted
                       curve, its knots (value ± 1σ) and the start; right: residuals against time.
  controller_fit.png   left: the muscle rest-length factor through one cycle, start (paper's
                       default) and fitted, for the aperture spring and the apex spring (whose
                       expansion is staggered); middle: both trajectories (the centroid's axial
                       displacement against time); right: the objective per iteration.
"""
import argparse
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import style  # noqa: E402


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def plot_spline(path, out_png):
    f = h5py.File(path, "r")
    fig, (curve, resid) = style.subplots(1, 2, height=4.2, gridspec_kw={"width_ratios": [3, 2]})
    phase, value, weight = f["data/phase"][...], f["data/value"][...], f["data/weight"][...]
    used = weight > 0
    curve.plot(phase[used], value[used], ".", color="0.55", ms=3, label=f"data ({used.sum()} samples)")
    if (~used).any():
        curve.plot(phase[~used], value[~used], "x", color="0.75", ms=3, label="weight 0")
    curve.plot(f["curve/phase"][...], f["curve/value"][...], "k", lw=1.6,
               label=f"fit (residual rms {f['residual_rms'][()]:.3g})")
    kp, kv, ks = f["knots/phase"][...], f["knots/value"][...], f["knots/value_sigma"][...]
    curve.errorbar(kp, kv, yerr=np.nan_to_num(ks), fmt="o", color="tab:red", ms=5, capsize=3, label="knots ± 1σ")
    curve.plot(kp, f["knots/start_value"][...], "s", mfc="none", color="tab:blue", ms=5, label="start")
    lo, hi = f.attrs["lower_value"], f.attrs["upper_value"]
    for b in (lo, hi):
        curve.axhline(b, color="tab:red", lw=0.6, ls=":")
    curve.set_xlim(0, 1)
    curve.set_xlabel("phase in the period (cycles)")
    name = text(f.attrs["data_source"]).rsplit("/", 1)[-1].replace("_", " ")
    curve.set_ylabel(f"{name} (dimensionless)")
    curve.set_title(style.wrap(f"period {f.attrs['period_s']:.4g} s ({text(f.attrs['period_source'])}); "
                               f"loss {text(f.attrs['loss'])}", 60))
    curve.legend(fontsize=9)
    resid.plot(f["data/time_s"][...][used], f["data/residual"][...][used], ".", color="0.3", ms=3)
    resid.axhline(0, color="k", lw=0.6)
    resid.set_xlabel("time (s)")
    resid.set_ylabel("fit - data (dimensionless)")
    resid.set_title("residuals", fontsize=9)
    fig.suptitle(style.wrap(text(f.attrs["data_source"]), 100))
    style.save(fig, out_png)


def plot_controller(path, out_png):
    f = h5py.File(path, "r")
    if not f.attrs.get("complete", False):
        raise SystemExit(f"{path}: the fit is not complete (run it again with --resume)")
    names = [text(n) for n in f["tuned/name"][...]]
    x0, x1 = f["result/x_start"][...], f["result/x_fitted"][...]
    metric = text(f.attrs["objective_metric"])
    fig, (curves, traj, hist) = style.subplots(1, 3, height=4.3)

    for group, color, label in (("start", "0.45", "start"), ("fitted", "tab:red", "fitted")):
        if f"{group}/curve" not in f:
            continue
        c = f[f"{group}/curve"]
        curves.plot(c["phase"][...], c["aperture"][...], color=color, lw=1.6, label=f"{label}: aperture")
        curves.plot(c["phase"][...], c["apex"][...], color=color, lw=1.0, ls="--", label=f"{label}: apex")
    curves.set_xlabel("phase in the cycle (cycles)")
    curves.set_ylabel("muscle rest-length factor")
    curves.set_title("contraction curves", fontsize=9)
    curves.legend(fontsize=9)

    for group, color in (("start", "0.45"), ("fitted", "tab:red")):
        ts = f[f"{group}/timeseries"]
        t, y = ts["time_s"][...], ts["centroid_y_m"][...] if "centroid_y_m" in ts else None
        if y is None:
            continue
        m = f[f"result/{group}_metrics/{metric}"][()]
        traj.plot(t, (y - y[0]) * 1e3, color=color, lw=1.4, label=f"{group}: {metric} = {m:.4g}")
    traj.set_xlabel("time (s)")
    traj.set_ylabel("axial displacement (mm)")
    traj.set_title("trajectories", fontsize=9)
    traj.legend(fontsize=9)

    h = f["history"]
    hist.plot(h["iteration"][...], h["objective"][...], "ko-", ms=4)
    hist.set_xlabel("iteration (count)")
    hist.set_ylabel(style.label(metric) if text(f.attrs["objective_type"]) == "maximise" else "cost (as the objective)")
    ev = f["evaluations"]
    hist.set_title(f"{ev['cost'].shape[0]} runs; " + ", ".join(
        f"{n} {a:.3g}→{b:.3g}" for n, a, b in zip(names, x0, x1)), fontsize=9)
    fig.suptitle(style.wrap(text(f.attrs["title"]), 100))
    style.save(fig, out_png)


def draw(run, out):
    """Every figure of the run folder `run`, as PNGs (and tables) in folder `out`."""
    os.makedirs(out, exist_ok=True)
    drawn = []
    for name, draw in (("spline_fit", plot_spline), ("controller_fit", plot_controller)):
        path = os.path.join(run, name + ".h5")
        if os.path.exists(path):
            png = os.path.join(out, name + ".png")
            draw(path, png)
            drawn.append(png)
    if not drawn:
        raise SystemExit(f"{run}: no spline_fit.h5 or controller_fit.h5")
    for png in drawn:
        print(png)


def figures(run):
    """(name, Figure) of every figure of the run folder `run`."""
    return style.collect(draw, run)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("fit_dir")
    ap.add_argument("--out", help="figure folder (default FIT_DIR/figures)")
    args = ap.parse_args()
    draw(args.fit_dir, args.out or os.path.join(args.fit_dir, "figures"))


if __name__ == "__main__":
    main()
