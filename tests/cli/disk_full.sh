#!/usr/bin/env bash
# Disk full: a run into a 300 KiB tmpfs fills it while a point file is written. The
# run must end cleanly: exit 3 (never a signal: HDF5 used to close the failed file a second time at
# exit, SIGSEGV 139), a "no space left on device" message naming the point file, no temporary file
# left, and the points written before it readable and listed in index.h5. Needs root (mount);
# exits 77 (ctest SKIP_RETURN_CODE) with the reason when the machine cannot make the filesystem.
# usage: disk_full.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
bin=$1 src=$2 scratch=$3
source "$(dirname "${BASH_SOURCE[0]}")/small_tmpfs.sh"  # fail, small_tmpfs
small_tmpfs 300k

# 6 points of ~52 KB each: the sixth does not fit.
run=$small/run
rc=0
"$bin" run tests/cli/strand_sweep.toml params.end_time_s=20 --out "$run" --jobs 1 >"$scratch/run.stdout" \
  2>"$scratch/run.stderr" || rc=$?
((rc < 128)) || fail "the run ended by signal $((rc - 128)) (exit $rc): $(tail -3 "$scratch/run.stderr")"
[[ $rc == 3 ]] || fail "exit code $rc, expected 3: $(tail -3 "$scratch/run.stderr")"
grep -qE "^error: cannot write $run/point_[0-9]{6}\.h5: no space left on device" "$scratch/run.stderr" ||
  fail "no message naming the file and the cause: $(tail -3 "$scratch/run.stderr")"
[[ -z $(find "$run" -name '*.tmp') ]] || fail "temporary files left: $(ls "$run")"
n=$(find "$run" -maxdepth 1 -name 'point_*.h5' | wc -l)
((n >= 1 && n < 6)) || fail "$n point files: the disk did not fill mid-sweep"
for f in "$run"/point_*.h5; do h5dump -H "$f" >/dev/null || fail "$f is not readable"; done
/usr/bin/python3 - "$run" "$n" <<'PY' || fail "index.h5 does not list the points written"
import sys, h5py
with h5py.File(sys.argv[1] + "/index.h5", "r") as f:
    status = [s.decode() for s in f["sweep/status"][()]]
    assert status.count("ok") == int(sys.argv[2]), status
PY
! grep -qE "HDF5-DIAG|minor:" "$scratch/run.stderr" || fail "HDF5's error stack was printed: $(grep -m3 -E 'HDF5-DIAG|minor:' "$scratch/run.stderr")"
echo "ok   disk full: exit 3, $n point files kept and listed: $(grep '^error:' "$scratch/run.stderr")"

# The disk fills while index.h5 is written (every point fits, 176 KiB): exit 3 and a message, the
# points stay; once there is space again, --resume writes the index.
umount "$small"
mount -t tmpfs -o size=176k tmpfs "$small"
rc=0
"$bin" run tests/cli/strand_sweep.toml --out "$run" --jobs 1 >/dev/null 2>"$scratch/index.stderr" || rc=$?
[[ $rc == 3 ]] || fail "index on a full disk: exit code $rc, expected 3: $(tail -3 "$scratch/index.stderr")"
grep -qF "error: cannot write $run/index.h5: no space left on device" "$scratch/index.stderr" ||
  fail "index on a full disk: $(grep -v '^\[' "$scratch/index.stderr" | head -5)"
[[ $(grep -vc '^\[' "$scratch/index.stderr") == 1 ]] || fail "index on a full disk: more than one message: $(grep -v '^\[' "$scratch/index.stderr" | head -5)"
[[ -z $(find "$run" -name '*.tmp') ]] || fail "index on a full disk: temporary files left: $(ls "$run")"
[[ $(find "$run" -maxdepth 1 -name 'point_*.h5' | wc -l) == 6 ]] || fail "index on a full disk: points missing: $(ls "$run")"
mount -o remount,size=1m "$small"
"$bin" run tests/cli/strand_sweep.toml --out "$run" --jobs 1 --resume >/dev/null 2>&1 || fail "--resume after freeing space failed"
[[ -e $run/index.h5 ]] || fail "--resume after freeing space wrote no index"
echo "ok   index on a full disk: exit 3, every point kept; --resume wrote the index once there was space"
