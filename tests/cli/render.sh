#!/usr/bin/env bash
# `creaturelab render` end to end: a short recorded swim becomes render.h5 (+ XDMF), a
# .glb and an OBJ per frame, bitwise the same twice; --figures draws Figs. 7, 9, 10 with POV-Ray
# (headless); bad input (a run of another kind, a point file without /lagrangian, frames outside
# the run, a crossing outline, an unknown setting, an existing output) exits 2 with one "error:"
# line and writes nothing.
# usage: render.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

cat >"$scratch/swim.toml" <<TOML
kind = "jellyfish"
title = "a short swim to render"
[params]
cells = 50
$jellyfish_earlier_defaults
contraction_hz = 1.0
warmup_cycles = 0
duration_s = 0.8
frame_rate_hz = 10.0
TOML
"$bin" run "$scratch/swim.toml" --out "$scratch/swim" >/dev/null 2>&1
small=(rings=12 segments=16 tentacles=3 tentacle_rings=4 tentacle_segments=4)
"$bin" render "$scratch/swim" "${small[@]}" -o "$scratch/a" >"$scratch/a.out"
grep -q "9 frame(s), $((2 + 2 * 11 * 16 + 3 * (2 + 4 * 4))) vertices" "$scratch/a.out" || fail "summary: $(cat "$scratch/a.out")"
"$bin" render "$scratch/swim/point_000000.h5" "${small[@]}" -o "$scratch/b" >/dev/null
[ "$(ls "$scratch/a/obj" | wc -l)" = 9 ] || fail "expected 9 OBJ frames"
cmp "$scratch/a/jellyfish.glb" "$scratch/b/jellyfish.glb" || fail "the .glb differs between two renders"
cmp "$scratch/a/obj/frame_000004.obj" "$scratch/b/obj/frame_000004.obj" || fail "an OBJ frame differs"
[ ! -e "$scratch/a.tmp" ] || fail "a.tmp left behind"
/usr/bin/python3 - "$scratch/a" "$scratch/b" <<'PY'
import sys, os, h5py, numpy as np
a = h5py.File(os.path.join(sys.argv[1], "render.h5"), "r")
b = h5py.File(os.path.join(sys.argv[2], "render.h5"), "r")
r = a["render"]
nv = 2 + 2 * 11 * 16 + 3 * (2 + 4 * 4)
assert r["positions_m"].shape == (9, nv, 3), r["positions_m"].shape
assert r["positions_m"].chunks == (1, nv, 3)
assert r["normals"].shape == (9, nv, 3)
assert r["triangles"].shape == (4 * 16 * 11 + 3 * 2 * 4 * 4, 3) and r["triangles"].dtype == np.int64
assert r["part"].shape == (nv,) and set(np.unique(r["part"][...])) == {0, 1, 2}
assert np.allclose(r["time_s"][...], np.arange(9) * 0.1) and list(r["frame_index"][...]) == list(range(9))
assert r.attrs["rings"] == 12 and r.attrs["thickness_m"] == 0.004 and r.attrs["thickness_m.unit"] == "m"
assert a.attrs["kind"] == "jellyfish_render" and a.attrs["source_point_file"].endswith("point_000000.h5")
assert np.allclose(np.linalg.norm(r["normals"][...], axis=2), 1.0)
for name in ("positions_m", "normals", "triangles", "part", "time_s", "frame_index"):
    assert a["render"][name][()].tobytes() == b["render"][name][()].tobytes(), name
x = open(os.path.join(sys.argv[1], "render.xdmf")).read()
assert x.count("<Grid Name=\"frame") == 9 and "render.h5:/render/triangles" in x
glb = open(os.path.join(sys.argv[1], "jellyfish.glb"), "rb").read()
assert glb[:4] == b"glTF" and int.from_bytes(glb[4:8], "little") == 2
PY

# Figures: POV-Ray, headless, small.
"$bin" render "$scratch/swim" "${small[@]}" --no-obj --figures --figure-scale 0.15 -o "$scratch/fig" >/dev/null
for f in fig07_disc_extrapolation fig09_variation fig10_contraction_cycle; do
  [ -s "$scratch/fig/figures/$f.png" ] || fail "no $f.png"
  [ -s "$scratch/fig/figures/$f.pov" ] || fail "no $f.pov"
done
[ ! -e "$scratch/fig/obj" ] || fail "--no-obj wrote OBJ frames"

