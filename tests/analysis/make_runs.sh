#!/bin/sh
# Small runs for the figure test (check_figures.py): one run folder per kind and per paper-figure
# run that analysis/draw_runs.py draws, each an experiment file of experiments/ with overrides that
# shrink it to a fraction of a second (coarse grids, short times, few frames; --points i/N runs a share
# of a sweep's points where one of a kind suffices). The folder names are
# the experiment files' stems, so analysis/figures/catalog.py picks the same figure modules as for
# `make reproduce`.
# usage: make_runs.sh CREATURELAB SOURCE_DIR OUT_DIR
set -eu
bin=$1
src=$2
out=$3
rm -rf "$out"
mkdir -p "$out"

# run NAME FILE OVERRIDES...: a run folder OUT/NAME; exit 1 (a failed check) is expected of runs this
# small, anything else is an error.
run() {
  name=$1
  file=$2
  shift 2
  rc=0
  "$bin" run "$src/experiments/$file" "$@" --out "$out/$name" -j 1 > "$out/$name.log" 2>&1 || rc=$?
  if [ "$rc" -ne 0 ] && [ "$rc" -ne 1 ]; then
    cat "$out/$name.log" >&2
    echo "make_runs.sh: $file exited $rc" >&2
    exit 1
  fi
}

jelly="params.cells=50 params.bell_segments=32 params.dt_s=0.005"
run integrators oscillator/integrators.toml params.end_time_s=1
run strand_layouts web/strand_layouts.toml params.end_time_s=0.2 params.lagrangian_interval_s=0.1 --points 0/2
for web in default sizes shapes spiral_spacing spoke_spacing combined; do
  run "$web" "web/$web.toml" params.end_time_s=0.2 params.lagrangian_interval_s=0.1
done
# Two of the four cases (the radial one alone takes seconds).
run spring_constants web/spring_constants.toml params.end_time_s=0.05 params.lagrangian_interval_s=0.025 --points 0/2
run wind web/wind.toml params.end_time_s=0.2 params.lagrangian_interval_s=0.05
run charlotte web/charlotte.toml params.resettle_time_s=0.05 params.canvas_px=120 --points 0/2
run taylor_green fluid/taylor_green.toml "sweep.cells=[32,64,128]" params.end_time_s=0.1 params.output_interval_s=0.05 \
  --points 0/2
run stagger jellyfish/stagger.toml $jelly params.duration_s=2
# Every third point: drives of the bell with and without tentacles, and both plucks.
run frequency jellyfish/frequency.toml $jelly params.duration_s=1.5 --points 2/3
run morphology jellyfish/morphology.toml $jelly params.warmup_cycles=1 params.tracers_per_side=10
run membrane jellyfish/membrane.toml params.duration_s=0.5 params.markers=64
"$bin" fit spline "$out/stagger" --point 0 --knots 4 --from 1.5384615384615385 --out "$out/fit_spline" \
  > "$out/fit_spline.log" 2>&1 || { cat "$out/fit_spline.log" >&2; exit 1; }
run block_wind control/block_wind.toml params.frames=30 params.average_frames=10 --points 0/2
run block_ball control/block_ball.toml params.frames=30 params.average_frames=10
run flyer_quick ../studies/control/flyer_quick.toml params.cells=32 params.frames=24 params.warmup_frames=4 \
  params.average_frames=4 params.flap_period_s=0.2 params.force_cycles=1 params.field_every_frames=12
# 96 cells: coarser grids break the swimmer's coupled stability limit (a marker moves > 1 cell a step).
run swimmer control/swimmer.toml params.cells=96 params.frames=30 params.warmup_frames=2 params.average_frames=4 \
  params.rise_cycles=1 params.cycle_s=0.4 params.field_every_frames=15
run swim fish/swim.toml 'params.schedule="swim 4"' params.warmup_s=1
run turn fish/turn.toml 'params.schedule="swim 2; left 1; swim 1"'
run air fish/air.toml 'params.schedule="swim 4"'
run school fish/school.toml 'params.schedule="swim 2"' params.warmup_s=1 "sweep.school_size=[1,3]"
run stability fish/stability.toml 'params.schedule="swim 2"' params.stable_iterations=4
run skin fish/skin.toml 'params.schedule="swim 3"' params.export_start_s=1 params.export_frames=4 params.pov_frames=0
