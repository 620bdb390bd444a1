// Provot strain limiting (thesis §5.1): over-stretched springs are shortened, pinned ends stay.
#include <gtest/gtest.h>

#include "springs/provot.hpp"

namespace sp = creaturelab::springs;

namespace {
// A chain of 11 particles, both ends pinned, pulled down in the middle so springs stretch.
sp::Network<2> sagged(sp::State<2>& s) {
  sp::Network<2> n;
  s = sp::zeroState<2>(11);
  for (int p = 0; p < 11; ++p) {
    n.addParticle(1e-8, p == 0 || p == 10);
    s.x_m.col(p) << 1e-3 * p, -1e-3 * (5 - std::abs(p - 5));  // a V, springs 41% over rest length
  }
  for (int p = 0; p < 10; ++p) n.addSpring(p, p + 1, 1e-3, 0.01);
  return n;
}
}  // namespace

TEST(SpringsProvot, DisabledDoesNothing) {
  sp::State<2> s;
  const auto n = sagged(s);
  const sp::State<2> before = s;
  EXPECT_EQ(sp::applyProvot(n, sp::ProvotOptions{}, s).corrections, 0);
  EXPECT_EQ(s.x_m, before.x_m);
}

TEST(SpringsProvot, ReducesMaxStrainAndKeepsPinnedEnds) {
  sp::State<2> s;
  const auto n = sagged(s);
  const sp::State<2> before = s;
  const double strain0 = sp::maxStrain(n, s);
  EXPECT_NEAR(strain0, std::sqrt(2.0) - 1, 1e-12);
  sp::ProvotOptions opt;
  opt.enabled = true;
  opt.max_strain = 0.1;
  // One in-order sweep pushes the excess along the strand into the last spring (the thesis'
  // "correcting one spring may overextend another"); repeated sweeps spread it out.
  opt.passes = 1;
  const sp::ProvotResult one = sp::applyProvot(n, opt, s);
  EXPECT_GT(one.corrections, 0);
  EXPECT_EQ(one.passes, 1);
  EXPECT_FALSE(one.converged);  // reported, not hidden
  EXPECT_GT(one.max_strain, opt.max_strain);
  EXPECT_EQ(one.max_strain, sp::maxStrain(n, s));
  // Repeated until no spring is over the limit: on this slack chain the sweeps reach it.
  opt.passes = 100000;
  const sp::ProvotResult all = sp::applyProvot(n, opt, s);
  EXPECT_TRUE(all.converged) << all.passes << " passes";
  EXPECT_LT(all.passes, opt.passes);
  const double strain1 = sp::maxStrain(n, s);
  EXPECT_EQ(all.max_strain, strain1);
  EXPECT_LE(strain1, opt.max_strain + (1 + opt.max_strain) * opt.tolerance * 1.01);  // |l| <= (1+cap) r (1+tol)
  EXPECT_LT(strain1, strain0);
  EXPECT_EQ(s.x_m.col(0), before.x_m.col(0));
  EXPECT_EQ(s.x_m.col(10), before.x_m.col(10));
  EXPECT_EQ(s.v_m_per_s, before.v_m_per_s);
}

TEST(SpringsProvot, SingleSpringIsCutToExactlyTheLimit) {
  sp::Network<2> n;
  sp::State<2> s = sp::zeroState<2>(4);
  n.addParticle(1, true);
  for (int p = 1; p < 4; ++p) n.addParticle(1, false);
  n.addSpring(0, 1, 1.0, 1.0);
  n.addSpring(2, 3, 1.0, 1.0);
  s.x_m.col(1) << 3, 4;   // length 5 from a pinned end: the free end takes all of the correction
  s.x_m.col(2) << 10, 0;  // length 3 between free ends: each takes half
  s.x_m.col(3) << 10, 3;
  sp::applyProvot(n, sp::ProvotOptions{true, 0.5, 1}, s);
  EXPECT_NEAR((s.x_m.col(1) - sp::Vec<2>(0.9, 1.2)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((s.x_m.col(2) - sp::Vec<2>(10, 0.75)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((s.x_m.col(3) - sp::Vec<2>(10, 2.25)).norm(), 0.0, 1e-14);
}

// One sweep leaves the V chain over the limit; the exact finish (a Newton projection) brings every
// spring to the limit within the tolerance, the anchors where they were.
TEST(SpringsProvot, ExactFinishHoldsTheLimit) {
  sp::State<2> s;
  const auto n = sagged(s);
  const sp::State<2> before = s;
  sp::ProvotOptions opt{true, 0.1, 1};
  opt.exact_finish = true;
  const sp::ProvotResult r = sp::applyProvot(n, opt, s);
  EXPECT_TRUE(r.finished_exactly);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.max_strain, sp::maxStrain(n, s));
  EXPECT_LE(r.max_strain, opt.max_strain + (1 + opt.max_strain) * opt.tolerance);
  EXPECT_GT(r.max_strain, opt.max_strain - 1e-9);  // pulled taut, at the limit
  EXPECT_EQ(s.x_m.col(0), before.x_m.col(0));
  EXPECT_EQ(s.x_m.col(10), before.x_m.col(10));
}

// With the step's start positions and dt, a moved particle takes the velocity of its whole step
// (x - x_start) / dt; a particle the sweeps leave alone keeps the integrator's velocity.
TEST(SpringsProvot, MovedParticlesTakeTheVelocityOfTheirStep) {
  sp::Network<2> n;
  n.addParticle(1, true);
  n.addParticle(1, false);
  n.addParticle(1, false);
  n.addSpring(0, 1, 1.0, 1.0);
  sp::State<2> s = sp::zeroState<2>(3);
  s.x_m.col(1) << 0, -2;  // twice the rest length below the pinned end
  s.x_m.col(2) << 5, 5;   // on no spring
  s.v_m_per_s.col(1) << 0, -7;
  s.v_m_per_s.col(2) << 1, 2;
  sp::Points<2> start = s.x_m;
  start.col(1) << 0, -1.05;
  const sp::ProvotResult r = sp::applyProvot(n, sp::ProvotOptions{true, 0.1, 10}, s, &start, 0.01);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(s.x_m(1, 1), -1.1, 1e-15);
  EXPECT_NEAR(s.v_m_per_s(1, 1), (-1.1 + 1.05) / 0.01, 1e-12);  // -5 m/s, not the integrator's -7
  EXPECT_EQ(s.v_m_per_s(0, 1), 0.0);
  EXPECT_EQ(s.v_m_per_s.col(2), sp::Vec<2>(1, 2));
  EXPECT_EQ(s.v_m_per_s.col(0), sp::Vec<2>(0, 0));
}

TEST(SpringsProvot, ValidateOptions) {
  EXPECT_EQ((sp::ProvotOptions{true, 0.1, 10}).validate(), "");
  EXPECT_EQ((sp::ProvotOptions{true, -0.1, 10}).validate(), "provot max_strain is -0.1; it must be zero or positive");
  EXPECT_EQ((sp::ProvotOptions{true, 0.1, 0}).validate(), "provot passes is 0; at least one pass is needed");
  EXPECT_EQ((sp::ProvotOptions{true, 0.1, 10, -1.0}).validate(), "provot tolerance is -1; it must lie in [0, 1e-3]");
}
