// Threads inside a step (FluidParams::threads, fluid/worker_pool.hpp) change only the time:
// the state after many steps is bitwise the same for 1, 2 and 3 threads, for every wall type,
// all three advection schemes, both pressure solvers, both viscosity solvers, odd and even grids, and viscosities that take
// the Richardson, the Chebyshev and the CG path of the viscosity stage (Box2D v3's golden-hash test over
// worker counts, STYLE.md).
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "fluid/fluid_solver2.hpp"
#include "fluid/initial_conditions2.hpp"
#include "fluid/worker_pool.hpp"

namespace creaturelab::fluid {
namespace {

struct Scene {
  int nx, ny;
  AdvectionScheme advection;
  PressureSolverType pressure;
  WallType left, right, bottom, top;
  double viscosity_m2_per_s;
  ViscositySolverType viscosity_solver;
};

MacGrid2 run(const Scene& scene, int threads, int steps) {
  FluidParams params;
  params.cells_x = scene.nx;
  params.cells_y = scene.ny;
  params.domain_width_m = 0.4;
  params.domain_height_m = 0.4 * scene.ny / scene.nx;
  params.advection = scene.advection;
  params.pressure_solver = scene.pressure;
  params.walls.left.type = scene.left;
  params.walls.right.type = scene.right;
  params.walls.bottom.type = scene.bottom;
  params.walls.top.type = scene.top;
  if (scene.top == WallType::moving) params.walls.top.tangential_velocity_m_per_s = 0.01;
  params.kinematic_viscosity_m2_per_s = scene.viscosity_m2_per_s;
  params.viscosity_solver = scene.viscosity_solver;
  params.body_acceleration_y_m_per_s2 = -9.81;
  params.threads = threads;
  FluidSolver2 solver(params);
  VortexPair pair;
  pair.circulation_m2_per_s = 2e-3;
  setVortexPair(solver.grid(), pair);
  solver.makeDivergenceFree();
  solver.tracers_m() = {{0.1, 0.2}, {0.3, 0.15}};
  for (int s = 0; s < steps; ++s) {
    solver.forceDensity_n_per_m3().x(scene.nx / 2, scene.ny / 3) = 3.0 * (s % 4);  // like a spread IB force
    solver.step();
  }
  return solver.grid();
}

void expect_bitwise_equal(const MacGrid2& a, const MacGrid2& b) {
  EXPECT_TRUE(a.u_m_per_s == b.u_m_per_s);
  EXPECT_TRUE(a.v_m_per_s == b.v_m_per_s);
  EXPECT_TRUE(a.pressure_pa == b.pressure_pa);
}

TEST(FluidThreads, StateIsBitwiseTheSameForOneTwoAndThreeThreads) {
  using A = AdvectionScheme;
  using P = PressureSolverType;
  const WallType F = WallType::free_slip, N = WallType::no_slip, M = WallType::moving, O = WallType::open;
  const ViscositySolverType I = ViscositySolverType::iterative, D = ViscositySolverType::fast_direct;
  const std::vector<Scene> scenes = {
      {50, 50, A::maccormack, P::fast_direct, F, F, F, F, 1.304e-6, I},   // the jellyfish's box (Richardson)
      {64, 64, A::semi_lagrangian, P::fast_direct, F, F, F, F, 1e-4, I},  // Chebyshev viscosity
      {64, 64, A::semi_lagrangian, P::fast_direct, F, F, F, F, 0.1, I},   // CG viscosity (alpha g > 64)
      {37, 53, A::maccormack, P::fast_direct, N, N, N, M, 1e-3, I},       // dense transform, Chebyshev
      {40, 31, A::maccormack, P::fast_direct, F, O, N, F, 1e-4, I},       // open wall
      {30, 34, A::semi_lagrangian, P::pcg, O, O, O, O, 1e-4, I},
      {48, 45, A::maccormack, P::fast_direct, F, F, F, O, 1e-4, I},      // transform along x
      {50, 50, A::upwind2_rk2, P::fast_direct, F, F, F, F, 1.304e-6, I},  // Eulerian flux form
      {37, 53, A::upwind2_rk2, P::fast_direct, N, N, N, M, 1e-3, I},
      {30, 34, A::upwind2_rk2, P::pcg, O, O, O, O, 1e-4, I},
      // the fast direct viscosity solver: FFT both ways, dense along y and x, open walls
      {50, 50, A::upwind2_rk2, P::fast_direct, F, F, F, F, 1.304e-6, D},
      {37, 53, A::maccormack, P::fast_direct, N, N, N, M, 1e-3, D},
      {40, 31, A::upwind2_rk2, P::fast_direct, F, O, N, F, 1e-4, D},
      {30, 34, A::semi_lagrangian, P::pcg, O, O, O, O, 1e-4, D},
  };
  for (const Scene& scene : scenes) {
    SCOPED_TRACE(::testing::Message() << scene.nx << "x" << scene.ny << " advection "
                                      << to_string(scene.advection) << " nu " << scene.viscosity_m2_per_s << " "
                                      << to_string(scene.viscosity_solver));
    const MacGrid2 one = run(scene, 1, 15);
    expect_bitwise_equal(one, run(scene, 2, 15));
    expect_bitwise_equal(one, run(scene, 3, 15));
  }
}

TEST(WorkerPool, PiecesCoverTheRangeOnceAndEveryPartRuns) {
  // 5 threads: 20 parts over 98 indices (pieces of 4 and 5).
  for (int threads : {1, 2, 3, 5}) {
    WorkerPool pool(threads);
    std::vector<std::atomic<int>> hits(101);
    std::atomic<int> parts_run{0};
    forPieces(&pool, 3, 101, [&](int lo, int hi, int) {
      for (int k = lo; k < hi; ++k) hits[k].fetch_add(1);
      parts_run.fetch_add(1);
    });
    for (int k = 0; k < 101; ++k) EXPECT_EQ(hits[k].load(), k >= 3 ? 1 : 0) << "index " << k;
    EXPECT_EQ(parts_run.load(), pool.parts());
    EXPECT_EQ(pool.parts(), threads == 1 ? 1 : threads * kPartsPerThread);
    for (int repeat = 0; repeat < 100; ++repeat) pool.run([](int) {});  // many short tasks
  }
}

}  // namespace
}  // namespace creaturelab::fluid
