#!/usr/bin/env bash
# `creaturelab reproduce` is quiet: off a terminal, one line per experiment on stderr
# ("[k/N] name: P points, wall T, ETA of the whole list ...", the ETA from the list's minutes when
# every entry lists them, else from the elapsed fraction), no line per point, and the check tables
# on stdout after every experiment. Each run folder's index.h5 holds the run's provenance
# (build_type, cpu_model, cpu_cores, started_utc, wall_s), which stays out of the digests.
# usage: reproduce_progress.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

cat >"$scratch/osc.toml" <<'TOML'
kind = "oscillator"
title = "two integrators"
[params]
end_time_s = 1.0
[sweep]
integrator = ["symplectic_euler", "rk4"]
[[check]]
name = "rk4 is the most accurate"
type = "argmin"
metric = "max_abs_error_m"
axis = "integrator"
expect = "rk4"
TOML

# No entry lists its time: the ETA from the elapsed fraction.
cat >"$scratch/plain.toml" <<TOML
experiments = [
  "$scratch/osc.toml",
  { file = "$scratch/osc.toml", name = "second", set = ["params.end_time_s=0.5"] },
]
TOML
"$bin" reproduce --list "$scratch/plain.toml" --out "$scratch/plain" --jobs 2 >"$scratch/plain.out" 2>"$scratch/plain.err" ||
  fail "reproduce exited $?: $(cat "$scratch/plain.err")"
err=$scratch/plain.err
# The two run side by side (--jobs 2): their lines come in the order they finish, numbered so.
[[ $(wc -l <"$err") == 2 ]] || fail "expected two progress lines, got: $(cat "$err")"
grep -qE '^\[1/2\] (osc|second): 2 points, wall [0-9.]+ s, ETA of the whole list [0-9.]+ s \(from the elapsed fraction\)$' "$err" ||
  fail "line 1: $(cat "$err")"
grep -qE '^\[2/2\] (osc|second): 2 points, wall [0-9.]+ s, the whole list took [0-9.]+ s$' "$err" || fail "line 2: $(cat "$err")"
[[ $(grep -c ' osc: ' "$err") == 1 && $(grep -c ' second: ' "$err") == 1 ]] || fail "not one line per experiment: $(cat "$err")"
# The check tables only after every experiment: stdout is a blank line, then the table of both runs.
[[ $(head -n 2 "$scratch/plain.out" | tail -n 1) == "== checks of every experiment" ]] ||
  fail "stdout does not start with the check tables: $(head -n 3 "$scratch/plain.out")"
grep -q "osc: rk4 is the most accurate" "$scratch/plain.out" || fail "no check of osc: $(cat "$scratch/plain.out")"
grep -q "second: rk4 is the most accurate" "$scratch/plain.out" || fail "no check of second"
grep -q "point(s)" "$scratch/plain.out" && fail "a per-experiment report line on stdout: $(cat "$scratch/plain.out")"

# Every entry lists minutes (one at a time, --jobs 1, so in order): the ETA from them, at the listed
# pace until a minute of listed time is done (4 min left after the first entry), then at the pace
# measured (these runs take well under a second, so far less than the 1 min listed for the last).
cat >"$scratch/timed.toml" <<TOML
experiments = [
  { file = "$scratch/osc.toml", name = "a", minutes = 0.5 },
  { file = "$scratch/osc.toml", name = "b", minutes = 3 },
  { file = "$scratch/osc.toml", name = "c", minutes = 1 },
]
TOML
"$bin" reproduce --list "$scratch/timed.toml" --out "$scratch/timed" --jobs 1 >"$scratch/timed.out" 2>"$scratch/timed.err" ||
  fail "reproduce (timed) exited $?: $(cat "$scratch/timed.err")"
err=$scratch/timed.err
grep -qF "== 3 experiments from $scratch/timed.toml: about 4 minutes on 2 cores" "$err" || fail "no total: $(cat "$err")"
grep -qE "^\[1/3\] a: 2 points, wall [0-9.]+ s, ETA of the whole list 4 min \(from the list's minutes\)$" "$err" ||
  fail "timed line 1: $(cat "$err")"
grep -qE "^\[2/3\] b: 2 points, wall [0-9.]+ s, ETA of the whole list [0-9.]+ s \(from the list's minutes\)$" "$err" ||
  fail "timed line 2 (the measured pace): $(cat "$err")"
grep -qE '^\[3/3\] c: ' "$err" || fail "timed line 3: $(cat "$err")"

# Provenance in the run folder, typed as the report reads it; a second run's digests are the same.
/usr/bin/python3 - "$scratch/plain/osc/index.h5" <<'PY' || fail "index.h5 provenance"
import re, sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    a = f.attrs
    for name in ("build_type", "cpu_model", "started_utc", "git_commit", "host", "compiler"):
        assert isinstance(a[name], str) and a[name], (name, a[name])
    assert isinstance(a["cpu_cores"], np.integer) and a["cpu_cores"] >= 1, a["cpu_cores"]
    assert isinstance(a["wall_s"], np.floating) and 0 < a["wall_s"] < 60, a["wall_s"]
    assert re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ", a["started_utc"]), a["started_utc"]
PY
"$bin" check "$scratch/plain/osc" >/dev/null || fail "check (verifies each point against the index) of a run with provenance"
"$bin" digest "$scratch/plain/osc" >"$scratch/d1" || fail "digest"
"$bin" run "$scratch/osc.toml" --out "$scratch/again" --force >/dev/null 2>&1 || fail "run again"
"$bin" digest "$scratch/again" >"$scratch/d2" || fail "digest again"
diff "$scratch/d1" "$scratch/d2" >/dev/null || fail "the digests differ between two runs: $(diff "$scratch/d1" "$scratch/d2")"

# A single run keeps its line per point.
grep -q "done in" <("$bin" run "$scratch/osc.toml" --out "$scratch/single" --force 2>&1 >/dev/null) ||
  fail "a single run printed no point lines"
echo "ok"
