"""creaturelab's house style for every figure of analysis/: one look, legible where it is shown.

Every figure module and plotter imports this module (which sets matplotlib's rcParams) and saves
through save(). The rules, checked on every module by tests/analysis/check_figures.py:
  - fonts of at least MIN_PT points at the width the report shows the figure (effective_pt());
  - every axis label of a quantity names its unit in parentheses, "time (s)"; labels are words,
    not variable names (LABELS maps the sweep axes' names to words);
  - colour that encodes a value has a legend or a colour bar;
  - titles fit inside the canvas: constrained layout, and wrap() for long ones.

Figures are built by functions that return them; save() writes one as PNG, or, inside collecting(),
hands it to the caller instead (the test inspects the figures without writing files).
"""
import argparse
import contextlib
import os
import tempfile
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# How the report shows a PNG: analysis/report.py's page is at most 1200 CSS px wide with 1 em
# (16 px) padding each side and <img max-width: 100%>, so an image is shown at its pixel width,
# shrunk to 1168 px when wider. A CSS px is 1/96 in.
REPORT_WIDTH_PX = 1168
CSS_PX_PER_IN = 96.0
DPI = 110  # pixels per figure inch in every PNG
MIN_PT = 9.0  # smallest font, in points at the width shown
WIDTH_IN = REPORT_WIDTH_PX / DPI  # 10.6 in: a figure this wide is shown unscaled at 110 dpi

RC = {
    "font.size": 10,
    "axes.titlesize": 10,
    "axes.labelsize": 10,
    "xtick.labelsize": 9,
    "ytick.labelsize": 9,
    "legend.fontsize": 9,
    "legend.title_fontsize": 9,
    "figure.titlesize": 11,
    "figure.dpi": DPI,
    "savefig.dpi": DPI,
    "figure.constrained_layout.use": True,
    "axes.titlelocation": "center",
    "image.cmap": "viridis",
}

# Axis names of the experiments' sweeps, as an axis label in words with the unit.
LABELS = {
    "contraction_hz": "contraction frequency (Hz)",
    "pulse_stagger": "pulse stagger (fraction of the pulse)",
    "cells": "fluid cells across the box",
    "dt_s": "time step (s)",
    "domain_m": "box width (m)",
    "bell_diameter_m": "bell diameter (m)",
    "wind_m_per_s": "wind speed (m/s)",
    "frame_scale": "frame scale (relative to the default)",
    "swim_rate": "swim rate (strokes per model second)",
}


def apply():
    """Sets the house style's rcParams (done on import)."""
    matplotlib.rcParams.update(RC)


apply()


def label(name, unit=""):
    """An axis label for a sweep axis or metric `name` (with its HDF5 unit, if known): the words of
    LABELS, else the name with spaces and the unit in parentheses."""
    if name in LABELS:
        return LABELS[name]
    words = name.replace("_", " ")
    for suffix, u in (("_m_per_s", "m/s"), ("_hz", "Hz"), ("_s", "s"), ("_m", "m"), ("_j", "J"), ("_n", "N")):
        if name.endswith(suffix):
            words, unit = name[: -len(suffix)].replace("_", " "), unit or u
            break
    return f"{words} ({unit})" if unit and unit != "-" else words


def value_label(name, value):
    """`name value unit` in words for a legend: 'contraction frequency 0.7 Hz'."""
    lab = label(name)
    v = f"{value:g}" if isinstance(value, (float, int)) and not isinstance(value, bool) else str(value)
    if lab.endswith(")") and " (" in lab:
        words, unit = lab[:-1].rsplit(" (", 1)
        return f"{words} {v} {unit}"
    return f"{lab} {v}"


def wrap(title, width=90):
    """A long title broken into lines of at most `width` characters (fits a WIDTH_IN figure)."""
    return "\n".join(textwrap.fill(line, width) for line in str(title).split("\n"))


def figure(width=WIDTH_IN, height=4.2, **kw):
    """plt.figure with the house size (the report's width) and constrained layout."""
    return plt.figure(figsize=(min(width, WIDTH_IN * 1.15), height), layout="constrained", **kw)


def subplots(nrows=1, ncols=1, width=WIDTH_IN, height=4.2, **kw):
    """plt.subplots with the house size and constrained layout."""
    return plt.subplots(nrows, ncols, figsize=(min(width, WIDTH_IN * 1.15), height), layout="constrained", **kw)


def legend_key(key_axis, source_axes, ncol=1, loc="center"):
    """The legends of source_axes drawn together, without a frame, in key_axis: an axis of its own
    below a figure's panels, so that a sweep's or a study's many lines do not crowd the panels."""
    key_axis.axis("off")
    handles, labels = [], []
    for ax in source_axes:
        h, lab = ax.get_legend_handles_labels()
        handles += h
        labels += lab
    key_axis.legend(handles, labels, ncol=ncol, loc=loc, frameon=False)


def shown_scale(fig, dpi=DPI):
    """Inches on the screen per figure inch where the report shows it (< 1: the PNG is wider than
    the page and is shrunk)."""
    px = fig.get_figwidth() * dpi
    return min(px, REPORT_WIDTH_PX) / CSS_PX_PER_IN / fig.get_figwidth()


def effective_pt(fig, size_pt, dpi=DPI):
    """A font of size_pt points in `fig`, in points as the report shows it."""
    return size_pt * shown_scale(fig, dpi)


# Figures handed to collecting() callers instead of written (a stack: collections may nest).
_collecting = []


@contextlib.contextmanager
def collecting():
    """Within this block save() appends (name, Figure) to the yielded list and writes nothing."""
    figs = []
    _collecting.append(figs)
    try:
        yield figs
    finally:
        _collecting.pop()


def save(fig, path, dpi=DPI):
    """Writes fig as the PNG `path` (".png" added when missing) and closes it; returns the path.
    Inside collecting(), keeps the figure open for the collector instead."""
    path = str(path)
    if not path.endswith(".png"):
        path += ".png"
    if _collecting:
        _collecting[-1].append((os.path.splitext(os.path.basename(path))[0], fig))
        return path
    fig.draw_without_rendering()  # a layout pass first: constrained layout settles over two draws
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path


def save_all(named, out, prefix=""):
    """Saves (name, Figure) pairs into folder `out` as PREFIX_name.png; returns the paths."""
    os.makedirs(out, exist_ok=True)
    return [save(fig, os.path.join(out, f"{prefix}_{name}" if prefix else name)) for name, fig in named]


def collect(draw, *args):
    """Calls draw(*args, out), a drawing function that saves its figures into folder `out` through
    save(), with a scratch folder for `out`, and returns the figures as (name, Figure) pairs
    (tables it writes besides are dropped with the scratch folder)."""
    with tempfile.TemporaryDirectory() as tmp, collecting() as figs:
        draw(*args, tmp)
    return figs


def main(draw, doc=None):
    """The command line of a plotter, `RUN [--out FOLDER]`: draw(RUN, FOLDER), FOLDER by default
    RUN/figures; doc (the module's docstring) gives its first line as the description."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0] if doc else None)
    ap.add_argument("run", help="run folder")
    ap.add_argument("--out", help="figure folder (default RUN/figures)")
    args = ap.parse_args()
    draw(args.run, args.out or os.path.join(args.run, "figures"))
