#!/usr/bin/env bash
# Every check that decides a fish claim (Tu 1996, chs. 4-5) fails when the mechanism the claim rests on is
# broken: the claim file is run with the water on or off, a side current, or a body ten times stiffer per
# mode, through overrides, and the check must then be FAIL in the table with exit code 1. The fish is cheap:
# the claim files run at their own setting (sweeps cut only where the check still resolves).
# usage: fish_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, study

# Ch. 4, in air: with the water's force on, sum m v is no longer kept (it drifts by 0.7 of itself), the
# centre of mass travels (2.4 body lengths) and the water's damping keeps the full-amplitude fish whole.
broken air_in_water experiments/fish/air.toml "sum m v conserved to 1e-12 relative (until the blow-up)" \
  params.water_mu=100
also air_in_water "the centre of mass does not travel (1e-12 body lengths)"
also air_in_water "the full-amplitude fish blows up in air"

# Ch. 5: with no water (the blow-up recorded, not a failed point) the fish goes nowhere: no speed to rise
# with the amplitude or the rate, and no straight course.
broken swim_no_water experiments/fish/swim.toml "speed rises with the amplitude (r = 0.004)" \
  params.water_mu=0 params.on_blowup=record
also swim_no_water "speed rises with the amplitude (r = 0.008)"
also swim_no_water "speed rises with the rate (alpha = 0.7)"
also swim_no_water "speed rises with the rate (alpha = 1)"
also swim_no_water "straight swimming drifts sideways less than 5% of the distance (r = 0.004, the default gait)"
also swim_no_water "straight swimming drifts sideways less than 5% of the distance (every gait; from rest, so it includes the start's turn)"
also swim_no_water "once settled, the fish swims straight: sideways drift from its settled heading < 5% (every gait)"
also swim_no_water "once settled, the direction of travel changes by less than 1 degree over the last 60 s (every gait)"
# A 5 mm/s side current breaks the left-right symmetry straight swimming rests on: the fish drifts 14-40%.
broken swim_current experiments/fish/swim.toml \
  "straight swimming drifts sideways less than 5% of the distance (every gait; from rest, so it includes the start's turn)" \
  params.current_y_m_per_s=0.005
also swim_current "straight swimming drifts sideways less than 5% of the distance (r = 0.004, the default gait)"
also swim_current "once settled, the direction of travel changes by less than 1 degree over the last 60 s (every gait)"

# Spec §3: the stride collapses because the fastest gait beats far above the body's lowest sideways mode;
# a body 100 times stiffer (mode 10 times higher, step cut to stay stable) keeps its stride (0.40 of r =
# 0.004's) and beats at 2.1 times its mode.
broken rate_stiff experiments/fish/swim_rate.toml \
  "the stride (body lengths per cycle) collapses once the gait outruns the body: r_max against r = 0.004 below 1/10" \
  params.stiffness_cross_n_per_m=3800 params.stiffness_other_n_per_m=3000 params.stiffness_muscle_n_per_m=2800 \
  params.dt_s=0.0015 params.on_blowup=record 'sweep.swim_rate=[0.004, 0.02, 0.075]'
also rate_stiff "the fastest gait beats at more than 10 times the body's lowest sideways mode"

# Ch. 5, turns: with no water nothing turns the fish; a side current turns every run its own way, so a
# stronger turn no longer tightens the radius, the glide turns as much, and left and right do not mirror.
broken turn_no_water experiments/fish/turn.toml "a stronger turn changes the direction of travel more" \
  params.water_mu=0 params.on_blowup=record
also turn_no_water "a stronger turn has a smaller radius"
also turn_no_water "the full-amplitude turn turns the fish more than the swim's restart alone (glide control), by > 1.5x"
broken turn_current experiments/fish/turn.toml "left and right turns mirror each other: heading change (alpha = 0.4)" \
  params.current_y_m_per_s=0.005
also turn_current "left and right turns mirror each other: heading change (alpha = 0.7)"
also turn_current "left and right turns mirror each other: heading change (alpha = 1)"
also turn_current "left and right turns mirror each other: radius (alpha = 1)"
also turn_current "a stronger turn has a smaller radius"

# School: with no water every fish of the school flails (the blow-up recorded) and none swims forward; with
# the explicit step at the school's 0.055 s every fish blows up (the failed points fail both checks, exit 3).
broken school_no_water experiments/fish/school.toml "every fish of the school swims forward" \
  params.water_mu=0 params.on_blowup=record 'sweep.school_size=[1, 10]'
rc=0
"$bin" run experiments/fish/school.toml --out "$scratch/run_school_explicit" --jobs 2 params.scheme=explicit_euler \
  'sweep.school_size=[1, 10]' >"$scratch/school_explicit.out" 2>&1 || rc=$?
[[ $rc == 3 ]] || fail "school_explicit: exit code $rc, expected 3"
also school_explicit "no fish of the school blows up"

# Ch. 7, skin: a control net drawn at 0.3 of the body's section (the surface inside the body) folds over.
broken skin_thin experiments/fish/skin.toml "no fold-over on any frame (no neighbouring triangles more than 90 degrees apart)" \
  params.skin_inflate=0.3