# expect_bad NAME PATTERN ARGS...: exit 2, one "error:" line naming the problem, nothing written.
expect_bad() {
  local name=$1 pattern=$2
  shift 2
  local rc=0
  "$bin" render "$@" -o "$scratch/out_$name" >"$scratch/$name.stdout" 2>"$scratch/$name.stderr" || rc=$?
  [[ $rc == 2 ]] || { cat "$scratch/$name.stderr" >&2; fail "$name: exit code $rc, expected 2"; }
  [[ $(wc -l <"$scratch/$name.stderr") == 1 ]] || { cat "$scratch/$name.stderr" >&2; fail "$name: not one line"; }
  grep -q '^error: ' "$scratch/$name.stderr" || fail "$name: no 'error: '"
  grep -qF -- "$pattern" "$scratch/$name.stderr" || fail "$name: does not say '$pattern': $(cat "$scratch/$name.stderr")"
  [[ ! -e $scratch/out_$name && ! -e $scratch/out_$name.tmp ]] || fail "$name: wrote $scratch/out_$name"
  echo "ok   $name: $(cat "$scratch/$name.stderr")"
}
"$bin" run tests/cli/strand_sweep.toml --out "$scratch/strand" >/dev/null 2>&1
expect_bad other_kind "a run of kind 'strand'" "$scratch/strand"
/usr/bin/python3 - "$scratch" <<'PY'
import sys, shutil, h5py, numpy as np
d = sys.argv[1]
shutil.copy(d + "/swim/point_000000.h5", d + "/no_lagrangian.h5")
with h5py.File(d + "/no_lagrangian.h5", "a") as f:
    del f["lagrangian"]
shutil.copy(d + "/swim/point_000000.h5", d + "/crossing.h5")
with h5py.File(d + "/crossing.h5", "a") as f:
    m = f["lagrangian/markers_m"]
    x = m[5]
    x[3, 0] += 0.06   # marker 3 pulled across the bell in frame 5
    m[5] = x
PY
reseal "$scratch/no_lagrangian.h5" "$scratch/crossing.h5"  # edited on purpose: render reads them, not the seal
expect_bad no_lagrangian "no /lagrangian/markers_m" "$scratch/no_lagrangian.h5"
expect_bad frames_outside "--frames 0:20: the run has 9 frames (0..8)" "$scratch/swim" --frames 0:20
expect_bad crossing "frame 5" "$scratch/crossing.h5" "${small[@]}"
grep -q "crosses itself" "$scratch/crossing.stderr" || fail "crossing: $(cat "$scratch/crossing.stderr")"
expect_bad unknown_setting "did you mean 'rings'" "$scratch/swim" rngs=12
expect_bad out_of_range "segments" "$scratch/swim" segments=2
expect_bad missing "no such point file or run folder" "$scratch/nothing"
mkdir -p "$scratch/out_exists"
rc=0
"$bin" render "$scratch/swim" -o "$scratch/out_exists" >/dev/null 2>"$scratch/exists.stderr" || rc=$?
[[ $rc == 2 ]] && grep -q "already exists: pass --force" "$scratch/exists.stderr" || fail "existing output: $rc"
[ -z "$(ls "$scratch/out_exists")" ] || fail "wrote into an existing folder"
"$bin" list render >"$scratch/list_render.txt" || fail "list render exited $?"
grep -q "noise_seed" "$scratch/list_render.txt" || fail "list render: no noise_seed"

# A reproduce list's [[render]] entry renders the run under the list's --out folder, not under
# results/runs/reproduce whatever --out says.
cat >"$scratch/list.toml" <<TOML
experiments = [{ file = "$scratch/swim.toml", name = "listed_swim" }]
[[render]]
run = "listed_swim"
frames = "0:4"
settings = { rings = 12, segments = 16, tentacles = 3, tentacle_rings = 4, tentacle_segments = 4 }
TOML
"$bin" reproduce --list "$scratch/list.toml" --out "$scratch/root" >/dev/null 2>"$scratch/list.stderr" ||
  fail "reproduce with a [[render]] entry: $(tail -3 "$scratch/list.stderr")"
[ -f "$scratch/root/listed_swim/render_point_000000/jellyfish.glb" ] ||
  fail "the [[render]] entry did not render under --out: $(ls -R "$scratch/root" | head -20)"
[ "$(ls "$scratch/root/listed_swim/render_point_000000/obj" | wc -l)" = 4 ] || fail "frames = 0:4: expected 4 OBJ frames"
echo "render cli: ok"
