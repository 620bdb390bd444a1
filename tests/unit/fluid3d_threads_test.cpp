// Determinism: the 3-D step gives bitwise the same state for 1 and 2 threads (parallel3.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fluid3d/fluid_solver3.hpp"
#include "fluid3d/initial_conditions3.hpp"

namespace creaturelab::fluid3d {
namespace {

MacGrid3 run(int threads, PressureSolverType3 pressure, AdvectionScheme3 advection) {
  FluidParams3 p;
  // FFTs along x (periodic) and y (solid-solid), the dense transform along z (an open top).
  p.cells_x = 16, p.cells_y = 8, p.cells_z = 10;
  p.domain_x_m = 0.16, p.domain_y_m = 0.08, p.domain_z_m = 0.1;
  p.boundaries.axis[0] = {BoundaryType3::periodic, BoundaryType3::periodic};
  p.boundaries.axis[1] = {BoundaryType3::no_slip, BoundaryType3::free_slip};
  p.boundaries.axis[2] = {BoundaryType3::no_slip, BoundaryType3::open};
  p.kinematic_viscosity_m2_per_s = 1e-4;
  p.viscosity_scheme = ViscosityScheme3::crank_nicolson;
  p.pressure_solver = pressure;
  p.advection = advection;
  p.body_acceleration_m_per_s2 = {0.0, 0.0, -1.0};
  p.threads = threads;
  FluidSolver3 solver(p);
  AbcFlow flow;
  flow.a_m_per_s = 0.05, flow.b_m_per_s = 0.03, flow.c_m_per_s = 0.02;
  flow.wavenumber_per_m = 2 * std::numbers::pi / 0.1;
  setAbcFlow(solver.grid(), flow, 0.0);
  solver.makeDivergenceFree();
  for (int s = 0; s < 4; ++s) solver.step();
  return solver.grid();
}

TEST(Fluid3dThreads, OneAndTwoThreadsGiveBitwiseTheSameState) {
  for (PressureSolverType3 pressure : {PressureSolverType3::mg_pcg, PressureSolverType3::spectral}) {
    for (AdvectionScheme3 advection :
         {AdvectionScheme3::semi_lagrangian, AdvectionScheme3::maccormack, AdvectionScheme3::upwind2_rk2}) {
      const MacGrid3 one = run(1, pressure, advection), two = run(2, pressure, advection);
      for (int a = 0; a < 3; ++a) EXPECT_TRUE(one.velocity_m_per_s[a] == two.velocity_m_per_s[a]) << a;
      EXPECT_TRUE(one.pressure_pa == two.pressure_pa);
      EXPECT_GT(std::fabs(one.velocity_m_per_s[0](3, 4, 5)), 1e-4);  // the flow is not trivial
    }
  }
}

}  // namespace
}  // namespace creaturelab::fluid3d
