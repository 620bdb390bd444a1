#!/usr/bin/env bash
# A damaged index.h5 is bad input: HDF5 keeps attributes without a checksum, so a
# flipped character in /sweep's columns_json, JSON of the wrong shape, an unknown column type and
# /sweep columns of different lengths end `check`, `compare` (either side) and `baseline` with
# exit 2 and a message naming index.h5, never an abort or a segfault. Each file is resealed after
# the edit, so the index reader itself is tested, not the seal.
# usage: damaged_index.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail(), reseal

exp=tests/cli/strand_sweep.toml  # 6 points
"$bin" run "$exp" --out "$scratch/good" --jobs 2 >/dev/null 2>&1 || fail "run failed"

# refused NAME: every reader of the index exits 2 and names it.
refused() {
  local name=$1 run=$scratch/$1
  for verb in "check $run" "compare $run $scratch/good" "compare $scratch/good $run" "baseline $run"; do
    # shellcheck disable=SC2086
    expect_code 2 "$name" "$bin" $verb
    grep -qF "$run/index.h5" "$scratch/$name.err" || fail "$name: '$verb' does not name index.h5: $(cat "$scratch/$name.err")"
  done
  echo "ok   $name: $(head -n 1 "$scratch/$name.err")"
}

# edit NAME PYTHON: a copy of the good run with index.h5 changed by PYTHON (h5py file f), resealed.
edit() {
  cp -r "$scratch/good" "$scratch/$1"
  /usr/bin/python3 -c "import h5py, numpy
with h5py.File('$scratch/$1/index.h5', 'r+') as f:
    $2" || fail "$1: h5py could not edit the index"
  reseal "$scratch/$1/index.h5"
}

# One flipped byte inside the stored attribute text (the same length: no library involved).
cp -r "$scratch/good" "$scratch/flipped"
/usr/bin/python3 - "$scratch/flipped/index.h5" <<'PY' || fail "flipped: the columns_json text was not found"
import sys
path = sys.argv[1]
data = bytearray(open(path, "rb").read())
text = b'["layout","overextension","spring_k_n_per_m"]'
assert data.count(text) == 1, data.count(text)
data[data.find(text) + 9] = ord(";")  # ["layout";"overextension",...
open(path, "wb").write(data)
PY
reseal "$scratch/flipped/index.h5"
refused flipped

edit not_a_list "f['sweep'].attrs['columns_json'] = '{\"layout\": 1}'"
refused not_a_list
edit unknown_type "f['sweep'].attrs['column_types_json'] = '{\"layout\":\"complex\",\"overextension\":\"double\",\"spring_k_n_per_m\":\"double\"}'"
refused unknown_type
edit untyped "f['sweep'].attrs['column_types_json'] = '{}'"
refused untyped
edit short_label "del f['sweep/label']; f['sweep'].create_dataset('label', data=numpy.array([b'a'], dtype=object), dtype=h5py.string_dtype())"
refused short_label
edit short_metric "del f['sweep/mid_sag_m']; f['sweep'].create_dataset('mid_sag_m', data=numpy.zeros(2))"
refused short_metric
edit short_column "del f['sweep/spring_k_n_per_m']; f['sweep'].create_dataset('spring_k_n_per_m', data=numpy.zeros(1))"
refused short_column
edit long_index "del f['sweep/point_index']; f['sweep'].create_dataset('point_index', data=numpy.arange(60))"
refused long_index
edit wrong_rank "del f['sweep/status']; f['sweep'].create_dataset('status', data=numpy.zeros((2, 3)))"
refused wrong_rank
edit bad_point_index "f['sweep/point_index'][0] = 2**40"
refused bad_point_index
echo "a damaged index.h5 is refused with exit 2 by check, compare and baseline"
