# Sourced by the disk-full tests: small_tmpfs SIZE empties the scratch folder and mounts a tmpfs of SIZE
# (e.g. 200k) at $scratch/small, unmounted on exit; without mount rights it exits 77 (ctest's
# SKIP_RETURN_CODE) with the reason. Uses bin, src, scratch set by the test; defines fail().
set -euo pipefail
cd "$src"
fail() { echo "FAIL: $*" >&2; exit 1; }
small_tmpfs() {
  small=$scratch/small
  if mountpoint -q "$small" 2>/dev/null; then umount "$small"; fi
  rm -rf "$scratch"
  mkdir -p "$small"
  if ! mount -t tmpfs -o size="$1" tmpfs "$small" 2>"$scratch/mount.stderr"; then
    echo "skip: cannot mount a small tmpfs here ($(id -un): $(cat "$scratch/mount.stderr"))"
    exit 77
  fi
  trap 'umount "$small" 2>/dev/null || true' EXIT
}
