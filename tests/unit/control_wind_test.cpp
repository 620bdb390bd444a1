// Simple wind forces, Lentine et al. 2010 §3.1 Eq. 2, against the analytic force on a block.
#include <gtest/gtest.h>

#include <cmath>

#include "control/simple_wind.hpp"
#include "control_models.hpp"

namespace creaturelab::control {
namespace {

class WindTest : public testing::ScratchDirTest {
 protected:
  WindTest() : ScratchDirTest("wind") {}
};

// One triangle across the flow: sign(u.n) A rho (u.n)^2 n with n inward, along the flow whichever
// way the triangle faces.
TEST_F(WindTest, TriangleForceFollowsEquation2) {
  const rigid::Triangle facing_upstream{{0, 0, 0}, {0, 0, 1}, {0, 1, 0}};  // outward normal -x
  const Vec3 f = triangleWindForce(facing_upstream, {3, 0, 0}, 1.2);
  EXPECT_NEAR(f[0], 0.5 * 1.2 * 9, 1e-12);
  EXPECT_NEAR(f[1], 0, 1e-15);
  const rigid::Triangle facing_downstream{{0, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // outward normal +x
  EXPECT_NEAR(triangleWindForce(facing_downstream, {3, 0, 0}, 1.2)[0], 0.5 * 1.2 * 9, 1e-12);
  EXPECT_NEAR(triangleWindForce(facing_downstream, {0, 0, 3}, 1.2)[0], 0, 1e-15);  // grazing
}

// Block of length 1, depth 1, thickness t at angle theta in a wind U along x: the broad faces give
// 2 rho U^2 sin^2(theta) across the block, the ends 2 rho t U^2 cos^2(theta) along it.
TEST_F(WindTest, BlockForceMatchesTheFacesSum) {
  const double t = 0.1, U = 10, rho = 1.2;
  const auto model = rigid::RigidModel::load(testing::writeText(file("block.xml"), testing::blockXml(t, 0)));
  rigid::RigidData d(model);
  const SimpleWind wind(rigid::geomSurfaces(model, 12), rho, constantWind({U, 0, 0}));
  std::vector<Vec3> force;
  for (double theta : {0.0, 0.3, -0.7, 1.2, 2.5}) {
    d.qpos()[0] = theta;
    d.qvel()[0] = 0;
    d.kinematics();
    std::fill(d.appliedForces(), d.appliedForces() + model.dofs(), 0.0);
    wind.apply(d, force);
    const double s = std::sin(theta), c = std::cos(theta);
    const double broad = 2 * rho * U * U * s * s * (s >= 0 ? 1 : -1), ends = 2 * rho * t * U * U * c * c * (c >= 0 ? 1 : -1);
    // Across: (sin, 0, cos); along: (cos, 0, -sin) (a hinge about +y turns +x towards -z).
    const Vec3 expected = {broad * s + ends * c, 0, broad * c - ends * s};
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(force[1][k], expected[k], 1e-9) << "theta " << theta << " axis " << k;
    // The moment about the hinge of forces through the face centres: only the broad faces', at 0.5 m.
    const double torque_y = -0.5 * broad;  // r = 0.5 (c, 0, -s), F = broad (s, 0, c): (r x F)_y = -0.5 broad
    EXPECT_NEAR(d.appliedForces()[0], torque_y, 1e-9) << "theta " << theta;
  }
}

// A moving body feels the relative velocity: a block swinging with the wind at the wind's speed
// at its centre feels no force on its broad faces there.
TEST_F(WindTest, RelativeVelocityCounts) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("block.xml"), testing::blockXml(0.02, 0)));
  rigid::RigidData d(model);
  const SimpleWind wind(rigid::geomSurfaces(model, 12), 1.2, constantWind({0, 0, -5}));
  std::vector<Vec3> still, moving;
  d.qpos()[0] = 0;
  d.qvel()[0] = 0;
  d.kinematics();
  wind.apply(d, still);
  d.qvel()[0] = 10;  // tip speed 10 m/s downwards at x = 1, 5 m/s at the centre
  d.kinematics();
  std::fill(d.appliedForces(), d.appliedForces() + model.dofs(), 0.0);
  wind.apply(d, moving);
  EXPECT_LT(std::abs(moving[1][2]), 0.2 * std::abs(still[1][2]));
}

}  // namespace
}  // namespace creaturelab::control
