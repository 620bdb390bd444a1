#!/usr/bin/env bash
# The runner writes and deletes only inside its run folder, and only its own files:
# a `reproduce` entry named "../victim" (or a [[render]] run of that name) is refused before any
# run (it replaced the run in the folder above --out with --force); planted symbolic links named
# like the runner's temporary files and XDMF sidecar are removed or replaced, never written
# through (their targets outside the folder were emptied or overwritten); `--force` keeps files
# it did not write (point_notes.h5 was deleted as "point_*.h5").
# usage: containment.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail(), expect_code
snapshot() { (cd "$1" && ls -l --time-style=+ && sha256sum ./*); }

exp=tests/cli/strand_sweep.toml  # 6 points
"$bin" run "$exp" --out "$scratch/victim" --jobs 2 >/dev/null 2>&1 || fail "run failed"
victim=$(snapshot "$scratch/victim")

# §6: names from a list cannot leave --out.
list() {
  printf '%s\n' "$@" >"$scratch/list.toml"
}
for name in ../victim .. a/b "" /abs; do
  list "experiments = [{file = \"$exp\", name = \"$name\"}]"
  expect_code 2 "name" "$bin" reproduce --list "$scratch/list.toml" --out "$scratch/out"
  grep -qF "name" "$scratch/name.err" || fail "name '$name': $(cat "$scratch/name.err")"
  [[ ! -e $scratch/out ]] || fail "name '$name': wrote $(ls -R "$scratch/out")"
  [[ $victim == "$(snapshot "$scratch/victim")" ]] || fail "name '$name' changed the run above --out"
done
list "experiments = [\"$exp\"]" "[[render]]" "run = \"../victim\""
expect_code 2 "render_run" "$bin" reproduce --list "$scratch/list.toml" --out "$scratch/out"
[[ ! -e $scratch/out ]] || fail "render run '../victim': ran before refusing: $(ls -R "$scratch/out")"
[[ $victim == "$(snapshot "$scratch/victim")" ]] || fail "render run '../victim' changed the run above --out"
echo "ok   names from a reproduce list cannot leave --out"

# §7: symbolic links planted as the runner's temporaries and sidecars are never written through.
mkdir "$scratch/outside"
for f in a b c d e; do echo "keep $f" >"$scratch/outside/$f.txt"; done
cp -r "$scratch/victim" "$scratch/planted"
rm "$scratch/planted/point_000003.h5"
ln -s "$scratch/outside/a.txt" "$scratch/planted/point_000003.h5.tmp"
ln -s "$scratch/outside/b.txt" "$scratch/planted/index.h5.tmp"
ln "$scratch/outside/e.txt" "$scratch/planted/point_000004.h5.tmp"  # a hard link: the same file, another name
expect_code 0 planted "$bin" run "$exp" --out "$scratch/planted" --resume --jobs 1
for f in a b e; do
  [[ $(cat "$scratch/outside/$f.txt") == "keep $f" ]] || fail "--resume wrote through a planted link to $f.txt"
done
[[ -z $(find "$scratch/planted" -name '*.tmp') ]] || fail "planted links left: $(ls -l "$scratch/planted")"
cat >"$scratch/fluid.toml" <<'TOML'
kind = "fluid"
title = "small vortex pair"
[params]
initial = "vortex_pair"
circulation_m2_per_s = 0.01
cells = 8
end_time_s = 0.05
output_interval_s = 0.025
TOML
mkdir "$scratch/fluid"
ln -s "$scratch/outside/c.txt" "$scratch/fluid/point_000000.xdmf"
ln -s "$scratch/outside/d.txt" "$scratch/fluid/point_000000.xdmf.tmp"
expect_code 0 fluid "$bin" run "$scratch/fluid.toml" --out "$scratch/fluid" --resume --jobs 1
for f in c d; do
  [[ $(cat "$scratch/outside/$f.txt") == "keep $f" ]] || fail "a fluid run wrote its XDMF through a planted link to $f.txt"
done
[[ -f $scratch/fluid/point_000000.xdmf && ! -L $scratch/fluid/point_000000.xdmf ]] || fail "no XDMF sidecar of its own"
grep -qF "<Xdmf" "$scratch/fluid/point_000000.xdmf" || fail "the XDMF sidecar is not XDMF"
echo "ok   planted links are removed or replaced, never written through"

# §8: --force removes the runner's own files only.
cp -r "$scratch/victim" "$scratch/forced"
for f in point_notes.h5 point_1.h5 point_0000001.h5 point_000001.h5.bak index.h5.bak notes.txt; do
  echo "mine" >"$scratch/forced/$f"
done
expect_code 0 forced "$bin" run "$exp" --out "$scratch/forced" --force --jobs 2
for f in point_notes.h5 point_1.h5 point_0000001.h5 point_000001.h5.bak index.h5.bak notes.txt; do
  [[ $(cat "$scratch/forced/$f" 2>/dev/null) == mine ]] || fail "--force deleted or changed $f"
done
echo "ok   --force keeps files the runner did not write"
