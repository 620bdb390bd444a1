#!/usr/bin/env bash
# The paper model's claim checks (Rudolf & Mould 2009 §3.3; studies/jellyfish/paper_model.toml at 0.7 Hz, Fig. 5,
# and paper_model_morphology.toml, Figs. 3 and 11) fail with their mechanisms broken: the rest-length curve held at 1
# (knot1_value = 1, the muscles never shorten) leaves the bell still and open, and a bending rigidity of the default
# model's order (1e-4 N m) lets the stiff muscle springs crush it to about 0.2 of its diameter. On 2 mm cells at twice
# the step, 64 segments, a 3 s window (Fig. 11: one warm-up cycle, no tracers or fields), on which the intact files pass
# (run here first). The argmax check of Fig. 5 is a known deviation and decides nothing. About 15 s of CPU.
# usage: jellyfish_paper_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, intact, study

study coarse studies/jellyfish/paper_model.toml <<'TOML'
[params]
cells = 125
dt_s = 0.0025
duration_s = 3.0
bell_segments = 64
[[case]]
label = "drive 0.7 Hz"
tentacles = true
active_cycles = 0
contraction_hz = 0.7
TOML
forward="every driven bell swims forward (whole cycles' mean speed above 0.1 mm/s, 0.3-1 Hz)"
closes="at 0.7 Hz the bell closes to 0.50-0.62 of its diameter (Fig. 3: 0.56)"
intact intact "$scratch/coarse.toml"
broken no_contraction "$scratch/coarse.toml" "$forward" params.knot1_value=1.0
also no_contraction "$closes"
broken soft "$scratch/coarse.toml" "$closes" params.bending_rigidity_n_m=1e-4

morphology=(params.cells=125 params.dt_s=0.0025 params.bell_segments=64 params.warmup_cycles=1 params.tracers_per_side=0
            params.store_fields=false)
contracts="the bell contracts to about the paper's 0.56 of its diameter (Fig. 3)"
intact morphology_intact studies/jellyfish/paper_model_morphology.toml "${morphology[@]}"
broken morphology_soft studies/jellyfish/paper_model_morphology.toml "$contracts" "${morphology[@]}" \
  params.bending_rigidity_n_m=1e-4
