#!/usr/bin/env bash
# The fluid3d kind end to end on 8^3 grids: a Taylor-Green decay and an updraft from an inflow floor
# (Lentine et al. 2010 §7.1) are bitwise the same with --jobs 1 and 2 and with 1 and 2 threads; the
# plane of fields is (frames, rows, columns) with its XDMF sidecar naming datasets that exist; bad input
# exits 2 with the problem in words and writes nothing; a step beyond upwind2_rk2's CFL bound exits 3,
# the failed point keeping its first frame.
# usage: fluid3d.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
cat >"$scratch/small.toml" <<'TOML'
kind = "fluid3d"
title = "small 3-D flows"
[params]
cells = 8
end_time_s = 0.4
output_interval_s = 0.1
kinematic_viscosity_m2_per_s = 1e-4
[[case]]
label = "taylor_green"
initial = "taylor_green"
amplitude_m_per_s = 0.01
slice_normal = "z"
[[case]]
label = "updraft"
side_z_low = "inflow"
inflow_z_low_m_per_s = 0.02
side_z_high = "open"
side_x_low = "no_slip"
side_x_high = "no_slip"
[sweep]
threads = [1, 2]
TOML
"$bin" run "$scratch/small.toml" --out "$scratch/a" --jobs 1 >/dev/null 2>&1 || fail "jobs 1: exit code $?"
"$bin" run "$scratch/small.toml" --out "$scratch/b" --jobs 2 >/dev/null 2>&1 || fail "jobs 2: exit code $?"
diff <("$bin" digest "$scratch/a") <("$bin" digest "$scratch/b") || fail "--jobs 1 and 2 differ"

/usr/bin/python3 - "$scratch/a" <<'PY'
import sys, os, h5py, numpy as np, xml.etree.ElementTree as ET
run = sys.argv[1]
points = [h5py.File(os.path.join(run, "point_%06d.h5" % i), "r") for i in range(4)]
for i in (0, 2):  # threads 1 and 2 of each case: the same datasets, bit for bit
    one, two = points[i], points[i + 1]
    for group in ("timeseries", "fields", "metrics"):
        for name in one[group]:
            assert np.array_equal(one[group][name][()], two[group][name][()], equal_nan=True), (i, group, name)
tg, up = points[0], points[2]
q = tg["fields/q_per_s2"]
assert q.shape == (5, 8, 8) and q.chunks == (1, 8, 8), (q.shape, q.chunks)
assert q[()].max() > 0, "no vortex core (Q > 0) on the Taylor-Green plane"
assert tg["metrics/max_divergence_rel"][()] <= 1e-8
assert 0 < tg["metrics/decay_rate_error"][()] < 0.1, tg["metrics/decay_rate_error"][()]
for name in ("kinetic_energy_j", "max_divergence_per_s", "max_vorticity_per_s", "kinetic_energy_error_rel"):
    assert len(tg["timeseries/" + name]) == 5, name
w = up["fields/w_m_per_s"][()]
assert w.shape == (5, 8, 8)
assert abs(w[-1, 4, 4] - 0.02) < 0.01 and w[-1, 4, 0] < w[-1, 4, 4], w[-1, 4]  # rising, slower beside the walls
root = ET.parse(os.path.join(run, "point_000002.xdmf")).getroot()
assert len(root.findall(".//Grid[@GridType='Uniform']")) == 5
names = set(up["fields"].keys())
for item in root.iter("DataItem"):
    if item.get("Format") == "HDF":
        path, slab = item.text.strip().split("|")
        assert path.split(":")[1].split("/")[-1] in names, path
        assert item.get("Dimensions") == "8 8" and slab.split(":")[-1] == "5 8 8", (item.get("Dimensions"), slab)
print("fluid3d series, plane of fields and XDMF ok")
PY

# Bad input: exit 2, the problem in words, nothing written.
printf 'base = "small.toml"\n[[case]]\nlabel = "closed updraft"\nside_z_low = "inflow"\nside_z_high = "no_slip"\n' \
  >"$scratch/bad.toml"
rc=0
"$bin" run "$scratch/bad.toml" --out "$scratch/bad" >"$scratch/bad.out" 2>&1 || rc=$?
[[ $rc == 2 ]] || fail "inflow without an open side: exit code $rc, expected 2"
grep -q "inflow side needs an open side" "$scratch/bad.out" || fail "no reason given: $(cat "$scratch/bad.out")"
[[ ! -e $scratch/bad/index.h5 ]] || fail "bad input wrote a run"

# A step beyond upwind2_rk2's CFL bound: exit 3, the point failed with its first frame kept.
printf 'base = "small.toml"\n[[case]]\nlabel = "fast"\ninitial = "taylor_green"\namplitude_m_per_s = 1.0\n' >"$scratch/fast.toml"
rc=0
"$bin" run "$scratch/fast.toml" --out "$scratch/blowup" params.advection=upwind2_rk2 params.dt_s=0.1 sweep.threads=[1] \
  >"$scratch/blowup.out" 2>&1 || rc=$?
[[ $rc == 3 ]] || fail "CFL blow-up: exit code $rc, expected 3: $(cat "$scratch/blowup.out")"
/usr/bin/python3 - "$scratch/blowup/point_000000.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    assert f.attrs["status"] == "failed", f.attrs["status"]
    assert "CFL number" in f.attrs["message"], f.attrs["message"]
    assert len(f["timeseries/time_s"]) == 1 and f["fields/u_m_per_s"].shape[0] == 1
print("fluid3d blow-up kept its first frame")
PY
echo "fluid3d ok"
