// Static equilibrium on cases with closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

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

TEST(SpringsEquilibriumSmall, ConstantForceAddsToGravity) {
  // m g + F = k x: a constant force F (System::setConstantForce) is part of the statics.
  sp::Network<3> n;
  n.addParticle(1e-8, true);
  n.addParticle(1e-8, false);
  n.addSpring(0, 1, 1e-3, 0.01);
  n.gravity_m_per_s2 << 0, 0, -9.81;
  sp::System<3> sys(n);
  sp::Points<3> force = sp::Points<3>::Zero(3, 2);
  force.col(1) << 2e-8, 0, -5e-8;
  force.col(0) << 1, 1, 1;  // on the pinned particle: discarded
  sys.setConstantForce(force);
  sp::State<3> s = sp::zeroState<3>(2);
  s.x_m.col(1) << 0, 0, -1e-3;
  sp::EquilibriumOptions opt;
  opt.gradient_tolerance_n = 1e-19;
  const auto r = sp::solveStaticEquilibrium(sys, s, opt);
  ASSERT_TRUE(r.converged) << r.max_residual_force_n;
  const Eigen::Vector3d load(2e-8, 0, -5e-8 - 1e-8 * 9.81);  // newtons on the free particle
  const Eigen::Vector3d expected = load.normalized() * (1e-3 + load.norm() / 0.01);
  EXPECT_LT((s.x_m.col(1) - expected).norm(), 1e-15);
  EXPECT_EQ(s.x_m.col(0), sp::Vec<3>::Zero());
}

TEST(SpringsEquilibriumSmall, ConstantForceIsMinusTheGradientOfItsEnergy) {
  // conservativeForces = -grad potentialEnergy with a constant force, by central differences.
  sp::Network<2> n;
  sp::State<2> s = sp::zeroState<2>(3);
  n.addParticle(1.0, true);
  n.addParticle(2.0, false);
  n.addParticle(0.5, false);
  s.x_m << 0, 1.1, 1.9, 0, 0.2, -0.3;
  n.addSpring(0, 1, 1.0, 3.0);
  n.addSpring(1, 2, 0.8, 2.0);
  n.gravity_m_per_s2 << 0, -9.81;
  sp::System<2> sys(n);
  sp::Points<2> force(2, 3);
  force << 7, 0.5, -1.5, 8, 2.0, 0.25;
  sys.setConstantForce(force);
  EXPECT_DOUBLE_EQ(sys.constantForceEnergy(s), -(0.5 * 1.1 + 2.0 * 0.2) - (-1.5 * 1.9 + 0.25 * -0.3));
  sp::Points<2> f;
  sys.conservativeForces(s, f);
  const double h = 1e-6;
  for (int p = 1; p < 3; ++p)
    for (int d = 0; d < 2; ++d) {
      sp::State<2> plus = s, minus = s;
      plus.x_m(d, p) += h;
      minus.x_m(d, p) -= h;
      const double fd = -(sys.potentialEnergy(plus) - sys.potentialEnergy(minus)) / (2 * h);
      EXPECT_NEAR(f(d, p), fd, 1e-7 * (1 + std::abs(fd))) << "particle " << p << " axis " << d;
    }
  EXPECT_EQ(f.col(0), sp::Vec<2>::Zero());
}

TEST(SpringsEquilibriumSmall, ConstantForceOfTheWrongSizeIsRejected) {
  sp::Network<2> n;
  n.addParticle(1.0, false);
  sp::System<2> sys(n);
  EXPECT_THROW(sys.setConstantForce(sp::Points<2>::Zero(2, 2)), std::invalid_argument);
  EXPECT_THROW(sys.setConstantForce(sp::Points<2>::Constant(2, 1, NAN)), std::invalid_argument);
  EXPECT_NO_THROW(sys.setConstantForce(sp::Points<2>()));  // none
}
