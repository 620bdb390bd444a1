#!/usr/bin/env bash
# Damaged point files are bad input, never a crash. libhdf5 itself can segfault on a
# corrupt global heap (where variable-length strings live), so every file this program writes
# carries a seal of its bytes that readers verify before libhdf5 sees the file. 36 copies of a
# point file, each with one heap object's size or index or the heap's size overwritten:
# `check` and `digest` exit 2 naming the file; on every fourth copy `run --resume` recomputes the
# point (exit 0) and the run is then whole again.
# usage: damaged_points.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail(), expect_code

exp=tests/cli/strand_sweep.toml  # 6 points
"$bin" run "$exp" --out "$scratch/good" --jobs 2 >/dev/null 2>&1 || fail "run failed"
"$bin" digest "$scratch/good" | grep point_ >"$scratch/good.digest"
mkdir "$scratch/heap"
/usr/bin/python3 - "$scratch/good/point_000001.h5" "$scratch/heap" 36 <<'PY' || fail "no global heap found"
# The global heap collection (HDF5 format spec III.E): "GCOL", version, 3 reserved bytes, the
# collection size (8 bytes); then objects: index (2), reference count (2), reserved (4), size (8),
# data padded to 8 bytes.
import os, struct, sys
src, out, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
data = open(src, "rb").read()
heap = data.find(b"GCOL")
assert heap > 0
size = struct.unpack_from("<Q", data, heap + 8)[0]
objects, at = [], heap + 16
while at + 16 <= heap + size:
    index, _, _, length = struct.unpack_from("<HHIQ", data, at)
    objects.append(at)
    if index == 0:
        break
    at += 16 + (length + 7) // 8 * 8
sizes = [0xFFFFFFFFFFFFFFFF, 0x7FFFFFFF, 1 << 40, 100000]
for i in range(n):
    copy = bytearray(data)
    obj = objects[i % len(objects)]
    what = (i // len(objects)) % 3
    if what == 0:
        struct.pack_into("<Q", copy, obj + 8, sizes[i % len(sizes)])
    elif what == 1:
        struct.pack_into("<H", copy, obj, 0xFFFF - i)
    else:
        struct.pack_into("<Q", copy, heap + 8, sizes[i % len(sizes)])
    open(os.path.join(out, "%02d.h5" % i), "wb").write(copy)
PY

for copy in "$scratch"/heap/*.h5; do
  i=$(basename "$copy" .h5) run=$scratch/heap/run$i
  cp -r "$scratch/good" "$run"
  cp "$copy" "$run/point_000001.h5"
  expect_code 2 "check$i" "$bin" check "$run"
  grep -qF "$run/point_000001.h5" "$scratch/check$i.err" || fail "check $i does not name the file: $(cat "$scratch/check$i.err")"
  expect_code 2 "digest$i" "$bin" digest "$run"
  grep -qF "$run/point_000001.h5" "$scratch/digest$i.err" || fail "digest $i does not name the file: $(cat "$scratch/digest$i.err")"
  ((10#$i % 4 == 0)) || continue  # --resume on every fourth copy (each run of the program costs ~0.1 s)
  expect_code 0 "resume$i" "$bin" run "$exp" --out "$run" --resume --jobs 1
  grep -qF "point_000001.h5" "$scratch/resume$i.err" || fail "resume $i does not say it recomputed: $(cat "$scratch/resume$i.err")"
  expect_code 0 "recheck$i" "$bin" check "$run"
  "$bin" digest "$run" | grep point_ | diff -q "$scratch/good.digest" - >/dev/null || fail "resume $i: not the good run's digests"
done
echo "ok   36 copies with a damaged global heap: check and digest exit 2 naming the file; --resume recomputes it (9 copies)"
