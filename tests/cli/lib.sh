# Sourced first by every CLI test (usage: SCRIPT CREATURELAB SOURCE_DIR SCRATCH_DIR): strict mode;
# bin, src and scratch from the arguments; the source tree as the working folder (experiment files
# are named from it); an empty scratch folder; fail MESSAGE.
set -euo pipefail
bin=$1 src=$2 scratch=$3
cd "$src"
rm -rf "$scratch"
mkdir -p "$scratch"
fail() { echo "FAIL: $*" >&2; exit 1; }
# A cheap jellyfish setting for CLI tests that check the runner, not the physics (the Hermite curve,
# the bilinear kernel, a 0.4 m box at twice the default step); their [params] expand it.
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
# reseal FILE...: after a test edits a sealed file (a value changed with h5py, a flipped byte), writes
# its seal again (the first line of its 512-byte user block: "creaturelab seal sha256 <hex of every
# byte after the block>"), so what is tested is the reader's own check, not the seal. Unsealed
# files are left as they are.
reseal() {
  /usr/bin/python3 - "$@" <<'PY'
import hashlib, sys
for path in sys.argv[1:]:
    with open(path, "r+b") as f:
        data = f.read()
        if not data.startswith(b"creaturelab seal sha256 "):
            continue
        line = b"creaturelab seal sha256 " + hashlib.sha256(data[512:]).hexdigest().encode() + b"\n"
        f.seek(0)
        f.write(line + bytes(512 - len(line)))
PY
}
# expect_code CODE NAME CMD...: runs CMD (its output in $scratch/NAME.out/.err) and fails unless it
# exits with CODE within 30 s (124 = a hang, 128+N = signal N).
expect_code() {
  local code=$1 name=$2 rc=0
  shift 2
  timeout -k 5 30 "$@" >"$scratch/$name.out" 2>"$scratch/$name.err" || rc=$?
  [[ $rc == "$code" ]] || fail "$name: '$*': exit code $rc, expected $code: $(head -c 600 "$scratch/$name.err")"
}
