// A start that is mirror-symmetric about the vertical mid-line stays symmetric to round-off:
// a vortex pair driving itself down onto a wall (the jellyfish's axis of symmetry, paper §3.1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "fluid/diagnostics2.hpp"
#include "fluid/fluid_solver2.hpp"
#include "fluid/initial_conditions2.hpp"

namespace creaturelab::fluid {
namespace {

// max over faces of the mirror defect, u(x) + u(W − x) and v(x) − v(W − x), over max |u|.
double relative_asymmetry(const MacGrid2& g) {
  double defect = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i <= g.nx; ++i) defect = std::max(defect, std::abs(g.u_m_per_s(i, j) + g.u_m_per_s(g.nx - i, j)));
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      defect = std::max(defect, std::abs(g.v_m_per_s(i, j) - g.v_m_per_s(g.nx - 1 - i, j)));
  return defect / maxVelocityComponent_m_per_s(g);
}

void check_symmetry(AdvectionScheme scheme, PressureSolverType pressure, const Walls& walls, double limit) {
  FluidParams params;
  params.cells_x = params.cells_y = 64;
  params.advection = scheme;
  params.pressure_solver = pressure;
  params.walls = walls;
  params.kinematic_viscosity_m2_per_s = 1e-5;
  FluidSolver2 solver(params);
  VortexPair pair;
  pair.circulation_m2_per_s = 2e-2;
  setVortexPair(solver.grid(), pair);
  solver.makeDivergenceFree();
  const double start = relative_asymmetry(solver.grid());
  const double y_start = 0.6 * params.domain_height_m;
  double worst = start;
  int steps = 0;
  while (solver.time_s() < 5.0) {
    solver.step();
    ++steps;
    worst = std::max(worst, relative_asymmetry(solver.grid()));
  }
  // The pair has travelled down to the wall meanwhile (its vorticity peak moved).
  Array2 omega;
  vorticityAtCentres(solver.grid(), solver.walls(), omega);
  int peak_j = 0;
  double peak = 0.0;
  for (int j = 0; j < 64; ++j)
    for (int i = 32; i < 64; ++i)
      if (omega(i, j) > peak) peak = omega(i, j), peak_j = j;
  std::printf("  %-15s %-11s %-24s steps %4d, initial %.2e, worst %.2e; core y %.3f -> %.3f m\n",
              std::string(to_string(scheme)).c_str(), std::string(to_string(pressure)).c_str(),
              walls.closed() ? "closed free-slip box" : "open top", steps, start, worst, y_start,
              (peak_j + 0.5) * solver.grid().dx_m);
  EXPECT_LE(worst, limit) << to_string(scheme) << ", " << to_string(pressure);
  EXPECT_LT((peak_j + 0.5) * solver.grid().dx_m, 0.75 * y_start);
}

TEST(MirrorSymmetry, VortexPairStaysSymmetric) {
  Walls open_top;
  open_top.top.type = WallType::open;
  for (AdvectionScheme scheme : {AdvectionScheme::semi_lagrangian, AdvectionScheme::maccormack}) {
    check_symmetry(scheme, PressureSolverType::fast_direct, Walls{}, 1e-12);
    check_symmetry(scheme, PressureSolverType::fast_direct, open_top, 1e-12);
    check_symmetry(scheme, PressureSolverType::pcg, Walls{}, 1e-10);
  }
}

}  // namespace
}  // namespace creaturelab::fluid
