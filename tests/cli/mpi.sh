#!/usr/bin/env bash
# MPI (the jellyfish too): `mpirun -np 3 creaturelab run FILE --jobs 1` spreads the points over the ranks,
# each writing its own point files and rank 0 the index, and gives the same digests as the threaded
# run. Exits 77 (ctest SKIP_RETURN_CODE) when mpirun is missing or the binary was built without MPI.
# usage: mpi.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

if ! command -v mpirun >/dev/null; then
  echo "skip: mpirun not found"
  exit 77
fi
# (ldd's output is captured first: `ldd | grep -q` under pipefail fails when grep exits early.)
if [[ $(ldd "$bin") != *libmpi* ]]; then
  echo "skip: $bin was built without MPI (ldd shows no libmpi)"
  exit 77
fi
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

exp=tests/cli/strand_sweep.toml  # 6 points: 2 per rank
points=6

"$bin" run "$exp" --out "$scratch/threads" --jobs 2 >/dev/null 2>&1 || fail "threaded run failed"
"$bin" digest "$scratch/threads" >"$scratch/threads.digest"

timeout 120 mpirun --allow-run-as-root --oversubscribe -np 3 "$bin" run "$exp" --out "$scratch/mpi" --jobs 1 \
  >"$scratch/mpi.stdout" 2>"$scratch/mpi.stderr" || { cat "$scratch/mpi.stderr" >&2; fail "mpirun failed"; }
cat "$scratch/mpi.stdout"
# Each rank ran its own share: one progress line per point over all ranks.
[[ $(grep -c ' done in ' "$scratch/mpi.stderr") == "$points" ]] || fail "expected $points finished points: $(cat "$scratch/mpi.stderr")"
# Only rank 0 reports.
[[ $(grep -c "point(s)" "$scratch/mpi.stdout") == 1 ]] || fail "expected one summary line: $(cat "$scratch/mpi.stdout")"
"$bin" digest "$scratch/mpi" >"$scratch/mpi.digest"
[[ $(wc -l <"$scratch/mpi.digest") == $((points + 1)) ]] || fail "missing point files: $(cat "$scratch/mpi.digest")"
diff "$scratch/threads.digest" "$scratch/mpi.digest" || fail "the MPI run differs from the threaded run"

# Rank 0 wrote an index that the checks can read.
"$bin" check "$scratch/mpi" >/dev/null || fail "checks of the MPI run failed"

echo "mpirun -np 3 gives the threaded run's digests ($points points)"

# The jellyfish: a 3-point frequency sweep on the 50² grid, one point per rank.
cat >"$scratch/jf.toml" <<TOML
kind = "jellyfish"
title = "three short strokes"
[params]
cells = 50
$jellyfish_earlier_defaults
duration_s = 1.0
[sweep]
contraction_hz = [0.8, 1.0, 1.2]
TOML
"$bin" run "$scratch/jf.toml" --out "$scratch/jf_threads" --jobs 2 >/dev/null 2>&1 || fail "threaded jellyfish run failed"
timeout 120 mpirun --allow-run-as-root --oversubscribe -np 3 "$bin" run "$scratch/jf.toml" --out "$scratch/jf_mpi" \
  --jobs 1 >/dev/null 2>"$scratch/jf_mpi.stderr" || { cat "$scratch/jf_mpi.stderr" >&2; fail "mpirun jellyfish failed"; }
diff <("$bin" digest "$scratch/jf_threads") <("$bin" digest "$scratch/jf_mpi") || fail "MPI jellyfish differs from threads"
echo "mpirun -np 3 gives the threaded jellyfish digests (3 points)"
