// The pressure projection: discrete operator properties, the fast direct solver against the
// dense path and PCG, and the projection itself (∇·u = 0, idempotent).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "fluid/boundary2.hpp"
#include "fluid/diagnostics2.hpp"
#include "fluid/fast_pressure_solver2.hpp"
#include "fluid/pcg_pressure_solver2.hpp"
#include "fluid/pressure_solver2.hpp"

namespace creaturelab::fluid {
namespace {

// Deterministic pseudo-random value in [−1, 1) from (seed, index).
double noise(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ULL + index + 0x632BE59BD9B4E019ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

void fill_noise(Array2& a, std::uint64_t seed) {
  for (std::size_t k = 0; k < a.size(); ++k) a.data()[k] = noise(seed, k);
}

// Wall configuration number `mask`: bit 0 left, 1 right, 2 bottom, 3 top open; others free-slip.
Walls walls_from_mask(int mask) {
  Walls walls;
  if (mask & 1) walls.left.type = WallType::open;
  if (mask & 2) walls.right.type = WallType::open;
  if (mask & 4) walls.bottom.type = WallType::open;
  if (mask & 8) walls.top.type = WallType::open;
  return walls;
}

std::string describe(const Walls& walls) {
  auto name = [](const Wall& w) { return std::string(to_string(w.type)); };
  return "left " + name(walls.left) + ", right " + name(walls.right) + ", bottom " + name(walls.bottom) + ", top " +
         name(walls.top);
}

double relative_residual(const Walls& walls, const Array2& q, const Array2& b) {
  Array2 aq;
  applyPressureMatrix(walls, q, aq);
  Array2 r = b;
  if (walls.closed()) removeMean(r);
  double m = 0.0;
  for (std::size_t k = 0; k < r.size(); ++k) m = std::max(m, std::abs(r.data()[k] - aq.data()[k]));
  return m / maxAbs(b);
}

TEST(PressureMatrix, IsSymmetricAndAnnihilatesConstantsInAClosedBox) {
  for (int mask = 0; mask < 16; ++mask) {
    const Walls walls = walls_from_mask(mask);
    Array2 x(7, 5), y(7, 5), ax, ay;
    fill_noise(x, 1);
    fill_noise(y, 2);
    applyPressureMatrix(walls, x, ax);
    applyPressureMatrix(walls, y, ay);
    EXPECT_NEAR(dot(x, ay), dot(y, ax), 1e-12) << describe(walls);
    EXPECT_GT(dot(x, ax), 0.0) << describe(walls);
    Array2 diagonal;
    pressureMatrixDiagonal(walls, 7, 5, diagonal);
    Array2 e(7, 5);
    e(3, 2) = 1.0;
    applyPressureMatrix(walls, e, ax);
    EXPECT_EQ(ax(3, 2), diagonal(3, 2));
    e.fill(0.0);
    e(0, 0) = 1.0;
    applyPressureMatrix(walls, e, ax);
    EXPECT_EQ(ax(0, 0), diagonal(0, 0)) << describe(walls);
  }
  Array2 ones(6, 4, 1.0), a_ones;
  applyPressureMatrix(Walls{}, ones, a_ones);
  EXPECT_EQ(maxAbs(a_ones), 0.0);
}

// Every wall combination, power-of-two sides (FFT paths) and others (dense path).
TEST(FastPressureSolver, SolvesEveryWallCombinationToRoundOff) {
  // FFT radices 4, 2 (16, 8, 32), 3 (12, 18), 5 (10, 100, 50), 7 (14); dense (22: n/2 = 11 prime).
  const int sizes[][2] = {{16, 8}, {8, 16}, {12, 10}, {2, 2}, {32, 32}, {18, 14}, {22, 6}, {100, 50}};
  for (const auto& size : sizes) {
    for (int mask = 0; mask < 16; ++mask) {
      const Walls walls = walls_from_mask(mask);
      Array2 b(size[0], size[1]), q;
      fill_noise(b, 10 + mask);
      FastPressureSolver2 solver;
      solver.solve(walls, b, q);
      EXPECT_LT(relative_residual(walls, q, b), 1e-12) << describe(walls) << " " << size[0] << "x" << size[1];
      Array2 q_dense;
      FastPressureSolver2 dense;
      dense.solve(walls, b, q_dense, /*prefer_dense=*/true);
      EXPECT_EQ(dense.method(), FastPressureSolver2::Method::dense_along_y);
      double difference = 0.0;
      for (std::size_t k = 0; k < q.size(); ++k)
        difference = std::max(difference, std::abs(q.data()[k] - q_dense.data()[k]));
      EXPECT_LT(difference, 1e-11 * std::max(1.0, maxAbs(q))) << describe(walls);
    }
  }
}

TEST(FastPressureSolver, ChoosesTheFftWhereItApplies) {
  Array2 b(16, 8), q;
  fill_noise(b, 3);
  FastPressureSolver2 solver;
  solver.solve(Walls{}, b, q);
  EXPECT_EQ(solver.method(), FastPressureSolver2::Method::fft_along_y);
  Walls open_top;
  open_top.top.type = WallType::open;
  solver.solve(open_top, b, q);
  EXPECT_EQ(solver.method(), FastPressureSolver2::Method::fft_along_x);
  Array2 b_paper(100, 100);  // the paper's grid: n/2 = 50 = 2 · 5 · 5
  fill_noise(b_paper, 4);
  solver.solve(Walls{}, b_paper, q);
  EXPECT_EQ(solver.method(), FastPressureSolver2::Method::fft_along_y);
  EXPECT_LT(relative_residual(Walls{}, q, b_paper), 1e-12);
  Array2 b_prime(22, 22);  // n/2 = 11: no FFT of ours
  fill_noise(b_prime, 5);
  solver.solve(Walls{}, b_prime, q);
  EXPECT_EQ(solver.method(), FastPressureSolver2::Method::dense_along_y);
  EXPECT_LT(relative_residual(Walls{}, q, b_prime), 1e-12);
}

TEST(PcgPressureSolver, MeetsItsToleranceAndAgreesWithTheDirectSolver) {
  for (int mask : {0, 1, 5, 15}) {
    const Walls walls = walls_from_mask(mask);
    Array2 b(24, 20), q(24, 20), q_direct;
    fill_noise(b, 20 + mask);
    PcgPressureSolver2 pcg(1e-10, 1000);
    const LinearSolveReport report = pcg.solve(walls, b, q);
    EXPECT_TRUE(report.converged) << describe(walls);
    EXPECT_GT(report.iterations, 0);
    EXPECT_LE(relative_residual(walls, q, b), 1.0001e-10) << describe(walls);
    FastPressureSolver2 direct;
    direct.solve(walls, b, q_direct);
    double difference = 0.0;
    for (std::size_t k = 0; k < q.size(); ++k)
      difference = std::max(difference, std::abs(q.data()[k] - q_direct.data()[k]));
    EXPECT_LT(difference, 1e-8 * maxAbs(q_direct)) << describe(walls);
  }
}

MacGrid2 random_velocity(int nx, int ny, const Walls& walls, std::uint64_t seed) {
  MacGrid2 grid(nx, ny, 0.01);
  fill_noise(grid.u_m_per_s, seed);
  fill_noise(grid.v_m_per_s, seed + 1);
  enforceWallNormalVelocity(grid, walls);
  return grid;
}

double max_velocity_change(const MacGrid2& a, const MacGrid2& b) {
  double m = 0.0;
  for (std::size_t k = 0; k < a.u_m_per_s.size(); ++k)
    m = std::max(m, std::abs(a.u_m_per_s.data()[k] - b.u_m_per_s.data()[k]));
  for (std::size_t k = 0; k < a.v_m_per_s.size(); ++k)
    m = std::max(m, std::abs(a.v_m_per_s.data()[k] - b.v_m_per_s.data()[k]));
  return m;
}

// After projection max |∇·u| ≤ 1e-10 max|u| / dx, and projecting twice changes nothing.
TEST(Projection, LeavesNoDivergenceAndIsIdempotent) {
  for (PressureSolverType type : {PressureSolverType::fast_direct, PressureSolverType::pcg}) {
    for (int mask : {0, 1, 3, 8, 15}) {
      const Walls walls = walls_from_mask(mask);
      FluidParams params;
      params.pressure_solver = type;
      auto solver = makePressureSolver(params);
      MacGrid2 grid = random_velocity(32, 24, walls, 100 + mask);
      const double rho = 1000.0, dt = 0.01;
      const double u_max = maxVelocityComponent_m_per_s(grid);  // before projection
      const LinearSolveReport first = solver->project(grid, walls, rho, dt);
      EXPECT_TRUE(first.converged);
      EXPECT_LE(maxDivergence_per_s(grid), 1e-10 * u_max / grid.dx_m) << to_string(type) << ", " << describe(walls);
      EXPECT_LE(first.relative_residual, 1e-10) << to_string(type);
      const MacGrid2 once = grid;
      solver->project(grid, walls, rho, dt);
      // The second projection removes what the first left: nothing for the direct solver,
      // a divergence of at most the tolerance for PCG.
      const double allowed = type == PressureSolverType::fast_direct ? 1e-13 : 1e-9;
      EXPECT_LE(max_velocity_change(once, grid), allowed * u_max) << to_string(type) << ", " << describe(walls);
      // Solid walls still carry no normal flow.
      if (isSolid(walls.left)) {
        EXPECT_EQ(grid.u_m_per_s(0, 5), 0.0);
      }
      if (isSolid(walls.top)) {
        EXPECT_EQ(grid.v_m_per_s(7, grid.ny), 0.0);
      }
    }
  }
}

TEST(Projection, FastAndPcgGiveTheSameVelocityAndPressure) {
  for (int mask : {0, 2, 12}) {
    const Walls walls = walls_from_mask(mask);
    MacGrid2 a = random_velocity(40, 40, walls, 7 + mask);
    MacGrid2 b = a;
    FastPressureSolver2 fast;
    PcgPressureSolver2 pcg(1e-12, 2000);
    fast.project(a, walls, 1000.0, 0.02);
    pcg.project(b, walls, 1000.0, 0.02);
    EXPECT_LT(max_velocity_change(a, b), 1e-9 * maxVelocityComponent_m_per_s(a)) << describe(walls);
    double dp = 0.0;
    for (std::size_t k = 0; k < a.pressure_pa.size(); ++k)
      dp = std::max(dp, std::abs(a.pressure_pa.data()[k] - b.pressure_pa.data()[k]));
    EXPECT_LT(dp, 1e-9 * maxAbs(a.pressure_pa)) << describe(walls);
  }
}

// A gradient field is removed entirely; a discrete curl (stream function) is kept unchanged.
TEST(Projection, RemovesGradientsAndKeepsCurls) {
  const Walls walls;  // closed free-slip box
  MacGrid2 grid(16, 16, 0.1);
  Array2 psi(17, 17);
  fill_noise(psi, 5);
  for (int i = 0; i <= 16; ++i) psi(i, 0) = psi(i, 16) = 0.0;  // ψ = 0 on the walls: no flux
  for (int j = 0; j <= 16; ++j) psi(0, j) = psi(16, j) = 0.0;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i <= 16; ++i) grid.u_m_per_s(i, j) = (psi(i, j + 1) - psi(i, j)) / 0.1;
  for (int j = 0; j <= 16; ++j)
    for (int i = 0; i < 16; ++i) grid.v_m_per_s(i, j) = -(psi(i + 1, j) - psi(i, j)) / 0.1;
  const MacGrid2 curl = grid;
  FastPressureSolver2 solver;
  solver.project(grid, walls, 1.0, 1.0);
  EXPECT_LT(max_velocity_change(curl, grid), 1e-12 * maxVelocityComponent_m_per_s(curl));

  MacGrid2 gradient(16, 16, 0.1);
  Array2 phi(16, 16);
  fill_noise(phi, 6);
  subtractGradient(gradient, walls, phi);  // u = −∇φ, zero on the walls
  solver.project(gradient, walls, 1.0, 1.0);
  EXPECT_LT(maxVelocityComponent_m_per_s(gradient), 1e-12);
}

}  // namespace
}  // namespace creaturelab::fluid
