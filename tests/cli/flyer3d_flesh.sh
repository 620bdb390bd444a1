#!/usr/bin/env bash
# The driven flyer wrapped in flesh (control_fluid3d, flesh = true; Lentine et al. 2010 Fig. 13) end to
# end on experiments/control/flyer3d_flesh.toml at 16 x 8 x 16 cells over two 0.1 s readings (twelve
# frames): both cases written, the flesh's vertices the markers, the controlled wings moved and the held
# ones not; the breaking test: with the controller off (strength 0 in both cases) the ratio is exactly 1
# and the §7.1 check is inconclusive, never ok; bad input (a zero flesh thickness, the flesh outside the
# box) exits 2 with one line naming it.
# usage: flyer3d_flesh.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status
small=(params.cells=16 params.frames=12 params.warmup_frames=4 params.average_frames=4 params.flap_period_s=0.1
       params.force_cycles=2 params.threads=1 params.fluid_threads=1)
experiment=experiments/control/flyer3d_flesh.toml

"$bin" run "$experiment" "${small[@]}" --out "$scratch/run" --jobs 2 >"$scratch/run.out" 2>&1 || true
[[ $(ls "$scratch"/run/point_*.h5 | wc -l) == 2 ]] || { cat "$scratch/run.out"; fail "flyer3d_flesh points missing"; }
/usr/bin/python3 - "$scratch/run" <<'PY' || fail "flyer3d_flesh series"
import sys, h5py, numpy as np
for i, moved in ((0, True), (1, False)):
    f = h5py.File(f"{sys.argv[1]}/point_{i:06d}.h5")
    t = f["timeseries/time_s"][()]
    assert len(t) == 12, len(t)
    a = np.abs(f["timeseries/angle_deg_outer_r"][()]).max()
    assert (a > 1.0) if moved else (a == 0.0), (i, a)
    assert np.all(np.isfinite(f["timeseries/force_z_n_bodies"][()]))
    assert f["metrics/markers"][()] > 100
    assert np.isfinite(f["metrics/mean_up_force_n_stderr"][()])
PY
echo "ok   flyer3d_flesh small: both cases written; the controlled outer joints move, the held ones stay at 0"

check="§7.1 in 3-D: mean upward force over whole flap cycles larger with the controller than with the outer joints held"
"$bin" run "$experiment" "${small[@]}" params.strength_rad_per_s=0.0 --out "$scratch/run_off" --jobs 2 \
  >"$scratch/off.out" 2>&1 || { cat "$scratch/off.out" >&2; fail "off: exit code $?, expected 0"; }
[[ $(status off "$check") == inconclusive ]] || { cat "$scratch/off.out" >&2; fail "off: not inconclusive"; }
grep -q "^$check .* 1 +- " "$scratch/off.out" || fail "off: the ratio is not exactly 1"
echo "ok   controller off with flesh: '$check' is inconclusive (ratio 1)"

source "$(dirname "${BASH_SOURCE[0]}")/expect_bad.sh"
expect_bad thickness "flesh_thickness_m" 'params.flesh_thickness_m=0.0'
expect_bad outside_box "outside the fluid box" 'params.origin_x_m=-0.5'
