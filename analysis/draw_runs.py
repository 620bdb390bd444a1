#!/usr/bin/python3
"""Draws the figures of every run folder under the given folders, from their HDF5 files alone:
each run's kind (index.h5's attribute) picks its plotter scripts (SCRIPTS: one line per kind), and
the run's folder name picks the paper-figure modules that draw from it (analysis/figures/catalog.py,
e.g. frequency -> figures/rm_fig5.py). `make reproduce` calls it on results/runs/reproduce after
the runs, then analysis/report.py writes report.html from what was drawn.

usage: /usr/bin/python3 analysis/draw_runs.py FOLDER [FOLDER ...]
"""
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from figures import catalog, runs  # noqa: E402

# Per kind: plotter scripts of analysis/ run as `SCRIPT RUN_DIR`, drawing into RUN_DIR/figures/.
# Add a line for a new kind; the report shows every PNG they draw.
SCRIPTS = {
    "oscillator": ["plot_run.py"],
    "strand": ["plot_run.py"],
    "web": ["draw_web.py"],
    "fluid": ["plot_fluid.py"],
    "jellyfish": ["plot_jellyfish.py"],
    "membrane": ["plot_membrane.py"],
    "charlotte": ["charlotte_sheet.py"],
    "control": ["plot_control.py"],
    "control_fluid": ["plot_control_fluid.py", "plot_flyer.py"],
    "control_fluid3d": ["plot_flyer.py"],
    "fish": ["plot_fish.py"],
}


def kind_of(run):
    return runs.Run(run).kind


def commands(run):
    """(label, argv) of every drawing for one run folder: the kind's plotters, then its paper figures."""
    out = []
    for script in SCRIPTS.get(kind_of(run), []):
        out.append((script, [sys.executable, os.path.join(HERE, script), run]))
    for module in catalog.module_of_run(os.path.basename(os.path.normpath(run))):
        out.append((f"figures/{module}.py", [sys.executable, os.path.join(HERE, "figures", module + ".py"), run]))
    return out


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    jobs = [(run, label, argv) for folder in sys.argv[1:] for run in runs.runs_under(folder)
            for label, argv in commands(run)]
    # Two drawings at a time (make reproduce's two cores); reported in a fixed order.
    with ThreadPoolExecutor(max_workers=max(1, min(2, os.cpu_count() or 1))) as pool:
        done = list(pool.map(lambda j: subprocess.run(j[2], capture_output=True, text=True), jobs))
    failed = 0
    for (run, label, _), d in zip(jobs, done):
        print(f"figures {'ok' if d.returncode == 0 else 'FAILED'}: {run} ({label})")
        if d.returncode != 0:
            failed += 1
            print(d.stderr.strip()[-2000:], file=sys.stderr)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
