#!/usr/bin/env bash
# Every check that decides a fish claim (Tu 1996, chs. 4-5, 7) fails when the mechanism the claim rests on
# is broken: the water off or on, the spec's soft units (a body that filters the gait), the spec's reading
# of the rate, the tail's beat stopped through a turn, a coarse speed map, heavy unit damping, a thin skin.
# Each broken run is cut to the least that still resolves the failure (short swims, one sweep row).
# usage: fish_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, study

# The spec's soft units: the [reimpl] stiffnesses, 10 ms steps, a blow-up recorded, not a failed point.
soft=(params.stiffness_cross_n_per_m=38 params.stiffness_other_n_per_m=30 params.stiffness_muscle_n_per_m=28
      params.dt_s=0.01 params.on_blowup=record)

# Ch. 4, in air: with the water's force on, sum m v is no longer kept and the centre of mass travels.
broken air_in_water experiments/fish/air.toml "sum m v conserved to 1e-12 relative" \
  params.water_mu=600 'params.schedule="swim 2"' 'sweep.swim_amplitude=[1.0]'
also air_in_water "the centre of mass does not travel (1e-12 body lengths)"

# Ch. 5, swim: on the spec's soft body (lowest sideways mode 0.15 Hz) the gait is filtered: the speed falls
# as the rate rises (doubling r from r_max / 8: 0.48x), the fastest gait crawls and the slow swim wanders.
# A 30 s swim after 10 s of warm-up, on which the intact file passes every check (20 s gave it 3.1x there).
broken swim_soft experiments/fish/swim.toml "speed rises with the rate (alpha = 1/4)" \
  "${soft[@]}" 'params.schedule="swim 30"' params.warmup_s=10
also swim_soft "speed rises with the rate (alpha = 1/2)"
also swim_soft "speed rises with the rate (alpha = 3/4)"
also swim_soft "speed rises with the rate (alpha = 1)"
also swim_soft "roughly proportional to the rate at small values: doubling r from r_max / 8 (alpha = 1) gives 1.5-3x the speed"
also swim_soft "the fastest gait (alpha = 1, r = r_max) swims at least half a body length per second"
also swim_soft "once settled, the fish swims straight: sideways drift from its settled heading < 5% (every gait)"
also swim_soft "once settled, the direction of travel changes by less than 2 degrees over the last 20 s (every gait)"
# The spec's reading of the rate (every stroke ramps at r l0 per step, a weaker one beats faster): the
# tail's lateral speed is then set by r alone, and a larger amplitude no longer swims faster.
broken swim_rest_length experiments/fish/swim.toml "speed rises with the amplitude (r = r_max / 8)" \
  params.rate_reading=rest_length 'params.schedule="swim 10"' params.warmup_s=5
also swim_rest_length "speed rises with the amplitude (r = r_max / 4)"
also swim_rest_length "speed rises with the amplitude (r = r_max / 2)"
also swim_rest_length "speed rises with the amplitude (r = r_max)"
also swim_rest_length "roughly proportional to the amplitude at small values: doubling alpha from 1/4 (r = r_max) gives 1.5-3x the speed"

# Spec §3: the soft body's lowest sideways mode lies far below the stroke; its speed falls with the rate on
# both shapes and its stride collapses.
broken rate_soft experiments/fish/swim_rate.toml "the fastest stroke beats below the body's lowest sideways mode" \
  "${soft[@]}"
also rate_soft "speed rises with the rate over the whole range (0, r_max] (our shape)"
also rate_soft "speed rises with the rate over the whole range (0, r_max] (the reimplementation's shape)"
also rate_soft "the stride (body lengths per stroke) holds at the fastest gait: r_max against r_max / 8 at least 1"

# Ch. 5, swim-MC: a speed map of two levels, s = 1/8 and 1, misses the curve between them by 26-45%.
broken swim_mc_coarse experiments/fish/swim_mc.toml \
  "the fish swims at the requested speed within 10% over the controller's range" \
  params.swim_mc_levels=2 params.swim_mc_slowest_knob=0.125 'sweep.swim_speed_body_lengths_per_s=[0.1, 0.3]'

# Ch. 5, turns: with no water nothing turns the fish (the heading wanders with the flailing body, no
# order). At the swim rate 0.75 r_max, where the intact file orders every row (but turns 80 degrees, so the
# 90-degree check is left to the glide below); at r_max one windless row happens to rise. With the tail's
# beat stopped through the turn the fish glides round less than 90 degrees.
broken turn_no_water experiments/fish/turn.toml "a stronger turn changes the direction of travel more (r = r_max / 8)" \
  params.water_mu=0 params.swim_rate=0.05625
for c in "a stronger turn changes the direction of travel more (r = r_max / 4)" \
         "a stronger turn changes the direction of travel more (r = r_max / 2)" \
         "a quicker turn changes the direction of travel more (alpha = 1/4)" \
         "a quicker turn changes the direction of travel more (alpha = 1/2)" \
         "a quicker turn changes the direction of travel more (alpha = 3/4)" \
         "a quicker turn changes the direction of travel more (alpha = 1)"; do
  also turn_no_water "$c"
done
broken turn_glide experiments/fish/turn.toml "one strong turn (alpha = 1, r = r_max / 2) turns the fish at least 90 degrees within 3 s" \
  params.swim_during_turn=false

# Ch. 4, stability: with the units' damping 1000 times the [reimpl] gamma the step is limited by the damping,
# which the spec's matrix carries only explicitly (through n_ij), so the semi-implicit step is no longer
# beyond explicit Euler's.
broken stability_damped experiments/fish/stability.toml "the semi-implicit step is well beyond the explicit-Euler limit (>= 5x)" \
  params.damping_ns_per_m=100

# School: with no water no fish swims forward; with the explicit step at the default 2 ms every fish blows
# up (the failed points fail both checks, exit 3).
broken school_no_water experiments/fish/school.toml "the school swims forward at the default gait: at least 0.1 body lengths per second on average" \
  params.water_mu=0 'sweep.school_size=[1, 10]'
rc=0
"$bin" run experiments/fish/school.toml --out "$scratch/run_school_explicit" --jobs 2 params.scheme=explicit_euler \
  'sweep.school_size=[1, 10]' >"$scratch/school_explicit.out" 2>&1 || rc=$?
[[ $rc == 3 ]] || fail "school_explicit: exit code $rc, expected 3"
also school_explicit "no fish of the school blows up"

# Ch. 7, skin: a control net shrunk to a thousandth of the body's section (every control point near the
# axis) folds over at once.
# (The outward-normal and seam checks are broken where they are measured: tests/unit/fish_skin_test.cpp,
# a mesh with one half turned inside out, and one half moved off the other.)
broken skin_collapsed experiments/fish/skin.toml "no fold-over on any frame (no neighbouring triangles more than 90 degrees apart)" \
  params.skin_inflate=0.001 'params.schedule="swim 1"' params.export_start_s=0 params.export_frames=2 params.pov_frames=0
