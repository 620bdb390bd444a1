// Inflow sides of the 3-D solver (BoundaryType3::inflow): the floor source of Lentine et al. 2010
// §7.1 ("open at the top and closed elsewhere with a source term at the floor forcing fluid flow
// upwards") as a floor through which fluid enters at a prescribed speed.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid3d/fluid_solver3.hpp"
#include "fluid3d/initial_conditions3.hpp"

namespace creaturelab::fluid3d {
namespace {

constexpr double kSpeed_m_per_s = 0.05;

// An 8 × 8 × 12 box of 1 cm cells: fluid enters through the floor at kSpeed_m_per_s, leaves by the
// open top; the four sides are walls of type `sides`.
FluidParams3 updraft(BoundaryType3 sides) {
  FluidParams3 p;
  p.cells_x = p.cells_y = 8, p.cells_z = 12;
  p.domain_x_m = p.domain_y_m = 0.08, p.domain_z_m = 0.12;
  p.boundaries = Boundaries3::allWalls(sides);
  p.boundaries.axis[2] = {BoundaryType3::inflow, BoundaryType3::open, kSpeed_m_per_s, 0.0};
  p.kinematic_viscosity_m2_per_s = 1e-4;  // Re = U L / ν = 40
  p.pressure_tolerance = 1e-12;
  return p;
}

// Volume flux (m³/s) through the faces of w at height index k, upwards.
double upwardFlux_m3_per_s(const MacGrid3& g, int k) {
  double sum = 0.0;
  for (int j = 0; j < g.n[1]; ++j)
    for (int i = 0; i < g.n[0]; ++i) sum += g.velocity_m_per_s[2](i, j, k);
  return sum * g.dx_m * g.dx_m;
}

// Every face of the floor holds the prescribed speed exactly.
bool floorHoldsTheInflowSpeed(const MacGrid3& g) {
  for (int j = 0; j < g.n[1]; ++j)
    for (int i = 0; i < g.n[0]; ++i)
      if (g.velocity_m_per_s[2](i, j, 0) != kSpeed_m_per_s) return false;
  return true;
}

// Flux in through the floor equals flux out through the open top to the pressure solve's tolerance,
// and the velocity is divergence-free to round-off, for each advection and viscosity scheme, with
// no-slip side walls (a boundary layer grows, the flow is not uniform).
TEST(Fluid3dInflow, FluxInEqualsFluxOutThroughTheOpenTop) {
  for (AdvectionScheme3 advection :
       {AdvectionScheme3::semi_lagrangian, AdvectionScheme3::maccormack, AdvectionScheme3::upwind2_rk2}) {
    for (ViscosityScheme3 viscosity :
         {ViscosityScheme3::backward_euler, ViscosityScheme3::crank_nicolson, ViscosityScheme3::explicit_euler}) {
      FluidParams3 p = updraft(BoundaryType3::no_slip);
      p.advection = advection;
      p.viscosity_scheme = viscosity;
      FluidSolver3 solver(p);
      solver.makeDivergenceFree();
      for (int s = 0; s < 6; ++s) solver.step(0.05);  // CFL ≤ 0.25 · max|w| / U (below ⅓ while max|w| < 1.33 U)
      const MacGrid3& g = solver.grid();
      const double in = kSpeed_m_per_s * 0.08 * 0.08;
      EXPECT_TRUE(floorHoldsTheInflowSpeed(g));
      EXPECT_NEAR(upwardFlux_m3_per_s(g, 12), in, 1e-10 * in) << toString(advection) << " " << toString(viscosity);
      EXPECT_LT(solver.maxDivergence_per_s(), 1e-9 * kSpeed_m_per_s / g.dx_m);
      // The side walls slow the fluid beside them, so it rises faster in the middle.
      EXPECT_GT(g.velocity_m_per_s[2](4, 4, 6), 1.05 * kSpeed_m_per_s);
      EXPECT_LT(g.velocity_m_per_s[2](0, 4, 6), 0.9 * kSpeed_m_per_s);
    }
  }
}

// Between free-slip walls the uniform updraft w = U is the exact steady solution: every stage keeps
// it (the viscosity's right-hand side carries the inflow face, the ghosts the inflow speed).
TEST(Fluid3dInflow, UniformUpdraftIsSteadyBetweenFreeSlipWalls) {
  for (AdvectionScheme3 advection :
       {AdvectionScheme3::semi_lagrangian, AdvectionScheme3::maccormack, AdvectionScheme3::upwind2_rk2}) {
    for (ViscosityScheme3 viscosity :
         {ViscosityScheme3::backward_euler, ViscosityScheme3::crank_nicolson, ViscosityScheme3::explicit_euler}) {
      FluidParams3 p = updraft(BoundaryType3::free_slip);
      p.advection = advection;
      p.viscosity_scheme = viscosity;
      FluidSolver3 solver(p);
      solver.grid().velocity_m_per_s[2].fill(kSpeed_m_per_s);
      for (int s = 0; s < 4; ++s) solver.step(0.05);
      double worst = 0.0;
      for (int a = 0; a < 3; ++a) {
        const Array3& u = solver.grid().velocity_m_per_s[a];
        for (std::size_t t = 0; t < u.size(); ++t)
          worst = std::max(worst, std::fabs(u.data()[t] - (a == 2 ? kSpeed_m_per_s : 0.0)));
      }
      EXPECT_LT(worst, 1e-12 * kSpeed_m_per_s) << toString(advection) << " " << toString(viscosity);
    }
  }
}

// The spectral solve sees an inflow side as a wall, like MG-PCG: the two projections of an ABC flow
// with the inflow agree.
TEST(Fluid3dInflow, SpectralAndMultigridProjectionsAgree) {
  FluidParams3 p = updraft(BoundaryType3::no_slip);
  FluidSolver3 mg(p);
  p.pressure_solver = PressureSolverType3::spectral;
  FluidSolver3 spectral(p);
  AbcFlow flow;
  flow.a_m_per_s = 0.02, flow.b_m_per_s = 0.03, flow.c_m_per_s = 0.01;
  flow.wavenumber_per_m = 50.0;
  for (FluidSolver3* s : {&mg, &spectral}) {
    setAbcFlow(s->grid(), flow, 0.0);
    s->makeDivergenceFree();
  }
  double worst = 0.0;
  for (int a = 0; a < 3; ++a)
    for (std::size_t t = 0; t < mg.grid().velocity_m_per_s[a].size(); ++t)
      worst = std::max(worst, std::fabs(mg.grid().velocity_m_per_s[a].data()[t] -
                                        spectral.grid().velocity_m_per_s[a].data()[t]));
  EXPECT_LT(worst, 1e-10 * kSpeed_m_per_s);
  EXPECT_TRUE(floorHoldsTheInflowSpeed(spectral.grid()));
  EXPECT_NEAR(upwardFlux_m3_per_s(spectral.grid(), 12), kSpeed_m_per_s * 0.08 * 0.08, 1e-12);
  EXPECT_LT(spectral.maxDivergence_per_s(), 1e-9 * kSpeed_m_per_s / p.cellSize_m());
}

TEST(Fluid3dInflow, AnInflowWithoutAnOpenSideIsRefused) {
  FluidParams3 p = updraft(BoundaryType3::no_slip);
  p.boundaries.axis[2].high = BoundaryType3::no_slip;
  EXPECT_NE(p.validate().find("inflow side needs an open side"), std::string::npos) << p.validate();
  p = updraft(BoundaryType3::no_slip);
  p.boundaries.axis[2].low_inflow_m_per_s = std::nan("");
  EXPECT_NE(p.validate().find("inflow speed must be finite"), std::string::npos) << p.validate();
}

}  // namespace
}  // namespace creaturelab::fluid3d
