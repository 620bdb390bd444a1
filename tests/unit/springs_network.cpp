// Network construction and validate(): every problem is named in words a user understands.
#include <gtest/gtest.h>

#include "springs/network.hpp"
#include "springs/system.hpp"

namespace sp = creaturelab::springs;

namespace {
sp::Network<3> twoParticles() {
  sp::Network<3> n;
  n.addParticle(1e-8, true);
  n.addParticle(1e-8, false);
  n.addSpring(0, 1, 1e-3, 0.01);
  return n;
}
}  // namespace

TEST(SpringsNetwork, AddReturnsIndicesAndCounts) {
  sp::Network<2> n;
  EXPECT_EQ(n.addParticle(1.0, false), 0);
  EXPECT_EQ(n.addParticle(1.0, true), 1);
  EXPECT_EQ(n.addParticle(1.0, false), 2);
  EXPECT_EQ(n.addSpring(0, 1, 1.0, 2.0), 0);
  EXPECT_EQ(n.addSpring(1, 2, 1.0, 2.0, 0.5), 1);
  EXPECT_EQ(n.addBend(0, 1, 2, 0.3, 1.0), 0);
  EXPECT_EQ(n.particleCount(), 3);
  EXPECT_EQ(n.springCount(), 2);
  EXPECT_EQ(n.bendCount(), 1);
  EXPECT_EQ(n.pinned[1], 1);
  EXPECT_EQ(n.damping_ns_per_m[0], 0.0);
  EXPECT_EQ(n.damping_ns_per_m[1], 0.5);
  EXPECT_EQ(n.validate(), "");
}

TEST(SpringsNetwork, ValidateNamesBadSpringIndex) {
  auto n = twoParticles();
  n.addSpring(1, 5, 1e-3, 0.01);
  EXPECT_EQ(n.validate(), "spring 1 joins particles 1 and 5, but particles are numbered 0 to 1");
}

TEST(SpringsNetwork, ValidateNamesNonPositiveValues) {
  {
    auto n = twoParticles();
    n.mass_kg[1] = 0;
    EXPECT_EQ(n.validate(), "particle 1 has mass 0 kg; masses must be positive and finite");
  }
  {
    auto n = twoParticles();
    n.rest_length_m[0] = -1;
    EXPECT_EQ(n.validate(), "spring 0 has rest length -1 m; rest lengths must be positive");
  }
  {
    auto n = twoParticles();
    n.stiffness_n_per_m[0] = 0;
    EXPECT_EQ(n.validate(), "spring 0 has stiffness 0 N/m; stiffness must be positive");
  }
  {
    auto n = twoParticles();
    n.damping_ns_per_m[0] = -0.1;
    EXPECT_EQ(n.validate(), "spring 0 has damping -0.1 N s/m; damping must be zero or positive");
  }
  {
    auto n = twoParticles();
    n.drag_ns_per_m = -1;
    EXPECT_EQ(n.validate(), "drag_ns_per_m is -1 N s/m; drag must be zero or positive");
  }
}

TEST(SpringsNetwork, ValidateNamesBadBends) {
  auto n = twoParticles();
  n.addParticle(1e-8, false);
  n.addBend(0, 1, 1, 0.0, 1.0);
  EXPECT_EQ(n.validate(), "bend 0 needs three different particles, got 0, 1, 1");
  n.bend_k[0] = 2;
  n.rest_angle_rad[0] = -0.5;  // 3D angles are unsigned
  EXPECT_EQ(n.validate(), "bend 0 has rest angle -0.5 rad; in 3D it must lie in [0, pi]");
  n.rest_angle_rad[0] = 0.5;
  EXPECT_EQ(n.validate(), "");
  n.bend_j.push_back(0);
  EXPECT_NE(n.validate().find("bend arrays differ in length"), std::string::npos);
}

TEST(SpringsNetwork, ValidateNamesInconsistentArrays) {
  auto n = twoParticles();
  n.pinned.push_back(0);
  EXPECT_EQ(n.validate(), "pinned has 3 entries but there are 2 particles");
  auto m = twoParticles();
  m.rest_length_m.push_back(1.0);
  EXPECT_NE(m.validate().find("spring arrays differ in length"), std::string::npos);
}

TEST(SpringsNetwork, SystemRefusesInvalidNetwork) {
  auto n = twoParticles();
  n.addSpring(0, 0, 1e-3, 0.01);
  try {
    sp::System<3> s(n);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "spring network: spring 1 joins particle 0 to itself");
  }
}

TEST(SpringsNetwork, TurningAngleIsSignedIn2DAndUnsignedIn3D) {
  using V2 = sp::Vec<2>;
  EXPECT_DOUBLE_EQ(sp::turningAngleRad<2>(V2(0, 0), V2(1, 0), V2(1, 1)), M_PI / 2);   // left turn
  EXPECT_DOUBLE_EQ(sp::turningAngleRad<2>(V2(0, 0), V2(1, 0), V2(1, -1)), -M_PI / 2); // right turn
  EXPECT_DOUBLE_EQ(sp::turningAngleRad<2>(V2(0, 0), V2(1, 0), V2(2, 0)), 0.0);
  using V3 = sp::Vec<3>;
  EXPECT_DOUBLE_EQ(sp::turningAngleRad<3>(V3(0, 0, 0), V3(1, 0, 0), V3(1, -1, 0)), M_PI / 2);
  EXPECT_NEAR(sp::turningAngleRad<3>(V3(0, 0, 0), V3(1, 0, 0), V3(1 + 0x1p-30, 0x1p-30, 0)), M_PI / 4, 1e-15);
}
