#!/usr/bin/env bash
# Real XDMF readers open what creaturelab writes: a short jellyfish swim's field sidecar
# (point_000000.xdmf) and its render's triangle-mesh series (render.xdmf), read by meshio's
# TimeSeriesReader when /usr/bin/python3 imports meshio and by ParaView's pvbatch when it is on PATH;
# counts, times and each frame's values are compared with the HDF5 (xdmf_readers.py). Exits 77
# (ctest SKIP_RETURN_CODE) with the reason when neither reader is installed.
# usage: xdmf_readers.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

pvbatch=$(command -v pvbatch || echo -)
if [[ $pvbatch == - ]] && ! /usr/bin/python3 -c "import meshio" 2>/dev/null; then
  echo "skip: no XDMF reader here: /usr/bin/python3 cannot import meshio and pvbatch is not on PATH" \
    "(apt-get install python3-meshio, paraview)"
  exit 77
fi
cat >"$scratch/swim.toml" <<TOML
kind = "jellyfish"
title = "a short swim for XDMF readers"
[params]
cells = 40
$jellyfish_earlier_defaults
contraction_hz = 1.0
warmup_cycles = 0
duration_s = 0.3
frame_rate_hz = 10.0
store_fields = true
TOML
"$bin" run "$scratch/swim.toml" --out "$scratch/swim" >/dev/null 2>&1 || fail "the swim did not run"
"$bin" render "$scratch/swim" rings=8 segments=12 tentacles=2 tentacle_rings=3 tentacle_segments=4 --no-obj --no-glb \
  -o "$scratch/render" >/dev/null || fail "the render did not run"
/usr/bin/python3 "$src/tests/cli/xdmf_readers.py" "$pvbatch" "$scratch/swim" "$scratch/render"
