#!/usr/bin/env bash
# check / baseline / compare round trip: run experiments/oscillator/integrators.toml,
# `check RUN` passes, a baseline written from the run compares clean, and the same baseline with
# one metric moved by 1% compares OUTSIDE with exit code 1. A check that must fail makes `run`
# and `check` exit 1.
# usage: check_compare.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

run=$scratch/run
"$bin" run experiments/oscillator/integrators.toml --out "$run" --jobs 2 >"$scratch/run.stdout" 2>/dev/null ||
  fail "run failed: $(cat "$scratch/run.stdout")"

"$bin" check "$run" >"$scratch/check.stdout" || fail "check failed: $(cat "$scratch/check.stdout")"
# A header and one line per check, every one ok (integrators.toml has 5 checks).
(($(grep -c '  ok  ' "$scratch/check.stdout") >= 5)) || fail "expected 5 passing checks: $(cat "$scratch/check.stdout")"
[[ $(grep -c '  ok  ' "$scratch/check.stdout") == $(($(wc -l <"$scratch/check.stdout") - 1)) ]] ||
  fail "not every check passed: $(cat "$scratch/check.stdout")"
grep -q 'FAIL' "$scratch/check.stdout" && fail "a check failed: $(cat "$scratch/check.stdout")"

"$bin" baseline "$run" -o "$scratch/b.json" || fail "baseline failed"
/usr/bin/python3 - "$scratch/b.json" <<'EOF'
import json, sys
b = json.load(open(sys.argv[1]))
assert b["experiment"] == "experiments/oscillator/integrators.toml", b["experiment"]
assert len(b["points"]) == 12, len(b["points"])
assert all(p["status"] == "ok" for p in b["points"])
assert "max_abs_error_m" in b["points"][0]["metrics"]
EOF
"$bin" compare "$run" "$scratch/b.json" >"$scratch/same.stdout" || fail "compare with its own baseline: $(cat "$scratch/same.stdout")"
grep -q "within tolerance" "$scratch/same.stdout" || fail "$(cat "$scratch/same.stdout")"
# A run folder is a baseline too.
"$bin" compare "$run" "$run" >/dev/null || fail "compare with itself as a folder"

# One metric moved by 1%: outside the default rtol.
/usr/bin/python3 - "$scratch/b.json" "$scratch/moved.json" <<'EOF'
import json, sys
b = json.load(open(sys.argv[1]))
b["points"][5]["metrics"]["max_abs_error_m"] *= 1.01
json.dump(b, open(sys.argv[2], "w"), indent=2)
EOF
rc=0
"$bin" compare "$run" "$scratch/moved.json" >"$scratch/moved.stdout" || rc=$?
[[ $rc == 1 ]] || fail "compare with a moved metric: exit code $rc, expected 1"
grep -q "OUTSIDE" "$scratch/moved.stdout" || fail "no OUTSIDE: $(cat "$scratch/moved.stdout")"
[[ $(grep -c "^5 .*max_abs_error_m.*OUTSIDE" "$scratch/moved.stdout") == 1 ]] ||
  fail "the moved value is not the one reported: $(cat "$scratch/moved.stdout")"

# ...but inside a per-metric tolerance of 2%.
/usr/bin/python3 - "$scratch/moved.json" "$scratch/tolerant.json" <<'EOF'
import json, sys
b = json.load(open(sys.argv[1]))
b["tolerances"]["max_abs_error_m"] = {"rtol": 0.02, "atol": 0.0}
json.dump(b, open(sys.argv[2], "w"), indent=2)
EOF
"$bin" compare "$run" "$scratch/tolerant.json" >/dev/null || fail "a 2% rtol does not cover a 1% change"

# A baseline that is not JSON: a user error.
echo "not json" >"$scratch/bad.json"
rc=0
"$bin" compare "$run" "$scratch/bad.json" >/dev/null 2>"$scratch/bad.stderr" || rc=$?
[[ $rc == 2 ]] || fail "malformed baseline: exit code $rc, expected 2"
grep -q "^error: .*bad.json" "$scratch/bad.stderr" || fail "$(cat "$scratch/bad.stderr")"

# A check that must fail does: run exits 1, and so does check.
cat >"$scratch/wrong.toml" <<'EOF'
kind = "oscillator"
[params]
end_time_s = 2.0
dt_s = 0.01
[sweep]
integrator = ["euler", "rk4"]
[[check]]
name = "euler is the most accurate (it is not)"
type = "argmin"
metric = "max_abs_error_m"
axis = "integrator"
expect = "euler"
EOF
rc=0
"$bin" run "$scratch/wrong.toml" --out "$scratch/wrong" --jobs 2 >"$scratch/wrong.stdout" 2>/dev/null || rc=$?
[[ $rc == 1 ]] || fail "a failing check: run exit code $rc, expected 1"
grep -q "FAIL" "$scratch/wrong.stdout" || fail "$(cat "$scratch/wrong.stdout")"
rc=0
"$bin" check "$scratch/wrong" >"$scratch/wrong_check.stdout" || rc=$?
[[ $rc == 1 ]] || fail "a failing check: check exit code $rc, expected 1"
grep -q 'integrator="rk4"' "$scratch/wrong_check.stdout" || fail "$(cat "$scratch/wrong_check.stdout")"

echo "check, baseline and compare agree"
