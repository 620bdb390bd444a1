// The fast direct viscosity solver (fluid/fast_diffusion2.hpp) against the iterative solver, for
// every wall type and transform path (its analytic tests, an eigenmode and the Couette profile,
// run for both solvers in fluid_stages_test.cpp).
#include <gtest/gtest.h>

#include <vector>

#include "fluid/boundary2.hpp"
#include "fluid/diffusion2.hpp"
#include "fluid/fast_diffusion2.hpp"
#include "fluid/initial_conditions2.hpp"

namespace creaturelab::fluid {
namespace {

using Method = FastPressureSolver2::Method;

struct Case {
  int nx, ny;
  WallType left, right, bottom, top;
  Method uMethod, vMethod;
};

// Same field, same walls: the direct solution and a CG solve to 1e-14 agree to 1e-12 ‖b‖∞
// (A = I + α L with L ≥ 0: ‖x − x*‖∞ ≲ ‖b − A x‖∞), at α from water on the paper's grid to
// far beyond the Richardson range; the report's residual is round-off.
TEST(FastDiffusion, AgreesWithTheIterativeSolverForEveryWallAndPath) {
  const WallType F = WallType::free_slip, N = WallType::no_slip, M = WallType::moving, O = WallType::open;
  const std::vector<Case> cases = {
      {40, 30, F, F, F, F, Method::fft_along_y, Method::fft_along_x},    // the jellyfish's box
      {37, 53, N, N, N, M, Method::dense_along_y, Method::dense_along_x},  // no FFT anywhere
      {40, 31, F, O, N, F, Method::dense_along_y, Method::fft_along_x},  // open and no-slip
      {30, 34, O, O, O, O, Method::dense_along_y, Method::fft_along_x},  // open box: Neumann lanes
      {48, 45, F, F, F, O, Method::dense_along_y, Method::fft_along_x},
  };
  for (const Case& c : cases) {
    Walls walls;
    walls.left.type = c.left, walls.right.type = c.right, walls.bottom.type = c.bottom, walls.top.type = c.top;
    if (c.top == M) walls.top.tangential_velocity_m_per_s = 0.05;
    for (double alpha : {6.7e-4, 0.05, 2.0, 300.0}) {
      SCOPED_TRACE(::testing::Message() << c.nx << "x" << c.ny << " alpha " << alpha);
      const double dx = 0.01;
      MacGrid2 grid(c.nx, c.ny, dx);
      setVortexPair(grid, VortexPair{});
      for (int j = 0; j < c.ny; ++j)
        for (int i = 0; i <= c.nx; ++i) grid.u_m_per_s(i, j) += 1e-3 * (((i * 7 + j * 13) % 5) - 2);
      for (int j = 0; j <= c.ny; ++j)
        for (int i = 0; i < c.nx; ++i) grid.v_m_per_s(i, j) += 1e-3 * (((i * 11 + j * 3) % 7) - 3);
      enforceWallNormalVelocity(grid, walls);  // the stage's precondition
      const double b_norm = std::max(maxAbs(grid.u_m_per_s), maxAbs(grid.v_m_per_s));
      MacGrid2 reference = grid;
      const double nu = 1e-3, dt = alpha * dx * dx / nu;
      FastDiffusion2 direct(1e-12);
      const LinearSolveReport r = direct.diffuseVelocity(grid, walls, nu, dt);
      EXPECT_TRUE(r.converged);
      EXPECT_LE(r.relative_residual, 1e-12);
      EXPECT_EQ(direct.uMethod(), c.uMethod);
      EXPECT_EQ(direct.vMethod(), c.vMethod);
      ImplicitDiffusion2 iterative(1e-14, 5000);
      EXPECT_TRUE(iterative.diffuseVelocity(reference, walls, nu, dt).converged);
      const double tolerance = 1e-12 * b_norm;
      EXPECT_LE(maxAbsDifference(grid.u_m_per_s.data(), reference.u_m_per_s.data(), grid.u_m_per_s.size()),
                tolerance);
      EXPECT_LE(maxAbsDifference(grid.v_m_per_s.data(), reference.v_m_per_s.data(), grid.v_m_per_s.size()),
                tolerance);
    }
  }
}

}  // namespace
}  // namespace creaturelab::fluid
