#!/usr/bin/env bash
# The run folder across invocations: `--points i/N` shares (a Slurm job array) fill
# one folder and give the whole run's digests; `--force` replaces a run and drops stale points;
# `--resume` refuses point files made by a different configuration and changes nothing.
# usage: run_folder.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
snapshot() { (cd "$1" && ls && sha256sum ./*); }

exp=tests/cli/strand_sweep.toml  # 6 points
"$bin" run "$exp" --out "$scratch/whole" --jobs 2 >/dev/null 2>&1 || fail "whole run failed"
"$bin" digest "$scratch/whole" >"$scratch/whole.digest"

# Two shares, the second one first: the index is complete (and the checks run) after the last.
"$bin" run "$exp" --out "$scratch/shares" --points 1/2 --jobs 1 >"$scratch/share1.stdout" 2>/dev/null || fail "share 1/2"
grep -qF "6 point(s), 3 ran, 0 reused, 0 failed, 3 not yet run" "$scratch/share1.stdout" || fail "$(cat "$scratch/share1.stdout")"
grep -qF "checks: not evaluated" "$scratch/share1.stdout" || fail "checks evaluated on a partial run"
shared=$(cd "$scratch/shares" && echo point_*.h5)
[[ $shared == "point_000001.h5 point_000003.h5 point_000005.h5" ]] || fail "share 1/2 wrote $shared"
"$bin" run "$exp" --out "$scratch/shares" --points 0/2 --jobs 1 >"$scratch/share0.stdout" 2>/dev/null || fail "share 0/2"
grep -qF "6 point(s), 3 ran, 0 reused, 0 failed" "$scratch/share0.stdout" || fail "$(cat "$scratch/share0.stdout")"
grep -qE "stiffer springs sag less.*  ok  " "$scratch/share0.stdout" || fail "checks after the last share: $(cat "$scratch/share0.stdout")"
"$bin" digest "$scratch/shares" | diff "$scratch/whole.digest" - || fail "shares differ from the whole run"
for bad in 2/2 -1/2 1/0 x 1/2/3; do
  rc=0
  "$bin" run "$exp" --out "$scratch/badshare" --points "$bad" >/dev/null 2>"$scratch/badshare.stderr" || rc=$?
  [[ $rc == 2 ]] || fail "--points $bad: exit code $rc, expected 2"
  [[ ! -e $scratch/badshare ]] || fail "--points $bad: wrote $scratch/badshare"
done

# --resume with another configuration: refused, nothing changed.
before=$(snapshot "$scratch/whole")
rc=0
"$bin" run "$exp" params.end_time_s=1.5 --out "$scratch/whole" --resume >/dev/null 2>"$scratch/mismatch.stderr" || rc=$?
[[ $rc == 2 ]] || fail "--resume with another configuration: exit code $rc, expected 2"
grep -qF "was made by a different configuration" "$scratch/mismatch.stderr" || fail "$(cat "$scratch/mismatch.stderr")"
[[ $(wc -l <"$scratch/mismatch.stderr") == 1 ]] || fail "expected one error line: $(cat "$scratch/mismatch.stderr")"
[[ $before == "$(snapshot "$scratch/whole")" ]] || fail "a refused --resume changed the folder"

# --force with a smaller sweep: the old run is replaced, no stale point files remain.
# (exit code 1: the monotonic check needs 2 points and fails, as it should)
rc=0
"$bin" run "$exp" "sweep.spring_k_n_per_m=[0.02]" --out "$scratch/whole" --force --jobs 2 >"$scratch/force.stdout" 2>/dev/null || rc=$?
[[ $rc == 1 ]] || fail "--force: exit code $rc, expected 1 (a check of one point fails)"
grep -qF "fewer than 2 points" "$scratch/force.stdout" || fail "$(cat "$scratch/force.stdout")"
grep -qF "2 point(s), 2 ran, 0 reused" "$scratch/force.stdout" || fail "$(cat "$scratch/force.stdout")"
[[ $(ls "$scratch/whole" | tr '\n' ' ') == "index.h5 point_000000.h5 point_000001.h5 " ]] ||
  fail "--force left: $(ls "$scratch/whole")"
/usr/bin/python3 - "$scratch/whole" <<'EOF' || fail "--force: the index does not describe the new sweep"
import sys, h5py
with h5py.File(sys.argv[1] + "/index.h5", "r") as f:
    assert list(f["sweep/spring_k_n_per_m"][()]) == [0.02, 0.02]
    assert list(f["sweep/point_index"][()]) == [0, 1]
EOF

echo "shares, --force and --resume keep the run folder consistent"
