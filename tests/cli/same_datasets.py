#!/usr/bin/python3
"""Exits 1 naming the first dataset that differs between the point files of two run folders (the
same number of points, every dataset bitwise equal), for the CLI tests' determinism checks.

usage: /usr/bin/python3 tests/cli/same_datasets.py RUN_A RUN_B POINTS
"""
import glob
import sys

import h5py
import numpy as np

a = sorted(glob.glob(sys.argv[1] + "/point_*.h5"))
b = sorted(glob.glob(sys.argv[2] + "/point_*.h5"))
if not len(a) == len(b) == int(sys.argv[3]):
    sys.exit(f"points: {len(a)} and {len(b)}, expected {sys.argv[3]}")
for x, y in zip(a, b):
    fx, fy = h5py.File(x, "r"), h5py.File(y, "r")
    names = []
    fx.visit(lambda n: names.append(n) if isinstance(fx[n], h5py.Dataset) else None)
    for n in names:
        if n not in fy or not np.array_equal(fx[n][()], fy[n][()]):
            sys.exit(f"{x}: {n} differs")
