#!/usr/bin/env bash
# Every check that decides an orb-web paper claim (A. Mehla, Modeling and Animation of Orb Webs, MSc thesis
# 2005) fails when the mechanism the claim rests on is broken: the claim file is run with one mechanism
# off (Provot's strain limit, the wind, the drag, ...) through overrides or a study on it, and the check
# must then be FAIL in the table with exit code 1. Runs are shortened only where the check still resolves.
# usage: web_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, study

# early NAME CHECK: CHECK's settling times in run NAME are all below 1 s: the web settled too soon, a value
# a run cut short could not give (it has no finite settling time).
early() {
  grep -F "$2" "$scratch/$1.out" |
    grep -Eq "FAIL +settling_time_s in \[5, 10\] +(0\.[0-9]+|\[0\.[0-9]+, 0\.[0-9]+\] over [0-9]+ points)$" ||
    fail "$1: '$2' did not settle within the first second"
  echo "ok   $1: settled within the first second"
}

# Fig. 5.2: with Provot off, the "constrained" strand is the free one: it sags as much and stretches 12%.
study no_provot experiments/web/strand_layouts.toml <<'TOML'
[[case]]
label = "rest layout (Fig. 5.1)"
layout = "rest"
overextension = 0.0

[[case]]
label = "rest layout + Provot 2% (Fig. 5.2)"
layout = "rest"
overextension = 0.0
provot = false
provot_max_strain = 0.02

[[case]]
label = "rest layout + Provot 2%, exact finish"
layout = "rest"
overextension = 0.0
provot = false
provot_max_strain = 0.02
provot_exact = true
TOML
broken no_provot_sag "$scratch/no_provot.toml" "Provot's strand sags as a chain 2% over rest (Fig. 5.2)"
[[ $(status no_provot_sag "Provot's strain limit holds within 0.5% strain after every step") == FAIL ]] || fail "no_provot: the strain-limit check did not fail"
[[ $(status no_provot_sag "Provot's strand settles, faster than the free one (0.5-5 s)") == FAIL ]] ||
  fail "no_provot: the Provot settling check did not fail"
for check in "with the exact finish the 2% limit holds to round-off after every step" \
  "with the exact finish the strand hangs as the chain 2% over rest"; do
  [[ $(status no_provot_sag "$check") == FAIL ]] || fail "no_provot: '$check' did not fail"
done
# The sweeps alone (no exact finish) leave springs over the limit: 2.4% after 100 sweeps (in the first
# second after the release).
study sweeps_only experiments/web/strand_layouts.toml <<'TOML'
[params]
end_time_s = 1.0
[[case]]
label = "rest layout (Fig. 5.1)"
layout = "rest"
overextension = 0.0

[[case]]
label = "rest layout + Provot 2% (Fig. 5.2)"
layout = "rest"
overextension = 0.0
provot = true
provot_max_strain = 0.02

[[case]]
label = "rest layout + Provot 2%, exact finish"
layout = "rest"
overextension = 0.0
provot = true
provot_max_strain = 0.02
provot_passes = 100
TOML
broken sweeps_only "$scratch/sweeps_only.toml" "with the exact finish the 2% limit holds to round-off after every step"

# Figs. 5.1 and §5.1: the 5-10 s settle is the air drag's (it damps the release as exp(-t / 2 s)): twenty
# times the drag settles every strand twenty times sooner, in 0.45-0.52 s; laid at rest whatever the
# over-extension says, the sag cannot fall.
broken strand_heavy_drag experiments/web/strand_layouts.toml "thesis parameters settle within 5-10 s (§5.1)" \
  params.drag_ns_per_m=2e-7 params.end_time_s=0.8
