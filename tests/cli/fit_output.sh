#!/usr/bin/env bash
# `fit spline` options and output: --period nan, --knots 0, a negative or NaN
# --loss-scale and a NaN bound are bad input (exit 2, nothing written; they were accepted); an
# existing output folder is kept unless --force is given (it was overwritten); the written files
# leave no temporary behind.
# usage: fit_output.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail(), expect_code

# A CSV over 3 periods of 1.2 s.
/usr/bin/python3 - "$scratch/profile.csv" <<'PY'
import sys, math
with open(sys.argv[1], "w") as out:
    out.write("time_s,value\n")
    for i in range(300):
        t = 3.6 * i / 299
        out.write(f"{t!r},{0.78 + 0.22 * math.cos(2 * math.pi * t / 1.2)!r}\n")
PY
data=$scratch/profile.csv

# bad NAME MESSAGE ARGS...: exit 2 naming the option, nothing written.
bad() {
  local name=$1 message=$2
  shift 2
  expect_code 2 "$name" "$bin" fit spline "$data" "$@" --out "$scratch/out_$name"
  grep -qF -- "$message" "$scratch/$name.err" || fail "$name: expected '$message': $(cat "$scratch/$name.err")"
  [[ ! -e $scratch/out_$name ]] || fail "$name: created its output folder"
  echo "ok   $name: $(cat "$scratch/$name.err")"
}
bad period_nan "--period" --period nan
bad period_inf "--period" --period inf
bad period_negative "--period" --period -1
bad knots_zero "--knots" --knots 0
bad knots_negative "--knots" --knots -3
bad loss_scale_negative "--loss-scale" --period 1.2 --loss huber --loss-scale -1
bad loss_scale_nan "--loss-scale" --period 1.2 --loss huber --loss-scale nan
bad lower_nan "--lower" --period 1.2 --lower nan
bad from_nan "--from" --period 1.2 --from nan

expect_code 0 first "$bin" fit spline "$data" --period 1.2 --out "$scratch/fit"
before=$(sha256sum "$scratch/fit/params.toml")
expect_code 2 again "$bin" fit spline "$data" --period 1.2 --knots 3 --out "$scratch/fit"
grep -qF -- "--force" "$scratch/again.err" || fail "the refusal does not mention --force: $(cat "$scratch/again.err")"
[[ $before == "$(sha256sum "$scratch/fit/params.toml")" ]] || fail "a refused fit changed params.toml"
expect_code 0 forced "$bin" fit spline "$data" --period 1.2 --knots 3 --out "$scratch/fit" --force
[[ $before != "$(sha256sum "$scratch/fit/params.toml")" ]] || fail "--force did not replace the fit"
[[ -z $(find "$scratch/fit" -name '*.tmp') ]] || fail "temporary files left: $(ls "$scratch/fit")"
echo "ok   an existing fit is replaced only with --force"
