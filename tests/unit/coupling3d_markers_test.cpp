// Surface markers of MuJoCo geoms (coupling3d/surface_markers3.hpp): they cover each surface (areas
// sum to its area), lie on it, are no farther apart than the spacing, and follow their geom.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "coupling3d/surface_markers3.hpp"
#include "coupling3d_scenes.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::coupling3d {
namespace {

constexpr double kPi = std::numbers::pi;

class SurfaceMarkers3Test : public ::testing::Test {
 protected:
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_ = testing::scratch("markers");
};

double largestGap(const std::vector<SurfaceMarker3>& m, int geom) {
  double gap = 0.0;  // the largest distance from a marker to its nearest neighbour on the same geom
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m[i].geom != geom) continue;
    double nearest = 1e300;
    for (std::size_t j = 0; j < m.size(); ++j) {
      if (j == i || m[j].geom != geom) continue;
      double d2 = 0;
      for (int a = 0; a < 3; ++a) d2 += (m[i].local_m[a] - m[j].local_m[a]) * (m[i].local_m[a] - m[j].local_m[a]);
      nearest = std::min(nearest, std::sqrt(d2));
    }
    gap = std::max(gap, nearest);
  }
  return gap;
}

TEST_F(SurfaceMarkers3Test, CoverTheSurfacesAtTheSpacing) {
  const auto model = testing::loadScene(dir_, "scene",
                                        "<geom type=\"box\" size=\"0.1 0.2 0.05\" pos=\"0.5 0.5 0.5\"/>"
                                        "<body pos=\"0.3 0.4 0.5\"><freejoint/><geom type=\"sphere\" size=\"0.1\"/></body>",
                                        0.01);
  const double spacing = 0.02;
  const std::vector<SurfaceMarker3> m = modelSurfaceMarkers(model, spacing);
  double area[2] = {0, 0};
  for (const SurfaceMarker3& k : m) {
    ASSERT_TRUE(k.geom == 0 || k.geom == 1);
    EXPECT_EQ(k.body, k.geom);  // the box on the world body, the sphere on body 1
    area[k.geom] += k.area_m2;
    if (k.geom == 0) {  // on one of the box's faces
      const double on = std::min({std::abs(std::abs(k.local_m[0]) - 0.1), std::abs(std::abs(k.local_m[1]) - 0.2),
                                  std::abs(std::abs(k.local_m[2]) - 0.05)});
      EXPECT_LT(on, 1e-12);
    } else {
      // On the sphere up to the facets' depth: a facet's triangles (sides at most the spacing h, on a
      // lat-long grid) have circumradius about h/√2, so a point on one lies within h²/(4r) of the sphere.
      const double r = std::hypot(k.local_m[0], k.local_m[1], k.local_m[2]);
      EXPECT_LT(0.1 - r, spacing * spacing / (4 * 0.1));
      EXPECT_LE(r, 0.1 + 1e-12);
    }
  }
  EXPECT_NEAR(area[0], 8 * (0.1 * 0.2 + 0.2 * 0.05 + 0.05 * 0.1), 1e-12);
  EXPECT_NEAR(area[1], 4 * kPi * 0.01, 4 * kPi * 0.01 * 0.01);  // the tessellation's area, within 1 %
  EXPECT_LE(largestGap(m, 0), spacing);
  EXPECT_LE(largestGap(m, 1), spacing);
}

// A solid's mirror symmetries hold for its markers (geom_surface.hpp): across x = 0, y = 0 and z = 0
// for the box, the sphere and the ellipsoid, across x = 0 and y = 0 for the cylinder and the capsule
// (their side quads straddle z = 0). Each marker's mirror image is a marker of the same area, so a
// mirror-symmetric creature in a mirror-symmetric flow feels no sideways force.
TEST_F(SurfaceMarkers3Test, AreTheirGeomsMirrorImages) {
  const auto model = testing::loadScene(dir_, "mirror",
                                        "<geom type=\"box\" size=\"0.25 0.15 0.02\" pos=\"0.5 0.5 0.5\"/>"
                                        "<geom type=\"sphere\" size=\"0.1\" pos=\"0.2 0.5 0.5\"/>"
                                        "<geom type=\"ellipsoid\" size=\"0.15 0.15 0.1\" pos=\"0.5 0.2 0.5\"/>"
                                        "<geom type=\"cylinder\" size=\"0.05 0.1\" pos=\"0.5 0.8 0.5\"/>"
                                        "<geom type=\"capsule\" size=\"0.05 0.1\" pos=\"0.8 0.5 0.5\"/>",
                                        0.01);
  const std::vector<SurfaceMarker3> m = modelSurfaceMarkers(model, 0.03);
  for (int geom = 0; geom < 5; ++geom)
    for (int axis = 0; axis < (geom < 3 ? 3 : 2); ++axis) {
      int unmatched = 0, markers = 0;
      for (const SurfaceMarker3& k : m) {
        if (k.geom != geom) continue;
        ++markers;
        Vec3 image = k.local_m;
        image[axis] = -image[axis];
        bool found = false;
        for (const SurfaceMarker3& q : m)
          if (q.geom == geom && std::abs(q.area_m2 - k.area_m2) <= 1e-12 * k.area_m2 &&
              std::hypot(q.local_m[0] - image[0], q.local_m[1] - image[1], q.local_m[2] - image[2]) < 1e-12)
            found = true;
        unmatched += found ? 0 : 1;
      }
      EXPECT_GT(markers, 20) << "geom " << geom;
      EXPECT_EQ(unmatched, 0) << "geom " << geom << ": markers without a mirror image across axis " << axis;
    }
}

