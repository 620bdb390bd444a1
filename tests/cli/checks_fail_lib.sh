# Helpers of the tests that break a claim's mechanism and see its check fail (web_checks_fail.sh,
# control_checks_fail.sh, control_fluid_checks_fail.sh). Sourced after lib.sh: uses bin, src, scratch and fail().

# status NAME CHECK: the status column (ok, FAIL, KNOWN) of CHECK in run NAME's table.
status() {
  awk -v c="$2" 'index($0, c) == 1 { rest = substr($0, length(c) + 1); sub(/^ +/, "", rest); split(rest, f, " "); print f[1]; exit }' \
    "$scratch/$1.out"
}

# broken NAME FILE CHECK OVERRIDES...: `run FILE OVERRIDES` exits 1 and prints CHECK as FAIL.
broken() {
  local name=$1 file=$2 check=$3 rc=0
  shift 3
  "$bin" run "$file" --out "$scratch/run_$name" --jobs 2 "$@" >"$scratch/$name.out" 2>"$scratch/$name.err" || rc=$?
  [[ $rc == 1 ]] || { cat "$scratch/$name.out" "$scratch/$name.err" >&2; fail "$name: exit code $rc, expected 1"; }
  [[ $(status "$name" "$check") == FAIL ]] || { cat "$scratch/$name.out" >&2; fail "$name: '$check' is not FAIL"; }
  echo "ok   $name: '$check' fails"
}

# also NAME CHECK: CHECK is FAIL in run NAME too.
also() {
  [[ $(status "$1" "$2") == FAIL ]] || { cat "$scratch/$1.out" >&2; fail "$1: '$2' is not FAIL"; }
  echo "ok   $1: '$2' fails"
}

# broken_known NAME FILE CHECK OVERRIDES...: `run FILE OVERRIDES` prints CHECK, a check marked known_deviation, as
# KNOWN (evaluated and failed; not counted in the exit code, so the run exits 0 unless another check fails).
broken_known() {
  local name=$1 file=$2 check=$3 rc=0
  shift 3
  "$bin" run "$file" --out "$scratch/run_$name" --jobs 2 "$@" >"$scratch/$name.out" 2>"$scratch/$name.err" || rc=$?
  [[ $rc == 0 || $rc == 1 ]] || { cat "$scratch/$name.out" "$scratch/$name.err" >&2; fail "$name: exit code $rc"; }
  [[ $(status "$name" "$check") == KNOWN ]] || { cat "$scratch/$name.out" >&2; fail "$name: '$check' is not KNOWN"; }
  echo "ok   $name: '$check' fails (KNOWN)"
}

# also_known NAME CHECK: CHECK, marked known_deviation, is KNOWN (failed) in run NAME too.
also_known() {
  [[ $(status "$1" "$2") == KNOWN ]] || { cat "$scratch/$1.out" >&2; fail "$1: '$2' is not KNOWN"; }
  echo "ok   $1: '$2' fails (KNOWN)"
}

# study NAME BASE: a study file in the scratch folder on the claim file BASE (its body from stdin).
study() {
  { echo "base = \"$src/$2\""; cat; } >"$scratch/$1.toml"
}

# nudged NAME RUN CHECK METRIC LABEL: the checks of the finished run RUN re-evaluated (`check --no-verify`,
# from index.h5) after METRIC of case LABEL's parallel points (threads or fluid_threads above 1) is moved by
# one unit in the last place, the least a race between threads could change it (and index.h5 sealed again):
# exits 1, CHECK FAIL.
nudged() {
  local name=$1 run=$2 check=$3 rc=0
  /usr/bin/python3 - "$run/index.h5" "$4" "$5" <<'PY'
import hashlib
import sys

import h5py
import numpy as np
with h5py.File(sys.argv[1], "r+") as f:
    s = f["sweep"]
    labels = [x.decode() if isinstance(x, bytes) else x for x in s["label"][()]]
    parallel = s["threads"][()] > 1
    if "fluid_threads" in s:
        parallel |= s["fluid_threads"][()] > 1
    values = s[sys.argv[2]][()]
    rows = [i for i, label in enumerate(labels) if label == sys.argv[3] and parallel[i]]
    if not rows:
        sys.exit("no parallel point of " + sys.argv[3])
    for i in rows:
        values[i] = np.nextafter(values[i], np.inf)
    s[sys.argv[2]][...] = values
# The runner's seal (src/io/file_seal.hpp): the SHA-256 of every byte after the 512-byte user block.
data = open(sys.argv[1], "rb").read()
line = b"creaturelab seal sha256 " + hashlib.sha256(data[512:]).hexdigest().encode() + b"\n"
open(sys.argv[1], "r+b").write(line.ljust(512, b"\0"))
PY
  "$bin" check "$run" --no-verify >"$scratch/$name.out" 2>"$scratch/$name.err" || rc=$?
  [[ $rc == 1 ]] || { cat "$scratch/$name.out" "$scratch/$name.err" >&2; fail "$name: exit code $rc, expected 1"; }
  [[ $(status "$name" "$check") == FAIL ]] || { cat "$scratch/$name.out" >&2; fail "$name: '$check' is not FAIL"; }
  echo "ok   $name: '$check' fails"
}

