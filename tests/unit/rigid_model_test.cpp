// The MuJoCo face (src/rigid/): load errors name the file, joints and subtrees, state snapshots
// re-run bitwise, geom surfaces are closed and face outwards.
#include <gtest/gtest.h>

#include <cmath>

#include "control_models.hpp"
#include "rigid/geom_surface.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::rigid {
namespace {

class RigidTest : public testing::ScratchDirTest {
 protected:
  RigidTest() : ScratchDirTest("rigid") {}
};

TEST_F(RigidTest, LoadErrorNamesTheFileAndMujocosMessage) {
  const std::string missing = file("missing.xml").string();
  try {
    RigidModel::load(missing);
    FAIL() << "loaded a missing file";
  } catch (const RigidError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  const std::string broken = testing::writeText(file("broken.xml"), "<mujoco><worldbody><body></mujoco>");
  try {
    RigidModel::load(broken);
    FAIL() << "loaded a broken file";
  } catch (const RigidError& e) {
    EXPECT_NE(std::string(e.what()).find(broken), std::string::npos) << e.what();
    EXPECT_GT(std::string(e.what()).size(), broken.size() + 10) << "no message from MuJoCo: " << e.what();
  }
}

TEST_F(RigidTest, JointsAndSubtrees) {
  const auto model = RigidModel::load(testing::writeText(file("chain.xml"), testing::chainXml(3)));
  ASSERT_EQ(model.joints(), 3);
  EXPECT_EQ(model.findJoint("nope"), -1);
  const JointInfo j1 = model.joint(model.findJoint("j1"));
  EXPECT_EQ(j1.type, JointType::hinge);
  const int b0 = model.joint(model.findJoint("j0")).body, b2 = model.joint(model.findJoint("j2")).body;
  EXPECT_TRUE(model.inSubtree(b2, j1.body));
  EXPECT_FALSE(model.inSubtree(b0, j1.body));
  EXPECT_DOUBLE_EQ(model.subtreeMass_kg(b0), 6.0);
}

TEST_F(RigidTest, RestoredStateRepeatsStepsBitwise) {
  const auto model = RigidModel::load(testing::writeText(file("chain.xml"), testing::chainXml(3)));
  RigidData d(model);
  d.qpos()[1] = 0.3;
  const RigidState s = d.save();
  for (int k = 0; k < 20; ++k) d.step();
  const std::vector<double> first(d.qpos(), d.qpos() + model.positions());
  d.restore(s);
  for (int k = 0; k < 20; ++k) d.step();
  for (int i = 0; i < model.positions(); ++i) EXPECT_EQ(d.qpos()[i], first[i]);
  EXPECT_TRUE(d.finite());
}

// A closed surface: its area vectors sum to zero, and with outward normals the divergence theorem
// gives its volume, sum (a . (b x c)) / 6 > 0, equal to the solid's for a box.
TEST_F(RigidTest, SurfacesAreClosedAndFaceOutwards) {
  const auto model = RigidModel::load(testing::writeText(
      file("shapes.xml"),
      "<mujoco><worldbody><body><joint type=\"hinge\"/><geom type=\"box\" size=\"0.1 0.2 0.3\"/>"
      "<geom type=\"sphere\" size=\"0.2\"/><geom type=\"capsule\" size=\"0.1 0.3\"/>"
      "<geom type=\"cylinder\" size=\"0.1 0.3\"/><geom type=\"ellipsoid\" size=\"0.1 0.2 0.3\"/></body></worldbody></mujoco>"));
  const auto surfaces = geomSurfaces(model, 16);
  ASSERT_EQ(surfaces.size(), 5u);
  for (const auto& s : surfaces) {
    double sum[3] = {0, 0, 0}, volume = 0;
    for (const auto& t : s.triangles) {
      const double u[3] = {t.b[0] - t.a[0], t.b[1] - t.a[1], t.b[2] - t.a[2]};
      const double v[3] = {t.c[0] - t.a[0], t.c[1] - t.a[1], t.c[2] - t.a[2]};
      const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      for (int k = 0; k < 3; ++k) sum[k] += n[k] / 2;
      volume += (t.a[0] * n[0] + t.a[1] * n[1] + t.a[2] * n[2]) / 6;
    }
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(sum[k], 0, 1e-12) << "geom " << s.geom;
    EXPECT_GT(volume, 0) << "geom " << s.geom << " faces inwards";
    if (s.geom == 0) {
      EXPECT_NEAR(volume, 0.2 * 0.4 * 0.6, 1e-12);
    }
    if (s.geom == 1) {  // an inscribed polyhedron: a little smaller than the sphere (16 x 8 facets: 6%)
      const double sphere = 4.0 / 3 * M_PI * 0.008;
      EXPECT_LT(volume, sphere);
      EXPECT_GT(volume, 0.9 * sphere);
    }
  }
}

}  // namespace
}  // namespace creaturelab::rigid
