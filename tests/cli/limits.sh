#!/usr/bin/env bash
# Counts that cannot wrap (§9): a sweep of 2^64 points (four axes of 65,536 values)
# overflowed the point count to 0 and ran as an empty sweep; 2^48 points; `--points` shares beyond
# an int wrapped and ran the whole run; an override value of several lines was cut at its first
# line. Each is now bad input: exit 2, one message, nothing written.
# usage: limits.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail(), expect_code

exp=tests/cli/strand_sweep.toml
axis=1:65536:1  # 65,536 values
# refused NAME MESSAGE ARGS...: `run ARGS --out OUT` exits 2, says MESSAGE and writes nothing.
refused() {
  local name=$1 message=$2
  shift 2
  expect_code 2 "$name" "$bin" run "$@" --out "$scratch/$name"
  grep -qF -- "$message" "$scratch/$name.err" || fail "$name: expected '$message': $(cat "$scratch/$name.err")"
  [[ ! -e $scratch/$name ]] || fail "$name: wrote $scratch/$name"
  echo "ok   $name: $(head -n 1 "$scratch/$name.err")"
}
four_axes=("sweep.n_springs=\"$axis\"" "sweep.end_time_s=\"$axis\"" "sweep.lagrangian_interval_s=\"$axis\""
           "sweep.mass_kg=[1e-8]" "sweep.spring_k_n_per_m=\"$axis\"")
refused sweep_2e64 "points" tests/cli/strand_slow.toml "${four_axes[@]}"
refused sweep_2e64_cases "points" "$exp" "${four_axes[@]}"
refused sweep_2e48 "points" "$exp" "sweep.n_springs=\"$axis\"" "sweep.end_time_s=\"$axis\"" "sweep.spring_k_n_per_m=\"$axis\""
expect_code 2 show_2e64 "$bin" show "$exp" "${four_axes[@]}"
for share in 0/4294967297 4294967296/4294967297 0/99999999999999999999 1/-4294967295; do
  refused "points_${share//\//_}" "--points" "$exp" --points "$share"
done
refused multiline "one line" "$exp" $'params.end_time_s=1.5\nparams.n_springs=3'
refused multiline_cr "one line" "$exp" $'params.end_time_s=1.5\rparams.n_springs=3'
