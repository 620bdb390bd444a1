#!/usr/bin/env bash
# The fluid kind end to end: /fields/<name> has shape (frames, ny, nx), one frame per
# chunk; the XDMF sidecar is well-formed XML whose HDF references name datasets that exist with
# the stated dimensions; /timeseries has kinetic energy, max_divergence and CFL; the fields are
# bitwise the same with --jobs 1 and 2.
# usage: fluid_fields.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
cat >"$scratch/fluid.toml" <<'TOML'
kind = "fluid"
title = "small vortex pair"
[params]
initial = "vortex_pair"
circulation_m2_per_s = 0.01
cells = 24
end_time_s = 0.5
output_interval_s = 0.125
tracers_per_side = 5
[sweep]
advection = ["semi_lagrangian", "maccormack"]
TOML
"$bin" run "$scratch/fluid.toml" --out "$scratch/a" --jobs 1 >/dev/null 2>&1
"$bin" run "$scratch/fluid.toml" --out "$scratch/b" --jobs 2 >/dev/null 2>&1
diff <("$bin" digest "$scratch/a") <("$bin" digest "$scratch/b")

/usr/bin/python3 - "$scratch/a" <<'PY'
import sys, os, h5py, xml.etree.ElementTree as ET
run = sys.argv[1]
with h5py.File(os.path.join(run, "point_000000.h5"), "r") as f:
    u = f["fields/u_m_per_s"]
    assert u.shape == (5, 24, 24), u.shape            # t = 0, 0.125, ..., 0.5
    assert u.chunks == (1, 24, 24), u.chunks
    assert list(f["fields/time_s"][...]) == [0.0, 0.125, 0.25, 0.375, 0.5], f["fields/time_s"][...]
    for name in ("kinetic_energy_j_per_m", "max_divergence", "cfl_number"):
        assert len(f["timeseries/" + name]) == 5, name
    assert f["lagrangian/tracers_m"].shape == (5, 25, 2)
    assert f["metrics/max_divergence_rel"][()] <= 1e-10
    names = set(f["fields"].keys())
root = ET.parse(os.path.join(run, "point_000000.xdmf")).getroot()
frames = root.findall(".//Grid[@GridType='Uniform']")
assert len(frames) == 5, len(frames)
for item in root.iter("DataItem"):
    if item.get("Format") == "HDF":
        path, slab = item.text.strip().split("|")  # XDMF 3: file:/dataset|start:stride:count:shape
        fname, dset = path.split(":")
        assert fname == "point_000000.h5", fname
        assert dset.split("/")[-1] in names, dset
        assert item.get("Dimensions") == "24 24" and slab.split(":")[-1] == "5 24 24", (item.get("Dimensions"), slab)
print("fluid fields and XDMF sidecar ok")
PY
