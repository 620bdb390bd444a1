// The 3-D pressure projection: properties of the discrete operator, the two solvers against each
// other, divergence at round-off, and multigrid-preconditioned CG's iterations under refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "fluid3d/fast_transform1.hpp"
#include "fluid3d/mac_grid3.hpp"
#include "fluid3d/pcg_pressure_solver3.hpp"
#include "fluid3d/pressure_operator3.hpp"
#include "fluid3d/spectral_pressure_solver3.hpp"
#include "fluid3d/stencil3.hpp"

namespace creaturelab::fluid3d {
namespace {

// A reproducible pseudo-random value in [−1, 1) (SplitMix64 of the index).
double noise(std::uint64_t index) {
  std::uint64_t z = index * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E5ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / 4503599627370496.0 - 1.0;
}

void fillNoise(Array3& a, std::uint64_t seed) {
  for (std::size_t t = 0; t < a.size(); ++t) a.data()[t] = noise(seed * 1000003ull + t);
}

MacGrid3 noisyGrid(const std::array<int, 3>& n, const Boundaries3& sides, std::uint64_t seed) {
  MacGrid3 grid(n, 0.01, sides);
  for (int a = 0; a < 3; ++a) fillNoise(grid.velocity_m_per_s[a], seed + a);
  enforceSolidWalls(grid);
  return grid;
}

Boundaries3 openTop() {
  Boundaries3 b = Boundaries3::allWalls(BoundaryType3::no_slip);
  b.axis[2].high = BoundaryType3::open;
  return b;
}

Boundaries3 mixed() {  // periodic x, free-slip y, open bottom and top z
  Boundaries3 b;
  b.axis[0] = {BoundaryType3::periodic, BoundaryType3::periodic};
  b.axis[1] = {BoundaryType3::free_slip, BoundaryType3::free_slip};
  b.axis[2] = {BoundaryType3::open, BoundaryType3::open};
  return b;
}

struct Case {
  const char* name;
  Boundaries3 sides;
};
const Case kCases[] = {{"periodic", Boundaries3::allPeriodic()},
                       {"free_slip_box", Boundaries3::allWalls(BoundaryType3::free_slip)},
                       {"open_top", openTop()},
                       {"mixed", mixed()}};

// The pressure matrix is symmetric: x·Ay = Ax·y, and its diagonal is what stencilDiagonal says.
TEST(Fluid3dPressure, MatrixIsSymmetricWithTheStatedDiagonal) {
  const std::array<int, 3> n{6, 5, 4};
  for (const Case& c : kCases) {
    const Stencil3 s = pressureStencil(n, c.sides);
    Array3 x(6, 5, 4), y(6, 5, 4), ax, ay, diag, unit(6, 5, 4), column;
    fillNoise(x, 1), fillNoise(y, 2);
    ax.resize(6, 5, 4), ay.resize(6, 5, 4), column.resize(6, 5, 4);
    applyStencil(s, 6.0, -1.0, x, ax, nullptr);
    applyStencil(s, 6.0, -1.0, y, ay, nullptr);
    std::vector<double> scratch;
    EXPECT_NEAR(dot3(x, ay, nullptr, scratch), dot3(ax, y, nullptr, scratch), 1e-12) << c.name;
    stencilDiagonal(s, 6.0, -1.0, diag);
    for (int k : {0, 3})
      for (int i : {0, 5}) {
        unit.fill(0.0);
        unit(i, 2, k) = 1.0;
        applyStencil(s, 6.0, -1.0, unit, column, nullptr);
        EXPECT_EQ(column(i, 2, k), diag(i, 2, k)) << c.name;
      }
  }
}

// The spectral solver's q solves A q = b to round-off, for a box with unequal sides.
TEST(Fluid3dPressure, SpectralSolveIsExact) {
  const std::array<int, 3> n{8, 6, 5};
  for (const Case& c : kCases) {
    MacGrid3 grid = noisyGrid(n, c.sides, 10);
    Array3 b, q, aq;
    projectionRhs(grid, b, nullptr);
    if (c.sides.closed()) {
      std::vector<double> scratch;
      subtractConstant3(sum3(b, nullptr, scratch) / b.size(), b, nullptr);
    }
    SpectralPressureSolver3 solver;
    solver.solve(n, c.sides, b, q);
    aq.resize(8, 6, 5);
    applyStencil(pressureStencil(n, c.sides), 6.0, -1.0, q, aq, nullptr);
    double worst = 0.0;
    for (std::size_t t = 0; t < b.size(); ++t) worst = std::max(worst, std::fabs(aq.data()[t] - b.data()[t]));
    EXPECT_LT(worst, 1e-13) << c.name;
  }
}

// The FFT transforms give the dense orthonormal basis's coefficients, and invert them.
TEST(Fluid3dPressure, FastTransformsMatchTheDenseBasis) {
  for (const AxisBoundary3 sides : {AxisBoundary3{BoundaryType3::periodic, BoundaryType3::periodic},
                                    AxisBoundary3{BoundaryType3::free_slip, BoundaryType3::no_slip}}) {
    for (int n : {2, 8, 16}) {
      ASSERT_TRUE(FastTransform1::applies(n, sides));
      const FastTransform1 fast(n, sides);
      const EigenBasis1 dense = eigenBasis(n, sides);
      std::vector<double> line(n), c(n), back(n), work(4 * n);
      for (int j = 0; j < n; ++j) line[j] = noise(100 + j);
      fast.forward(line.data(), c.data(), work.data());
      for (int m = 0; m < n; ++m) {
        double expected = 0.0;
        for (int j = 0; j < n; ++j) expected += dense.basis[j * n + m] * line[j];
        EXPECT_NEAR(c[m], expected, 1e-13) << toString(sides.low) << " n = " << n << " m = " << m;
      }
      fast.inverse(c.data(), back.data(), work.data());
      for (int j = 0; j < n; ++j) EXPECT_NEAR(back[j], line[j], 1e-13) << toString(sides.low) << " n = " << n;
    }
  }
  EXPECT_FALSE(FastTransform1::applies(12, {BoundaryType3::periodic, BoundaryType3::periodic}));
  EXPECT_FALSE(FastTransform1::applies(8, {BoundaryType3::free_slip, BoundaryType3::open}));
}

// The spectral solve by FFTs equals the dense one to round-off.
TEST(Fluid3dPressure, FastAndDenseSpectralSolvesAgree) {
  const std::array<int, 3> n{8, 16, 4};
  for (const Case& c : kCases) {
    MacGrid3 grid = noisyGrid(n, c.sides, 50);
    Array3 b, q_fast, q_dense;
    projectionRhs(grid, b, nullptr);
    if (c.sides.closed()) {
      std::vector<double> scratch;
      subtractConstant3(sum3(b, nullptr, scratch) / b.size(), b, nullptr);
    }
    SpectralPressureSolver3 fast, dense(false);
    fast.solve(n, c.sides, b, q_fast);
    dense.solve(n, c.sides, b, q_dense);
    EXPECT_TRUE(fast.fastAlong(0) && fast.fastAlong(1)) << c.name;
    EXPECT_FALSE(dense.fastAlong(0)) << c.name;
    for (std::size_t t = 0; t < b.size(); ++t) ASSERT_NEAR(q_fast.data()[t], q_dense.data()[t], 1e-12) << c.name;
  }
}

// Both solvers leave the divergence at round-off and agree on the velocity to their tolerance.
TEST(Fluid3dPressure, ProjectionLeavesDivergenceAtRoundOffAndSolversAgree) {
  // Two levels of multigrid, and one (an odd side: Jacobi sweeps alone precondition).
  for (const std::array<int, 3> n : {std::array<int, 3>{8, 8, 6}, std::array<int, 3>{12, 10, 7}}) {
    for (const Case& c : kCases) {
      MacGrid3 spectral = noisyGrid(n, c.sides, 20), pcg = spectral;
      SpectralPressureSolver3 exact;
      MgPcgPressureSolver3 iterative(1e-12);
      exact.project(spectral, 1000.0, 0.01);
      const SolveReport3 report = iterative.project(pcg, 1000.0, 0.01);
      EXPECT_TRUE(report.converged) << c.name;
      // Velocities of order 1 on cells of 0.01 m: round-off of the divergence is ~1e-14 / 0.01.
      EXPECT_LT(maxDivergence_per_s(spectral, nullptr), 1e-11) << c.name;
      EXPECT_LT(maxDivergence_per_s(pcg, nullptr), 1e-9) << c.name;
      double worst = 0.0;
      for (int a = 0; a < 3; ++a)
        for (std::size_t t = 0; t < pcg.velocity_m_per_s[a].size(); ++t)
          worst = std::max(worst, std::fabs(pcg.velocity_m_per_s[a].data()[t] - spectral.velocity_m_per_s[a].data()[t]));
      EXPECT_LT(worst, 1e-10) << c.name;
      double p_worst = 0.0;
      for (std::size_t t = 0; t < pcg.pressure_pa.size(); ++t)
        p_worst = std::max(p_worst, std::fabs(pcg.pressure_pa.data()[t] - spectral.pressure_pa.data()[t]));
      EXPECT_LT(p_worst, 1e-5) << c.name;  // p = q ρ/dt: 1e5 times q's scale
    }
  }
}

// Projecting twice changes nothing more (a projection is idempotent).
TEST(Fluid3dPressure, ProjectionIsIdempotent) {
  MacGrid3 grid = noisyGrid({6, 6, 6}, openTop(), 30);
  SpectralPressureSolver3 solver;
  solver.project(grid, 1000.0, 0.01);
  const FaceField3 once = grid.velocity_m_per_s;
  grid.pressure_pa.fill(0.0);
  solver.project(grid, 1000.0, 0.01);
  for (int a = 0; a < 3; ++a)
    for (std::size_t t = 0; t < once[a].size(); ++t)
      EXPECT_NEAR(grid.velocity_m_per_s[a].data()[t], once[a].data()[t], 1e-13);
}

// MG-PCG's iterations stay about flat as the grid doubles (plain CG's would double).
TEST(Fluid3dPressure, MultigridPcgIterationsStayFlatUnderRefinement) {
  for (const Case& c : {kCases[0], kCases[2]}) {
    int iterations[3] = {0, 0, 0};
    const int sizes[3] = {16, 32, 64};
    for (int s = 0; s < 3; ++s) {
      const int n = sizes[s];
      MacGrid3 grid = noisyGrid({n, n, n}, c.sides, 40);
      MgPcgPressureSolver3 solver(1e-8);
      const SolveReport3 report = solver.project(grid, 1000.0, 0.01);
      EXPECT_TRUE(report.converged) << c.name << " n = " << n;
      iterations[s] = report.iterations;
    }
    std::printf("MG-PCG iterations (%s): %d, %d, %d at 16^3, 32^3, 64^3\n", c.name, iterations[0], iterations[1],
                iterations[2]);
    EXPECT_LE(iterations[2], iterations[0] + 3) << c.name;
    EXPECT_LE(iterations[2], 16) << c.name;
  }
}

}  // namespace
}  // namespace creaturelab::fluid3d
