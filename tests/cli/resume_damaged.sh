#!/usr/bin/env bash
# --resume reuses a point file only when it is whole and unchanged: a value changed
# inside a point file, a value changed and the file's seal rewritten (the index's content digest
# still disagrees), and an object header whose HDF5 checksum fails are each recomputed, said on
# stderr, and `check` then passes with the good run's digests (before, --resume sealed the changed
# file into the index, or exited 3 asking to free space on every retry).
# usage: resume_damaged.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail(), reseal, expect_code

exp=tests/cli/strand_sweep.toml  # 6 points
"$bin" run "$exp" --out "$scratch/good" --jobs 2 >/dev/null 2>&1 || fail "run failed"
"$bin" digest "$scratch/good" | grep point_ >"$scratch/good.digest"

# recomputed NAME: check refuses the damage, --resume recomputes point 2 and says so, then all is whole.
recomputed() {
  local name=$1 run=$scratch/$1
  expect_code 2 "$name.check" "$bin" check "$run"
  expect_code 0 "$name.resume" "$bin" run "$exp" --out "$run" --resume --jobs 1
  grep -qF "point_000002.h5" "$scratch/$name.resume.err" || fail "$name: --resume did not say it recomputed point 2: $(cat "$scratch/$name.resume.err")"
  grep -qF "6 point(s), 1 ran, 5 reused, 0 failed" "$scratch/$name.resume.out" || fail "$name: $(cat "$scratch/$name.resume.out")"
  expect_code 0 "$name.recheck" "$bin" check "$run"
  "$bin" digest "$run" | grep point_ | diff "$scratch/good.digest" - || fail "$name: the resumed run differs from the good run"
  echo "ok   $name: $(head -n 1 "$scratch/$name.resume.err")"
}

edit_value() {
  /usr/bin/python3 - "$1" <<'PY' || fail "h5py could not edit $1"
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    f["timeseries/time_s"][0] = 1.0
PY
}

cp -r "$scratch/good" "$scratch/changed"
edit_value "$scratch/changed/point_000002.h5"
recomputed changed

cp -r "$scratch/good" "$scratch/resealed"
edit_value "$scratch/resealed/point_000002.h5"
reseal "$scratch/resealed/point_000002.h5"
recomputed resealed

# One byte of an object header changed: HDF5's metadata checksum fails on reading it.
cp -r "$scratch/good" "$scratch/header"
/usr/bin/python3 - "$scratch/header/point_000002.h5" <<'PY' || fail "no object header found"
import sys
path = sys.argv[1]
data = bytearray(open(path, "rb").read())
at = data.find(b"OHDR", data.find(b"OHDR") + 4)  # the second object header: not the root group's
assert at > 0
data[at + 12] ^= 0x5A
open(path, "wb").write(data)
PY
reseal "$scratch/header/point_000002.h5"
recomputed header
