# Sourced first by every CLI test (usage: SCRIPT CREATURELAB SOURCE_DIR SCRATCH_DIR): strict mode;
# bin, src and scratch from the arguments; the source tree as the working folder (experiment files
# are named from it); an empty scratch folder; fail MESSAGE.
set -euo pipefail
bin=$1 src=$2 scratch=$3
cd "$src"
rm -rf "$scratch"
mkdir -p "$scratch"
fail() { echo "FAIL: $*" >&2; exit 1; }
# The jellyfish kind's defaults until 2026-11-29 (the Hermite curve, hat kernel, 0.4 m box, twice
# today's step): the cheap setting the jellyfish CLI tests were written on; their [params] expand it.
jellyfish_earlier_defaults='activation_shape = "hermite"
muscle_tension_n_per_m2 = 5.0
kinematic_viscosity_m2_per_s = 1.304e-5
kernel = "bilinear"
domain_m = 0.4
dt_s = 0.00125
bell_segments = 0
force_stage = "before_advection"
box_aspect = 1.5
start_y_fraction = 0.2'