early strand_heavy_drag "thesis parameters settle within 5-10 s (§5.1)"
# The dynamic settle ends on the static solve's equilibrium because the drag takes the release's energy
# out; without drag, over the claim's whole 15 s, the free strands still swing 2-48% off their static sags
# (the rest layout and 75% over; the Provot cases, which the file's other checks name, 0.1 s long).
study strand_no_drag experiments/web/strand_layouts.toml <<'TOML'
[params]
drag_ns_per_m = 0.0
[[case]]
label = "rest layout (Fig. 5.1)"
layout = "rest"
overextension = 0.0
[[case]]
label = "over-extended 75%"
layout = "overextended"
overextension = 0.75
[[case]]
label = "rest layout + Provot 2% (Fig. 5.2)"
layout = "rest"
overextension = 0.0
provot = true
end_time_s = 0.1
[[case]]
label = "rest layout + Provot 2%, exact finish"
layout = "rest"
overextension = 0.0
provot = true
provot_exact = true
end_time_s = 0.1
TOML
broken strand_no_drag "$scratch/strand_no_drag.toml" "dynamic settle agrees with the static Newton solve"
study strand_all_rest experiments/web/strand_layouts.toml <<'TOML'
[params]
end_time_s = 1.0
[[case]]
label = "rest layout (Fig. 5.1)"
layout = "rest"
overextension = 0.0
[[case]]
label = "over-extended 75%"
layout = "rest"
overextension = 0.75
[[case]]
label = "rest layout + Provot 2% (Fig. 5.2)"
layout = "rest"
overextension = 0.0
provot = true
[[case]]
label = "rest layout + Provot 2%, exact finish"
layout = "rest"
overextension = 0.0
provot = true
TOML
broken strand_all_rest "$scratch/strand_all_rest.toml" "sag decreases with over-extension"

# Default web (Figs. 5.7-5.14): twenty times the drag settles it in 0.5 s; a secondary spoke from every
# frame mass gives more particles than the thesis's 5,000-7,000.
broken web_heavy_drag experiments/web/default.toml "settles within 5-10 s (thesis §5.1)" \
  params.drag_ns_per_m=2e-7 params.end_time_s=0.8
early web_heavy_drag "settles within 5-10 s (thesis §5.1)"
# The dynamic web and the static solve carry the same forces (the inward frame force is in both): started
# on the statics it stays there (1.4e-11 off after 1 s). A force the dynamics has and the statics lacks, the
# calibrated wind, moves the hub 36% of its sag off them.
broken web_wind_static experiments/web/default.toml "dynamic hub sag within 0.5% of the static equilibrium" \
  params.start=static params.end_time_s=1.0 params.wind_scale=0.03
broken web_dense experiments/web/default.toml "particle count within the thesis text's 5,000-7,000 (ch. 3)" \
  params.secondary_spoke_stride=1 params.end_time_s=0.0
# The silk check is a known deviation on the default web (KNOWN) and passes on a web 0.6 times the size.
silk="silk length within the thesis's 20-60 m (ch. 3)"
[[ $(status web_dense "$silk") == KNOWN ]] || fail "web_dense: the silk check is not KNOWN"
rc=0
"$bin" run experiments/web/default.toml --out "$scratch/run_web_small" --jobs 1 params.frame_scale=0.6 \
  params.end_time_s=0.0 >"$scratch/web_small.out" 2>&1 || rc=$?
[[ $(status web_small "$silk") == ok ]] || { cat "$scratch/web_small.out" >&2; fail "web_small: the silk check is not ok"; }
echo "ok   web_small: '$silk' passes at 0.6 of the size"

# Wind (Figs. 5.45-5.47), over the first 2 s, on which the intact file passes both checks (52.7 mm, ratio
# 2.009): with the wind off the hub stays put.
study no_wind experiments/web/wind.toml <<'TOML'
[params]
end_time_s = 2.0
lagrangian_interval_s = 1.0
[[case]]
label = "calibrated wind"
wind_scale = 0.0
[[case]]
label = "twice the wind"
wind_scale = 0.0
TOML
broken no_wind "$scratch/no_wind.toml" "the hub sways 50-60 mm rms under the calibrated wind"
# The sway doubles with WIND because the web answers the calibrated wind linearly, its sway small against
# its size (53 mm of about 1 m). Ten times that wind sways it a quarter to half a metre, where its changing
# shape makes the answer nonlinear: twice the wind sways it 1.85 times as far.
study wind_nonlinear experiments/web/wind.toml <<'TOML'
[params]
end_time_s = 2.0
lagrangian_interval_s = 1.0
[[case]]
label = "calibrated wind"
wind_scale = 0.3
[[case]]
label = "twice the wind"
wind_scale = 0.6
TOML
broken wind_nonlinear "$scratch/wind_nonlinear.toml" "the sway doubles with WIND"

