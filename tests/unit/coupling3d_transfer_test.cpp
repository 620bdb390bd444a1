// The 3-D immersed-boundary transfer (coupling3d/transfer3.hpp): exact interpolation of a linear
// field, exact transfer of force and torque, adjointness, walls and periodic wrap, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "coupling3d/transfer3.hpp"

namespace creaturelab::coupling3d {
namespace {

using fluid3d::BoundaryType3;
using fluid3d::MacGrid3;

MacGrid3 walledGrid() {
  return MacGrid3({12, 10, 9}, 0.1, fluid3d::Boundaries3::allWalls(BoundaryType3::no_slip));
}

// Markers scattered through the interior (at least 2 cells from the walls of walledGrid()).
std::vector<Vec3> scattered(int count) {
  std::vector<Vec3> x;
  for (int k = 0; k < count; ++k)
    x.push_back({0.2 + 0.8 * std::fmod(0.37 * k + 0.11, 1.0), 0.2 + 0.6 * std::fmod(0.61 * k + 0.3, 1.0),
                 0.2 + 0.5 * std::fmod(0.23 * k + 0.7, 1.0)});
  return x;
}

fluid3d::FaceField3 zeroField(const MacGrid3& g) {
  fluid3d::FaceField3 f;
  for (int a = 0; a < 3; ++a) {
    const auto e = g.faceExtents(a);
    f[a] = fluid3d::Array3(e[0], e[1], e[2]);
  }
  return f;
}

TEST(Transfer3, InterpolatesALinearFieldExactly) {
  for (ib::Kernel kernel : {ib::Kernel::peskin4, ib::Kernel::bilinear}) {
    MacGrid3 g = walledGrid();
    // Component a = c_a + Σ_b G_ab x_b at every face position.
    const double c[3] = {0.3, -0.2, 0.7};
    const double G[3][3] = {{1.0, -2.0, 0.5}, {0.25, 3.0, -1.0}, {-0.75, 1.5, 2.0}};
    for (int a = 0; a < 3; ++a) {
      const auto e = g.faceExtents(a);
      for (int k = 0; k < e[2]; ++k)
        for (int j = 0; j < e[1]; ++j)
          for (int i = 0; i < e[0]; ++i) {
            const auto x = g.facePosition_m(a, i, j, k);
            g.velocity_m_per_s[a](i, j, k) = c[a] + G[a][0] * x[0] + G[a][1] * x[1] + G[a][2] * x[2];
          }
    }
    const std::vector<Vec3> x = scattered(40);
    Transfer3 t;
    t.locate(g, kernel, x);
    std::vector<Vec3> u(x.size());
    t.interpolate(g.velocity_m_per_s, u);
    for (std::size_t k = 0; k < x.size(); ++k)
      for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(u[k][a], c[a] + G[a][0] * x[k][0] + G[a][1] * x[k][1] + G[a][2] * x[k][2], 1e-13)
            << "marker " << k << " component " << a;
  }
}

// dx³ Σ f = Σ F (momentum) and dx³ Σ x × f = Σ X × F (angular momentum), to round-off.
TEST(Transfer3, SpreadKeepsForceAndTorque) {
  const MacGrid3 g = walledGrid();
  const std::vector<Vec3> x = scattered(25);
  std::vector<Vec3> F(x.size());
  for (std::size_t k = 0; k < F.size(); ++k) F[k] = {std::sin(1.0 + k), std::cos(2.0 * k), 0.5 - 0.1 * k};
  Transfer3 t;
  t.locate(g, ib::Kernel::peskin4, x);
  fluid3d::FaceField3 f = zeroField(g);
  t.spread(F, f);
  Vec3 force{}, torque{}, want_force{}, want_torque{};
  for (std::size_t k = 0; k < F.size(); ++k)
    for (int a = 0; a < 3; ++a) {
      want_force[a] += F[k][a];
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      want_torque[a] += x[k][b] * F[k][c] - x[k][c] * F[k][b];
    }
  const double vol = g.cellVolume_m3();
  for (int a = 0; a < 3; ++a) {
    const auto e = g.faceExtents(a);
    for (int k = 0; k < e[2]; ++k)
      for (int j = 0; j < e[1]; ++j)
        for (int i = 0; i < e[0]; ++i) {
          const double v = vol * f[a](i, j, k);
          const auto p = g.facePosition_m(a, i, j, k);
          force[a] += v;
          // p × (v e_a): (p × e_a)_b = p_c and (p × e_a)_c = −p_b for b = a + 1, c = a + 2 (mod 3).
          const int b = (a + 1) % 3, c = (a + 2) % 3;
          torque[b] += p[c] * v;
          torque[c] -= p[b] * v;
        }
  }
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(force[a], want_force[a], 1e-12) << "axis " << a;
    EXPECT_NEAR(torque[a], want_torque[a], 1e-12) << "axis " << a;
  }
}

// <S F, u>_grid = <F, I u>_markers for any F and u: the transfer's energy identity.
TEST(Transfer3, SpreadIsTheAdjointOfInterpolation) {
  MacGrid3 g({8, 8, 8}, 0.05, fluid3d::Boundaries3::allPeriodic());
  for (int a = 0; a < 3; ++a)
    for (std::size_t t = 0; t < g.velocity_m_per_s[a].size(); ++t)
      g.velocity_m_per_s[a].data()[t] = std::sin(0.7 * t + a) + 0.1 * a;
  // Markers near the periodic seams too, so the wrapped stencils are checked.
  const std::vector<Vec3> x{{0.01, 0.2, 0.39}, {0.395, 0.0, 0.1}, {0.2, 0.21, 0.22}, {0.05, 0.38, 0.001}};
  std::vector<Vec3> F{{1, 2, 3}, {-1, 0.5, 2}, {0.3, -0.7, 1.1}, {2, 2, -2}};
  Transfer3 t;
  t.locate(g, ib::Kernel::peskin4, x);
  fluid3d::FaceField3 f = zeroField(g);
  t.spread(F, f);
  std::vector<Vec3> U(x.size());
  t.interpolate(g.velocity_m_per_s, U);
  double grid = 0.0, markers = 0.0, total[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a)
    for (std::size_t s = 0; s < f[a].size(); ++s) {
      grid += g.cellVolume_m3() * f[a].data()[s] * g.velocity_m_per_s[a].data()[s];
      total[a] += g.cellVolume_m3() * f[a].data()[s];
    }
  for (std::size_t k = 0; k < x.size(); ++k) markers += F[k][0] * U[k][0] + F[k][1] * U[k][1] + F[k][2] * U[k][2];
  EXPECT_NEAR(grid, markers, 1e-12 * std::abs(markers));
  EXPECT_NEAR(total[0], 2.3, 1e-13);  // periodic wrap keeps the partition of unity
  EXPECT_NEAR(total[1], 3.8, 1e-13);
  EXPECT_NEAR(total[2], 4.1, 1e-13);
}

TEST(Transfer3, RefusesMarkersNearAWallOrNotFinite) {
  const MacGrid3 g = walledGrid();
  Transfer3 t;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Vec3& bad : {Vec3{0.15, 0.5, 0.4}, Vec3{0.5, 0.5, 0.75}, Vec3{nan, 0.5, 0.4}, Vec3{-3.0, 0.5, 0.4}}) {
    const std::vector<Vec3> x{{0.5, 0.5, 0.4}, bad};
    EXPECT_THROW(t.locate(g, ib::Kernel::peskin4, x), std::invalid_argument);
    EXPECT_EQ(t.markerCount(), 0);
  }
  // Two cells from the low wall is allowed for peskin4 (the stencil's first face is face 1).
  const std::vector<Vec3> ok{{0.2, 0.2, 0.2}};
  EXPECT_NO_THROW(t.locate(g, ib::Kernel::peskin4, ok));
  std::vector<Vec3> wrong_size(3);
  EXPECT_THROW(t.interpolate(g.velocity_m_per_s, wrong_size), std::invalid_argument);
}

}  // namespace
}  // namespace creaturelab::coupling3d
