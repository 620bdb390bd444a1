#!/usr/bin/env bash
# Fig. 5's checks (Rudolf & Mould 2009 §3.3, experiments/jellyfish/frequency.toml) fail with the muscles off in the
# driven cases (the plucks that measure the natural frequencies kept): on frequency_coarse's setting (2 mm cells at
# 0.0025 s, 64 segments, 3 s windows; the bell with its tentacles at 0.5 and 0.6 Hz, alone at 0.7 Hz, both plucks),
# on which the intact file passes (run here first). The bell pluck's one-mode check: jellyfish_bell_checks_fail.sh.
# About 22 s of CPU in all.
# usage: jellyfish_frequency_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, intact, frequency_coarse, reused

frequency_coarse coarse
intact intact "$scratch/coarse.toml"
# Muscles off in the driven cases (the plucks set their own tension and are reused): the bell moves and strokes by
# round-off, and the range checks fail; the bell alone neither swims nor closes.
reused no_muscles 3 4
broken no_muscles "$scratch/coarse.toml" "every driven bell swims forward (whole cycles' mean speed above 0.1 mm/s, 0.3-1 Hz)" \
  params.muscle_tension_n_per_m2=0 --resume
also no_muscles "every driven bell strokes (stroke amplitude above 0.1, 0.3-1 Hz)"
also no_muscles "the bell alone swims forward at every drive frequency (whole cycles' mean speed above 0.1 mm/s, 0.3-1 Hz)"
also no_muscles "at 0.7 Hz the bell alone closes to 0.50-0.62 of its diameter (Fig. 3: 0.56)"
