// Forces against the gradient of the potential energy, and the Jacobian triplets against finite
// differences of the forces (the Ceres GradientChecker habit, STYLE.md), in 2D and 3D.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "springs/system.hpp"
#include "support/dense_linalg.hpp"

namespace sp = creaturelab::springs;

namespace {

// Deterministic numbers in [lo, hi) (a 64-bit LCG: the same on every platform).
struct Lcg {
  uint64_t state;
  double uniform(double lo, double hi) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(state >> 11) * 0x1.0p-53;
  }
};

// Five particles (particle 0 pinned), springs stretched and compressed, with damping, three bends.
template <int D> sp::System<D> testSystem(sp::State<D>& s, uint64_t seed) {
  Lcg rng{seed};
  sp::Network<D> n;
  s = sp::zeroState<D>(5);
  // A polyline turning by at most about 1 rad per joint, so no bend sits near the +-pi fold.
  sp::Vec<D> dir = sp::Vec<D>::Zero();
  dir[0] = 1;
  for (int p = 0; p < 5; ++p) {
    n.addParticle(rng.uniform(0.5, 2.0), p == 0);
    if (p > 0) {
      sp::Vec<D> turn;
      for (int d = 0; d < D; ++d) turn[d] = rng.uniform(-0.7, 0.7);
      dir = (dir + turn).normalized();
      s.x_m.col(p) = s.x_m.col(p - 1) + rng.uniform(0.5, 1.5) * dir;
    }
  }
  const int pairs[6][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {0, 2}, {1, 4}};
  for (const auto& pr : pairs) {
    const double len = (s.x_m.col(pr[0]) - s.x_m.col(pr[1])).norm();
    n.addSpring(pr[0], pr[1], len * rng.uniform(0.6, 1.4), rng.uniform(1.0, 3.0), rng.uniform(0.1, 0.5));
  }
  const int triples[3][3] = {{0, 1, 2}, {1, 2, 3}, {2, 3, 4}};
  for (const auto& t : triples) {
    const double theta = sp::turningAngleRad<D>(s.x_m.col(t[0]), s.x_m.col(t[1]), s.x_m.col(t[2]));
    const double rest = D == 2 ? theta + rng.uniform(-0.4, 0.4) : std::max(0.0, theta + rng.uniform(-0.4, 0.4));
    n.addBend(t[0], t[1], t[2], rest, rng.uniform(0.5, 2.0));
  }
  n.gravity_m_per_s2 = sp::Vec<D>::Constant(-1.5);
  n.drag_ns_per_m = 0.3;
  return sp::System<D>(n);
}

template <int D> Eigen::MatrixXd dense(const std::vector<Eigen::Triplet<double>>& t, int dofs) {
  Eigen::SparseMatrix<double> m(dofs, dofs);
  m.setFromTriplets(t.begin(), t.end());
  return Eigen::MatrixXd(m);
}

template <int D> void expectForcesAreMinusEnergyGradient(const sp::System<D>& sys, const sp::State<D>& s0) {
  const double h = 1e-6;
  sp::Points<D> f;
  sys.forces(s0, 0.0, f);
  for (int p = 0; p < sys.particleCount(); ++p) {
    for (int d = 0; d < D; ++d) {
      sp::State<D> plus = s0, minus = s0;
      plus.x_m(d, p) += h;
      minus.x_m(d, p) -= h;
      const double fd = -(sys.potentialEnergy(plus) - sys.potentialEnergy(minus)) / (2 * h);
      const double expected = sys.network().pinned[p] ? 0.0 : fd;
      EXPECT_NEAR(f(d, p), expected, 1e-7 * std::max(1.0, f.cwiseAbs().maxCoeff())) << "particle " << p << " axis " << d;
    }
  }
}

