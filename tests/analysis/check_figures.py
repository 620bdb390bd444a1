#!/usr/bin/python3
"""Renders every figure module and plotter of analysis/ on the run folders under ROOT and checks
each figure against the house style (analysis/style.py):
  - every axes that shows tick numbers has a non-empty label on that axis;
  - a label of a quantity names its unit in parentheses or brackets, unless it is one of the
    dimensionless words of DIMENSIONLESS, or its ticks are categories (words);
  - every title and the suptitle lie inside the canvas;
  - every text is at least style.MIN_PT points at the width the report shows the figure;
  - an axes with two or more colours of lines, or an image or scatter coloured by a colormap, has a
    legend or a colour bar (in the axes, a twin of it, or the figure).
Which modules draw a run: analysis/draw_runs.py's SCRIPTS (by the run's kind) and
analysis/figures/catalog.py (by the run folder's name), as `make reproduce` draws them. Each
module's figures(RUN_DIR) returns (name, Figure) pairs.

usage: /usr/bin/python3 tests/analysis/check_figures.py ROOT [--expect MODULE ...] [--catalog-only RUN ...]
       /usr/bin/python3 tests/analysis/check_figures.py --self-test
Exit 0 when every figure passes, 1 when one does not (each failure printed), 2 on bad input.
"""
import argparse
import importlib
import os
import re
import sys
import time

ANALYSIS = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "analysis")
sys.path.insert(0, ANALYSIS)
import style  # noqa: E402
import draw_runs  # noqa: E402
from figures import catalog, runs  # noqa: E402

import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import Collection  # noqa: E402
from matplotlib.image import AxesImage  # noqa: E402
from matplotlib.text import Text  # noqa: E402

# Words that mark a label as dimensionless (no unit needed): ratios, fractions, counts, phases.
DIMENSIONLESS = ("ratio", "fraction", "relative", "phase", "number of", "count", "activation", "factor",
                 "cycles", "particles", "cells", "order", "efficiency", "amplitude", "scale", "/ rest", "index",
                 "point", "segments", "spokes", "strouhal", "reynolds", "normalised", "share", "setting")
UNIT = re.compile(r"\([^()]*\)|\[[^\[\]]*\]")
NUMBER = re.compile(r"^[\s\u2212+\-−]*[0-9.]+([eE][\u2212+\-−]?\d+)?\s*$|^\$.*\$$|^$")


def needs_unit(label):
    low = label.lower()
    return not UNIT.search(label) and not any(w in low for w in DIMENSIONLESS)


def numeric_ticks(axis):
    """Whether the axis shows numbers (visible tick labels that read as numbers)."""
    if not axis.get_visible():
        return False
    labels = [t for t in axis.get_ticklabels() if t.get_visible() and t.get_text()]
    return bool(labels) and all(NUMBER.match(t.get_text()) for t in labels)


def shows_ticks(axis):
    return axis.get_visible() and any(t.get_visible() and t.get_text() for t in axis.get_ticklabels())


def is_colorbar(ax):
    return hasattr(ax, "_colorbar")


def has_key(ax, fig):
    """A legend or a colour bar in the figure (panels may share one key: "colours as left")."""
    return bool(fig.legends) or any(is_colorbar(a) or a.get_legend() is not None for a in fig.axes)


def grey(colour):
    r, g, b, _ = mcolors.to_rgba(colour)
    return max(r, g, b) - min(r, g, b) < 0.05


def coloured(ax):
    """Whether colour encodes something in the axes: two or more non-grey line colours, or a
    colormapped image or collection."""
    colours = {mcolors.to_hex(l.get_color()) for l in ax.get_lines()
               if l.get_visible() and len(l.get_xdata()) > 1 and not grey(l.get_color())}
    if len(colours) >= 2:
        return True
    for a in ax.get_children():
        if isinstance(a, AxesImage) and a.get_array() is not None and a.get_array().ndim == 2:
            return True
        if isinstance(a, Collection) and a.get_array() is not None and len(a.get_array()) > 1:
            return True
    return False


def check(fig, where):
    """The list of the figure's faults, each a line naming `where`."""
    bad = []
    # Two layout passes, as style.save() draws (constrained layout settles over two); no pixels.
    fig.draw_without_rendering()
    fig.draw_without_rendering()
    renderer = fig.canvas.get_renderer()
    canvas = fig.bbox
    small = [(style.effective_pt(fig, t.get_fontsize()), t.get_text()) for t in fig.findobj(Text)
             if t.get_visible() and t.get_text().strip()]
    small = sorted(x for x in small if x[0] < style.MIN_PT - 1e-6)
    if small:
        bad.append(f"{where}: {len(small)} text(s) below {style.MIN_PT:g} pt as shown, the smallest "
                   f"{small[0][1][:30]!r} at {small[0][0]:.1f} pt")
    titles = [fig._suptitle] if fig._suptitle is not None else []
    for ax in fig.axes:
        titles += [ax.title, ax._left_title, ax._right_title]
    for t in titles:
        if t is None or not t.get_visible() or not t.get_text().strip():
            continue
        e = t.get_window_extent(renderer)
        if e.x0 < canvas.x0 - 1 or e.x1 > canvas.x1 + 1 or e.y0 < canvas.y0 - 1 or e.y1 > canvas.y1 + 1:
            bad.append(f"{where}: title {t.get_text()[:50]!r} leaves the canvas")
    for ax in fig.axes:
        if not ax.get_visible() or not ax.axison:
            continue
        name = f"{where} [{ax.get_title()[:30] or ax.get_label() or 'axes'}]"
        axes = [("x", ax.xaxis), ("y", ax.yaxis)] + ([("z", ax.zaxis)] if hasattr(ax, "zaxis") else [])
        for letter, axis in axes:
            if not shows_ticks(axis):
                continue
            lab = axis.get_label().get_text().strip()
            if not lab:
                bad.append(f"{name}: no {letter} label")
            elif numeric_ticks(axis) and needs_unit(lab) and not is_colorbar(ax):
                bad.append(f"{name}: {letter} label {lab!r} names no unit")
            elif is_colorbar(ax) and needs_unit(lab):
                bad.append(f"{name}: colour bar label {lab!r} names no unit")
        if not is_colorbar(ax) and coloured(ax) and not has_key(ax, fig):
            bad.append(f"{name}: colour encodes a value but there is no legend or colour bar")
    return bad


