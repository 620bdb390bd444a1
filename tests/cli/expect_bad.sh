# Sourced by the CLI tests (exit 2 and exit 3 expectations): expect_bad NAME PATTERN OVERRIDES... runs "$bin run $experiment
# ${small[@]} OVERRIDES" and requires exit 2, one line on stderr naming PATTERN, nothing written
# (the caller sets bin, experiment, small, scratch and fail).
expect_bad() {
  local name=$1 pattern=$2
  shift 2
  local out=$scratch/out_$name rc=0
  "$bin" run "$experiment" "${small[@]}" "$@" --out "$out" --jobs 1 >"$scratch/$name.out" \
    2>"$scratch/$name.err" || rc=$?
  [[ $rc == 2 ]] || { cat "$scratch/$name.err"; fail "$name: exit $rc, expected 2"; }
  [[ $(wc -l <"$scratch/$name.err") == 1 ]] || { cat "$scratch/$name.err"; fail "$name: expected one line"; }
  grep -qF -- "$pattern" "$scratch/$name.err" || fail "$name: does not name '$pattern': $(cat "$scratch/$name.err")"
  [[ ! -e $out ]] || fail "$name: wrote $out"
  echo "ok   $name: $(cat "$scratch/$name.err")"
}

# expect_failed_point NAME PATTERN OVERRIDES...: the run exits 3 (a point failed) and its log names PATTERN.
expect_failed_point() {
  local name=$1 pattern=$2
  shift 2
  local rc=0
  "$bin" run "$experiment" "${small[@]}" "$@" --out "$scratch/$name" --jobs 1 >"$scratch/$name.log" 2>&1 || rc=$?
  [[ $rc == 3 ]] || { cat "$scratch/$name.log"; fail "$name: exit $rc, expected 3"; }
  grep -q -- "$pattern" "$scratch/$name.log" || fail "$name: '$pattern' not named"
  echo "ok   $name: exit 3, '$pattern' named"
}
