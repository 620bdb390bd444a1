#!/usr/bin/env bash
# MPI and user errors: a user error found by rank 0 alone (an output folder that
# already holds a run) must end every rank with exit code 2 instead of leaving ranks 1..N-1 in a
# barrier; an error is printed once, not once per rank; the summary counts the points of all ranks.
# Exits 77 when mpirun is missing or the binary was built without MPI.
# usage: mpi_errors.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

command -v mpirun >/dev/null || { echo "skip: mpirun not found"; exit 77; }
[[ $(ldd "$bin") == *libmpi* ]] || { echo "skip: $bin was built without MPI"; exit 77; }
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi() { timeout -k 5 30 mpirun --allow-run-as-root --oversubscribe -np 3 "$bin" "$@"; }

exp=tests/cli/strand_sweep.toml  # 6 points

# The summary line counts every rank's points.
mpi run "$exp" --out "$scratch/run" --jobs 1 >"$scratch/first.stdout" 2>/dev/null || fail "first run failed"
grep -qF "6 point(s), 6 ran, 0 reused, 0 failed" "$scratch/first.stdout" ||
  fail "summary counts only rank 0's points: $(head -1 "$scratch/first.stdout")"

# Again into the same folder without --resume: refused by rank 0; every rank must stop.
rc=0
mpi run "$exp" --out "$scratch/run" --jobs 1 >/dev/null 2>"$scratch/again.stderr" || rc=$?
[[ $rc != 124 && $rc != 137 ]] || fail "mpirun hung (killed by timeout): ranks 1-2 wait in a barrier for rank 0"
[[ $rc == 2 ]] || fail "exit code $rc, expected 2"
grep -qF "already holds a run" "$scratch/again.stderr" || fail "$(cat "$scratch/again.stderr")"

# A bad file: every rank finds the error, one reports it.
printf 'kind = "strand"\n[params]\nn_sprngs = 3\n' >"$scratch/bad.toml"
rc=0
mpi run "$scratch/bad.toml" --out "$scratch/bad" --jobs 1 >/dev/null 2>"$scratch/bad.stderr" || rc=$?
[[ $rc == 2 ]] || fail "bad file: exit code $rc, expected 2"
[[ $(grep -c '^error: ' "$scratch/bad.stderr") == 1 ]] || fail "the error is printed by every rank: $(grep '^error: ' "$scratch/bad.stderr")"
[[ ! -e $scratch/bad ]] || fail "bad file: wrote $scratch/bad"
echo "MPI errors end every rank once"
