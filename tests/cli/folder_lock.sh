#!/usr/bin/env bash
# One writer per run folder. Two runs with different settings into one --out at the
# same time: the second is refused with exit 2 naming the holder's pid, and the first finishes with
# an index of its own configuration only. The lock is the kernel's (fcntl): a run killed with -9
# leaves nothing that refuses the next one. --points shares of different configurations are
# refused when the index is written (configuration fingerprints), never mixed.
# usage: folder_lock.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

exp=tests/cli/strand_slow.toml  # 8 points of ~0.3 s with --jobs 1
run=$scratch/run
"$bin" run "$exp" --out "$run" --jobs 1 >"$scratch/first.stdout" 2>"$scratch/first.stderr" &
pid=$!
deadline=$((SECONDS + 60))
# Once the folder exists the first run holds it (it is created and locked in one go), before its
# first point file (~0.3 s) appears: the moment two runs both found the folder free before.
until [[ -d $run ]]; do
  kill -0 "$pid" 2>/dev/null || fail "the first run ended too soon: $(cat "$scratch/first.stderr")"
  ((SECONDS < deadline)) || { kill "$pid"; fail "no run folder after 60 s"; }
  sleep 0.05
done
kill -0 "$pid" 2>/dev/null || fail "the first run ended before the second started: make the points slower"

# The second writer, with other settings.
sleep 0.05
rc=0
"$bin" run "$exp" params.end_time_s=140 --out "$run" --jobs 1 >"$scratch/second.stdout" 2>"$scratch/second.stderr" || rc=$?
kill -0 "$pid" 2>/dev/null || echo "note: the first run ended while the second ran"
[[ $rc == 2 ]] || { kill "$pid" 2>/dev/null; fail "second writer: exit code $rc, expected 2: $(cat "$scratch/second.stderr")"; }
grep -qF "(pid $pid)" "$scratch/second.stderr" || fail "the refusal does not name the holder's pid $pid: $(cat "$scratch/second.stderr")"
grep -qF "$run" "$scratch/second.stderr" || fail "the refusal does not name the folder: $(cat "$scratch/second.stderr")"
echo "ok   second writer refused: $(cat "$scratch/second.stderr")"

wait "$pid" || fail "the first run failed: $(cat "$scratch/first.stderr")"
grep -qF "8 point(s), 8 ran, 0 reused, 0 failed" "$scratch/first.stdout" || fail "first run: $(cat "$scratch/first.stdout")"
# Every point file carries the first run's configuration (end_time_s = 150).
/usr/bin/python3 - "$run" <<'PY' || fail "the folder mixes configurations"
import sys, glob, h5py
for f in sorted(glob.glob(sys.argv[1] + "/point_*.h5")):
    with h5py.File(f, "r") as h:
        assert h.attrs["end_time_s"] == 150.0, (f, h.attrs["end_time_s"])
with h5py.File(sys.argv[1] + "/index.h5", "r") as h:
    assert len(h["sweep/point_index"]) == 8
PY

# A holder killed with -9: the kernel drops its lock; the next writer goes ahead.
"$bin" run "$exp" --out "$scratch/killed" --jobs 1 >/dev/null 2>&1 &
pid=$!
sleep 0.3
kill -9 "$pid"
wait "$pid" 2>/dev/null || true
"$bin" run tests/cli/strand_sweep.toml --out "$scratch/killed" --force --jobs 2 >/dev/null 2>"$scratch/after_kill.stderr" ||
  fail "a run after a killed holder was refused: $(cat "$scratch/after_kill.stderr")"

# --points shares with different settings into one folder: the second share refuses to list the
# first share's points (another configuration), exit 2, naming a point file.
shares=$scratch/shares
"$bin" run tests/cli/strand_sweep.toml --out "$shares" --points 0/2 --jobs 1 >/dev/null 2>&1 || fail "share 0/2"
rc=0
"$bin" run tests/cli/strand_sweep.toml params.end_time_s=1.5 --out "$shares" --points 1/2 --jobs 1 >/dev/null \
  2>"$scratch/share_mix.stderr" || rc=$?
[[ $rc == 2 ]] || fail "shares of two configurations: exit code $rc, expected 2: $(cat "$scratch/share_mix.stderr")"
grep -qE "point_00000[024]\.h5 was made by a different configuration" "$scratch/share_mix.stderr" ||
  fail "shares of two configurations: $(cat "$scratch/share_mix.stderr")"
echo "ok   shares of two configurations refused: $(cat "$scratch/share_mix.stderr")"
echo "one writer per folder; killed holders leave no lock; configurations never mix"
