#!/usr/bin/env bash
# Runs the experiment a baseline names (with its overrides) and compares the run with it.
# usage: regress.sh CREATURELAB SOURCE_DIR BASELINE_JSON SCRATCH_DIR
set -euo pipefail
bin=$1 src=$2 baseline=$3 scratch=$4
cd "$src"
experiment=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["experiment"])' "$baseline")
mapfile -t overrides < <(/usr/bin/python3 -c 'import json,sys; [print(o) for o in json.load(open(sys.argv[1])).get("overrides", [])]' "$baseline")
rm -rf "$scratch"
"$bin" run "$experiment" "${overrides[@]}" --out "$scratch" --force --jobs 2 >/dev/null
"$bin" compare "$scratch" "$baseline"
