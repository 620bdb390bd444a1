#!/usr/bin/env bash
# Fig. 4's check that the bell swims by its muscles (Rudolf & Mould 2009 §3.3, experiments/jellyfish/
# stagger.toml) fails with the muscle tension zero: on 2 mm cells at 0.0025 s, 64 segments and 3 s,
# a setting on which the intact file passes too (run here first: unison moves 1.4 mm a cycle). The
# membrane's checks: jellyfish_membrane_checks_fail.sh. About 12 s of CPU.
# usage: jellyfish_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, study

coarse=(params.cells=125 params.dt_s=0.0025 params.duration_s=3 params.bell_segments=64 params.store_fields=false)
"$bin" run experiments/jellyfish/stagger.toml --out "$scratch/run_stagger_intact" --jobs 2 "${coarse[@]}" \
  >"$scratch/stagger_intact.out" 2>&1 || fail "stagger_intact: exit code $?, expected 0"
[[ $(status stagger_intact "unison expansion still moves forward") == ok ]] ||
  { cat "$scratch/stagger_intact.out" >&2; fail "stagger_intact: 'unison expansion still moves forward' is not ok"; }
echo "ok   stagger_intact: 'unison expansion still moves forward' passes on the coarse setting"
# With the muscle tension zero the unison bell does not move forward (round-off).
broken stagger_no_muscles experiments/jellyfish/stagger.toml "unison expansion still moves forward" \
  "${coarse[@]}" params.muscle_tension_n_per_m2=0
