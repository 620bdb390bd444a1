#!/usr/bin/env bash
# Leftovers and signals. A stale *.tmp in a run folder is removed by --resume; SIGINT
# and SIGTERM mid-sweep stop the run (exit 130 / 143, as before) leaving no temporary file, every
# point file whole and an index.h5 that lists them; --resume then finishes the run.
# usage: interrupt.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

exp=tests/cli/strand_slow.toml  # 8 points of ~0.3 s with --jobs 1
total=8
count_points() { find "$1" -maxdepth 1 -name 'point_*.h5' 2>/dev/null | wc -l; }

# interrupt SIGNAL CODE: a run with 2 workers, signalled once 2 point files exist.
interrupt() {
  local sig=$1 code=$2 run=$scratch/$1
  # Job control on: a background job of a script otherwise starts with SIGINT ignored.
  set -m
  "$bin" run "$exp" --out "$run" --jobs 2 >"$run.stdout" 2>"$run.stderr" &
  local pid=$!
  set +m
  local deadline=$((SECONDS + 60)) rc=0
  while (($(count_points "$run") < 2)); do
    kill -0 "$pid" 2>/dev/null || fail "$sig: the run ended before it could be signalled"
    ((SECONDS < deadline)) || { kill -9 "$pid"; fail "$sig: no 2 point files after 60 s"; }
    sleep 0.02
  done
  kill "-$sig" "$pid"
  wait "$pid" || rc=$?
  [[ $rc == "$code" ]] || fail "$sig: exit code $rc, expected $code: $(cat "$run.stderr")"
  [[ -z $(find "$run" -name '*.tmp') ]] || fail "$sig: temporary files left: $(ls "$run")"
  local n
  n=$(count_points "$run")
  ((n >= 2 && n < total)) || fail "$sig: $n point files: the signal did not land mid-sweep"
  for f in "$run"/point_*.h5; do h5dump -H "$f" >/dev/null || fail "$sig: $f is not whole"; done
  # The index lists exactly the point files present, the rest as missing.
  /usr/bin/python3 - "$run" "$n" <<'PY' || fail "$sig: the index does not match the point files"
import sys, h5py
with h5py.File(sys.argv[1] + "/index.h5", "r") as f:
    status = [s.decode() for s in f["sweep/status"][()]]
    assert status.count("ok") == int(sys.argv[2]), status
    assert len(status) == 8, status
PY
  grep -qF "interrupted by SIG$sig" "$run.stderr" || fail "$sig: no message: $(cat "$run.stderr")"
  echo "ok   $sig: exit $rc with $n of $total point files and a consistent index"
  "$bin" run "$exp" --out "$run" --jobs 2 --resume >"$run.resume.stdout" 2>/dev/null || fail "$sig: --resume failed"
  grep -qF "$total point(s), $((total - n)) ran, $n reused, 0 failed" "$run.resume.stdout" ||
    fail "$sig: --resume: $(cat "$run.resume.stdout")"
}
interrupt INT 130
interrupt TERM 143

# A stale temporary file (a crash mid-write) does not survive --resume.
run=$scratch/stale
"$bin" run tests/cli/strand_sweep.toml --out "$run" --jobs 2 >/dev/null 2>&1 || fail "stale: first run failed"
rm "$run/point_000002.h5"
echo "half a file" >"$run/point_000002.h5.tmp"
echo "half an index" >"$run/index.h5.tmp"
echo "half a render" >"$run/point_000004_render.png.tmp"
"$bin" run tests/cli/strand_sweep.toml --out "$run" --jobs 2 --resume >/dev/null 2>"$scratch/stale.stderr" ||
  fail "stale: --resume failed: $(cat "$scratch/stale.stderr")"
[[ -z $(find "$run" -name '*.tmp') ]] || fail "stale temporary files survived --resume: $(ls "$run")"
grep -qF "removed 3 temporary file(s)" "$scratch/stale.stderr" || fail "stale: $(cat "$scratch/stale.stderr")"
echo "ok   stale temporaries removed by --resume"
