#!/usr/bin/env bash
# Determinism (DESIGN.md): the same sweep with --jobs 1 and --jobs 2 (and a second
# --jobs 1 run) gives identical `creaturelab digest` output: every point file's datasets and
# parameters, and the index, bitwise. The digest must also notice a real change.
# usage: determinism.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

exp=tests/cli/strand_sweep.toml  # 2 cases x 3 spring constants
points=6

"$bin" run "$exp" --out "$scratch/j1" --jobs 1 >/dev/null 2>"$scratch/j1.log" || fail "--jobs 1 run failed"
"$bin" run "$exp" --out "$scratch/j2" --jobs 2 >/dev/null 2>"$scratch/j2.log" || fail "--jobs 2 run failed"
"$bin" run "$exp" --out "$scratch/j1b" --jobs 1 >/dev/null 2>&1 || fail "second --jobs 1 run failed"

"$bin" digest "$scratch/j1" >"$scratch/j1.digest"
"$bin" digest "$scratch/j2" >"$scratch/j2.digest"
"$bin" digest "$scratch/j1b" >"$scratch/j1b.digest"
[[ $(wc -l <"$scratch/j1.digest") == $((points + 1)) ]] || fail "expected $points point digests and the index: $(cat "$scratch/j1.digest")"
# 64 hex digits, then the file name.
grep -qvE '^[0-9a-f]{64}  (point_[0-9]{6}|index)\.h5$' "$scratch/j1.digest" && fail "malformed digest lines"
diff "$scratch/j1.digest" "$scratch/j2.digest" || fail "--jobs 1 and --jobs 2 differ"
diff "$scratch/j1.digest" "$scratch/j1b.digest" || fail "two --jobs 1 runs differ"
# The points really ran in parallel: with --jobs 2 the finish order is free, the results are not.
[[ $(grep -c ' done in ' "$scratch/j2.log") == "$points" ]] || fail "--jobs 2 did not report $points finished points"
# stderr is not a terminal here: plain lines, no carriage returns or escape codes.
grep -q $'[\r\033]' "$scratch/j2.log" && fail "terminal control characters in piped progress output"

# Provenance differs between the runs (times), the digest ignores it; a parameter change is seen.
"$bin" run "$exp" params.end_time_s=2.02 --out "$scratch/changed" --jobs 2 >/dev/null 2>&1 || fail "changed run failed"
"$bin" digest "$scratch/changed" >"$scratch/changed.digest"
same=$(comm -12 <(sort "$scratch/j1.digest") <(sort "$scratch/changed.digest") | wc -l)
[[ $same == 0 ]] || fail "the digest did not change with end_time_s: $same identical lines"

echo "digests identical across --jobs 1, --jobs 2 and a rerun ($points points)"
