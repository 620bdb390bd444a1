#!/usr/bin/env bash
# Results read by h5py (DESIGN.md "Results (HDF5)"): /usr/bin/python3 opens RUN/index.h5, reads the
# /sweep columns as numpy arrays and strings as str (variable-length UTF-8), follows the
# /points/point_000000 external link, and reads /timeseries/time_s with its unit attribute;
# parameters are typed root attributes with their unit beside them.
# usage: h5py.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

"$bin" run tests/cli/strand_sweep.toml --out "$scratch/run" --jobs 2 >/dev/null 2>&1 || { echo "FAIL: run failed" >&2; exit 1; }

# Run from another folder: the external links must resolve relative to index.h5, not the cwd.
cd /
/usr/bin/python3 - "$scratch/run" <<'EOF'
import json, sys
import h5py, numpy as np

run = sys.argv[1]
def check(cond, msg):
    if not cond:
        sys.exit("FAIL: " + msg)

with h5py.File(f"{run}/index.h5", "r") as f:
    check(f.attrs["kind"] == "strand" and isinstance(f.attrs["kind"], str), "kind attribute as str")
    check(f.attrs["experiment"] == "tests/cli/strand_sweep.toml", f"experiment attribute {f.attrs['experiment']!r}")
    json.loads(f.attrs["config_json"])
    s = f["sweep"]
    # Numeric columns: numpy arrays of the right dtype, a row per point, in point order.
    k = s["spring_k_n_per_m"][()]
    check(isinstance(k, np.ndarray) and k.dtype == np.float64, f"spring_k column {k!r}")
    check(list(k) == [0.01, 0.02, 0.04] * 2, f"spring_k values {k}")
    check(s["spring_k_n_per_m"].attrs["unit"] == "N/m", "column unit")
    idx = s["point_index"][()]
    check(idx.dtype == np.int64 and list(idx) == list(range(6)), f"point_index {idx}")
    ovx = s["overextension"][()]
    check(list(ovx) == [0.0] * 3 + [1.5] * 3, f"overextension {ovx}")
    # Strings: variable-length UTF-8, read as str.
    for name in ("label", "layout", "status", "message"):
        info = h5py.check_string_dtype(s[name].dtype)
        check(info is not None and info.encoding == "utf-8" and info.length is None,
              f"/sweep/{name} is not a variable-length UTF-8 string: {info}")
    labels = s["label"].asstr()[()]
    check(all(isinstance(x, str) for x in labels), "labels as str")
    check(list(labels) == ["rest"] * 3 + ["over-extended 150%"] * 3, f"labels {labels}")
    check(list(s["layout"].asstr()[()]) == ["rest"] * 3 + ["overextended"] * 3, "layout column")
    check(list(s["status"].asstr()[()]) == ["ok"] * 6, "status column")
    sag = s["mid_sag_m"][()]
    check(sag.shape == (6,) and np.all(np.isfinite(sag)), f"mid_sag_m metric column {sag}")
    check(s["mid_sag_m"].attrs["unit"] == "m", "metric unit")
    # Checks table.
    c = f["checks"]
    check(list(c["name"].asstr()[()]) == ["stiffer springs sag less (static solve)"], "check names")
    check(list(c["passed"][()]) == [1], "check passed")

    # The external link to a point file.
    p = f["points/point_000000"]
    check(isinstance(p, h5py.Group), "point link is a group")
    check(p.attrs["point_index"] == 0 and p.attrs["status"] == "ok", "point attributes")
    check(p.attrs["label"] == "rest", "point label")
    t = p["timeseries/time_s"]
    check(t.attrs["unit"] == "s" and isinstance(t.attrs["unit"], str), "time_s unit attribute")
    tv = t[()]
    check(tv.dtype == np.float64 and tv.ndim == 1 and abs(tv[-1] - 2.0) < 1e-12, f"time_s {tv[:3]}...{tv[-1]}")
    for name, d in p["timeseries"].items():
        check(d.shape == tv.shape, f"/timeseries/{name} has {d.shape}, time_s {tv.shape}")
        check("unit" in d.attrs, f"/timeseries/{name} has no unit")
    check(p["metrics/mid_sag_m"].shape == () and p["metrics/mid_sag_m"].attrs["unit"] == "m", "scalar metric")
    # Parameters as typed attributes with units beside them.
    a = p.attrs
    check(isinstance(a["n_springs"], (np.integer, int)) and a["n_springs"] == 12, f"n_springs {a['n_springs']!r}")
    check(isinstance(a["mass_kg"], (np.floating, float)) and a["mass_kg"] == 1e-8, "mass_kg")
    check(a["mass_kg.unit"] == "kg", "mass_kg.unit")
    check(a["layout"] == "rest" and isinstance(a["layout"], str), "layout as str")
    check(bool(a["provot"]) is False, "provot")
    check(a["dt_s"] == "auto", "dt_s")
    # Settled positions: (frames, particles, 2).
    pos = p["lagrangian/positions_m"]
    check(pos.ndim == 3 and pos.shape[1] == 13 and pos.shape[2] == 2, f"positions {pos.shape}")
    check(len(p["lagrangian/time_s"]) == pos.shape[0], "lagrangian time_s")
    # The last point too.
    check(f["points/point_000005"].attrs["label"] == "over-extended 150%", "last point")
print("h5py reads the index, its columns, strings, links, series and attributes")
EOF
