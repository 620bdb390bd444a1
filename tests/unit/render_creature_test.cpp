// A 3-D creature's render chain (Lentine et al. 2010 Figs. 11, 13): MuJoCo's primitive geoms as
// closed meshes of the right volume (render/geom_mesh.hpp); the .glb of recorded poses reloads with
// tinygltf and puts each geom's vertices where MuJoCo's pose puts them (render/creature_gltf.hpp).
// The recorder's side: render_creature_record_test.cpp.
#include <tiny_gltf.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/creature_gltf.hpp"
#include "render/geom_mesh.hpp"

namespace creaturelab::render {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(RenderGeomMesh, VolumesOfThePrimitives) {
  const double r = 0.1, h = 0.3;
  struct Case {
    GeomShape shape;
    std::array<double, 3> size;
    double volume;
  };
  const Case cases[] = {
      {GeomShape::box, {0.25, 0.15, 0.02}, 8 * 0.25 * 0.15 * 0.02},
      {GeomShape::sphere, {r, 0, 0}, 4.0 / 3 * kPi * r * r * r},
      {GeomShape::ellipsoid, {0.15, 0.15, 0.1}, 4.0 / 3 * kPi * 0.15 * 0.15 * 0.1},
      {GeomShape::capsule, {r, h, 0}, kPi * r * r * 2 * h + 4.0 / 3 * kPi * r * r * r},
      {GeomShape::cylinder, {r, h, 0}, kPi * r * r * 2 * h},
  };
  for (const Case& c : cases) {
    const TriangleMesh m = geomMesh(int(c.shape), c.size, 48);
    if (c.shape != GeomShape::box) {
      EXPECT_EQ("", checkClosedOriented(m)) << int(c.shape);
    }
    // A 48-gon inscribed in each circle: the volume within 1% below the surface's.
    EXPECT_NEAR(signedVolume(m) / c.volume, c.shape == GeomShape::box ? 1.0 : 0.995, 0.006) << int(c.shape);
    ASSERT_EQ(m.normals.size(), m.positions.size());
  }
  EXPECT_THROW(geomMesh(7, {1, 1, 1}), std::invalid_argument);  // a mesh geom
  EXPECT_THROW(geomMesh(int(GeomShape::box), {0.1, 0, 0.1}), std::invalid_argument);
}

// A rotation matrix (row-major) of angle a about the unit axis n (Rodrigues).
std::array<double, 9> rotation(std::array<double, 3> n, double a) {
  const double c = std::cos(a), s = std::sin(a), t = 1 - c;
  return {t * n[0] * n[0] + c,        t * n[0] * n[1] - s * n[2], t * n[0] * n[2] + s * n[1],
          t * n[0] * n[1] + s * n[2], t * n[1] * n[1] + c,        t * n[1] * n[2] - s * n[0],
          t * n[0] * n[2] - s * n[1], t * n[1] * n[2] + s * n[0], t * n[2] * n[2] + c};
}

TEST(RenderCreatureGltf, QuaternionOfARotation) {
  // Angles that pick each of Shepperd's four branches (w, x, y or z largest).
  for (const auto& [axis, angle] : {std::pair{std::array<double, 3>{0.6, 0.0, 0.8}, 0.4},
                                    std::pair{std::array<double, 3>{1.0, 0.0, 0.0}, 3.0},
                                    std::pair{std::array<double, 3>{0.0, 1.0, 0.0}, 3.0},
                                    std::pair{std::array<double, 3>{0.0, 0.6, 0.8}, 3.1}}) {
    const auto q = quaternionOf(rotation(axis, angle).data());
    const double sign = q[0] < 0 ? -1 : 1;
    EXPECT_NEAR(sign * q[0], std::cos(angle / 2), 1e-12);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(sign * q[1 + a], axis[a] * std::sin(angle / 2), 1e-12);
  }
}

TEST(RenderCreatureGltf, GlbPlacesEachGeomAtItsPose) {
  const std::vector<CreatureGeom> geoms = {{6, {0.25, 0.15, 0.02}}, {3, {0.04, 0.2, 0}}};
  CreatureAnimation a(geoms);
  const std::vector<double> pos0 = {0.1, 0.2, 0.3, -0.4, 0.0, 0.5};
  const auto r0 = rotation({0, 1, 0}, 0.3), r1 = rotation({0.6, 0, 0.8}, -1.1);
  std::vector<double> rot(r0.begin(), r0.end());
  rot.insert(rot.end(), r1.begin(), r1.end());
  a.addFrame(1.0, pos0, rot);
  std::vector<double> pos1 = pos0;
  pos1[2] += 0.1;
  a.addFrame(1.5, pos1, rot);
  EXPECT_THROW(a.addFrame(1.5, pos1, rot), std::invalid_argument);                      // time not after the last
  EXPECT_THROW(a.addFrame(2.0, {0, 0, 0}, rot), std::invalid_argument);                 // a geom short
  std::vector<double> sheared = rot;
  sheared[1] += 0.1;
  EXPECT_THROW(a.addFrame(2.0, pos1, sheared), std::invalid_argument);                  // not a rotation
  EXPECT_THROW(CreatureAnimation(std::vector<CreatureGeom>{{7, {1, 1, 1}}}), std::invalid_argument);  // a mesh geom
  const auto bytes = a.glb("flyer");

  tinygltf::TinyGLTF loader;
  tinygltf::Model m;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&m, &err, &warn, bytes.data(), unsigned(bytes.size()))) << err;
  ASSERT_EQ(m.nodes.size(), 3u);
  ASSERT_EQ(m.nodes[0].children, (std::vector<int>{1, 2}));
  ASSERT_EQ(m.animations.size(), 1u);
  ASSERT_EQ(m.animations[0].channels.size(), 4u);
  // Node k's first vertex, at frame 0's pose, through the root's z-up -> y-up rotation, is MuJoCo's
  // world point pos + R v as (x, z, -y).
  const auto floatsOf = [&](int accessor) {
    const tinygltf::Accessor& acc = m.accessors[accessor];
    const tinygltf::BufferView& v = m.bufferViews[acc.bufferView];
    const auto* p = reinterpret_cast<const float*>(m.buffers[v.buffer].data.data() + v.byteOffset + acc.byteOffset);
    const int n = acc.type == TINYGLTF_TYPE_VEC4 ? 4 : acc.type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
    return std::vector<float>(p, p + acc.count * n);
  };
  const std::vector<std::vector<double>> rots = {{r0.begin(), r0.end()}, {r1.begin(), r1.end()}};
  for (int k = 0; k < 2; ++k) {
    const tinygltf::Node& node = m.nodes[k + 1];
    const auto v = floatsOf(m.meshes[node.mesh].primitives[0].attributes.at("POSITION"));
    const TriangleMesh local = geomMesh(geoms[k].mujoco_type, geoms[k].size_m);
    ASSERT_EQ(v.size(), 3 * local.positions.size());
    // The node's rotation (x, y, z, w) applied to its first vertex: v + 2 w (u x v) + 2 u x (u x v).
    const double w = node.rotation[3];
    const Vec3 u{node.rotation[0], node.rotation[1], node.rotation[2]}, p{v[0], v[1], v[2]};
    const Vec3 uv = cross(u, p);
    const Vec3 turned = p + 2 * w * uv + 2.0 * cross(u, uv);
    const Vec3 world{node.translation[0] + turned.x, node.translation[1] + turned.y, node.translation[2] + turned.z};
    const double* r = rots[k].data();
    const Vec3 l = local.positions[0];
    const Vec3 expect{pos0[3 * k] + r[0] * l.x + r[1] * l.y + r[2] * l.z,
                      pos0[3 * k + 1] + r[3] * l.x + r[4] * l.y + r[5] * l.z,
                      pos0[3 * k + 2] + r[6] * l.x + r[7] * l.y + r[8] * l.z};
    EXPECT_NEAR(world.x, expect.x, 1e-6);
    EXPECT_NEAR(world.y, expect.y, 1e-6);
    EXPECT_NEAR(world.z, expect.z, 1e-6);
    // The root turns MuJoCo's z up into glTF's y up: (x, y, z) -> (x, z, -y) is -90 deg about x.
    EXPECT_NEAR(m.nodes[0].rotation[0], -std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(m.nodes[0].rotation[3], std::sqrt(0.5), 1e-12);
  }
  // The animation's second key moves geom 0 up by 0.1 m (z, before the root's turn).
  const tinygltf::AnimationChannel& ch = m.animations[0].channels[0];
  ASSERT_EQ(ch.target_path, "translation");
  const auto keys = floatsOf(m.animations[0].samplers[ch.sampler].output);
  const auto times = floatsOf(m.animations[0].samplers[ch.sampler].input);
  ASSERT_EQ(times, (std::vector<float>{0.0f, 0.5f}));
  EXPECT_NEAR(keys[5] - keys[2], 0.1, 1e-6);
}

}  // namespace
}  // namespace creaturelab::render
