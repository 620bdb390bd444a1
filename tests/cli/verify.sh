#!/usr/bin/env bash
# check and compare verify the point files against index.h5: a truncated, garbage,
# swapped or rewritten point file gives exit 2 and a message naming it; --no-verify trusts the
# index as before.
# usage: verify.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

exp=tests/cli/strand_sweep.toml  # 6 points
"$bin" run "$exp" --out "$scratch/good" --jobs 2 >/dev/null 2>&1 || fail "run failed"
"$bin" check "$scratch/good" >/dev/null || fail "check of a whole run failed"
"$bin" compare "$scratch/good" "$scratch/good" >/dev/null || fail "compare of a whole run failed"

# damaged NAME FILE... : `check` and `compare` (either side) refuse, naming each file.
damaged() {
  local name=$1 run=$scratch/$1
  shift
  for verb in "check $run" "compare $run $scratch/good" "compare $scratch/good $run"; do
    local rc=0
    # shellcheck disable=SC2086
    "$bin" $verb >"$scratch/$name.stdout" 2>"$scratch/$name.stderr" || rc=$?
    [[ $rc == 2 ]] || fail "$name: '$verb': exit code $rc, expected 2: $(cat "$scratch/$name.stderr")"
    for f in "$@"; do
      grep -qF "$run/$f" "$scratch/$name.stderr" || fail "$name: '$verb' does not name $f: $(cat "$scratch/$name.stderr")"
    done
  done
  echo "ok   $name: $(tr '\n' ' ' <"$scratch/$name.stderr")"
}

cp -r "$scratch/good" "$scratch/truncated"
truncate -s 3000 "$scratch/truncated/point_000002.h5"
damaged truncated point_000002.h5

cp -r "$scratch/good" "$scratch/garbage"
head -c 24001 /dev/urandom >"$scratch/garbage/point_000004.h5"
damaged garbage point_000004.h5

cp -r "$scratch/good" "$scratch/swapped"
mv "$scratch/swapped/point_000001.h5" "$scratch/swapped/tmp.h5"
mv "$scratch/swapped/point_000003.h5" "$scratch/swapped/point_000001.h5"
mv "$scratch/swapped/tmp.h5" "$scratch/swapped/point_000003.h5"
damaged swapped point_000001.h5 point_000003.h5

# The same point, rewritten by another configuration (a run with other settings copied in).
"$bin" run "$exp" params.end_time_s=1.5 --out "$scratch/other" --jobs 2 >/dev/null 2>&1 || fail "other run failed"
cp -r "$scratch/good" "$scratch/foreign"
cp "$scratch/other/point_000005.h5" "$scratch/foreign/point_000005.h5"
damaged foreign point_000005.h5

# Same id and configuration, one stored value changed in place.
cp -r "$scratch/good" "$scratch/rewritten"
/usr/bin/python3 - "$scratch/rewritten/point_000002.h5" <<'PY' || fail "h5py could not edit the point file"
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    f["timeseries/time_s"][0] = 1.0
PY
damaged rewritten point_000002.h5

cp -r "$scratch/good" "$scratch/deleted"
rm "$scratch/deleted/point_000000.h5"
damaged deleted point_000000.h5

# --no-verify trusts the index (fast path, the behaviour before verification).
"$bin" check --no-verify "$scratch/swapped" >/dev/null || fail "check --no-verify refused"
"$bin" compare --no-verify "$scratch/swapped" "$scratch/good" >/dev/null || fail "compare --no-verify refused"
echo "damaged point files are named; --no-verify skips the check"
