// Highest-frequency estimate and stability limits (stability.hpp), integrator names.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "springs/stability.hpp"
#include "support/dense_linalg.hpp"

namespace sp = creaturelab::springs;

namespace {
// A straight chain along `dir`: particle 0 pinned, the others free, springs at rest length.
sp::Network<3> chain(int particles, const sp::Vec<3>& dir, sp::State<3>& s, bool pin_far_end) {
  sp::Network<3> n;
  s = sp::zeroState<3>(particles);
  for (int p = 0; p < particles; ++p) {
    n.addParticle(10e-9, p == 0 || (pin_far_end && p == particles - 1));
    s.x_m.col(p) = p * 1e-3 * dir.normalized();
  }
  for (int p = 0; p + 1 < particles; ++p) n.addSpring(p, p + 1, 1e-3, 0.01);
  return n;
}
}  // namespace

TEST(SpringsStability, OneSpringToPinnedEndGivesSqrtKOverM) {
  sp::State<3> s;
  const auto n = chain(2, sp::Vec<3>(1, 0, 0), s, false);
  EXPECT_NEAR(sp::estimateOmegaMaxRadPerS(n, s), 1000.0, 1e-9);  // sqrt(0.01 N/m / 10 ug)
}

TEST(SpringsStability, InteriorChainNodeGivesTwiceSqrtKOverM) {
  for (const sp::Vec<3>& dir : {sp::Vec<3>(1, 0, 0), sp::Vec<3>(1, 1, 1), sp::Vec<3>(0.3, -0.7, 0.2)}) {
    sp::State<3> s;
    const auto n = chain(10, dir, s, true);
    EXPECT_NEAR(sp::estimateOmegaMaxRadPerS(n, s), 2000.0, 1e-9) << dir.transpose();
  }
}

// Exact top natural frequency sqrt(max |eig(M^-1/2 K M^-1/2)|) over the free coordinates.
template <int D> double exactOmegaMax(const sp::Network<D>& n, const sp::State<D>& s) {
  const sp::System<D> sys(n);
  std::vector<Eigen::Triplet<double>> t;
  sys.addStiffnessTriplets(s, -1.0, t, false);
  const int dofs = D * n.particleCount();
  Eigen::SparseMatrix<double> k(dofs, dofs);
  k.setFromTriplets(t.begin(), t.end());
  const Eigen::MatrixXd kd(k);
  std::vector<int> free;
  for (int p = 0; p < n.particleCount(); ++p)
    for (int d = 0; d < D; ++d)
      if (!n.pinned[p]) free.push_back(D * p + d);
  Eigen::MatrixXd a(free.size(), free.size());
  for (size_t r = 0; r < free.size(); ++r)
    for (size_t c = 0; c < free.size(); ++c)
      a(r, c) = kd(free[r], free[c]) / std::sqrt(n.mass_kg[free[r] / D] * n.mass_kg[free[c] / D]);
  return std::sqrt(creaturelab::test::symmetricEigenvalues(0.5 * (a + a.transpose())).cwiseAbs().maxCoeff());
}

TEST(SpringsStability, BoundIsAboveTrueTopFrequencyOfAGrid) {
  // A stretched, skewed grid with diagonals and unequal masses and stiffnesses, in 3D.
  sp::Network<3> n;
  const int w = 5;
  sp::State<3> s = sp::zeroState<3>(w * w);
  for (int j = 0; j < w; ++j)
    for (int i = 0; i < w; ++i) {
      n.addParticle(1.0 + 0.1 * i, i == 0 && j == 0);
      s.x_m.col(j * w + i) << i, j, 0.1 * i * j;
    }
  auto link = [&](int a, int b) { n.addSpring(a, b, 0.9 * (s.x_m.col(a) - s.x_m.col(b)).norm(), 1.0 + 0.05 * (a + b)); };
  for (int j = 0; j < w; ++j)
    for (int i = 0; i < w; ++i) {
      if (i + 1 < w) link(j * w + i, j * w + i + 1);
      if (j + 1 < w) link(j * w + i, (j + 1) * w + i);
      if (i + 1 < w && j + 1 < w) link(j * w + i, (j + 1) * w + i + 1);
    }
  const double exact = exactOmegaMax(n, s);
  const double bound = sp::estimateOmegaMaxRadPerS(n, s);
  EXPECT_GE(bound, exact);
  EXPECT_LT(bound, 1.6 * exact);
}