# Figs. 5.17-5.38: every variant's settling rests on the air drag (exp(-t / 2 s)): twenty times the drag
# settles each in 0.45-0.53 s. As on the default web, a shape started on its statics stays there (the
# triangle 1.0e-11 off after 1 s) until the calibrated wind, which the statics lack, moves it 19% off.
broken sizes_heavy_drag experiments/web/sizes.toml "every size settles within 5-10 s" \
  params.drag_ns_per_m=2e-7 params.end_time_s=0.8
early sizes_heavy_drag "every size settles within 5-10 s"
broken shapes_heavy_drag experiments/web/shapes.toml "every shape settles within 5-10 s" \
  params.drag_ns_per_m=2e-7 params.end_time_s=0.8
early shapes_heavy_drag "every shape settles within 5-10 s"
broken shapes_wind_static experiments/web/shapes.toml "every shape's dynamic hub sag matches its statics within 2%" \
  params.start=static params.end_time_s=1.0 params.wind_scale=0.03 'sweep.frame_shape=["triangle"]'
for claim in spiral_spacing spoke_spacing combined; do
  broken ${claim}_heavy_drag experiments/web/$claim.toml "every variant settles within 5-10 s" \
    params.drag_ns_per_m=2e-7 params.end_time_s=0.8
  early ${claim}_heavy_drag "every variant settles within 5-10 s"
done

# Fig. 5.33: a secondary spoke leaves every stride-th inner-frame mass, so spreading the masses spreads the
# spokes; with the stride cut as the placement grows (about 120 mm of frame per spoke) the count holds.
study spokes_same_spacing experiments/web/spoke_spacing.toml <<'TOML'
[params]
end_time_s = 0.0
[[case]]
label = "Fig. 5.29 (preset)"
frame_rest_length_m = 0.015
frame_placement_m = 0.020
secondary_spoke_stride = 6
[[case]]
label = "Fig. 5.30"
frame_rest_length_m = 0.025
frame_placement_m = 0.030
secondary_spoke_stride = 4
[[case]]
label = "Fig. 5.31"
frame_rest_length_m = 0.035
frame_placement_m = 0.040
secondary_spoke_stride = 3
[[case]]
label = "Fig. 5.32"
frame_rest_length_m = 0.050
frame_placement_m = 0.057
secondary_spoke_stride = 2
TOML
broken spokes_same_spacing "$scratch/spokes_same_spacing.toml" "spokes fall as the frame masses spread"

# Figs. 6.10-6.18: with nothing scoring above the threshold nothing is cut and the letters hold as much
# spiral as the web around them; without the cross-hatch the letters are empty, not denser.
study charlotte_no_cut experiments/web/charlotte.toml <<'TOML'
[params]
resettle = "static"
renders = false
[[case]]
label = "plain"
threshold = 10
[[case]]
label = "cross_hatch"
emphasis = "none"
TOML
broken charlotte_no_cut "$scratch/charlotte_no_cut.toml" "plain PIG: the letters hold much less spiral than the web around them"
[[ $(status charlotte_no_cut "cross-hatch: the letters hold more silk than the web around them (Fig. 6.12)") == FAIL ]] ||
  fail "charlotte_no_cut: the cross-hatch check did not fail"
# A 61-pixel dilation spills the cut far off the letters.
study charlotte_spill experiments/web/charlotte.toml <<'TOML'
[params]
renders = false
resettle_time_s = 0.5
dilation_px = 61
[[case]]
label = "plain"
[[case]]
label = "cross_hatch"
emphasis = "cross_hatch"
TOML
broken charlotte_spill "$scratch/charlotte_spill.toml" \
  "segments are removed where the target is: at least 90% of them have their middle on it"
# The resettle's 5-10 s is the air drag's (exp(-t / 2 s) for 10 ug masses): twenty times the drag settles
# both webs in 0.47-0.48 s, too soon (the same times over the claim's 12 s as over the 1 s run here).
settle="the web settles again in 5-10 s, as the thesis's webs do (§5.1)"
study charlotte_heavy_drag experiments/web/charlotte.toml <<'TOML'
[params]
renders = false
drag_ns_per_m = 2e-7
resettle_time_s = 1.0
[[case]]
label = "plain"
[[case]]
label = "cross_hatch"
emphasis = "cross_hatch"
TOML
broken charlotte_heavy_drag "$scratch/charlotte_heavy_drag.toml" "$settle"
early charlotte_heavy_drag "$settle"

