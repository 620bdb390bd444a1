#!/usr/bin/env bash
# The control kind end to end: block_effort runs with its checks passing, the figures
# are drawn from the HDF5 alone, --jobs 1 and 2 give bitwise-equal datasets (creaturelab digest),
# and bad input (missing or broken MJCF, unknown joint, weights of the wrong length, negative
# strength or delta; an unknown or wrong-length motion pattern, weights per ball-joint axis, a
# ball pose with one angle) exits 2 with one line naming the problem and nothing written.
# usage: control.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

"$bin" run experiments/control/block_effort.toml --out "$scratch/j1" --jobs 1 >"$scratch/j1.log" 2>&1 || { cat "$scratch/j1.log"; fail "block_effort failed"; }
"$bin" run experiments/control/block_effort.toml --out "$scratch/j2" --jobs 2 >"$scratch/j2.log" 2>&1 || fail "block_effort --jobs 2 failed"
"$bin" digest "$scratch/j1" >"$scratch/j1.digest"
"$bin" digest "$scratch/j2" >"$scratch/j2.digest"
[[ $(wc -l <"$scratch/j1.digest") == 7 ]] || fail "expected 6 point digests and the index"
diff "$scratch/j1.digest" "$scratch/j2.digest" || fail "--jobs 1 and --jobs 2 differ"
echo "ok   block_effort: checks pass, --jobs 1 == --jobs 2"
/usr/bin/python3 analysis/plot_control.py "$scratch/j1" || fail "figures"
[[ -s $scratch/j1/figures/frames.png && -s $scratch/j1/figures/angles.png ]] || fail "no figures"
echo "ok   figures"

# Threads inside a point (per-DOF evaluations) do not change the datasets either.
"$bin" run experiments/control/parallel_dofs.toml --out "$scratch/p" --jobs 1 params.frames=20 \
  >"$scratch/p.log" 2>&1 || { cat "$scratch/p.log"; fail "parallel_dofs failed"; }
echo "ok   parallel_dofs: threads give identical angles (its checks)"

toml=experiments/control/block_effort.toml
expect_bad() {
  local name=$1 pattern=$2
  shift 2
  local out=$scratch/out_$name rc=0
  "$bin" run "$toml" "$@" --out "$out" --jobs 1 >"$scratch/$name.out" 2>"$scratch/$name.err" || rc=$?
  [[ $rc == 2 ]] || { cat "$scratch/$name.err"; fail "$name: exit $rc, expected 2"; }
  [[ $(wc -l <"$scratch/$name.err") == 1 ]] || { cat "$scratch/$name.err"; fail "$name: expected one line"; }
  grep -qF -- "$pattern" "$scratch/$name.err" || fail "$name: does not name '$pattern': $(cat "$scratch/$name.err")"
  [[ ! -e $out ]] || fail "$name: wrote $out"
  echo "ok   $name: $(cat "$scratch/$name.err")"
}
printf '<mujoco><worldbody><body></mujoco>' >"$scratch/broken.xml"
expect_bad missing_model "$scratch/none.xml" "params.model_file=\"$scratch/none.xml\""
expect_bad broken_model "$scratch/broken.xml" "params.model_file=\"$scratch/broken.xml\""
expect_bad unknown_joint "'elbow'" 'params.controlled="elbow"'
expect_bad weights_length "weights: row 1" 'params.weights="1,0"'
expect_bad negative_strength "strength_rad_per_s" 'sweep.strength_rad_per_s=[-1.0]'
expect_bad negative_delta "delta_rad" 'params.delta_rad=-0.01'

toml=experiments/control/human_gravity.toml
expect_bad unknown_pattern "kinematic_pattern (right_hip_y): 'cosine(0, 20, 1, 0)' is not hold" \
  'params.kinematic_pattern="right_hip_y = cosine(0, 20, 1, 0)"'
expect_bad sine_length "kinematic_pattern (right_knee): sine takes 4 numbers" 'params.kinematic_pattern="right_knee = sine(0, 20, 1)"'
expect_bad table_point "pd_pattern (left_elbow): table point '0.5'" \
  'params.pd_driven="left_elbow"' 'params.pd_pattern="left_elbow = table(0 0, 0.5, 1 10)"'
expect_bad pattern_not_kinematic "kinematic_pattern: joint 'lower_back' is not in kinematic" \
  'params.kinematic_pattern="lower_back = sine(0, 20, 1, 0)"'
toml=experiments/control/block_ball.toml
expect_bad ball_weights "a ball joint counts once" 'params.weights="1,0,0"'
expect_bad ball_pose "initial_deg: joint 'ball' takes three numbers" 'params.initial_deg="ball=30"'
