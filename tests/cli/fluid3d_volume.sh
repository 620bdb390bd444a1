#!/usr/bin/env bash
# The fluid3d kind's whole-box fields (stored_fields = "volume"): an updraft in a box of unequal sides
# (8 x 6 x 10 cells) stores (frames, nz, ny, nx) datasets, one frame per chunk, with the grid's spacing
# and origin; its XDMF sidecar (3D co-rectilinear meshes, cell attributes) opens in ParaView's pvbatch
# with the HDF5's counts, times, bounds, ranges and every value in its own cell (xdmf_readers.py).
# Exits 77 (ctest SKIP_RETURN_CODE) after the HDF5 checks when pvbatch is not on PATH.
# usage: fluid3d_volume.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
cat >"$scratch/volume.toml" <<'TOML'
kind = "fluid3d"
title = "an updraft's whole box"
[params]
cells = 8
domain_y_m = 0.3
domain_z_m = 0.5
end_time_s = 0.2
output_interval_s = 0.1
kinematic_viscosity_m2_per_s = 1e-4
side_z_low = "inflow"
inflow_z_low_m_per_s = 0.02
side_z_high = "open"
side_x_low = "no_slip"
side_x_high = "no_slip"
stored_fields = "volume"
TOML
"$bin" run "$scratch/volume.toml" --out "$scratch/run" >"$scratch/run.out" 2>&1 || fail "exit code $?: $(cat "$scratch/run.out")"

/usr/bin/python3 - "$scratch/run" <<'PY'
import sys, os, h5py, numpy as np, xml.etree.ElementTree as ET
run = sys.argv[1]
with h5py.File(os.path.join(run, "point_000000.h5"), "r") as f:
    g = f["fields"]
    names = sorted(n for n in g if n != "time_s")
    assert names == ["pressure_pa", "q_per_s2", "u_m_per_s", "v_m_per_s", "vorticity_magnitude_per_s", "w_m_per_s"], names
    for n in names:
        assert g[n].shape == (3, 10, 6, 8) and g[n].chunks == (1, 10, 6, 8), (n, g[n].shape, g[n].chunks)
    assert [g.attrs[a] for a in ("dx_m", "dy_m", "dz_m")] == [0.05] * 3, dict(g.attrs)
    assert [g.attrs["origin_%s_m" % a] for a in "xyz"] == [0.0] * 3, dict(g.attrs)
    w = g["w_m_per_s"][-1]
    assert abs(w[5, 3, 4] - 0.02) < 0.01 and w[5, 3, 0] < w[5, 3, 4], w[5, 3]  # rising, slower beside the x walls
root = ET.parse(os.path.join(run, "point_000000.xdmf")).getroot()
assert len(root.findall(".//Grid[@GridType='Uniform']")) == 3
assert {t.get("Dimensions") for t in root.iter("Topology")} == {"11 7 9"}
print("fluid3d volume datasets and sidecar ok")
PY

pvbatch=$(command -v pvbatch || echo -)
if [[ $pvbatch == - ]]; then
  echo "skip: pvbatch is not on PATH, the sidecar was not opened in ParaView (apt-get install paraview)"
  exit 77
fi
/usr/bin/python3 "$src/tests/cli/xdmf_readers.py" "$pvbatch" "$scratch/run"
echo "fluid3d volume ok"