template <int D> void expectStiffnessMatchesForceDifferences(const sp::System<D>& sys, const sp::State<D>& s0) {
  const int dofs = D * sys.particleCount();
  std::vector<Eigen::Triplet<double>> t;
  sys.addStiffnessTriplets(s0, 1.0, t, /*clamp_compression=*/false);
  const Eigen::MatrixXd k = dense<D>(t, dofs);
  const double h = 1e-6;
  Eigen::MatrixXd fd(dofs, dofs);
  for (int c = 0; c < dofs; ++c) {
    sp::State<D> plus = s0, minus = s0;
    plus.x_m.data()[c] += h;
    minus.x_m.data()[c] -= h;
    sp::Points<D> fp, fm;
    sys.forces(plus, 0.0, fp);
    sys.forces(minus, 0.0, fm);
    fd.col(c) = (fp - fm).reshaped() / (2 * h);
  }
  const double scale = std::max(1.0, fd.cwiseAbs().maxCoeff());
  EXPECT_LT((k - fd).cwiseAbs().maxCoeff(), 1e-6 * scale) << "analytic\n" << k << "\nfinite differences\n" << fd;
  Eigen::MatrixXd free_block = k;  // pinned rows are zero, their columns are not: compare free x free
  for (int p = 0; p < sys.particleCount(); ++p)
    if (sys.network().pinned[p]) free_block.middleCols(D * p, D).setZero();
  EXPECT_LT((free_block - free_block.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale) << "df/dx must be symmetric";
}

template <int D> void expectDampingMatchesForceDifferences(const sp::System<D>& sys, sp::State<D> s0) {
  Lcg rng{99};
  for (int i = 0; i < s0.v_m_per_s.size(); ++i) s0.v_m_per_s.data()[i] = rng.uniform(-1, 1);
  const int dofs = D * sys.particleCount();
  std::vector<Eigen::Triplet<double>> t;
  sys.addDampingTriplets(s0, 1.0, t);
  const Eigen::MatrixXd c = dense<D>(t, dofs);
  Eigen::MatrixXd fd(dofs, dofs);
  const double h = 1e-6;
  for (int col = 0; col < dofs; ++col) {
    sp::State<D> plus = s0, minus = s0;
    plus.v_m_per_s.data()[col] += h;
    minus.v_m_per_s.data()[col] -= h;
    sp::Points<D> fp, fm;
    sys.forces(plus, 0.0, fp);
    sys.forces(minus, 0.0, fm);
    fd.col(col) = (fp - fm).reshaped() / (2 * h);
  }
  EXPECT_LT((c - fd).cwiseAbs().maxCoeff(), 1e-8);
}

}  // namespace

TEST(SpringsForcesFd, Forces2DAreMinusEnergyGradient) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    sp::State<2> s;
    const auto sys = testSystem<2>(s, seed);
    expectForcesAreMinusEnergyGradient(sys, s);
  }
}

TEST(SpringsForcesFd, Forces3DAreMinusEnergyGradient) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    sp::State<3> s;
    const auto sys = testSystem<3>(s, seed);
    expectForcesAreMinusEnergyGradient(sys, s);
  }
}

TEST(SpringsForcesFd, Stiffness2DMatchesForceDifferences) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    sp::State<2> s;
    const auto sys = testSystem<2>(s, seed);
    expectStiffnessMatchesForceDifferences(sys, s);
  }
}

TEST(SpringsForcesFd, Stiffness3DMatchesForceDifferences) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    sp::State<3> s;
    const auto sys = testSystem<3>(s, seed);
    expectStiffnessMatchesForceDifferences(sys, s);
  }
}

TEST(SpringsForcesFd, DampingMatchesForceDifferences) {
  sp::State<2> s2;
  const auto sys2 = testSystem<2>(s2, 4);
  expectDampingMatchesForceDifferences(sys2, s2);
  sp::State<3> s3;
  const auto sys3 = testSystem<3>(s3, 4);
  expectDampingMatchesForceDifferences(sys3, s3);
}

// The 3D angle |a x b| is not differentiable at a straight joint; with rest angle 0 the energy
// 0.5 kb theta^2 is, and its Hessian there must match finite differences of the forces.
TEST(SpringsForcesFd, Straight3DBendUsesSmoothLimit) {
  for (double offset : {0.0, 1e-9, 1e-3}) {
    sp::Network<3> n;
    sp::State<3> s = sp::zeroState<3>(3);
    for (int p = 0; p < 3; ++p) n.addParticle(1.0, false);
    s.x_m.col(0) << 0, 0, 0;
    s.x_m.col(1) << 1, 0.2, -0.1;
    s.x_m.col(2) << 2.5, 0.5 + offset, -0.25;
    n.addBend(0, 1, 2, 0.0, 1.7);
    const sp::System<3> sys(n);
    sp::Points<3> f;
    sys.forces(s, 0.0, f);
    if (offset == 0.0) {
      EXPECT_LT(f.cwiseAbs().maxCoeff(), 1e-15);
    }
    expectForcesAreMinusEnergyGradient(sys, s);
    expectStiffnessMatchesForceDifferences(sys, s);
  }
}