def self_test():
    """Each check fires on a figure with its fault, and a clean figure passes: the checker can fail.
    Returns the list of checks that did not behave."""
    wrong = []

    def faults(build):
        fig, ax = style.subplots(width=6, height=4)
        ax.plot([0, 1], [0, 1], color="C0", label="a")
        ax.set_xlabel("time (s)")
        ax.set_ylabel("height (m)")
        ax.set_title("clean")
        ax.legend()
        build(fig, ax)
        out = check(fig, "self-test")
        plt.close(fig)
        return out

    if faults(lambda fig, ax: None):
        wrong.append(f"a clean figure fails: {faults(lambda fig, ax: None)}")
    cases = {
        "no x label": lambda fig, ax: ax.set_xlabel(""),
        "names no unit": lambda fig, ax: ax.set_ylabel("contraction_hz"),
        "leaves the canvas": lambda fig, ax: fig.suptitle("a title far too long for its figure " * 6),
        "below": lambda fig, ax: ax.tick_params(labelsize=5),
        "no legend or colour bar": lambda fig, ax: (ax.plot([0, 1], [1, 0], color="C1"), ax.get_legend().remove()),
    }
    for expected, build in cases.items():
        if not any(expected in f for f in faults(build)):
            wrong.append(f"the check '{expected}' did not fire")
    fig, ax = style.subplots(width=6, height=4)
    ax.imshow([[0, 1], [2, 3]])
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    if not any("no legend or colour bar" in f for f in check(fig, "self-test")):
        wrong.append("an image without a colour bar passes")
    plt.close(fig)
    return wrong


def modules_of(run_dir, plotters=True):
    """(label, module) for every plotter (when `plotters`) and figure module that draws this run folder."""
    out = []
    kind = runs.Run(run_dir).kind
    for script in draw_runs.SCRIPTS.get(kind, []) if plotters else []:
        out.append((script[:-3], importlib.import_module(script[:-3])))
    for module in catalog.module_of_run(os.path.basename(os.path.normpath(run_dir))):
        out.append((f"figures/{module}", importlib.import_module(f"figures.{module}")))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("root", nargs="?")
    ap.add_argument("--self-test", action="store_true", help="check the checker on figures with known faults")
    ap.add_argument("--expect", nargs="*", default=[], help="modules that must have drawn at least one figure")
    ap.add_argument("--only", nargs="*", default=None, help="check only these modules (e.g. plot_fish figures/rm_fig4)")
    ap.add_argument("--catalog-only", nargs="*", default=[],
                    help="run folders (by name) on which only the paper-figure modules are checked, not the "
                         "kind's plotters (checked on another run of the kind)")
    a = ap.parse_args()
    if a.self_test:
        wrong = self_test()
        for w in wrong:
            print("SELF-TEST FAIL", w)
        print(f"self-test: {'ok' if not wrong else 'FAILED'}")
        sys.exit(1 if wrong else 0)
    if not a.root:
        ap.error("ROOT is required")
    folders = runs.runs_under(a.root)
    if not folders:
        print(f"{a.root}: no run folders", file=sys.stderr)
        sys.exit(2)
    faults, drawn = [], {}
    for run_dir in folders:
        for label, module in modules_of(run_dir, os.path.basename(os.path.normpath(run_dir)) not in a.catalog_only):
            if a.only is not None and label not in a.only:
                continue
            if not hasattr(module, "figures"):
                faults.append(f"{label}: has no figures(RUN_DIR)")
                continue
            started = time.process_time()
            try:
                figs = module.figures(run_dir)
            except Exception as e:  # a module that cannot draw its run is a fault, reported by name
                faults.append(f"{label} on {run_dir}: {type(e).__name__}: {e}")
                continue
            drawn[label] = drawn.get(label, 0) + len(figs)
            for fig_name, fig in figs:
                faults += check(fig, f"{label}:{fig_name} ({os.path.basename(run_dir)})")
                plt.close(fig)
            print(f"{label} on {os.path.basename(run_dir)}: {len(figs)} figure(s), "
                  f"{time.process_time() - started:.1f} CPU s")
    for m in a.expect:
        if not drawn.get(m):
            faults.append(f"{m}: drew no figure")
    for f in faults:
        print("FAIL", f)
    print(f"{sum(drawn.values())} figures from {len(drawn)} modules, {len(faults)} fault(s)")
    sys.exit(1 if faults else 0)


if __name__ == "__main__":
    main()
