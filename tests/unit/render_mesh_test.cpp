// The disc extrapolation (render/disc_extrapolation.hpp, Rudolf & Mould 2009 §3.5, Fig. 7): an
// axisymmetric slice gives a surface of revolution, and every mesh is closed, manifold and
// outward, with the Euler characteristic of its genus-0 pieces.
#include "render/jellyfish_renderer.hpp"

#include <gtest/gtest.h>

#include "render_test_slice.hpp"

namespace creaturelab::render {
namespace {

using test::noVariation;
using test::testSlice;

TEST(RenderDiscs, AxisymmetricSliceGivesSurfaceOfRevolution) {
  const auto s = testSlice(32, 0);
  RenderParams params = noVariation();
  params.rings = 33;
  params.segments = 48;
  JellyfishRenderer r(params, s.topology, s.markers());
  const TriangleMesh& mesh = r.render(s.frame());
  const MeshLayout& m = r.layout();
  const Slice2& slice = r.slice();
  for (int i = 0; i < params.rings - 1; ++i)
    for (int side = 0; side < 2; ++side) {
      const int first = side == 0 ? m.exumbrellaRing(i) : m.subumbrellaRing(i);
      const auto& left = side == 0 ? slice.exum_left : slice.sub_left;
      const auto& right = side == 0 ? slice.exum_right : slice.sub_right;
      // The pair's disc: radius half the pair's distance, centre on the common axis (x = z = 0).
      const double radius = 0.5 * (right[i] - left[i]).norm();
      EXPECT_NEAR(0.5 * (left[i].x() + right[i].x()), 0.0, 1e-17);
      for (int j = 0; j < params.segments; ++j) {
        const Vec3 p = mesh.positions[first + j];
        EXPECT_NEAR(std::hypot(p.x, p.z), radius, 1e-15) << i << " " << j;
        EXPECT_NEAR(p.y, left[i].y(), 1e-15) << i << " " << j;
      }
    }
  // The two apexes are single points on the axis.
  EXPECT_NEAR(mesh.positions[m.exumbrellaPole()].x, 0.0, 1e-15);
  EXPECT_NEAR(mesh.positions[m.subumbrellaPole()].x, 0.0, 1e-15);
  EXPECT_EQ(mesh.positions[m.subumbrellaPole()].z, 0.0);
  // The wall's thickness survives the extrapolation: on rings through the markers the exumbrellar
  // ring lies one profile thickness from the subumbrellar one, along the meridian.
  for (int i = 0; i < params.rings - 1; i += 2) {
    const double d = 1.0 - i / 32.0;
    const Vec3 a = mesh.positions[m.exumbrellaRing(i) + 5], b = mesh.positions[m.subumbrellaRing(i) + 5];
    EXPECT_NEAR(norm(a - b), params.thickness.at(d), 1e-12) << i;
  }
}

TEST(RenderDiscs, AsymmetricSliceHasAnAxisPerPair) {
  auto s = testSlice(32, 0);
  for (std::size_t k = 0; k < s.xy.size(); k += 2) s.xy[k] += 0.15 * s.xy[k + 1];  // sheared: each pair off-axis
  JellyfishRenderer r(noVariation(), s.topology, s.markers());
  const TriangleMesh& mesh = r.render(s.frame());
  const Slice2& slice = r.slice();
  const int i = 20, first = r.layout().subumbrellaRing(i);
  const Eigen::Vector2d c = 0.5 * (slice.sub_left[i] + slice.sub_right[i]);
  const double radius = 0.5 * (slice.sub_right[i] - slice.sub_left[i]).norm();
  EXPECT_GT(std::abs(c.x()), 1e-3);
  for (int j = 0; j < r.layout().segments; ++j)
    EXPECT_NEAR(norm(mesh.positions[first + j] - Vec3{c.x(), c.y(), 0}), radius, 1e-15);
  // σ = 0 is the right-hand point and σ = π the left-hand one.
  EXPECT_NEAR(mesh.positions[first].x, slice.sub_right[i].x(), 1e-16);
  EXPECT_NEAR(mesh.positions[first + r.layout().segments / 2].x, slice.sub_left[i].x(), 1e-15);
  EXPECT_EQ(checkClosedOriented(mesh), "");
  EXPECT_GT(signedVolume(mesh), 0.0);
}

TEST(RenderDiscs, ClosedManifoldOutward) {
  for (bool vary : {false, true}) {
    const auto s = testSlice(32, 8);
    RenderParams params = vary ? RenderParams{} : noVariation();
    params.tentacles = 6;
    JellyfishRenderer r(params, s.topology, s.markers());
    const TriangleMesh& mesh = r.render(s.frame(0.3));
    const MeshLayout& m = r.layout();
    ASSERT_EQ(int(mesh.positions.size()), m.vertices());
    ASSERT_EQ(int(mesh.triangles.size()), m.triangles());
    EXPECT_EQ(checkClosedOriented(mesh), "");
    EXPECT_EQ(componentCount(mesh), 1 + 6);
    EXPECT_EQ(eulerCharacteristic(mesh), 2 * (1 + 6));  // seven spheres
    EXPECT_GT(signedVolume(mesh), 0.0);
    // Outward: up at the exumbrella's apex, down into the cavity at the subumbrella's, and away
    // from the axis on the exumbrella's side.
    EXPECT_GT(mesh.normals[m.exumbrellaPole()].y, 0.99);
    EXPECT_LT(mesh.normals[m.subumbrellaPole()].y, -0.99);
    const Vec3 p = mesh.positions[m.exumbrellaRing(20)], n = mesh.normals[m.exumbrellaRing(20)];
    EXPECT_GT(n.x * p.x, 0.0);
    // The umbrella alone: the volume of its flesh, a shell of about the profile's thickness.
    TriangleMesh umbrella = mesh;
    umbrella.triangles.resize(4 * m.segments * (m.rings - 1));
    EXPECT_EQ(checkClosedOriented(umbrella), "");
    const double shell = signedVolume(umbrella);
    EXPECT_GT(shell, 0.3e-6);  // a 32 x 24 mm dome 1-4 mm thick holds a few cm³
    EXPECT_LT(shell, 8e-6);
  }
}

TEST(RenderDiscs, UpsideDownIsStillOutward) {
  auto s = testSlice(32, 8);
  for (std::size_t k = 1; k < s.xy.size(); k += 2) s.xy[k] = -s.xy[k];
  for (std::size_t k = 0; k < s.xy.size(); k += 2) s.xy[k] = -s.xy[k];  // and mirrored
  JellyfishRenderer r(RenderParams{}, s.topology, s.markers());
  const TriangleMesh& mesh = r.render(s.frame());
  EXPECT_EQ(checkClosedOriented(mesh), "");
  EXPECT_GT(signedVolume(mesh), 0.0);
}

TEST(RenderDiscs, TentaclesHangFromTheAperture) {
  const auto s = testSlice(32, 8);
  RenderParams params = noVariation();
  params.tentacles = 4;
  JellyfishRenderer r(params, s.topology, s.markers());
  const TriangleMesh& mesh = r.render(s.frame());
  const MeshLayout& m = r.layout();
  const double aperture = 0.016;  // the test slice's half width
  for (int k = 0; k < 4; ++k) {
    const double sigma = 2 * M_PI * (k + 0.5) / 4;
    // The root ring's centre sits on the aperture's disc at the tentacle's longitude, the tip
    // 20 mm below it.
    Vec3 root{}, tip{};
    for (int j = 0; j < m.tentacle_segments; ++j) {
      root = root + (1.0 / m.tentacle_segments) * mesh.positions[m.tentacleRing(k, 0) + j];
      tip = tip + (1.0 / m.tentacle_segments) * mesh.positions[m.tentacleRing(k, m.tentacle_rings - 1) + j];
    }
    EXPECT_NEAR(root.x, aperture * std::cos(sigma), 1e-12);
    EXPECT_NEAR(root.z, aperture * std::sin(sigma), 1e-12);
    EXPECT_NEAR(root.y - tip.y, 0.02, 1e-12);
    EXPECT_NEAR(norm(mesh.positions[m.tentacleRing(k, 0)] - root), 0.5 * params.tentacle_thickness_m, 1e-12);
  }
}

}  // namespace
}  // namespace creaturelab::render