# intact NAME FILE OVERRIDES...: `run FILE OVERRIDES` exits 0 (every check ok or KNOWN), the run in
# $scratch/run_NAME for a later `nudged`.
intact() {
  local name=$1 file=$2 rc=0
  shift 2
  "$bin" run "$file" --out "$scratch/run_$name" --jobs 2 "$@" >"$scratch/$name.out" 2>"$scratch/$name.err" || rc=$?
  [[ $rc == 0 ]] || { cat "$scratch/$name.out" "$scratch/$name.err" >&2; fail "$name: exit code $rc, expected 0"; }
  echo "ok   $name: the intact run passes"
}

# frequency_coarse NAME [BELL_PLUCK_LINE...]: $scratch/NAME.toml, experiments/jellyfish/frequency.toml (Fig. 5 and
# the bell alone, with its checks) on the setting its breaking tests share: 2 mm cells at 0.0025 s, 64 segments,
# 3 s windows; the bell with its tentacles driven at 0.5 and 0.6 Hz (points 0 and 1: its speed peaks at the second,
# in Fig. 5's window) and alone at 0.7 Hz (point 2), and both 4 s plucks (points 3 and 4: with the tentacles, and the
# bell pluck, tentacles = false unless BELL_PLUCK_LINE, extra TOML lines of the bell pluck's case, set it). The plucks
# set their own tension, so a run that changes only the drives' can reuse them (--resume).
frequency_coarse() {
  local name=$1 label
  shift
  {
    cat <<'TOML'
[params]
cells = 125
dt_s = 0.0025
duration_s = 3.0
bell_segments = 64
[[case]]
label = "drive 0.5 Hz"
tentacles = true
active_cycles = 0
contraction_hz = 0.5
[[case]]
label = "drive 0.6 Hz"
tentacles = true
active_cycles = 0
contraction_hz = 0.6
[[case]]
label = "bell alone 0.7 Hz"
tentacles = false
active_cycles = 0
contraction_hz = 0.7
TOML
    for label in pluck "bell pluck"; do
      printf '[[case]]\nlabel = "%s"\nactive_cycles = 1\npulse_duration_s = 0.1\n' "$label"
      printf 'muscle_tension_n_per_m2 = 20.0\ncontraction_hz = 1.0\nwarmup_cycles = 0.0\nduration_s = 4.0\n'
      if [[ $label == pluck ]]; then
        echo "tentacles = true"
      elif (($# == 0)); then
        echo "tentacles = false"
      else
        printf '%s\n' "$@"
      fi
    done
  } | study "$name" experiments/jellyfish/frequency.toml
}

# reused NAME POINT...: the intact run's ($scratch/run_intact) point files POINT (indices) copied into run NAME's
# folder, for a `broken NAME ... --resume` whose change leaves those points' configuration as it was.
reused() {
  local name=$1 p
  shift
  mkdir -p "$scratch/run_$name"
  for p in "$@"; do cp "$scratch/run_intact/$(printf 'point_%06d.h5' "$p")" "$scratch/run_$name/"; done
}

# got NAME CHECK: the got column of CHECK in run NAME's table (what the check measured).
got() {
  awk -v c="$2" '/^check +pass +expected +got$/ && !p { p = index($0, " got") + 1 } p && index($0, c) == 1 { print substr($0, p); exit }' \
    "$scratch/$1.out"
}

# argmax_at NAME CHECK AXIS VALUE: CHECK (an argmax or argmin) in run NAME found its extremum at AXIS=VALUE.
argmax_at() {
  local text
  text=$(got "$1" "$2")
  [[ $text == "$3=$4 ("* ]] || { cat "$scratch/$1.out" >&2; fail "$1: '$2' got '$text', expected it at $3=$4"; }
  echo "ok   $1: '$2' at $3=$4"
}
