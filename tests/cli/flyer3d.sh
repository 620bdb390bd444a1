#!/usr/bin/env bash
# The control_fluid3d kind end to end on experiments/control/flyer3d.toml at 16 x 8 x 16 cells over two
# 0.1 s readings (twelve frames): both cases written with the outer angles and the force per frame, the
# controlled wings moved and the held ones not; with the controller off (strength 0 in both cases) the
# two cases are one run, each ratio is exactly 1 and the §7.1 check and §3.2's two are inconclusive, never
# ok; bad input (a body outside the fluid box, a twisting model's unknown joint) exits 2 with one line naming it.
# usage: flyer3d.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status
experiment=experiments/control/flyer3d.toml
source "$(dirname "${BASH_SOURCE[0]}")/flyer3d_lib.sh"  # small, flyer3d_cases, flyer3d_off

flyer3d_cases flyer3d angle_deg_outer_r angle_deg_outer_l force_z_n_bodies pd_angle_deg_inner_r
flyer3d_off "controller off"

source "$(dirname "${BASH_SOURCE[0]}")/expect_bad.sh"
expect_bad outside_box "outside the fluid box" 'params.origin_x_m=-0.5'
expect_bad twist_joint "is not in the model" 'params.model_file=experiments/control/models/flyer3d_twist.xml' \
  'params.controlled=outer_r, tip_l' 'params.stroke_sense='
