#!/usr/bin/env bash
# The bell alone rings as one mode (experiments/jellyfish/frequency.toml: the bell first): the check fails
# with the paper's tentacles on in the bell pluck, impermeable chains on the bell's 4 mm kernel, which then ring with
# the bell (two modes; the default's porous filaments ring with it as one). On frequency_coarse's
# setting (2 mm cells at 0.0025 s, 64 segments, 3 s windows, 4 s plucks), on which the intact file passes (run
# here first); the drives and the other pluck are reused. The bell's muscle-driven checks:
# jellyfish_frequency_checks_fail.sh. About 18 s of CPU.
# usage: jellyfish_bell_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, intact, frequency_coarse, reused

frequency_coarse coarse
intact intact "$scratch/coarse.toml"
frequency_coarse tentacled "tentacles = true" "tentacle_kernel_radius_m = 0.004" "tentacle_permeability_m = 0.0" \
  "tentacle_axial_permeability_m = 0.0"
reused tentacled 0 1 2 3
broken tentacled "$scratch/tentacled.toml" "the bell alone rings as one mode (the bell pluck's one-mode fit residual at most 0.1)" \
  --resume
