#!/usr/bin/python3
"""Draws the figures of every run folder under the given folders, from their HDF5 files alone:
each run's kind (index.h5's attribute) picks its figure script. `make reproduce` calls it on
results/runs/reproduce after the runs, so that every reproduced experiment has its figures.

usage: /usr/bin/python3 analysis/draw_runs.py FOLDER [FOLDER ...]
"""
import os
import subprocess
import sys

import h5py

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = {
    "oscillator": ["plot_run.py"],
    "strand": ["plot_run.py"],
    "web": ["draw_web.py"],
    "fluid": ["plot_fluid.py"],
    "jellyfish": ["plot_jellyfish.py"],
    "membrane": ["plot_membrane.py"],
    "charlotte": ["charlotte_sheet.py"],
    "control": ["plot_control.py"],
    "fish": ["plot_fish.py"],
}


def runs(folder):
    if os.path.exists(os.path.join(folder, "index.h5")):
        yield folder
        return
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if os.path.isdir(path) and os.path.exists(os.path.join(path, "index.h5")):
            yield path


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    failed = 0
    for folder in sys.argv[1:]:
        for run in runs(folder):
            with h5py.File(os.path.join(run, "index.h5"), "r") as index:
                kind = index.attrs.get("kind")
            kind = kind.decode() if isinstance(kind, bytes) else str(kind)
            for script in SCRIPTS.get(kind, []):
                done = subprocess.run([sys.executable, os.path.join(HERE, script), run], capture_output=True, text=True)
                status = "ok" if done.returncode == 0 else "FAILED"
                print(f"figures {status}: {run} ({script})")
                if done.returncode != 0:
                    failed += 1
                    print(done.stderr.strip()[-2000:], file=sys.stderr)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
