# Helpers of the tests that break a claim's mechanism and see its check fail (web_checks_fail.sh,
# control_checks_fail.sh). Sourced after lib.sh: uses bin, src, scratch and fail().

# status NAME CHECK: the status column (ok, FAIL, KNOWN) of CHECK in run NAME's table.
status() {
  awk -v c="$2" 'index($0, c) == 1 { rest = substr($0, length(c) + 1); sub(/^ +/, "", rest); split(rest, f, " "); print f[1]; exit }' \
    "$scratch/$1.out"
}

# broken NAME FILE CHECK OVERRIDES...: `run FILE OVERRIDES` exits 1 and prints CHECK as FAIL.
broken() {
  local name=$1 file=$2 check=$3 rc=0
  shift 3
  "$bin" run "$file" --out "$scratch/run_$name" --jobs 2 "$@" >"$scratch/$name.out" 2>"$scratch/$name.err" || rc=$?
  [[ $rc == 1 ]] || { cat "$scratch/$name.out" "$scratch/$name.err" >&2; fail "$name: exit code $rc, expected 1"; }
  [[ $(status "$name" "$check") == FAIL ]] || { cat "$scratch/$name.out" >&2; fail "$name: '$check' is not FAIL"; }
  echo "ok   $name: '$check' fails"
}

# also NAME CHECK: CHECK is FAIL in run NAME too.
also() {
  [[ $(status "$1" "$2") == FAIL ]] || { cat "$scratch/$1.out" >&2; fail "$1: '$2' is not FAIL"; }
  echo "ok   $1: '$2' fails"
}

# study NAME BASE: a study file in the scratch folder on the claim file BASE (its body from stdin).
study() {
  { echo "base = \"$src/$2\""; cat; } >"$scratch/$1.toml"
}