TEST(SpringsStability, BoundIsAboveTrueTopFrequencyWithBends) {
  // A curved 2D chain (jellyfish-bell-like) with stiff bends, rest angles off the current ones.
  sp::Network<2> n;
  const int count = 12;
  sp::State<2> s = sp::zeroState<2>(count);
  for (int p = 0; p < count; ++p) {
    n.addParticle(1e-6 * (1 + 0.1 * p), p == 0);
    s.x_m.col(p) << std::cos(0.25 * p), std::sin(0.25 * p);
  }
  for (int p = 0; p + 1 < count; ++p) n.addSpring(p, p + 1, 0.24, 0.05);
  for (int p = 0; p + 2 < count; ++p) n.addBend(p, p + 1, p + 2, 0.2, 0.02);
  const double exact = exactOmegaMax(n, s);
  const double bound = sp::estimateOmegaMaxRadPerS(n, s);
  EXPECT_GE(bound, exact);
  EXPECT_LT(bound, 2.5 * exact);
}

TEST(SpringsStability, UndampedLimits) {
  using K = sp::IntegratorKind;
  EXPECT_DOUBLE_EQ(sp::stabilityLimitOmegaDt(K::SymplecticEuler, 0), 2.0);
  EXPECT_NEAR(sp::stabilityLimitOmegaDt(K::RK4, 0), 2 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(sp::stabilityLimitOmegaDt(K::ExplicitEuler, 0), 0.0);
  EXPECT_TRUE(std::isinf(sp::stabilityLimitOmegaDt(K::ImplicitEuler, 0)));
}

TEST(SpringsStability, DampedLimits) {
  using K = sp::IntegratorKind;
  EXPECT_DOUBLE_EQ(sp::stabilityLimitOmegaDt(K::ExplicitEuler, 0.1), 0.2);
  EXPECT_DOUBLE_EQ(sp::stabilityLimitOmegaDt(K::ExplicitEuler, 1.0), 2.0);
  // Symplectic Euler: a^2 + 4 zeta a - 4 = 0.
  const double a = sp::stabilityLimitOmegaDt(K::SymplecticEuler, 0.3);
  EXPECT_NEAR(a * a + 4 * 0.3 * a - 4, 0.0, 1e-12);
  // RK4 on the real axis (zeta = 1): |R(-2.785...)| = 1.
  EXPECT_NEAR(sp::stabilityLimitOmegaDt(K::RK4, 1.0), 2.785293563405, 1e-9);
}

TEST(SpringsStability, AutoStep) {
  using K = sp::IntegratorKind;
  EXPECT_DOUBLE_EQ(sp::autoStepS(K::SymplecticEuler, 2000.0, 0.0), 0.5 / 1000.0);
  EXPECT_DOUBLE_EQ(sp::autoStepS(K::SymplecticEuler, 2000.0, 0.0, 1.0), 1.0 / 1000.0);
  EXPECT_TRUE(std::isinf(sp::autoStepS(K::ImplicitEuler, 2000.0, 0.0)));
  EXPECT_EQ(sp::autoStepS(K::ExplicitEuler, 2000.0, 0.0), 0.0);
}

TEST(SpringsStability, DampingRatioBounds) {
  sp::State<3> s;
  auto n = chain(3, sp::Vec<3>(1, 0, 0), s, false);
  n.drag_ns_per_m = 1e-8;        // c/m = 1/s
  n.damping_ns_per_m[1] = 2e-8;  // on particles 1 and 2
  const auto z = sp::estimateDampingRatio(n, 1000.0);
  EXPECT_DOUBLE_EQ(z.low, 1.0 / 2000.0);
  EXPECT_DOUBLE_EQ(z.high, (1e-8 + 2 * 2e-8) / (2 * 10e-9 * 1000.0));
}

TEST(SpringsIntegrator, NamesRoundTrip) {
  using K = sp::IntegratorKind;
  for (K k : {K::ExplicitEuler, K::SymplecticEuler, K::RK4, K::ImplicitEuler}) {
    EXPECT_EQ(sp::parseIntegrator(sp::integratorName(k)), k);
    EXPECT_NE(sp::makeIntegrator<2>(k), nullptr);
    EXPECT_NE(sp::makeIntegrator<3>(k), nullptr);
  }
  EXPECT_EQ(sp::integratorName(K::ExplicitEuler), "euler");
  EXPECT_EQ(sp::parseIntegrator("rk4"), K::RK4);
  EXPECT_FALSE(sp::parseIntegrator("RK4").has_value());
  EXPECT_FALSE(sp::parseIntegrator("verlet").has_value());
}
