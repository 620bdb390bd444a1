#!/usr/bin/env bash
# Fuzz: a small run's files are damaged at random (a seeded list: a few bytes changed,
# a file cut short, a block zeroed) and every tool that reads a run folder (check, compare,
# digest, baseline, run --resume; one per seed, in turn) must end within 10 s with exit 0, 1, 2 or
# 3, never a signal or a hang; after --resume the run is whole again (check exits 0).
# usage: fuzz.sh CREATURELAB SOURCE_DIR SCRATCH_DIR [FIRST_SEED LAST_SEED]
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
first=${4:-1} last=${5:-200}

exp=tests/cli/strand_sweep.toml  # 6 points of ~24 KB
"$bin" run "$exp" --out "$scratch/good" --jobs 1 >/dev/null 2>&1 || fail "run failed"
files=(index.h5 point_000000.h5 point_000001.h5 point_000002.h5 point_000003.h5 point_000004.h5 point_000005.h5)
run=$scratch/run

# tool SEED WHAT ARGS...: runs creaturelab ARGS; fails on a signal, a hang or an exit code above 3.
tool() {
  local seed=$1 what=$2 rc=0
  shift 2
  timeout -k 2 10 "$bin" "$@" >"$scratch/out" 2>"$scratch/err" || rc=$?
  ((rc <= 3)) || fail "seed $seed ($damage): $what: exit code $rc (124 = hang, 128+N = signal N): $(head -c 400 "$scratch/err")"
}

for ((seed = first; seed <= last; ++seed)); do
  RANDOM=$seed
  rm -rf "$run"
  cp -r "$scratch/good" "$run"
  file=$run/${files[RANDOM % ${#files[@]}]}
  size=$(stat -c %s "$file")
  mode=$((RANDOM % 8))
  if ((mode == 0)); then  # cut short
    cut=$(((RANDOM * 32768 + RANDOM) % size))
    truncate -s "$cut" "$file"
    damage="$(basename "$file") cut to $cut bytes"
  elif ((mode == 1)); then  # 64 zero bytes
    at=$(((RANDOM * 32768 + RANDOM) % size))
    dd if=/dev/zero of="$file" bs=1 seek="$at" count=64 conv=notrunc status=none
    damage="$(basename "$file") zeroed at $at"
  else  # 1-4 bytes changed
    damage="$(basename "$file") bytes"
    for ((k = 0; k <= mode % 4; ++k)); do
      at=$(((RANDOM * 32768 + RANDOM) % size))
      printf "\\x$(printf %02x $((RANDOM % 256)))" | dd of="$file" bs=1 seek="$at" conv=notrunc status=none
      damage+=" $at"
    done
  fi
  case $((seed % 5)) in  # one tool per seed (each run of the program costs ~0.1 s of start-up)
    0) tool "$seed" check check "$run" ;;
    1) tool "$seed" compare compare "$scratch/good" "$run" ;;
    2) tool "$seed" digest digest "$run" ;;
    3) tool "$seed" baseline baseline "$run" ;;
    4)
      tool "$seed" resume run "$exp" --out "$run" --resume --jobs 1
      timeout -k 2 10 "$bin" check "$run" >/dev/null 2>"$scratch/err" ||
        fail "seed $seed ($damage): check after --resume: $(cat "$scratch/err")"
      ;;
  esac
done
echo "ok   seeds $first-$last: every tool ended with exit 0-3; --resume made each run whole"
