#!/usr/bin/env bash
# The driven flyer (Lentine et al. 2010 §7.1; studies/control/flyer_quick.toml, make
# reproduce's version of flyer.toml) end to end
# on 32^2 for half a second: every point written with its flyer series (senses following the
# stroke, the PD-driven angles, the force on all bodies) and a finite mean upward force over whole
# cycles; --jobs 1 and 2 give bitwise-equal datasets; the figures are drawn from the HDF5 alone;
# bad input (a wing outside the box, stroke_sense on a joint without a stroke, a flap period not a
# whole number of frames) exits 2 naming it, nothing written; a diverging point exits 3.
# usage: flyer.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
small=(params.cells=32 params.frames=30 params.warmup_frames=2 params.average_frames=5 params.field_every_frames=10
       params.flap_period_s=0.25 'params.pd_pattern=inner_r = sine(0, 30, 4, 0); inner_l = sine(0, 30, 4, 0)'
       )

"$bin" run studies/control/flyer_quick.toml "${small[@]}" --out "$scratch/j1" --jobs 1 >"$scratch/j1.log" 2>&1 || true
[[ $(ls "$scratch"/j1/point_*.h5 | wc -l) == 2 ]] || { cat "$scratch/j1.log"; fail "flyer points missing"; }
"$bin" run studies/control/flyer_quick.toml "${small[@]}" --out "$scratch/j2" --jobs 2 >"$scratch/j2.log" 2>&1 || true
/usr/bin/python3 tests/cli/same_datasets.py "$scratch/j1" "$scratch/j2" 2 || fail "--jobs 1 and 2 differ"
/usr/bin/python3 - "$scratch/j1" <<'PY' || fail "flyer series"
import sys, glob, h5py, numpy as np
for x in sorted(glob.glob(sys.argv[1] + "/point_*.h5")):
    fx = h5py.File(x)
    ts = fx["timeseries"]
    t = ts["time_s"][...]
    # sense +1 (max) while the 4 Hz sine turns the wing down (its rate > 0), -1 on the up-stroke
    rate = np.cos(2 * np.pi * 4 * (t - 0.5 / 60))
    clear = np.abs(rate) > 0.2
    s = ts["sense_outer_r"][...]
    label = str(fx.attrs["label"])
    want = np.ones_like(s) if label == "lift" else np.where(rate > 0, 1.0, -1.0)  # lift: no stroke_sense
    assert np.array_equal(s[clear], want[clear]), (label, s, rate)
    inner = ts["pd_angle_deg_inner_r"][...]
    assert inner.max() > 15 and inner.min() < -15, inner  # the PD drive flaps the wing
    assert np.isfinite(fx["metrics/mean_up_force_n"][()])
    held = label.startswith("held")
    outer = ts["angle_deg_outer_r"][...]
    assert (np.abs(outer).max() == 0) == held, (fx.attrs["label"], outer)
PY
echo "ok   flyer small: 2 points, senses follow the stroke, PD wings flap, --jobs 1 == --jobs 2 (every dataset)"
/usr/bin/python3 analysis/plot_flyer.py "$scratch/j1" || fail "flyer figures"
/usr/bin/python3 analysis/plot_control_fluid.py "$scratch/j1" || fail "control_fluid figures"
[[ -s $scratch/j1/figures/flyer_angles.png && -s $scratch/j1/figures/flyer_force.txt && -s $scratch/j1/figures/vorticity.png ]] \
  || fail "no figures"
# Each point's ratio to the held point of its setting: the held one's own 1, the controlled one a number.
grep -Eq '^held +.* 1\.0000$' "$scratch/j1/figures/flyer_force.txt" || fail "no held reference in the force table"
grep -Eq '^controlled +.* [0-9]+\.[0-9]{4}$' "$scratch/j1/figures/flyer_force.txt" || fail "no force ratio"
echo "ok   figures"

experiment=studies/control/flyer_quick.toml
source "$(dirname "${BASH_SOURCE[0]}")/expect_bad.sh"
expect_bad wing_outside "outside the fluid box" 'params.origin_x_m=-1.0'
expect_bad no_stroke "stroke_sense: 'inner_r' holds" 'params.pd_pattern=inner_l = sine(0, 30, 4, 0)'
expect_bad not_controlled "stroke_sense" 'params.stroke_sense=inner_r = inner_l'
expect_bad period "flap_period_s" 'params.flap_period_s=0.26'

# A PD drive far too stiff for its explicit step (kp 1e7 N m/rad on 4 kg wings) diverges: exit 3, named.
expect_failed_point diverge "coupled stability limit" params.pd_kp_n_m_per_rad=1e7
