#!/usr/bin/env bash
# Crash-safe resume with a real kill: a sweep of 8 points (~0.3 s each) runs with
# --jobs 1 in the background; once at least 2 point files exist it is killed with SIGKILL. Every
# point file left is readable, `--resume` runs only the missing points (and says how many it
# reused, leaving the finished files untouched), and the result equals an uninterrupted run's.
# usage: resume_kill.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

exp=tests/cli/strand_slow.toml
total=8
run=$scratch/killed

# The interrupted run.
"$bin" run "$exp" --out "$run" --jobs 1 >"$scratch/killed.stdout" 2>"$scratch/killed.stderr" &
pid=$!
count_points() { find "$run" -maxdepth 1 -name 'point_*.h5' 2>/dev/null | wc -l; }
deadline=$((SECONDS + 60))
while (($(count_points) < 2)); do
  kill -0 "$pid" 2>/dev/null || fail "the run ended before it could be killed: make the points slower ($(cat "$scratch/killed.stderr"))"
  ((SECONDS < deadline)) || { kill -9 "$pid"; fail "no 2 point files after 60 s"; }
  sleep 0.05
done
kill -9 "$pid"
rc=0
wait "$pid" 2>/dev/null || rc=$?
[[ $rc == 137 ]] || fail "expected the run to die of SIGKILL (137), got $rc"

done_before=$(count_points)
echo "killed with $done_before of $total point files written; left over: $(cd "$run" && ls | tr "\n" " ")"
((done_before >= 2 && done_before < total)) || fail "$done_before point files: the kill did not land mid-sweep"
[[ ! -e $run/index.h5 ]] || fail "index.h5 written by an unfinished run"

# Every point file that exists is whole: HDF5 opens it and it records a finished point.
for f in "$run"/point_*.h5; do
  h5dump -H "$f" >/dev/null || fail "$f is not readable after the kill"
  [[ $(h5dump -a /status "$f") == *'"ok"'* ]] || fail "$f does not record status ok"
done
(cd "$run" && sha256sum point_*.h5) >"$scratch/before.sha"
# A kill during a write leaves NAME.h5.tmp behind; emulate one for the last (missing) point.
echo "half a file" >"$run/point_$(printf %06d $((total - 1))).h5.tmp"

# Resume: only the missing points run.
"$bin" run "$exp" --out "$run" --jobs 2 --resume >"$scratch/resume.stdout" 2>"$scratch/resume.stderr" ||
  fail "--resume failed: $(cat "$scratch/resume.stderr")"
grep -qF "resume: $done_before point file(s) already complete, $((total - done_before)) to run" "$scratch/resume.stderr" ||
  fail "--resume did not say how many points it reused: $(cat "$scratch/resume.stderr")"
[[ $(grep -c ' done in ' "$scratch/resume.stderr") == $((total - done_before)) ]] ||
  fail "--resume ran a different number of points than were missing: $(cat "$scratch/resume.stderr")"
grep -qF "$total point(s), $((total - done_before)) ran, $done_before reused, 0 failed" "$scratch/resume.stdout" ||
  fail "unexpected summary: $(cat "$scratch/resume.stdout")"
(cd "$run" && sha256sum -c --quiet "$scratch/before.sha") || fail "--resume rewrote a finished point file"
[[ -z $(find "$run" -name '*.tmp') ]] || fail "temporary files left after --resume: $(ls "$run")"
[[ $(count_points) == "$total" ]] || fail "$(count_points) point files after --resume"

# An uninterrupted run gives the same digests.
"$bin" run "$exp" --out "$scratch/whole" --jobs 2 >/dev/null 2>&1 || fail "uninterrupted run failed"
"$bin" digest "$scratch/whole" >"$scratch/whole.digest"
"$bin" digest "$run" >"$scratch/resumed.digest"
diff "$scratch/whole.digest" "$scratch/resumed.digest" || fail "the resumed run differs from an uninterrupted run"

# Resuming a finished run runs nothing and changes nothing.
"$bin" run "$exp" --out "$run" --jobs 2 --resume >/dev/null 2>"$scratch/again.stderr" || fail "second --resume failed"
grep -qF "resume: $total point file(s) already complete, 0 to run" "$scratch/again.stderr" ||
  fail "second --resume: $(cat "$scratch/again.stderr")"
"$bin" digest "$run" | diff "$scratch/whole.digest" - || fail "a second --resume changed the run"

echo "killed after $done_before/$total points; --resume ran $((total - done_before)); digests equal"
