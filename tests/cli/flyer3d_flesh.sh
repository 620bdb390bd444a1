#!/usr/bin/env bash
# The driven flyer wrapped in flesh (control_fluid3d, flesh = true; Lentine et al. 2010 Fig. 13) end to
# end on experiments/control/flyer3d_flesh.toml at 16 x 8 x 16 cells over two 0.1 s readings (twelve
# frames): both cases written, the flesh's vertices the markers, the controlled wings moved and the held
# ones not; the breaking test: with the controller off (strength 0 in both cases) each ratio is exactly 1
# and the §7.1 check and §3.2's two are inconclusive, never ok; bad input (a zero flesh thickness, the flesh
# outside the box) exits 2 with one line naming it.
# usage: flyer3d_flesh.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status
experiment=experiments/control/flyer3d_flesh.toml
source "$(dirname "${BASH_SOURCE[0]}")/flyer3d_lib.sh"  # small, flyer3d_cases, flyer3d_off

flyer3d_cases flyer3d_flesh
flyer3d_off "controller off with flesh"

source "$(dirname "${BASH_SOURCE[0]}")/expect_bad.sh"
expect_bad thickness "flesh_thickness_m" 'params.flesh_thickness_m=0.0'
expect_bad outside_box "outside the fluid box" 'params.origin_x_m=-0.5'
