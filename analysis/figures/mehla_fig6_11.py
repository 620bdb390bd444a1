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
import matplotlib.pyplot as plt  # noqa: E402
import style  # noqa: E402

RENDERS = [("overlay", "target over the web, removed in red"), ("result", "settled again")]


def draw(run, out):
    idx = list(run.sweep.get("point_index", []))
    labels = run.labels()
    if not idx:
        return []
    fig, axes = plt.subplots(2, len(idx), figsize=(3.1 * len(idx), 6.6), squeeze=False)
    for col, p in enumerate(idx):
        for row, (name, what) in enumerate(RENDERS):
            ax = axes[row][col]
            ax.axis("off")
            path = os.path.join(run.folder, f"point_{int(p):06d}_{name}.png")
            if os.path.exists(path):
                ax.imshow(mpimg.imread(path))
            title = f"{labels[col]}: {what}"
            if row == 1:
                iou, con = run.metric("emptied_iou")[col], run.metric("letter_contrast")[col]
                title += f"\nIoU {iou:.2f}, contrast {con:+.2f}"
            ax.set_title(title, fontsize=9)
    fig.suptitle(run.title, fontsize=9)
    return [style.save(fig, os.path.join(out, "mehla_fig6_11"))]


def figures(folder):
    """(name, Figure) pairs of this figure, drawn from the run folder `folder`."""
    with runs.Run(folder) as run:
        return style.collect(draw, run)


if __name__ == "__main__":
    runs.main(draw, __doc__)
