#!/usr/bin/env bash
# `base = "<path>"` in experiment files (docs/experiments.md): a missing base and a cycle exit 2 with
# the chain of files on stderr and nothing written; a study on a base runs, and `check` re-checks
# its run folder after the base file is gone (the run folder stores the merged document).
# usage: base_file.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

# expect_bad NAME PATTERN FILE: `run FILE` exits 2, one "error:" line naming PATTERN, nothing written.
expect_bad() {
  local name=$1 pattern=$2 file=$3 rc=0 out=$scratch/out_$1
  "$bin" run "$file" --out "$out" --jobs 1 >"$scratch/$name.stdout" 2>"$scratch/$name.stderr" || rc=$?
  [[ $rc == 2 ]] || { cat "$scratch/$name.stderr" >&2; fail "$name: exit code $rc, expected 2"; }
  [[ $(wc -l <"$scratch/$name.stderr") == 1 ]] || { cat "$scratch/$name.stderr" >&2; fail "$name: expected one line"; }
  grep -qF -- "error: $pattern" "$scratch/$name.stderr" || fail "$name: stderr lacks '$pattern': $(cat "$scratch/$name.stderr")"
  [[ ! -e $out ]] || fail "$name: created $out"
  echo "ok   $name: $(cat "$scratch/$name.stderr")"
}

mkdir -p "$scratch/studies" "$scratch/claims"
printf 'base = "../claims/gone.toml"\n[params]\ndt_s = 0.01\n' >"$scratch/studies/missing.toml"
expect_bad missing "$scratch/studies/missing.toml -> $scratch/claims/gone.toml: base file not found" \
  "$scratch/studies/missing.toml"

printf 'base = "../claims/loop.toml"\n' >"$scratch/studies/loop.toml"
printf 'base = "../studies/loop.toml"\nkind = "oscillator"\n' >"$scratch/claims/loop.toml"
expect_bad cycle "$scratch/studies/loop.toml -> $scratch/claims/loop.toml -> $scratch/studies/loop.toml: base cycle" \
  "$scratch/studies/loop.toml"

# A study on a claim: runs, stem of its own, and re-checks without the claim file.
cat >"$scratch/claims/claim.toml" <<'TOML'
kind = "oscillator"
[params]
end_time_s = 1.0
[sweep]
dt_s = [0.01, 0.02]
[[check]]
name = "rk4 error small"
type = "range"
metric = "max_abs_error_m"
expect = [0, 1e-3]
TOML
printf 'base = "../claims/claim.toml"\n[params]\nend_time_s = 0.5\n' >"$scratch/studies/study.toml"
rc=0
"$bin" run "$scratch/studies/study.toml" --out "$scratch/run" --jobs 1 >"$scratch/run.stdout" 2>"$scratch/run.stderr" || rc=$?
[[ $rc == 0 ]] || { cat "$scratch/run.stderr" >&2; fail "study run: exit code $rc"; }
grep -qF "rk4 error small" "$scratch/run.stdout" || fail "study run: the base's check is not in the table"
[[ -f $scratch/run/index.h5 ]] || fail "study run: no index.h5"
mv "$scratch/claims/claim.toml" "$scratch/claims/claim.moved"
rc=0
"$bin" check "$scratch/run" >"$scratch/check.stdout" || rc=$?
[[ $rc == 0 ]] || fail "check after the base is gone: exit code $rc"
grep -qF "rk4 error small" "$scratch/check.stdout" || fail "check: the base's check is not in the table"
rc=0
"$bin" run "$scratch/studies/study.toml" --out "$scratch/run" --resume >/dev/null 2>"$scratch/resume.stderr" || rc=$?
[[ $rc == 2 ]] || fail "--resume without the base file: exit code $rc, expected 2"
grep -qF "$scratch/studies/study.toml -> $scratch/claims/claim.toml: base file not found" "$scratch/resume.stderr" ||
  fail "--resume: no chain: $(cat "$scratch/resume.stderr")"
mv "$scratch/claims/claim.moved" "$scratch/claims/claim.toml"
rc=0
"$bin" run "$scratch/studies/study.toml" --out "$scratch/run" --resume >/dev/null 2>"$scratch/resume.stderr" || rc=$?
[[ $rc == 0 ]] || { cat "$scratch/resume.stderr" >&2; fail "--resume: exit code $rc"; }
echo "ok   study run, check without the base, --resume"
