#!/usr/bin/python3
"""Contact sheet and metric table of a Charlotte's-web run (Mehla 2005 thesis ch. 6).

usage: /usr/bin/python3 analysis/charlotte_sheet.py RUN_DIR [--out DIR]

Prints one row per point (label, segments removed inside / outside the target, legibility, settling
time after removal) from RUN_DIR/index.h5, and puts the renders the kind left beside each point file
(point_NNNNNN_{web,overlay,cut,result}.png) side by side, a row per point, in
RUN_DIR/figures/charlotte_sheet.png.
"""
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import style  # noqa: E402

COLUMNS = [
    ("segments_removed", "removed", "{:.0f}"),
    ("removed_inside_target", "inside", "{:.0f}"),
    ("removed_outside_target", "outside", "{:.0f}"),
    ("crosshatch_kept", "hatch", "{:.0f}"),
    ("attachments", "attach", "{:.0f}"),
    ("outline_segments", "outline", "{:.0f}"),
    ("cut_emptied_iou", "IoU cut", "{:.3f}"),
    ("emptied_iou", "IoU", "{:.3f}"),
    ("letter_contrast", "contrast", "{:+.3f}"),
    ("settling_time_s", "settle s", "{:.2f}"),
    ("hub_shift_m", "hub mm", "{:.2f}"),
]
RENDERS = ["web", "overlay", "cut", "result"]


def draw(run, out):
    """The table of the run folder `run` (printed) and its contact sheet, as a PNG in folder `out`."""
    with h5py.File(os.path.join(run, "index.h5"), "r") as idx:
        s = idx["sweep"]
        labels = [lab or str(i) for lab, i in zip(s["label"].asstr()[...], s["point_index"][...])]
        points = list(s["point_index"][...])
        values = {m: s[m][...] for m, _, _ in COLUMNS if m in s}
        title = idx.attrs["title"]
    width = max(len(x) for x in labels + ["label"])
    print(f"{'label':<{width}}  " + "  ".join(f"{h:>8}" for _, h, _ in COLUMNS))
    for r, lab in enumerate(labels):
        cells = []
        for m, _, fmt in COLUMNS:
            v = values.get(m, [float("nan")] * len(labels))[r]
            cells.append(f"{fmt.format(v * 1000 if m == 'hub_shift_m' else v):>8}")
        print(f"{lab:<{width}}  " + "  ".join(cells))

    os.makedirs(out, exist_ok=True)
    panel = style.WIDTH_IN / len(RENDERS)
    fig, axes = style.subplots(len(points), len(RENDERS), height=(panel + 0.45) * len(points), squeeze=False)
    for row, (p, lab) in enumerate(zip(points, labels)):
        for col, name in enumerate(RENDERS):
            ax = axes[row][col]
            ax.axis("off")
            path = os.path.join(run, f"point_{p:06d}_{name}.png")
            if os.path.exists(path):
                ax.imshow(mpimg.imread(path))
            ax.set_title(f"{lab}: {name}", fontsize=9)
    fig.suptitle(style.wrap(title, 100))
    png = os.path.join(out, "charlotte_sheet.png")
    style.save(fig, png)
    print(png)


def figures(run):
    """(name, Figure) of the contact sheet of the run folder `run`."""
    return style.collect(draw, run)


def main():
    style.main(draw, __doc__)

if __name__ == "__main__":
    main()
