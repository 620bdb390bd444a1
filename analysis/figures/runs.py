"""Reading run folders (the runner's HDF5, DESIGN.md "Results"): one place for every figure module
and the report, so that each figure is drawn from the HDF5 files alone.

A run folder holds index.h5 (attributes kind, title, experiment, overrides_json; /sweep, one row per
point; /checks, one row per check) and point_NNNNNN.h5 files (attributes, /timeseries, /metrics,
/lagrangian, /topology, /fields), plus renders beside them (point_NNNNNN_<name>.png) and figures
drawn into figures/.
"""
import glob
import json
import os

import h5py
import numpy as np

FIGURES_DIR = "figures"


def text(v):
    """A string attribute or dataset value as str (h5py gives bytes for fixed-length strings)."""
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, np.ndarray) and v.shape == ():
        return text(v[()])
    return str(v)


FIT_FILES = ("spline_fit.h5", "controller_fit.h5")  # what `creaturelab fit` writes (no index.h5)


def is_run(folder):
    """A run folder (index.h5) or a fit folder (spline_fit.h5 / controller_fit.h5)."""
    return any(os.path.exists(os.path.join(folder, n)) for n in ("index.h5",) + FIT_FILES)


def runs_under(folder):
    """The run folders at or directly under `folder`, sorted by name."""
    if is_run(folder):
        return [folder]
    if not os.path.isdir(folder):
        return []
    return [p for p in (os.path.join(folder, n) for n in sorted(os.listdir(folder))) if is_run(p)]


def figures_dir(run, out=None):
    """Where a run's figures go (created): `out` or RUN/figures."""
    path = out or os.path.join(run, FIGURES_DIR)
    os.makedirs(path, exist_ok=True)
    return path


class Run:
    """A finished run folder, read lazily. Use as a context manager, or call close()."""

    def __init__(self, folder):
        self.folder = folder
        self.name = os.path.basename(os.path.normpath(folder))
        self._points = None
        self.sweep, self.units, self.checks, self.overrides = {}, {}, [], []
        if not os.path.exists(os.path.join(folder, "index.h5")):
            self._read_fit()
            return
        with h5py.File(os.path.join(folder, "index.h5"), "r") as idx:
            a = idx.attrs
            self.kind = text(a.get("kind", ""))
            self.title = text(a.get("title", ""))
            self.experiment = text(a.get("experiment", ""))
            self.overrides = json.loads(text(a.get("overrides_json", "[]")) or "[]")
            self.sweep = {}
            self.units = {}
            if "sweep" in idx:
                for k, d in idx["sweep"].items():
                    v = d[...]
                    if v.dtype.kind in "OS":
                        v = np.array([text(x) for x in v])
                    self.sweep[k] = v
                    self.units[k] = text(d.attrs.get("unit", ""))
            self.checks = read_checks(idx)

    def _read_fit(self):
        """A `creaturelab fit` folder: kind "fit", the title of its record, no sweep or checks."""
        self.kind = "fit"
        self.experiment = ""
        for name in FIT_FILES:
            path = os.path.join(self.folder, name)
            if os.path.exists(path):
                with h5py.File(path, "r") as f:
                    self.title = text(f.attrs.get("title", name))
                return

    # --- points
    @property
    def point_paths(self):
        return sorted(glob.glob(os.path.join(self.folder, "point_*.h5")))

    def points(self):
        """Every point file, opened read-only (closed by close())."""
        if self._points is None:
            self._points = [h5py.File(p, "r") for p in self.point_paths]
        return self._points

    def ok_points(self):
        return [f for f in self.points() if text(f.attrs.get("status", "ok")) == "ok"]

    def labels(self):
        """A short label per sweep row: the [[case]] label, followed by the swept values that differ
        among the rows sharing it (a case crossed with a [sweep]); else the swept values."""
        n = len(self.sweep.get("point_index", []))
        out = []
        axes = json.loads(self._columns_json()) if n else []
        if n:
            axes = [a for a in axes if a != "label" and a in self.sweep and len(set(map(str, self.sweep[a]))) > 1]
        cases = self.sweep.get("label", [""] * n)
        for k in range(n):
            lab = cases[k]
            same = [j for j in range(n) if cases[j] == lab]
            varying = [a for a in axes if not lab or len({str(self.sweep[a][j]) for j in same}) > 1]
            values = ", ".join(f"{a}={self.sweep[a][k]}" for a in varying)
            out.append(", ".join(v for v in (lab, values) if v) or str(k))
        return out

    def _columns_json(self):
        with h5py.File(os.path.join(self.folder, "index.h5"), "r") as idx:
            return text(idx["sweep"].attrs.get("columns_json", "[]")) if "sweep" in idx else "[]"

    def metric(self, name):
        """A metric column of the sweep table (NaN where a point has none)."""
        return np.asarray(self.sweep.get(name, np.full(len(self.sweep.get("point_index", [])), np.nan)), dtype=float)

    # --- files beside the points
    def renders(self):
        """Renders the kind left beside the point files (point_NNNNNN_<name>.png), sorted."""
        return sorted(glob.glob(os.path.join(self.folder, "point_*_*.png")))

    def figures(self):
        """Every PNG drawn into RUN/figures, then those `creaturelab render --figures` drew into
        RUN/render_point_NNNNNN/figures, sorted."""
        return (sorted(glob.glob(os.path.join(self.folder, FIGURES_DIR, "*.png"))) +
                sorted(glob.glob(os.path.join(self.folder, "render_point_*", FIGURES_DIR, "*.png"))))

    def close(self):
        for f in self._points or []:
            f.close()
        self._points = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def read_checks(idx):
    """The /checks table of an open index.h5 as a list of dicts: name, type, expected, got, passed,
    known_deviation, inconclusive (optional int8 column: 1 = the run cannot resolve the claim),
    status (ok | FAILED | KNOWN | inconclusive: neither passed nor failed)."""
    if "checks" not in idx or "name" not in idx["checks"]:
        return []
    c = idx["checks"]
    cols = {k: c[k][...] for k in c}
    out = []
    for i in range(len(cols["name"])):
        row = {k: (text(v[i]) if v.dtype.kind in "OS" else v[i].item()) for k, v in cols.items()}
        row["passed"] = bool(row.get("passed", False))
        row["inconclusive"] = bool(row.get("inconclusive", False))
        known = row.get("known_deviation", "")
        row["status"] = ("inconclusive" if row["inconclusive"] else "ok" if row["passed"] else
                         "KNOWN" if known else "FAILED")
        out.append(row)
    return out


