// The MuJoCo face (src/rigid/): load errors name the file, joints and subtrees, state snapshots
// re-run bitwise, geom surfaces are closed and face outwards.
#include <gtest/gtest.h>

#include <algorithm>
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

// kinematics() reads the state and leaves it alone: MuJoCo normalises a free joint's quaternion in place,
// which can change its last bits each time, so a state restored and then brought up to date would
// otherwise no longer be the one saved.
TEST_F(RigidTest, KinematicsLeavesTheStateBitForBit) {
  const auto model = RigidModel::load(testing::writeText(file("free.xml"), testing::freeCreatureXml()));
  RigidData d(model);
  const double quaternion[] = {0.9, 0.1, -0.2, 0.3};  // not of unit length
  std::copy(std::begin(quaternion), std::end(quaternion), d.qpos() + 3);
  d.qpos()[7] = 0.4;
  const RigidState s = d.save();
  d.kinematics();
  d.kinematics();
  for (int i = 0; i < model.positions(); ++i) EXPECT_EQ(d.qpos()[i], s.qpos[i]) << "qpos " << i;
  for (int k = 0; k < 3; ++k) d.step();
  const std::vector<double> first(d.qpos(), d.qpos() + model.positions());
  d.restore(s);
  d.kinematics();
  for (int k = 0; k < 3; ++k) d.step();
  for (int i = 0; i < model.positions(); ++i) EXPECT_EQ(d.qpos()[i], first[i]) << "qpos " << i << " after a restore";
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

// §3.3 for a free creature: freezing the shape zeroes every relative joint velocity and keeps the
// total linear momentum and the angular momentum (mj_subtreeVel, computed apart from the mass
// matrix the freeze solves with). Keeping the root's own velocity instead would not.
TEST_F(RigidTest, FreezeShapeOfAFreeCreatureKeepsItsMomentum) {
  const auto model = RigidModel::load(testing::writeText(file("free.xml"), testing::freeCreatureXml()));
  ASSERT_EQ(model.dofs(), 6 + 1 + 1 + 3 + 1 + 1);
  RigidData d(model);
  const double qvel[] = {0.3, -0.2, 0.1, 0.4, -0.5, 0.2, 2.0, -1.5, 0.7, -0.9, 1.1, 0.8, -3.0};
  std::copy(std::begin(qvel), std::end(qvel), d.qvel());
  d.qpos()[7] = 0.4;  // shoulder
  d.qpos()[8] = -0.3; // hip
  d.kinematics();
  const int torso = model.joint(model.findJoint("root")).body;
  Vec3 p0, l0, p1, l1, p2, l2;
  d.subtreeMomentum(torso, p0, l0);
  const RigidState moving = d.save();
  d.freezeShape();
  for (int i = 6; i < model.dofs(); ++i) EXPECT_EQ(d.qvel()[i], 0.0) << "dof " << i;
  d.subtreeMomentum(torso, p1, l1);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(p1[k], p0[k], 1e-12 * (1 + std::abs(p0[k]))) << "linear " << k;
    EXPECT_NEAR(l1[k], l0[k], 1e-12 * (1 + std::abs(l0[k]))) << "angular " << k;
  }
  // The naive freeze (root velocity kept, joints zeroed) loses the joints' momentum.
  d.restore(moving);
  for (int i = 6; i < model.dofs(); ++i) d.qvel()[i] = 0;
  d.subtreeMomentum(torso, p2, l2);
  EXPECT_GT(std::abs(p2[0] - p0[0]) + std::abs(l2[0] - l0[0]), 0.1);
}

// A creature rooted in the world comes to rest (the block of Figs. 3, 6).
TEST_F(RigidTest, FreezeShapeOfARootedCreatureStopsIt) {
  const auto model = RigidModel::load(testing::writeText(file("chain.xml"), testing::chainXml(3)));
  RigidData d(model);
  for (int i = 0; i < model.dofs(); ++i) d.qvel()[i] = 0.5 + i;
  d.freezeShape();
  for (int i = 0; i < model.dofs(); ++i) EXPECT_EQ(d.qvel()[i], 0.0);
}

}  // namespace
}  // namespace creaturelab::rigid
