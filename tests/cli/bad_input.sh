#!/usr/bin/env bash
# Bad input: malformed TOML, unknown key, wrong type, out of range, unknown kind, empty
# sweep or range, an output folder that cannot be created, a folder that already holds a run, bad
# overrides. Each: exit code 2, exactly one "error:" line on stderr naming the problem, nothing on
# stdout, and nothing written.
# usage: bad_input.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()


# expect_bad NAME PATTERN FILE [ARGS...]: `run FILE ARGS --out OUT` must be refused, where OUT is
# $bad_out if set, else scratch/out_NAME.
expect_bad() {
  local name=$1 pattern=$2 file=$3
  shift 3
  local out=${bad_out:-$scratch/out_$name} err=$scratch/$name.stderr std=$scratch/$name.stdout rc=0
  "$bin" run "$file" "$@" --out "$out" --jobs 1 >"$std" 2>"$err" || rc=$?
  [[ $rc == 2 ]] || { cat "$err" >&2; fail "$name: exit code $rc, expected 2"; }
  [[ $(wc -l <"$err") == 1 ]] || { cat "$err" >&2; fail "$name: expected one line on stderr"; }
  grep -q '^error: ' "$err" || fail "$name: stderr does not start with 'error: ': $(cat "$err")"
  grep -qF -- "$pattern" "$err" || fail "$name: stderr does not name the problem ('$pattern'): $(cat "$err")"
  [[ ! -s $std ]] || fail "$name: wrote to stdout: $(cat "$std")"
  [[ ! -e $out ]] || fail "$name: created $out"
  echo "ok   $name: $(cat "$err")"
}

# write NAME: the experiment text on stdin, to scratch/NAME.toml
write() { cat >"$scratch/$1.toml"; }

