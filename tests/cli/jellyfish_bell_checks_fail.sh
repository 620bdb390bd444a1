#!/usr/bin/env bash
# The bell-alone checks (studies/jellyfish/bell_alone.toml: issue 59, the bell first) fail when their
# mechanism is broken: on 2 mm cells at twice the step, 64 segments, 2.5 s windows at 0.7 and 0.9 Hz and a
# 3.5 s pluck, a setting on which the intact study passes (run here first; its speed peak at 0.9 Hz stays
# a known deviation). Muscles off: the driven bell neither swims nor closes. Tentacles on: the pluck's
# ring-down is no longer one mode (the chains ring with the bell). About 20 s of CPU.
# usage: jellyfish_bell_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, study

study coarse studies/jellyfish/bell_alone.toml <<'TOML'
[params]
cells = 125
dt_s = 0.0025
duration_s = 2.5
bell_segments = 64
[[case]]
label = "drive 0.7 Hz"
active_cycles = 0
contraction_hz = 0.7
[[case]]
label = "drive 0.9 Hz"
active_cycles = 0
contraction_hz = 0.9
[[case]]
label = "pluck"
active_cycles = 1
pulse_duration_s = 0.1
muscle_tension_n_per_m2 = 20.0
contraction_hz = 1.0
warmup_cycles = 0.0
duration_s = 3.5
TOML
"$bin" run "$scratch/coarse.toml" --out "$scratch/run_intact" --jobs 2 >"$scratch/intact.out" 2>&1 ||
  { cat "$scratch/intact.out" >&2; fail "intact: exit code $?, expected 0"; }
echo "ok   intact: every check passes on the coarse setting"
broken no_muscles "$scratch/coarse.toml" \
  "the bell alone swims forward at every drive frequency (whole cycles' mean speed above 0.1 mm/s)" \
  params.muscle_tension_n_per_m2=0
also no_muscles "at 0.7 Hz the bell alone closes to 0.50-0.62 of its diameter (Fig. 3: 0.56)"
broken tentacles "$scratch/coarse.toml" "the bell alone rings as one mode (pluck's one-mode fit residual at most 0.1)" \
  params.tentacles=true