# Figs. 5.19-5.23: with no spring constant cut, no family elongates and none more than another (the
# static equilibria are compared: end_time_s = 0).
study no_cut experiments/web/spring_constants.toml <<'TOML'
[params]
end_time_s = 0.0
[[case]]
label = "original (Fig. 5.19)"
[[case]]
label = "outer frame k / 10 (Fig. 5.20)"
[[case]]
label = "inner frame k / 10 (Fig. 5.21)"
[[case]]
label = "radial k / 10 (Fig. 5.22)"
TOML
broken no_cut "$scratch/no_cut.toml" "cutting the outer-frame k elongates the outer frame"
for check in "cutting the inner-frame k elongates the inner frame" "cutting the radial k elongates the radials" \
  "outer frame elongates relatively more than the inner frame" "inner frame elongates relatively more than the radials"; do
  [[ $(status no_cut "$check") == FAIL ]] || fail "no_cut: '$check' did not fail"
done

# Fig. 5.17: the radii come from the inner-frame masses (a secondary spoke from every stride-th one); with
# the primary spokes alone, set by the frame's corners, the count no longer follows the size.
broken sizes_primary_only experiments/web/sizes.toml "radii decrease as the web shrinks" \
  params.secondary_spoke_stride=1000 params.end_time_s=0.0
# Fig. 5.17's spiral falls because the spacings are set for the full-size web. A web scaled as a whole
# (every placement and rest length with the frame: 0.4-1.0) keeps its spiral: 2296, 3091, 3043, 3333
# segments, not rising. The claim's own check, copied from sizes.toml, on four such cases.
"$bin" list web >"$scratch/web_params.txt"
/usr/bin/python3 - "$src/experiments/web/sizes.toml" "$scratch/web_params.txt" >"$scratch/sizes_self_similar.toml" <<'PY'
import sys
import tomllib
claim = tomllib.load(open(sys.argv[1], "rb"))
check = next(c for c in claim["check"] if c["name"] == "spiral decreases as the web shrinks")
print('kind = "web"\ntitle = "Fig. 5.17 with every spacing scaled with the web"\n[params]\nend_time_s = 0.0')
keys = [f"{strand}_{what}_m" for strand in ("spiral", "spoke", "frame", "outer_frame")
        for what in ("placement", "rest_length")]
full = {}  # the kind's defaults (`creaturelab list web`: "name unit default VALUE range ...")
for line in open(sys.argv[2]):
    words = line.split()
    if words and words[0] in keys:
        full[words[0]] = float(words[words.index("default") + 1])
assert len(full) == len(keys), full
for scale in claim["sweep"]["frame_scale"]:
    print(f'[[case]]\nlabel = "scaled {scale}"\nframe_scale = {scale}')
    for key, value in full.items():
        print(f"{key} = {value * scale!r}")
print("[[check]]")
for key, value in check.items():
    print(f"{key} = {value!r}".replace("'", '"'))
PY
broken sizes_self_similar "$scratch/sizes_self_similar.toml" "spiral decreases as the web shrinks"
# Fig. 5.38: as in Fig. 5.33, the stride cut as the frame masses spread keeps the spokes' spacing.
study combined_same_spacing experiments/web/combined.toml <<'TOML'
[params]
end_time_s = 0.0
[[case]]
label = "Fig. 5.34 (preset)"
spoke_rest_length_m = 0.003
spoke_placement_m = 0.007
frame_rest_length_m = 0.015
frame_placement_m = 0.020
secondary_spoke_stride = 6

[[case]]
label = "Fig. 5.35"
spoke_rest_length_m = 0.003
spoke_placement_m = 0.009
frame_rest_length_m = 0.025
frame_placement_m = 0.030
secondary_spoke_stride = 4

[[case]]
label = "Fig. 5.36"
spoke_rest_length_m = 0.005
spoke_placement_m = 0.011
frame_rest_length_m = 0.035
frame_placement_m = 0.040
secondary_spoke_stride = 3

[[case]]
label = "Fig. 5.37"
spoke_rest_length_m = 0.007
spoke_placement_m = 0.012
frame_rest_length_m = 0.040
frame_placement_m = 0.045
secondary_spoke_stride = 3

