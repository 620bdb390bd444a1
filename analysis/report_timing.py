"""Lentine et al. 2010 Figs. 10 and 14 as tables: our wall seconds per frame beside the paper's.

Ours is each point file's wall_time_s attribute over its frames attribute (both provenance, written
by the runner), averaged over the points of one case; the paper's numbers are its Fig. 10 table
(§5: a 2-D block in the full Navier-Stokes fluid, four processors in parallel) and its Fig. 14 table
(§7.3: every example, serial controller). A table is (caption, header, rows, note).
"""
import glob
import os

import h5py

import report_provenance as P
import report_units as U
from figures import runs as R

# Fig. 10: seconds per frame, serial and parallel (four processors), for 1-4 controlled joints.
FIG10_PAPER = {1: (14, 14), 2: (29, 15), 3: (43, 15), 4: (58, 15)}

# Fig. 14: (the paper's row, its seconds per frame, our claim run, our case label or None = all
# points, what differs in ours).
FIG14 = [
    ("Block minimizing effort - Simple Forces", 0.03, "block_effort", None, ""),
    ("Block minimizing drag - Simple Forces", 0.03, "block_wind", "min_drag", ""),
    ("Block maximizing drag - Simple Forces", 0.03, "block_wind", "max_drag", ""),
    ("Block minimizing effort - Navier-Stokes", 15, "block_flow", "min_effort", ""),
    ("Block minimizing drag - Navier-Stokes", 14, "block_flow", "min_drag", ""),
    ("Block maximizing drag - Navier-Stokes", 14, "block_flow", "max_drag", ""),
    ("Human minimizing effort on back (gravity)", 0.26, "human_gravity", "a_all_min_back", ""),
    ("Human minimizing effort on back and arms (gravity)", 0.63, "human_gravity", "b_arms_average", ""),
    ("Human minimizing effort on back (gravity, wind)", 0.44, "human_wind", "a_all_min_back", ""),
    ("Human minimizing effort on back and arms (gravity, wind)", 0.81, "human_wind", "b_arms_average", ""),
    ("Human minimizing effort on back, drag on arms (gravity, wind)", 0.79, "human_wind", "c_arms_min_drag", ""),
    ("Driven Flyer without flesh", 3.2, "flyer", "controlled", ""),
    ("Driven Flyer with flesh", 34, None, None, "not modelled (no flesh)"),
    ("Aqueous swimmer with flesh", 83, "swimmer", "controller", "ours without flesh"),
]


def per_frame(run):
    """[(attrs of the point, seconds per frame)] of a run's whole points (wall_time_s / frames)."""
    out = []
    for path in sorted(glob.glob(os.path.join(run.folder, "point_*.h5"))):
        with h5py.File(path, "r") as f:
            a = {k: R.text(v) for k, v in f.attrs.items()}
        try:
            s = float(a["wall_time_s"]) / float(a["frames"])
        except (KeyError, ValueError, ZeroDivisionError):
            continue
        out.append((a, s))
    return out


def _mean(xs):
    return sum(xs) / len(xs) if xs else None


def _paper(v):
    """A paper's number as it prints it: "0.03 s", "14 s"."""
    return f"{v:g} s"


def _sec(v):
    return U.quantity(v, "s") if v is not None else "not run"


def fig10(simple, fluid, cores):
    """Fig. 10's table: the paper's serial and parallel seconds per frame for 1-4 joints beside ours,
    with simple forces (parallel_dofs: 1 or 2 evaluation threads) and in the fluid
    (parallel_dofs_fluid: evaluation threads x fluid threads). simple, fluid: Run or None."""
    combos = [("simple forces, 1 thread", simple, {"threads": "1"}),
              ("simple forces, 2 threads", simple, {"threads": "2"})]
    combos += [(f"Navier-Stokes, {t} eval. x {ft} fluid threads", fluid, {"threads": t, "fluid_threads": ft})
               for t in ("1", "2") for ft in ("1", "2")]
    points = {id(r): per_frame(r) for r in (simple, fluid) if r is not None}
    header = ["joints", "paper serial", "paper parallel (4 processors)"] + [f"ours: {c[0]}" for c in combos]
    rows = []
    for n, (ser, par) in FIG10_PAPER.items():
        label = "1_joint" if n == 1 else f"{n}_joints"
        row = [str(n), _paper(ser), _paper(par)]
        for _, run, match in combos:
            pts = points.get(id(run), []) if run is not None else []
            sel = [s for a, s in pts if a.get("label") == label and all(a.get(k) == v for k, v in match.items())]
            row.append(_sec(_mean(sel)))
        rows.append(row)
    note = (f"Seconds per frame (s/frame). Ours: wall_time_s / frames of each point, on {cores}; the two "
            "runs' grids, frames and bodies are not the paper's (a 5-capsule chain, "
            "experiments/control/parallel_dofs*.toml), so compare how the time grows with the joints, "
            "not the seconds.")
    return ("Lentine et al. 2010, Fig. 10: seconds per frame against controlled joints", header, rows, note)


def fig14(find, cores):
    """Fig. 14's table: each paper example's seconds per frame beside ours (find(claim) -> Run or None)."""
    header = ["example (paper)", "paper", "ours", "our run (points)", "note"]
    rows = []
    for title, paper, key, label, note in FIG14:
        run = find(key) if key else None
        if run is None:
            rows.append([title, _paper(paper), "not run", "", note or (f"{key} not in this folder" if key else "")])
            continue
        sel = [s for a, s in per_frame(run) if label is None or a.get("label") == label]
        where = f"{run.name}" + (f" {label}" if label else "") + f" ({len(sel)})"
        if P.setting(run) == "QUICK":
            note = ", ".join(n for n in (note, "QUICK setting") if n)
        rows.append([title, _paper(paper), _sec(_mean(sel)), where, note])
    note = (f"Seconds per frame (s/frame), the paper's serial controller; ours the mean over the case's points "
            f"on {cores}, one evaluation thread unless the run sets more.")
    return ("Lentine et al. 2010, Fig. 14: seconds per frame of each example", header, rows, note)
