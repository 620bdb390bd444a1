#!/usr/bin/python3
"""The settling time of every web variant: one row per point of each web run folder given.

usage: /usr/bin/python3 analysis/web_settling_table.py RUN_DIR [RUN_DIR ...]
       /usr/bin/python3 analysis/web_settling_table.py results/runs/*   (non-web runs are skipped)
"""
import os
import sys

import h5py


def main():
    rows = []
    for run in sys.argv[1:]:
        path = os.path.join(run, "index.h5")
        if not os.path.exists(path):
            continue
        with h5py.File(path, "r") as idx:
            if idx.attrs["kind"] not in ("web", "strand"):
                continue
            s = idx["sweep"]
            name = os.path.basename(os.path.normpath(run))
            for k in range(len(s["point_index"])):
                label = s["label"].asstr()[k] or f"point {s['point_index'][k]}"
                cols = [c for c in ("frame_scale", "frame_shape") if c in s]
                if not s["label"].asstr()[k] and cols:
                    c = cols[0]
                    v = s[c].asstr()[k] if s[c].dtype.kind == "O" else s[c][k]
                    label = f"{c}={v}"
                particles = s["particles"][k]
                settle = s["settling_time_s"][k]
                rows.append((name, label, int(particles), settle, s["status"].asstr()[k]))
    if not rows:
        raise SystemExit("no web or strand runs found")
    w = max(len(r[0]) + len(r[1]) + 3 for r in rows)
    print(f"{'run / variant':<{w}} {'particles':>9} {'settling time (s)':>18}  status")
    for name, label, n, t, status in rows:
        print(f"{name + ' / ' + label:<{w}} {n:>9} {t:>18.3f}  {status}")


if __name__ == "__main__":
    main()