TOML
broken combined_same_spacing "$scratch/combined_same_spacing.toml" "spokes fall row by row"

# Figs. 5.24-5.28: the spiral stops spiral_free_masses masses short of the hub, so spreading the masses
# widens the free zone; held at 42-45 mm (6, 5, 4, 3 masses) the coverage falls too little.
study spiral_same_free_zone experiments/web/spiral_spacing.toml <<'TOML'
[params]
end_time_s = 0.0
[[case]]
label = "Fig. 5.24 (preset)"
spoke_rest_length_m = 0.003
spoke_placement_m = 0.007
spiral_free_masses = 6
[[case]]
label = "Fig. 5.25"
spoke_rest_length_m = 0.003
spoke_placement_m = 0.009
spiral_free_masses = 5
[[case]]
label = "Fig. 5.26"
spoke_rest_length_m = 0.005
spoke_placement_m = 0.011
spiral_free_masses = 4
[[case]]
label = "Fig. 5.27"
spoke_rest_length_m = 0.007
spoke_placement_m = 0.015
spiral_free_masses = 3
TOML
broken spiral_same_free_zone "$scratch/spiral_same_free_zone.toml" \
  "the hub's free zone takes about 6% of the coverage at 15 mm placement"

# Figs. 5.24-5.28 and 5.38: the spiral joins the masses of neighbouring radii, so its strands follow the
# masses per radius; with more radii as the masses spread (a secondary spoke from every 4th, 3rd, 2nd, every
# inner-frame mass) the count holds (3333, 3142, 3279, 3345) and the coverage no longer falls.
study spiral_more_radii experiments/web/spiral_spacing.toml <<'TOML'
[params]
end_time_s = 0.0
[[case]]
label = "Fig. 5.24 (preset)"
spoke_rest_length_m = 0.003
spoke_placement_m = 0.007
secondary_spoke_stride = 4
[[case]]
label = "Fig. 5.25"
spoke_rest_length_m = 0.003
spoke_placement_m = 0.009
secondary_spoke_stride = 3
[[case]]
label = "Fig. 5.26"
spoke_rest_length_m = 0.005
spoke_placement_m = 0.011
secondary_spoke_stride = 2
[[case]]
label = "Fig. 5.27"
spoke_rest_length_m = 0.007
spoke_placement_m = 0.015
secondary_spoke_stride = 1
TOML
broken spiral_more_radii "$scratch/spiral_more_radii.toml" "spiral segments fall as the spoke masses spread"
also spiral_more_radii "spiral coverage falls as the spoke masses spread"
study combined_more_radii experiments/web/combined.toml <<'TOML'
[params]
end_time_s = 0.0
[[case]]
label = "Fig. 5.34 (preset)"
spoke_rest_length_m = 0.003
spoke_placement_m = 0.007
frame_rest_length_m = 0.015
frame_placement_m = 0.020
secondary_spoke_stride = 6
[[case]]
label = "Fig. 5.35"
spoke_rest_length_m = 0.003
spoke_placement_m = 0.009
frame_rest_length_m = 0.025
frame_placement_m = 0.030
secondary_spoke_stride = 3
[[case]]
label = "Fig. 5.36"
spoke_rest_length_m = 0.005
spoke_placement_m = 0.011
frame_rest_length_m = 0.035
frame_placement_m = 0.040
secondary_spoke_stride = 2
[[case]]
label = "Fig. 5.37"
spoke_rest_length_m = 0.007
spoke_placement_m = 0.012
frame_rest_length_m = 0.040
frame_placement_m = 0.045
secondary_spoke_stride = 1
TOML
broken combined_more_radii "$scratch/combined_more_radii.toml" "spiral segments fall row by row"
# The silk falls with the spiral's: of the preset's 86 m about 75 m is spiral. With the spiral's rest length
# cut to 0.01 mm (the strands still laid) the rest follows the spokes' rest / placement (3/7, 3/9, 5/11,
# 7/15): 10.9, 9.0, 11.4, 11.6 m, not falling.
broken spiral_no_silk experiments/web/spiral_spacing.toml "silk falls as the spiral thins" \
  params.spiral_rest_length_m=1e-5 params.end_time_s=0.0