def savefig(fig, out_dir, name, dpi=110):
    """Saves a matplotlib figure as OUT/name.png, closes it and returns the path."""
    import matplotlib.pyplot as plt

    path = os.path.join(out_dir, name + ".png")
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path


def analysis_dir():
    """analysis/, where the per-kind plotters (draw_web.py, plot_jellyfish.py, ...) live."""
    return os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def plotter(name):
    """Imports one of the per-kind plotter scripts of analysis/ as a module (e.g. "plot_jellyfish")."""
    import importlib
    import sys

    if analysis_dir() not in sys.path:
        sys.path.insert(0, analysis_dir())
    return importlib.import_module(name)


def moved_outputs(out, prefix, draw):
    """Calls draw(tmp_dir), then moves every file it wrote into `out` as PREFIX_<name>, so a
    plotter's own file names (trajectories.png, ...) can change without this module knowing.
    Returns the moved PNG paths, sorted."""
    import shutil
    import tempfile

    with tempfile.TemporaryDirectory(dir=out) as tmp:
        draw(tmp)
        moved = []
        for name in sorted(os.listdir(tmp)):
            dest = os.path.join(out, f"{prefix}_{name}")
            shutil.move(os.path.join(tmp, name), dest)
            if name.endswith(".png"):
                moved.append(dest)
    return moved


def main(draw, doc):
    """Command line of a figure module: MODULE.py RUN_DIR [--out DIR]; prints the PNGs drawn."""
    import argparse

    ap = argparse.ArgumentParser(description=doc)
    ap.add_argument("run")
    ap.add_argument("--out", default=None, help="figure folder (default RUN/figures)")
    a = ap.parse_args()
    with Run(a.run) as run:
        pngs = draw(run, figures_dir(a.run, a.out))
    if not pngs:
        raise SystemExit(f"{a.run}: nothing drawn")
    for p in pngs:
        print(p)
