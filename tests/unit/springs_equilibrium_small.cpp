// Static equilibrium on cases with closed forms.
#include <gtest/gtest.h>

#include "springs/equilibrium.hpp"

namespace sp = creaturelab::springs;

TEST(SpringsEquilibriumSmall, HangingMassStretchesByMgOverK) {
  // Thesis Eq. 4.9: m g = -k x.
  sp::Network<3> n;
  n.addParticle(1e-8, true);
  n.addParticle(1e-8, false);
  n.addSpring(0, 1, 1e-3, 0.01);
  n.gravity_m_per_s2 << 0, 0, -9.81;
  const sp::System<3> sys(n);
  sp::State<3> s = sp::zeroState<3>(2);
  s.x_m.col(1) << 2e-4, 1e-4, -1e-3;  // off-axis start: Newton must swing it under the pin
  s.v_m_per_s.col(1) << 1, 1, 1;
  sp::EquilibriumOptions opt;
  opt.gradient_tolerance_n = 1e-19;  // k = 0.01 N/m: 1e-19 N is 1e-17 m of position error
  const auto r = sp::solveStaticEquilibrium(sys, s, opt);
  EXPECT_TRUE(r.converged) << r.max_residual_force_n;
  EXPECT_LT(r.iterations, 20);
  EXPECT_NEAR(s.x_m(2, 1), -(1e-3 + 1e-8 * 9.81 / 0.01), 1e-15);
  EXPECT_NEAR(s.x_m(0, 1), 0.0, 1e-15);
  EXPECT_NEAR(s.x_m(1, 1), 0.0, 1e-15);
  EXPECT_EQ(s.v_m_per_s.norm(), 0.0);
  EXPECT_EQ(s.x_m.col(0), sp::Vec<3>::Zero());
}

TEST(SpringsEquilibriumSmall, BentJointReturnsToRestAngle) {
  // 2D: two free particles, pins fix the first segment; the bend must bring the angle to 0.6 rad.
  sp::Network<2> n;
  sp::State<2> s = sp::zeroState<2>(3);
  n.addParticle(1, true);
  n.addParticle(1, true);
  n.addParticle(1, false);
  s.x_m.col(1) << 1, 0;
  s.x_m.col(2) << 2, -0.5;
  n.addSpring(1, 2, 1.0, 10.0);
  n.addBend(0, 1, 2, 0.6, 1.0);
  const sp::System<2> sys(n);
  const auto r = sp::solveStaticEquilibrium(sys, s);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(sp::turningAngleRad<2>(s.x_m.col(0), s.x_m.col(1), s.x_m.col(2)), 0.6, 1e-12);
  EXPECT_NEAR((s.x_m.col(2) - s.x_m.col(1)).norm(), 1.0, 1e-12);
  EXPECT_NEAR(r.energy_j, 0.0, 1e-20);
}