write malformed <<'EOF'
kind = "strand"
[params
n_springs = 3
EOF
expect_bad malformed "$scratch/malformed.toml:2:" "$scratch/malformed.toml"
grep -q "malformed TOML" "$scratch/malformed.stderr" || fail "malformed: no 'malformed TOML'"

write unknown_key <<'EOF'
kind = "strand"
[params]
n_sprngs = 3
EOF
expect_bad unknown_key "unknown parameter 'n_sprngs'" "$scratch/unknown_key.toml"
grep -qF "did you mean 'n_springs'" "$scratch/unknown_key.stderr" || fail "unknown_key: no suggestion"
grep -qF "$scratch/unknown_key.toml:3" "$scratch/unknown_key.stderr" || fail "unknown_key: no file:line"

write unknown_top <<'EOF'
kind = "strand"
[sweeps]
n_springs = [3]
EOF
expect_bad unknown_top "unknown key 'sweeps'" "$scratch/unknown_top.toml"
grep -qF "did you mean 'sweep'" "$scratch/unknown_top.stderr" || fail "unknown_top: no suggestion"

write wrong_type <<'EOF'
kind = "strand"
[params]
n_springs = "ten"
EOF
expect_bad wrong_type 'params.n_springs: got "ten", expected an integer' "$scratch/wrong_type.toml"

write out_of_range <<'EOF'
kind = "strand"
[params]
mass_kg = 5.0
EOF
expect_bad out_of_range "params.mass_kg: got 5, expected a value in [1e-15, 1]" "$scratch/out_of_range.toml"

# A kernel radius that is no whole number of the grid's reach (3 mm on 2 mm cells) is refused
# before any point runs: a grid study must refine one body.
write kernel_radius <<'EOF'
kind = "jellyfish"
[params]
domain_m = 0.4
cells = 200
kernel = "bilinear"
kernel_radius_m = 0.003
EOF
expect_bad kernel_radius "kernel_radius_m = 0.003 m must be a whole multiple" "$scratch/kernel_radius.toml"

write unknown_kind <<'EOF'
kind = "jelyfish_xyz"
EOF
expect_bad unknown_kind "unknown kind 'jelyfish_xyz'" "$scratch/unknown_kind.toml"

write empty_sweep <<'EOF'
kind = "oscillator"
[sweep]
dt_s = []
EOF
expect_bad empty_sweep "sweep.dt_s: empty sweep axis" "$scratch/empty_sweep.toml"

write empty_range <<'EOF'
kind = "oscillator"
[sweep]
dt_s = "0.5:0.1:0.1"
EOF
expect_bad empty_range 'range "0.5:0.1:0.1" is empty' "$scratch/empty_range.toml"

write bad_check <<'EOF'
kind = "oscillator"
[sweep]
dt_s = [0.01, 0.02]
[[check]]
name = "c"
type = "argmin"
metric = "max_abs_error_m"
axis = "integrator"
expect = "rk4"
EOF
expect_bad bad_check "axis 'integrator' is not swept" "$scratch/bad_check.toml"

write both_span <<'EOF'
kind = "strand"
[params]
span_m = 0.2
n_springs = 10
EOF
expect_bad both_span "set span_m or n_springs, not both" "$scratch/both_span.toml"

# Refused before any point runs.
write duplicate_label <<'EOF'
kind = "strand"
[[case]]
label = "rest"
overextension = 1.0
[[case]]
label = "rest"
overextension = 1.5
EOF
expect_bad duplicate_label '"rest" is already the label of case[0]' "$scratch/duplicate_label.toml"
grep -qF "case[1].label" "$scratch/duplicate_label.stderr" || fail "duplicate_label: does not name case[1].label"

write where_value <<'EOF'
kind = "oscillator"
[sweep]
dt_s = [0.01, 0.02]
[[check]]
name = "small step"
type = "range"
metric = "max_abs_error_m"
where = { dt_s = 0.03 }
expect = [0, 1]
EOF
expect_bad where_value "check 'small step': where = {dt_s=0.03}: no point has dt_s = 0.03 (dt_s takes 0.01, 0.02)" \
  "$scratch/where_value.toml"

write where_label <<'EOF'
kind = "strand"
[[case]]
label = "rest"
overextension = 1.0
[[check]]
name = "sag"
type = "range"
metric = "mid_sag_m"
where = { label = "reset" }
expect = [0, 1]
EOF
expect_bad where_label 'no point has label = "reset" (label takes "rest")' "$scratch/where_label.toml"

write ratio_key <<'EOF'
kind = "oscillator"
[sweep]
dt_s = [0.01, 0.02]
[[check]]
name = "ratio"
type = "ratio"
metric = "max_abs_error_m"
numerator = { dt_s = 0.02 }
denominator = { label = "none" }
expect = [0, 10]
EOF
expect_bad ratio_key 'denominator = {label="none"}: no point has label = "none" (the file has no [[case]] labels)' "$scratch/ratio_key.toml"

# Explicit Euler at dt_s = "auto" picks 1.25e-7 s: refused with the estimate unless --allow-long.
write euler_auto <<'EOF'
kind = "strand"
[params]
integrator = "euler"
EOF
expect_bad euler_auto 'point 0 would take about 1.2e+08 time steps (dt = 1.25e-07 s (dt_s = "auto" for euler)' \
  "$scratch/euler_auto.toml"
grep -qF -- "--allow-long" "$scratch/euler_auto.stderr" || fail "euler_auto: does not mention --allow-long"
"$bin" run "$scratch/euler_auto.toml" --allow-long --dry-run >/dev/null 2>&1 || fail "euler_auto: --allow-long still refused"

# A point whose stored fields cannot fit in memory: refused before it starts, never killed by the
# kernel half-way (4096^2 cells x 1e6 stored frames: about 670 TB, more than any machine has).
write memory <<'EOF'
kind = "fluid"
[params]
cells = 4096
end_time_s = 1000.0
output_interval_s = 0.001
EOF
expect_bad memory "of memory but" "$scratch/memory.toml"
grep -qF "point 0 needs about" "$scratch/memory.stderr" || fail "memory: does not name the point: $(cat "$scratch/memory.stderr")"
grep -qF "4096^2 cells" "$scratch/memory.stderr" || fail "memory: does not say how: $(cat "$scratch/memory.stderr")"

# A folder where a file is expected says so.
mkdir -p "$scratch/a_folder"
expect_bad folder_as_file "$scratch/a_folder: is a folder; expected an experiment file" "$scratch/a_folder"

# A good file, refused for its overrides.
write good <<'EOF'
kind = "oscillator"
[params]
end_time_s = 0.5
[sweep]
dt_s = [0.01, 0.02]
EOF
expect_bad bad_override_key "unknown parameter 'dt'" "$scratch/good.toml" params.dt=0.1
expect_bad bad_override_value "sweep.dt_s: got -1" "$scratch/good.toml" "sweep.dt_s=[-1]"
expect_bad bad_override_syntax "expected dotted.key=value" "$scratch/good.toml" params.dt_s
expect_bad missing_file "$scratch/nope.toml: no such experiment file" "$scratch/nope.toml"

# An output folder that cannot be created: its parent is a regular file. (Tests run as root, so a
# chmod 555 folder would still be writable.)
echo "a file" >"$scratch/afile"
bad_out=$scratch/afile/run expect_bad unwritable "$scratch/afile is not a folder" "$scratch/good.toml"
bad_out=$scratch/afile/deeper/run expect_bad unwritable_deep "$scratch/afile is not a folder" "$scratch/good.toml"
[[ $(cat "$scratch/afile") == "a file" ]] || fail "unwritable: the file was changed"

# A folder that already holds a run is neither replaced nor mixed without --resume/--force.
"$bin" run "$scratch/good.toml" --out "$scratch/done" --jobs 1 >/dev/null 2>&1 || fail "good run failed"
before=$(cd "$scratch/done" && ls -l --time-style=+%s.%N && sha256sum ./*)
rc=0
"$bin" run "$scratch/good.toml" --out "$scratch/done" --jobs 1 >"$scratch/again.stdout" 2>"$scratch/again.stderr" || rc=$?
[[ $rc == 2 ]] || fail "existing run: exit code $rc, expected 2"
[[ $(wc -l <"$scratch/again.stderr") == 1 ]] || fail "existing run: expected one stderr line"
grep -qF "already holds a run" "$scratch/again.stderr" || fail "existing run: $(cat "$scratch/again.stderr")"
[[ $before == "$(cd "$scratch/done" && ls -l --time-style=+%s.%N && sha256sum ./*)" ]] || fail "existing run: files changed"
echo "ok   existing run: $(cat "$scratch/again.stderr")"

# A file where a run folder is expected, and a folder where a file is expected, say so.
rc=0
"$bin" check "$scratch/good.toml" >/dev/null 2>"$scratch/check_file.stderr" || rc=$?
[[ $rc == 2 ]] || fail "check FILE: exit code $rc"
grep -qF "$scratch/good.toml: is a file; expected a run folder" "$scratch/check_file.stderr" || fail "$(cat "$scratch/check_file.stderr")"
rc=0
"$bin" show "$scratch/a_folder" >/dev/null 2>"$scratch/show_folder.stderr" || rc=$?
[[ $rc == 2 ]] || fail "show FOLDER: exit code $rc"
grep -qF "is a folder; expected an experiment file" "$scratch/show_folder.stderr" || fail "$(cat "$scratch/show_folder.stderr")"

# The same errors from `show` (nothing to write, but the same message and exit code).
rc=0
"$bin" show "$scratch/wrong_type.toml" >"$scratch/show.stdout" 2>"$scratch/show.stderr" || rc=$?
[[ $rc == 2 ]] || fail "show: exit code $rc"
grep -qF 'expected an integer' "$scratch/show.stderr" || fail "show: $(cat "$scratch/show.stderr")"

# An unknown option is a usage error: exit code 2.
rc=0
"$bin" run "$scratch/good.toml" --no-such-option >/dev/null 2>&1 || rc=$?
[[ $rc == 2 ]] || fail "unknown option: exit code $rc"

echo "all bad-input cases refused"
