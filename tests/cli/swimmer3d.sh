#!/usr/bin/env bash
# The 3-D swimmer (experiments/control/swimmer3d.toml, Lentine et al. 2010 §7.2) with its legs held in both
# cases (the breaking test: the controller off), on its default coupled solve (Eq. 9) with the mouth, two
# cycles of 1/3 s: both cases write the rise, phase and mouth flux series and the rise metrics, the mouth
# alone barely moves the creature, and the claim's checks that it rises with the controller FAIL; bad input
# (phases not adding up, a body outside the fluid box, a mouth on no body, the armature's added mass with
# the coupled solve) exits 2, nothing written.
# usage: swimmer3d.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also
experiment=experiments/control/swimmer3d.toml
small=(params.frames=40 params.cycle_s=0.3333333333333333 params.rise_cycles=2 params.average_frames=10)
off=(params.strength_rad_per_s=0.0 'params.phase_strength_rad_per_s="0, 0, 0"' params.search_every_frames=100000)

rises="the swimmer rises with the controller (§7.2)"
broken off "$experiment" "$rises" "${small[@]}" "${off[@]}"
also off "the controller rises farther than the legs held"
/usr/bin/python3 - "$scratch/run_off" <<'PY' || fail "swimmer3d datasets"
import sys, glob, h5py, numpy as np
points = sorted(glob.glob(sys.argv[1] + "/point_*.h5"))
assert len(points) == 2, points
for p in points:
    f = h5py.File(p)
    n = f["timeseries/time_s"].shape[0]
    assert n == 40, n
    for s in ("rise_z_m", "com_x_m", "com_y_m", "phase", "mouth_flux_m_per_s", "angle_deg_leg0"):
        assert f[f"timeseries/{s}"].shape[0] == n, s
    assert set(np.unique(f["timeseries/phase"][()])) == {0, 1, 2}
    assert set(np.unique(f["timeseries/mouth_flux_m_per_s"][()])) == {-0.25, 0.5, 0.0}
    rise = f["metrics/rise_per_cycle_m"][()]
    assert rise != 0.0 and abs(rise) < 0.005, rise  # the mouth moves it, a millimetre or so
    assert 1.99 < f["metrics/creature_density_ratio"][()] < 2.01
    assert f["metrics/markers"][()] > 1000
PY
echo "ok   controller off: both cases written, the mouth alone barely moves it"

source "$(dirname "${BASH_SOURCE[0]}")/expect_bad.sh"
expect_bad phases "phase_fractions must sum to 1" 'params.phase_fractions="0.5, 0.1, 0.7"'
expect_bad outside_box "outside the fluid box" 'params.origin_z_m=0.0'
expect_bad mouth "has no body 'jaw'" 'params.mouth_body=jaw'
expect_bad armature "armature_added_mass: only with forcing = projected" params.armature_added_mass=true
