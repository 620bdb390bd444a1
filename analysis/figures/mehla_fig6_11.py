"""Mehla 2005 ch. 6, Figs. 6.10-6.18: Charlotte's web: per point (plain PIG Fig. 6.11, cross-hatch
6.12, random attachments 6.13, strong outline 6.14, an image target 6.16, random gaps 6.18) the
target over the web with the segments removed (Figs. 6.10, 6.15, 6.17) and the web settled again,
from the renders the kind left beside each point file, with its legibility measures.
"""
if __package__ in (None, ""):  # run as a script: make `figures` importable
    import os
    import sys

    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from figures import runs  # noqa: E402
import os  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import style  # noqa: E402

RENDERS = [("overlay", "target over the web, removed in red"), ("result", "settled again")]


def draw(run, out):
    idx = list(run.sweep.get("point_index", []))
    labels = run.labels()
    if not idx:
        return []
    # Two cases a row, each as its two renders side by side.
    pairs = 2 if len(idx) > 1 else 1
    rows = (len(idx) + pairs - 1) // pairs
    cols = pairs * len(RENDERS)
    panel = style.WIDTH_IN / cols
    fig, axes = style.subplots(rows, cols, height=(panel + 0.75) * rows, squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for k, p in enumerate(idx):
        for j, (name, what) in enumerate(RENDERS):
            ax = axes[k // pairs][(k % pairs) * len(RENDERS) + j]
            path = os.path.join(run.folder, f"point_{int(p):06d}_{name}.png")
            if os.path.exists(path):
                ax.imshow(mpimg.imread(path))
            title = f"{labels[k]}: {what}"
            if j == 1:
                iou, con = run.metric("emptied_iou")[k], run.metric("letter_contrast")[k]
                title += f"; IoU {iou:.2f}, contrast {con:+.2f}"
            ax.set_title(style.wrap(title, 30))
    fig.suptitle(style.wrap(run.title, 100))
    return [style.save(fig, os.path.join(out, "mehla_fig6_11"))]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
