#!/usr/bin/env bash
# Every check that decides a fluid-controller claim (Lentine et al. 2010, Figs. 2, 8, 10-13, §7.2) fails when
# the controller the claim rests on is off (strength zero, no search): the claim file runs at its own
# setting (the fluid is cheap when nothing searches), and the check must then be FAIL with exit code 1 (the
# flyer's, decided on its standard error, inconclusive: never ok); Fig. 10's threads, which have no switch,
# are seen to fail on a run moved by one unit in the last place.
# usage: control_fluid_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, study

# Fig. 8, Fig. 2's Navier-Stokes rows: without the controller the block stays where it starts, 30 degrees
# off the flow, whatever it would minimise or maximise.
broken flow_no_control experiments/control/block_flow.toml \
  "min_drag: minimising drag turns the block near the flow (within 5 degrees, Fig. 8a; not exact: §4.3)" \
  params.strength_rad_per_s=0.0 params.search_every_frames=100000 params.field_every_frames=0
also flow_no_control "max_drag: maximising drag turns the block across the flow (within 10 degrees, Fig. 8b)"
also flow_no_control \
  "min_effort: minimising effort (Eq. 1) turns the block near the flow (within 5 degrees; Fig. 2's third Navier-Stokes row)"

# §7.2: without the controller (its strength and its phases' strengths zero) the swimmer is moved by its
# mouth alone: 1.6 mm a cycle, the mouth-only case's rise, so both cases are the same run.
broken swimmer_no_control experiments/control/swimmer.toml "the swimmer rises with the controller (§7.2)" \
  params.strength_rad_per_s=0.0 params.search_every_frames=100000 'params.phase_strength_rad_per_s="0, 0, 0"' \
  params.field_every_frames=0
also swimmer_no_control "the controller rises farther than the mouth alone (§7.2: 'significant locomotion')"
also swimmer_no_control \
  "the mouth alone moves the creature less than a quarter as far as the controller (§7.2: 'not enough to move the creature significantly')"

# Figs. 11-13 (§7.1): with the controller off both cases are one run: the ratio is exactly 1 and its
# interval holds 1, so the check is inconclusive, never ok (exit 0). [1, 1e9] alone passed it. On 32^2 over
# two 0.25 s flaps (tests/cli/flyer.sh's setting), where the intact file is inconclusive too: the flyer's
# noise needs flyer.toml's twenty flaps to decide, beyond this test's time.
small=(params.cells=32 params.frames=30 params.warmup_frames=2 params.average_frames=5 params.field_every_frames=0
       params.flap_period_s=0.25 'params.pd_pattern=inner_r = sine(0, 30, 4, 0); inner_l = sine(0, 30, 4, 0)')
check="§7.1: mean upward force over whole flap cycles larger with the controller than with the outer joints held"
"$bin" run studies/control/flyer_quick.toml "${small[@]}" params.strength_rad_per_s=0.0 --out "$scratch/run_flyer_off" \
  --jobs 2 >"$scratch/flyer_off.out" 2>&1 || { cat "$scratch/flyer_off.out" >&2; fail "flyer_off: exit code $?, expected 0"; }
[[ $(status flyer_off "$check") == inconclusive ]] || { cat "$scratch/flyer_off.out" >&2; fail "flyer_off: not inconclusive"; }
grep -q "^$check .* 1 +- " "$scratch/flyer_off.out" || fail "flyer_off: the ratio is not exactly 1"
echo "ok   flyer_off: '$check' is inconclusive (ratio 1)"

# Fig. 10 in the fluid (§5): each joint's central difference runs on its own copy of the fluid, so evaluation
# and fluid threads give the serial run bitwise; they have no switch that breaks that, so a parallel point is
# moved by one unit in the last place (the least a race could change it) and the checks, evaluated again,
# must fail. The intact run (the checked cases, 64^2, six frames) passes first.
study parallel_fluid experiments/control/parallel_dofs_fluid.toml <<'TOML'
[params]
cells = 64
frames = 6
warmup_frames = 2
average_frames = 2
[[case]]
label = "2_joints"
controlled = "j0, j1"
kinematic = "j2, j3, j4"
objectives = "drag_along, drag_along"
senses = "min, min"
[[case]]
label = "4_joints"
controlled = "j0, j1, j2, j3"
kinematic = "j4"
objectives = "drag_along, drag_along, drag_along, drag_along"
senses = "min, min, min, min"
TOML
intact parallel_fluid "$scratch/parallel_fluid.toml"
nudged parallel_fluid_4_angle "$scratch/run_parallel_fluid" \
  "4 joints: two evaluation and two fluid threads give exactly the serial run (final angle)" final_angle_deg 4_joints
nudged parallel_fluid_4_drag "$scratch/run_parallel_fluid" \
  "4 joints: two evaluation and two fluid threads give exactly the serial run (final drag)" final_drag_along_n 4_joints
nudged parallel_fluid_2_angle "$scratch/run_parallel_fluid" \
  "2 joints: two evaluation and two fluid threads give exactly the serial run (final angle)" final_angle_deg 2_joints
