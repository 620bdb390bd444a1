#!/usr/bin/env bash
# Fig. 5's checks (Rudolf & Mould 2009 §3.3, experiments/jellyfish/frequency.toml) fail with the bell's
# muscles off in its driven cases (the pluck that measures the natural frequency kept): on 2 mm cells at
# twice the step, 64 segments, 3 s windows, at 0.6 and 0.7 Hz with a 4 s pluck, a setting on which the
# intact file passes (run here first; its speed peaks at 0.7 Hz, 1.18 f_n, its stroke at 0.6 Hz). About
# 18 s of CPU in all.
# usage: jellyfish_frequency_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, study

study coarse experiments/jellyfish/frequency.toml <<'TOML'
[params]
cells = 125
dt_s = 0.0025
duration_s = 3.0
bell_segments = 64
[[case]]
label = "drive 0.6 Hz"
active_cycles = 0
contraction_hz = 0.6
[[case]]
label = "drive 0.7 Hz"
active_cycles = 0
contraction_hz = 0.7
[[case]]
label = "pluck"
active_cycles = 1
pulse_duration_s = 0.1
muscle_tension_n_per_m2 = 20.0
contraction_hz = 1.0
warmup_cycles = 0.0
duration_s = 4.0
TOML
"$bin" run "$scratch/coarse.toml" --out "$scratch/run_intact" --jobs 2 >"$scratch/intact.out" 2>&1 ||
  { cat "$scratch/intact.out" >&2; fail "intact: exit code $?, expected 0"; }
echo "ok   intact: every check passes on the coarse setting"
# Muscles off in the driven cases (the pluck sets its own tension): the bell moves and strokes by round-off,
# and the range checks fail.
broken no_muscles "$scratch/coarse.toml" "every driven bell swims forward (whole cycles' mean speed above 0.1 mm/s, 0.3-1 Hz)" \
  params.muscle_tension_n_per_m2=0
also no_muscles "every driven bell strokes (stroke amplitude above 0.1, 0.3-1 Hz)"
