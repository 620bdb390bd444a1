#!/usr/bin/env bash
# The 3-D driven flyer's renders from its HDF5 alone (Lentine et al. 2010 Figs. 11, 13): a control_fluid3d
# run of experiments/control/flyer3d.toml at 16 x 8 x 16 over twelve frames with stored_fields = volume
# every fourth frame stores the fluid's fields (frames, nz, ny, nx) and every geom's pose per frame; the
# poses are MuJoCo's hinge kinematics of the recorded angles (inner wing about y at its anchor, outer wing
# at the inner angle plus its own); analysis/figures/lentine_q3d.py draws the Q-criterion strip of each
# point and passes the house style; `creaturelab creature-glb` writes the animated .glb (a node per geom,
# a translation and a rotation channel each, a key per frame); bad input exits 2 with one line.
# usage: flyer3d_render.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
experiment=experiments/control/flyer3d.toml
source "$(dirname "${BASH_SOURCE[0]}")/flyer3d_lib.sh"  # small
run=$scratch/flyer3d  # the catalog's run name: check_figures picks lentine_q3d by it

"$bin" run "$experiment" "${small[@]}" params.stored_fields=volume params.field_every=4 --out "$run" --jobs 2 \
  >"$scratch/run.out" 2>&1 || { cat "$scratch/run.out"; fail "the volume run: exit $?"; }
/usr/bin/python3 - "$run" <<'PY' || fail "flyer3d recording"
import sys, h5py, numpy as np
f = h5py.File(f"{sys.argv[1]}/point_000000.h5")
t = f["lagrangian/time_s"][()]
assert np.array_equal(t, f["timeseries/time_s"][()])
assert np.array_equal(f["fields/time_s"][()], t[[0, 4, 8]]), f["fields/time_s"][()]
for name in ("q_per_s2", "w_m_per_s", "u_m_per_s", "vorticity_magnitude_per_s"):
    assert f[f"fields/{name}"].shape == (3, 16, 8, 16), (name, f[f"fields/{name}"].shape)
assert f["fields"].attrs["origin_z_m"] == -2.0 and f["fields"].attrs["dz_m"] == 0.25
assert list(f["topology/geom_type"][()]) == [4, 6, 6, 6, 6]  # body ellipsoid, four wing plates
pos, rot = f["lagrangian/geom_position_m"][()], f["lagrangian/geom_rotation"][()].reshape(12, 5, 3, 3)
assert np.allclose(f["lagrangian/geom_size_m"][()][:, 1], [0.25, 0.15, 0.02])
def about_y(a):  # MuJoCo's hinge about +y
    return np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])
inner = np.radians(f["timeseries/pd_angle_deg_inner_r"][()])
outer = np.radians(f["timeseries/angle_deg_outer_r"][()])
assert np.ptp(inner) > 0.01 and np.ptp(outer) > 0.01, "the wings do not move"
for k in range(12):
    r_in, r_out = about_y(inner[k]), about_y(inner[k] + outer[k])
    anchor_out = np.array([0.15, 0, 0]) + r_in @ [0.5, 0, 0]
    assert np.allclose(pos[k, 1], np.array([0.15, 0, 0]) + r_in @ [0.25, 0, 0], atol=1e-9), (k, pos[k, 1])
    assert np.allclose(rot[k, 1], r_in, atol=1e-9) and np.allclose(rot[k, 2], r_out, atol=1e-9), k
    assert np.allclose(pos[k, 2], anchor_out + r_out @ [0.25, 0, 0], atol=1e-9), (k, pos[k, 2])
assert np.allclose(pos[:, 0], 0) and np.allclose(rot[:, 0], np.eye(3))  # the body is held
PY
echo "ok   flyer3d volume run: fields (3, 16, 8, 16) every fourth frame; the wings' poses are the hinges' kinematics"

/usr/bin/python3 analysis/figures/lentine_q3d.py "$run" >"$scratch/draw.out" 2>&1 || { cat "$scratch/draw.out"; fail "lentine_q3d"; }
for png in "$run"/figures/lentine_q3d.png "$run"/figures/lentine_q3d_1.png; do
  [[ $(head -c 8 "$png" | od -An -c | tr -d ' ') == '211PNG\r\n032\n' ]] || fail "$png is not a PNG"
done
/usr/bin/python3 tests/analysis/check_figures.py "$scratch" --catalog-only flyer3d >"$scratch/style.out" 2>&1 ||
  { cat "$scratch/style.out"; fail "lentine_q3d breaks the house style"; }
echo "ok   lentine_q3d: the Q-criterion strips of both points, in the house style"

"$bin" creature-glb "$run" --point 1 >"$scratch/glb.out" 2>&1 || { cat "$scratch/glb.out"; fail "creature-glb"; }
/usr/bin/python3 - "$run/point_000001_creature.glb" <<'PY' || fail "creature .glb"
import json, struct, sys
data = open(sys.argv[1], "rb").read()
magic, version, length = struct.unpack("<4sII", data[:12])
assert magic == b"glTF" and version == 2 and length == len(data)
size, kind = struct.unpack("<I4s", data[12:20])
gltf = json.loads(data[20:20 + size])
assert len(gltf["nodes"]) == 6 and gltf["nodes"][0]["children"] == [1, 2, 3, 4, 5]
channels = gltf["animations"][0]["channels"]
assert sorted(c["target"]["path"] for c in channels) == ["rotation"] * 5 + ["translation"] * 5
sampler = gltf["animations"][0]["samplers"][channels[0]["sampler"]]
assert gltf["accessors"][sampler["input"]]["count"] == 12
PY
echo "ok   creature-glb: point_000001_creature.glb, 5 geom nodes animated over 12 frames"

rc=0
"$bin" creature-glb "$run" --point 7 >/dev/null 2>"$scratch/bad.err" || rc=$?
[[ $rc == 2 && $(wc -l <"$scratch/bad.err") == 1 ]] && grep -q "no such point file" "$scratch/bad.err" ||
  fail "creature-glb on a missing point: exit $rc, $(cat "$scratch/bad.err")"
echo "ok   creature-glb on a missing point: exit 2, $(cat "$scratch/bad.err")"
source "$(dirname "${BASH_SOURCE[0]}")/expect_bad.sh"
expect_bad stored_fields "stored_fields" 'params.stored_fields=surface'
