# Sourced by flyer3d.sh and flyer3d_flesh.sh after lib.sh and checks_fail_lib.sh (uses bin, scratch, fail(),
# status; the caller sets experiment), and by flyer3d_render.sh for `small`: the driven flyer's small setting,
# 16 x 8 x 16 cells over two 0.1 s readings (twelve frames), the inner joints flapping at 10 Hz so that each
# reading holds both strokes; the claim's checks; and two helpers.
small=(params.cells=16 params.frames=12 params.warmup_frames=4 params.average_frames=4 params.flap_period_s=0.1
       "params.pd_pattern=inner_r = sine(0, 30, 10, 0); inner_l = sine(0, 30, 10, 0)"
       params.force_cycles=2 params.threads=1 params.fluid_threads=1)
# the claim's check and the two of §3.2's mechanism behind it
checks=("§7.1 in 3-D: mean upward force over whole flap cycles larger with the controller than with the outer joints held"
        "§3.2 in 3-D: the controller raises its objective (F_d on the creature) over the frames it maximises it"
        "§3.2 in 3-D: the controller lowers its objective (F_d on the creature) over the frames it minimises it")

# flyer3d_cases NAME [SERIES...]: the small run writes both cases, twelve frames each (each SERIES as long),
# the controlled outer joints move and the held ones stay at 0, the force is finite, more than 100 markers
# and a finite standard error of the upward force.
flyer3d_cases() {
  local name=$1
  shift
  "$bin" run "$experiment" "${small[@]}" --out "$scratch/run" --jobs 2 >"$scratch/run.out" 2>&1 || true
  [[ $(ls "$scratch"/run/point_*.h5 | wc -l) == 2 ]] || { cat "$scratch/run.out"; fail "$name points missing"; }
  /usr/bin/python3 - "$scratch/run" "$@" <<'PY' || fail "$name series"
import sys, h5py, numpy as np
for i, moved in ((0, True), (1, False)):
    f = h5py.File(f"{sys.argv[1]}/point_{i:06d}.h5")
    t = f["timeseries/time_s"][()]
    assert len(t) == 12, len(t)
    for name in sys.argv[2:]:
        assert f[f"timeseries/{name}"].shape == t.shape, name
    a = np.abs(f["timeseries/angle_deg_outer_r"][()]).max()
    assert (a > 1.0) if moved else (a == 0.0), (i, a)
    assert np.all(np.isfinite(f["timeseries/force_z_n_bodies"][()]))
    assert f["metrics/markers"][()] > 100
    assert np.isfinite(f["metrics/mean_up_force_n_stderr"][()])
PY
  echo "ok   $name small: both cases written; the controlled outer joints move, the held ones stay at 0"
}

# flyer3d_off WHAT: the breaking test: with the controller off (strength 0 in both cases) the two cases are
# one run, each check's ratio is exactly 1 and each check is inconclusive, never ok.
flyer3d_off() {
  "$bin" run "$experiment" "${small[@]}" params.strength_rad_per_s=0.0 --out "$scratch/run_off" --jobs 2 \
    >"$scratch/off.out" 2>&1 || { cat "$scratch/off.out" >&2; fail "off: exit code $?, expected 0"; }
  local check
  for check in "${checks[@]}"; do
    [[ $(status off "$check") == inconclusive ]] \
      || { cat "$scratch/off.out" >&2; fail "off: '$check' not inconclusive"; }
    grep -q "^$check .* 1 +- " "$scratch/off.out" || fail "off: '$check': the ratio is not exactly 1"
    echo "ok   $1: '$check' is inconclusive (ratio 1)"
  done
}