// Interior markers: on the lattice, at least the margin inside, filling the inner volume.
TEST_F(SurfaceMarkers3Test, InteriorMarkersFillTheInside) {
  const auto model = testing::loadScene(dir_, "scene",
                                        "<geom type=\"box\" size=\"0.1 0.2 0.05\" pos=\"0.5 0.5 0.5\"/>"
                                        "<body pos=\"0.3 0.4 0.5\"><freejoint/><geom type=\"sphere\" size=\"0.1\"/></body>"
                                        "<body pos=\"0.3 0.4 0.5\"><freejoint/><geom type=\"capsule\" size=\"0.009 0.2\"/></body>",
                                        0.01);
  const double h = 0.01, margin = 0.01;
  const std::vector<SurfaceMarker3> m = interiorMarkers(model, h, margin);
  double volume[3] = {0, 0, 0};
  for (const SurfaceMarker3& k : m) {
    EXPECT_EQ(k.area_m2, 0.0);
    EXPECT_NEAR(k.volume_m3, h * h * h, 1e-18);
    volume[k.geom] += k.volume_m3;
    if (k.geom == 1) {
      EXPECT_LE(std::hypot(k.local_m[0], k.local_m[1], k.local_m[2]), 0.1 - margin + 1e-12);
    }
    if (k.geom == 0) {
      EXPECT_LE(std::abs(k.local_m[2]), 0.05 - margin + 1e-12);
    }
  }
  // The lattice counts the inner box (0.09 × 0.19 × 0.04 half sizes: 19 × 39 × 9 points) exactly and the
  // inner ball (radius 0.09) to within the lattice's resolution; the thin capsule (radius under the margin) has none.
  EXPECT_NEAR(volume[0], 19 * 39 * 9 * h * h * h, 1e-12);
  EXPECT_NEAR(volume[1], 4.0 / 3.0 * kPi * std::pow(0.09, 3), 0.03 * 4.0 / 3.0 * kPi * std::pow(0.09, 3));
  EXPECT_EQ(volume[2], 0.0);
}

TEST_F(SurfaceMarkers3Test, FollowTheirGeom) {
  const auto model = testing::loadScene(
      dir_, "scene", "<body pos=\"0.3 0.4 0.5\"><freejoint/><geom type=\"box\" size=\"0.05 0.1 0.02\"/></body>", 0.01);
  rigid::RigidData data(model);
  data.kinematics();
  const std::vector<SurfaceMarker3> m = modelSurfaceMarkers(model, 0.03);
  ASSERT_FALSE(m.empty());
  // Turn the body by 90° about z (quaternion (cos 45°, 0, 0, sin 45°)) and move it.
  double* q = data.qpos();
  q[0] = 1.0, q[1] = 2.0, q[2] = 3.0;
  q[3] = std::sqrt(0.5), q[4] = 0, q[5] = 0, q[6] = std::sqrt(0.5);
  data.kinematics();
  for (const SurfaceMarker3& k : m) {
    const Vec3 w = markerWorld(data, k);
    EXPECT_NEAR(w[0], 1.0 - k.local_m[1], 1e-12);
    EXPECT_NEAR(w[1], 2.0 + k.local_m[0], 1e-12);
    EXPECT_NEAR(w[2], 3.0 + k.local_m[2], 1e-12);
  }
  EXPECT_THROW(modelSurfaceMarkers(model, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace creaturelab::coupling3d
