#!/usr/bin/env bash
# `baseline -o` writes atomically: on a full disk it exits 2 naming the file and the
# old baseline stays whole (it was left as a 0-byte file), with no temporary file behind. Needs
# root (mount); exits 77 (ctest SKIP_RETURN_CODE) with the reason when it cannot make the filesystem.
# usage: baseline_disk_full.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
bin=$1 src=$2 scratch=$3
source "$(dirname "${BASH_SOURCE[0]}")/small_tmpfs.sh"  # fail, small_tmpfs
small_tmpfs 200k

"$bin" run tests/cli/strand_sweep.toml --out "$scratch/run" --jobs 2 >/dev/null 2>&1 || fail "run failed"
"$bin" baseline "$scratch/run" -o "$small/base.json" || fail "baseline failed"
before=$(sha256sum <"$small/base.json")
[[ -s $small/base.json ]] || fail "empty baseline"
dd if=/dev/zero of="$small/filler" bs=4k 2>/dev/null || true  # fills the disk (dd ends with ENOSPC)
rc=0
"$bin" baseline "$scratch/run" -o "$small/base.json" --rtol 0.5 2>"$scratch/full.stderr" || rc=$?
[[ $rc == 2 ]] || fail "baseline on a full disk: exit code $rc, expected 2: $(cat "$scratch/full.stderr")"
grep -qF "$small/base.json" "$scratch/full.stderr" || fail "no message naming the file: $(cat "$scratch/full.stderr")"
[[ $before == "$(sha256sum <"$small/base.json")" ]] || fail "the old baseline was changed ($(stat -c %s "$small/base.json") bytes)"
[[ -z $(find "$small" -name '*.tmp') ]] || fail "temporary files left: $(ls "$small")"
echo "ok   baseline -o on a full disk: exit 2, the old baseline whole"
