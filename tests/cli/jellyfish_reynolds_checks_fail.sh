#!/usr/bin/env bash
# The Reynolds study's checks (studies/jellyfish/reynolds.toml: the bell alone's speed falls with Re and collapses
# below Re ~ 10, as Herschlag & Miller 2011 find for 2-D bells) fail with the muscles off: the bell then moves by
# round-off at every viscosity. On 2 mm cells at 0.0025 s, 64 segments and 3 s windows, on which the intact
# study passes (run here first).
# usage: jellyfish_reynolds_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, intact, study

study coarse studies/jellyfish/reynolds.toml <<'TOML'
[params]
cells = 125
dt_s = 0.0025
duration_s = 3.0
bell_segments = 64
TOML
intact intact "$scratch/coarse.toml"
broken no_muscles "$scratch/coarse.toml" "the bell's forward speed falls as the Reynolds number falls (the viscosity rises)" \
  params.muscle_tension_n_per_m2=0
also no_muscles "below Re = 10 the speed collapses: at Re 3.2 under a fifth of the default's (Re 25.6)"