TEST(SpringsForcesFd, ClampedStiffnessIsNegativeSemidefinite) {
  for (uint64_t seed : {1u, 2u, 3u, 5u, 8u}) {
    sp::State<3> s;
    const auto sys = testSystem<3>(s, seed);
    std::vector<Eigen::Triplet<double>> t;
    sys.addStiffnessTriplets(s, 1.0, t, /*clamp_compression=*/true);
    Eigen::MatrixXd k = dense<3>(t, 15).bottomRightCorner(12, 12);  // free particles 1..4
    EXPECT_GT(creaturelab::test::symmetricEigenvalues(-k).minCoeff(), -1e-12) << "seed " << seed;
  }
}

TEST(SpringsForcesFd, InternalForcesConserveMomentum) {
  sp::State<3> s;
  auto sys0 = testSystem<3>(s, 7);
  sp::Network<3> n = sys0.network();
  std::fill(n.pinned.begin(), n.pinned.end(), 0);
  n.gravity_m_per_s2.setZero();
  n.drag_ns_per_m = 0;
  const sp::System<3> sys(n);
  Lcg rng{3};
  for (int i = 0; i < s.v_m_per_s.size(); ++i) s.v_m_per_s.data()[i] = rng.uniform(-1, 1);
  sp::Points<3> f;
  sys.forces(s, 0.0, f);
  EXPECT_LT(f.rowwise().sum().cwiseAbs().maxCoeff(), 1e-14 * f.cwiseAbs().maxCoeff());
}

TEST(SpringsForcesFd, PinnedParticlesFeelNoForceAndExternalForceAdds) {
  sp::State<2> s;
  auto sys = testSystem<2>(s, 1);
  sys.setExternalForce([](double t_s, const sp::State<2>&, sp::Points<2>& f) { f.row(0).array() += 2.0 * t_s; });
  sp::Points<2> f0, f1;
  sys.forces(s, 0.0, f0);
  sys.forces(s, 0.5, f1);
  EXPECT_EQ(f1.col(0), sp::Vec<2>::Zero());
  for (int p = 1; p < 5; ++p) EXPECT_NEAR(f1(0, p) - f0(0, p), 1.0, 1e-14);
  sp::Points<2> a;
  sys.accelerations(s, 0.5, a);
  for (int p = 1; p < 5; ++p)
    EXPECT_NEAR((a.col(p) - f1.col(p) / sys.network().mass_kg[p]).norm(), 0.0, 1e-13);
  EXPECT_EQ(a.col(0), sp::Vec<2>::Zero());
}

// 2D signed angles jump from pi to -pi at a fold; theta - theta0 is wrapped so the energy and
// force stay smooth there.
TEST(SpringsForcesFd, Bend2DIsSmoothAcrossTheFold) {
  sp::Network<2> n;
  sp::State<2> s = sp::zeroState<2>(3);
  for (int p = 0; p < 3; ++p) n.addParticle(1.0, false);
  const double theta = -3.1;  // just past the fold; the rest angle 3.0 is on the other side
  s.x_m.col(1) << 1, 0;
  s.x_m.col(2) << 1 + 0.8 * std::cos(theta), 0.8 * std::sin(theta);
  n.addBend(0, 1, 2, 3.0, 2.0);
  const sp::System<2> sys(n);
  const double dev = theta - 3.0 + 2 * M_PI;
  EXPECT_NEAR(sys.elasticEnergy(s), 0.5 * 2.0 * dev * dev, 1e-12);
  expectForcesAreMinusEnergyGradient(sys, s);
  expectStiffnessMatchesForceDifferences(sys, s);
}
