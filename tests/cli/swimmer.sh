#!/usr/bin/env bash
# The swimmer (experiments/control/swimmer.toml, Lentine et al. 2010 §7.2) end to end,
# small (64^2, two cycles of 0.1 s): both cases write the rise, phase and mouth flux series and the
# rise metrics, the figures are drawn from the HDF5 alone; without the armature stabilisation the
# free creature (twice the water it displaces) stops at the coupled stability limit, exit 3, the
# message naming the density ratio; a phase table that does not add up exits 2, nothing written.
# usage: swimmer.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
# One coupled step a frame (1/60 s): on 64^2 the default's two (1/120 s) pass the coupled stability
# limit with the armature's stabilisation too (a marker moves 1.2-1.3 cells in a step, exit 3; stable
# on 96^2 and 128^2 for two cycles, on 192^2 and 256^2 for six), so the smoke run keeps the longer step.
small=(params.cells=64 params.frames=12 params.average_frames=6 params.cycle_s=0.1 params.rise_cycles=1
       params.field_every_frames=6 params.substeps=1 params.average_steps=1)

rc=0
"$bin" run experiments/control/swimmer.toml "${small[@]}" --out "$scratch/run" --jobs 2 >"$scratch/run.log" 2>&1 || rc=$?
[[ $rc == 0 || $rc == 1 ]] || { cat "$scratch/run.log"; fail "swimmer small: exit $rc"; }
/usr/bin/python3 - "$scratch/run" <<'PY' || fail "swimmer datasets"
import sys, glob, h5py, numpy as np
points = sorted(glob.glob(sys.argv[1] + "/point_*.h5"))
assert len(points) == 2, points
for p in points:
    f = h5py.File(p)
    n = f["timeseries/time_s"].shape[0]
    for s in ("rise_z_m", "phase", "mouth_flux_m_per_s"):
        assert f[f"timeseries/{s}"].shape[0] == n, s
    assert set(np.unique(f["timeseries/phase"][()])) == {0, 1, 2}
    assert np.isfinite(f["metrics/rise_per_cycle_m"][()])
    assert 1.9 < f["metrics/creature_density_ratio"][()] < 2.1
PY
/usr/bin/python3 analysis/plot_control_fluid.py "$scratch/run" || fail "figures"
[[ -s $scratch/run/figures/rise.png && -s $scratch/run/figures/rise.txt && -s $scratch/run/figures/vorticity.png ]] \
  || fail "no swimmer figures"
echo "ok   swimmer small: both cases, rise series and metrics, figures"

rc=0
"$bin" run experiments/control/swimmer.toml "${small[@]}" params.armature_added_mass=false --out "$scratch/unstable" \
  --jobs 2 >"$scratch/unstable.log" 2>&1 || rc=$?
[[ $rc == 3 ]] || { cat "$scratch/unstable.log"; fail "unstabilised swimmer: exit $rc, expected 3"; }
grep -q "coupled stability limit" "$scratch/unstable.log" || fail "instability not named"
grep -q "displaced fluid mass" "$scratch/unstable.log" || fail "density ratio not named"
echo "ok   unstabilised free swimmer: exit 3, named"

rc=0
"$bin" run experiments/control/swimmer.toml "${small[@]}" 'params.phase_fractions="0.5, 0.1, 0.7"' \
  --out "$scratch/bad" >"$scratch/bad.out" 2>"$scratch/bad.err" || rc=$?
[[ $rc == 2 ]] || { cat "$scratch/bad.err"; fail "bad phases: exit $rc, expected 2"; }
grep -q "phase_fractions must sum to 1" "$scratch/bad.err" || fail "bad phases not named: $(cat "$scratch/bad.err")"
[[ ! -e $scratch/bad ]] || fail "bad phases: wrote a folder"
echo "ok   phase fractions not summing to 1: exit 2, named, nothing written"
