#!/bin/bash
# The house style of every figure (analysis/style.py): small runs of every kind and paper-figure
# experiment (make_runs.sh), then every plotter and figure module drawn on them and checked
# (check_figures.py: labelled axes with units, titles inside the canvas, fonts >= 9 pt as shown,
# a legend or colour bar where colour encodes a value). The checker first proves it can fail
# (--self-test: a figure with each fault). About 55 CPU s.
# usage: figures.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
set -euo pipefail
bin=$1
src=$2
scratch=$3
here=$(cd "$(dirname "$0")" && pwd)
cd "$src"  # model files are named relative to the source folder
/usr/bin/python3 "$here/check_figures.py" --self-test
bash "$here/make_runs.sh" "$bin" "$src" "$scratch"
# draw_web is checked on default and wind; on these web runs only their paper-figure modules (Mehla
# Figs. 5.17-5.38, each a grid of the sweep's webs).
/usr/bin/python3 "$here/check_figures.py" "$scratch" \
  --catalog-only sizes shapes spring_constants spiral_spacing spoke_spacing combined \
  --expect plot_run draw_web plot_fluid plot_jellyfish plot_membrane charlotte_sheet plot_control \
           plot_control_fluid plot_flyer plot_fish figures/rm_fig4 figures/rm_fig5 figures/rm_fig6 \
           figures/rm_fig11 figures/fit_spline figures/fluid_taylor_green figures/mehla_fig5_46
