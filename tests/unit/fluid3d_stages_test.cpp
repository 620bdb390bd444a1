// Stages of the 3-D fluid step, each alone against an analytic answer (Jet's one-stage tests).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fluid3d/fluid_solver3.hpp"
#include "fluid3d/initial_conditions3.hpp"
#include "fluid3d/velocity_sampler3.hpp"

namespace creaturelab::fluid3d {
namespace {

FluidParams3 smallBox(const Boundaries3& sides, int n = 8) {
  FluidParams3 p;
  p.cells_x = p.cells_y = p.cells_z = n;
  p.domain_x_m = p.domain_y_m = p.domain_z_m = 0.08;
  p.boundaries = sides;
  return p;
}

void onlyStage(FluidSolver3& solver, bool forces, bool advection, bool viscosity, bool pressure) {
  solver.stages() = {forces, advection, viscosity, pressure};
}

// Jet's check: with only external forces, one 0.01 s step under g = −10 m/s² gives w = −0.1 m/s
// on every face that is not a solid wall's.
TEST(Fluid3dStages, GravityAloneAcceleratesTheFluid) {
  FluidParams3 p = smallBox(Boundaries3::allWalls(BoundaryType3::free_slip));
  p.body_acceleration_m_per_s2 = {0.0, 0.0, -10.0};
  FluidSolver3 solver(p);
  onlyStage(solver, true, false, false, false);
  solver.step(0.01);
  const Array3& w = solver.grid().velocity_m_per_s[2];
  EXPECT_DOUBLE_EQ(w(3, 4, 4), -0.1);
  EXPECT_EQ(w(3, 4, 0), 0.0);
  EXPECT_EQ(w(3, 4, 8), 0.0);
  EXPECT_EQ(solver.grid().velocity_m_per_s[0](4, 4, 4), 0.0);
}

// In a closed box gravity is balanced by a hydrostatic pressure: the projection removes it all,
// and the pressure rises by ρ g dx per cell downwards.
TEST(Fluid3dStages, ClosedBoxHoldsGravityByHydrostaticPressure) {
  FluidParams3 p = smallBox(Boundaries3::allWalls(BoundaryType3::no_slip));
  p.body_acceleration_m_per_s2 = {0.0, 0.0, -9.81};
  FluidSolver3 solver(p);
  onlyStage(solver, true, false, false, true);
  solver.step(0.01);
  EXPECT_LT(solver.maxVelocityComponent_m_per_s(), 1e-9 * 0.0981);  // MG-PCG tolerance 1e-10
  const double per_cell = p.density_kg_per_m3 * 9.81 * p.cellSize_m();
  EXPECT_NEAR(solver.grid().pressure_pa(2, 3, 2) - solver.grid().pressure_pa(2, 3, 3), per_cell, 1e-6 * per_cell);
}

// The incremental projection: after the first step has found the hydrostatic pressure, the next
// predictor's (dt/ρ) ∇pⁿ cancels gravity's dt g, so the projection's increment is nearly zero and the
// pressure stays.
TEST(Fluid3dStages, IncrementalProjectionCarriesTheHydrostaticPressure) {
  FluidParams3 p = smallBox(Boundaries3::allWalls(BoundaryType3::no_slip));
  p.body_acceleration_m_per_s2 = {0.0, 0.0, -9.81};
  p.projection = ProjectionScheme3::incremental;
  FluidSolver3 solver(p);
  onlyStage(solver, true, false, false, true);
  solver.step(0.01);
  const Array3 first = solver.grid().pressure_pa;
  solver.step(0.01);
  EXPECT_LT(solver.maxVelocityComponent_m_per_s(), 1e-9 * 0.0981);
  double change = 0.0;
  for (std::size_t t = 0; t < first.size(); ++t)
    change = std::max(change, std::fabs(solver.grid().pressure_pa.data()[t] - first.data()[t]));
  const double per_cell = p.density_kg_per_m3 * 9.81 * p.cellSize_m();
  EXPECT_LT(change, 1e-8 * per_cell);
  p.viscosity_scheme = ViscosityScheme3::crank_nicolson;
  EXPECT_NE(p.validate().find("projection = incremental needs"), std::string::npos) << p.validate();
}

// Advection of a uniform flow in a periodic box leaves it uniform, bit for bit (a + t (b − a)).
TEST(Fluid3dStages, UniformFlowAdvectsUnchanged) {
  for (AdvectionScheme3 scheme :
       {AdvectionScheme3::semi_lagrangian, AdvectionScheme3::maccormack, AdvectionScheme3::upwind2_rk2}) {
    FluidParams3 p = smallBox(Boundaries3::allPeriodic());
    p.advection = scheme;
    FluidSolver3 solver(p);
    for (int a = 0; a < 3; ++a) solver.grid().velocity_m_per_s[a].fill(0.1 * (a + 1));
    onlyStage(solver, false, true, false, false);
    solver.step(0.0065);  // CFL 0.0195 / 0.01 · 0.3 / 0.01: 0.195, below upwind2_rk2's bound of 1/3
    for (int a = 0; a < 3; ++a)
      for (std::size_t t = 0; t < solver.grid().velocity_m_per_s[a].size(); ++t)
        ASSERT_EQ(solver.grid().velocity_m_per_s[a].data()[t], 0.1 * (a + 1)) << toString(scheme);
  }
}

// A shear wave u = sin(2π y / L) carried by a uniform w moves with it: after a step of exactly
// one cell, semi-Lagrangian advection reproduces the shifted field to round-off (t = 0 or 1).
TEST(Fluid3dStages, AdvectionShiftsByWholeCellsExactly) {
  FluidParams3 p = smallBox(Boundaries3::allPeriodic());
  p.advection = AdvectionScheme3::semi_lagrangian;
  FluidSolver3 solver(p);
  MacGrid3& g = solver.grid();
  const double L = 0.08, dx = p.cellSize_m();
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) g.velocity_m_per_s[0](i, j, k) = std::sin(2 * std::numbers::pi * (k + 0.5) / 8);
  g.velocity_m_per_s[2].fill(1.0);
  onlyStage(solver, false, true, false, false);
  solver.step(dx / 1.0);
  for (int k = 0; k < 8; ++k)
    EXPECT_NEAR(g.velocity_m_per_s[0](3, 2, k), std::sin(2 * std::numbers::pi * (((k + 7) % 8) + 0.5) / 8), 1e-12);
  (void)L;
}

// Viscosity alone on a discrete eigenmode: backward Euler multiplies it by 1 / (1 + ν dt k_h²)
// with k_h² = (2 − 2 cos(k dx)) / dx², Crank–Nicolson by (1 − ½ν dt k_h²) / (1 + ½ν dt k_h²).
TEST(Fluid3dStages, ViscosityDampsAnEigenmodeByTheSchemesFactor) {
  for (ViscosityScheme3 scheme : {ViscosityScheme3::backward_euler, ViscosityScheme3::crank_nicolson,
                                  ViscosityScheme3::explicit_euler}) {
    FluidParams3 p = smallBox(Boundaries3::allPeriodic());
    p.kinematic_viscosity_m2_per_s = 1e-3;
    p.viscosity_scheme = scheme;
    p.viscosity_tolerance = 1e-13;
    FluidSolver3 solver(p);
    AbcFlow flow;
    flow.wavenumber_per_m = 2 * std::numbers::pi / 0.08;
    setAbcFlow(solver.grid(), flow, 0.0);
    const double before = solver.grid().velocity_m_per_s[0](2, 3, 5);
    onlyStage(solver, false, false, true, false);
    const double dt = 0.01, dx = p.cellSize_m();
    solver.step(dt);
    const double kh2 = (2.0 - 2.0 * std::cos(flow.wavenumber_per_m * dx)) / (dx * dx);
    const double x = p.kinematic_viscosity_m2_per_s * dt * kh2;
    const double factor = scheme == ViscosityScheme3::backward_euler   ? 1.0 / (1.0 + x)
                          : scheme == ViscosityScheme3::crank_nicolson ? (1.0 - 0.5 * x) / (1.0 + 0.5 * x)
                                                                       : 1.0 - x;
    EXPECT_NEAR(solver.grid().velocity_m_per_s[0](2, 3, 5), factor * before, 1e-12) << toString(scheme);
  }
}

// No-slip walls take momentum out of a flow along them; free-slip walls do not.
TEST(Fluid3dStages, NoSlipWallsDragTheFlowFreeSlipWallsDoNot) {
  double energy_after[2];
  for (int t = 0; t < 2; ++t) {
    FluidParams3 p = smallBox(Boundaries3::allWalls(t == 0 ? BoundaryType3::free_slip : BoundaryType3::no_slip));
    p.boundaries.axis[0] = {BoundaryType3::periodic, BoundaryType3::periodic};  // the flow runs along x
    p.kinematic_viscosity_m2_per_s = 1e-4;
    FluidSolver3 solver(p);
    Array3& u = solver.grid().velocity_m_per_s[0];
    for (int k = 0; k < 8; ++k)
      for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) u(i, j, k) = 0.01;
    onlyStage(solver, false, false, true, false);
    const double before = solver.kineticEnergy_joule();
    solver.step(0.01);
    energy_after[t] = solver.kineticEnergy_joule() / before;
  }
  EXPECT_NEAR(energy_after[0], 1.0, 1e-10);
  EXPECT_LT(energy_after[1], 0.99);  // about 2 % lost in one step at nu dt / dx^2 = 0.01
}

// The explicit upwind scheme refuses a step above its stability bound (CFL 1/3), before changing
// anything; the adaptive step stays below it.
TEST(Fluid3dStages, UpwindAdvectionRefusesAnUnstableStep) {
  FluidParams3 p = smallBox(Boundaries3::allPeriodic());
  p.advection = AdvectionScheme3::upwind2_rk2;
  p.cfl_safety_factor = 0.9;
  p.max_step_s = 1.0;
  FluidSolver3 solver(p);
  solver.grid().velocity_m_per_s[0].fill(0.1);
  const MacGrid3 before = solver.grid();
  EXPECT_THROW(solver.step(0.04), FluidBlowUpError3);  // CFL 0.4
  EXPECT_TRUE(solver.grid().velocity_m_per_s[0] == before.velocity_m_per_s[0]);
  EXPECT_NEAR(solver.nextTimeStep_s() * 0.1 / p.cellSize_m(), 1.0 / 3.0, 1e-12);
  EXPECT_NO_THROW(solver.step());
}

// A flow straight through a box open at the bottom and the top is divergence-free: the projection
// keeps it (the open sides are unknowns, p = 0 on them), while a solid bottom would stop it.
TEST(Fluid3dStages, FlowLeavesThroughOpenSides) {
  Boundaries3 sides = Boundaries3::allWalls(BoundaryType3::no_slip);
  sides.axis[2] = {BoundaryType3::open, BoundaryType3::open};
  FluidParams3 p = smallBox(sides);
  p.pressure_solver = PressureSolverType3::spectral;
  FluidSolver3 solver(p);
  solver.grid().velocity_m_per_s[2].fill(0.05);
  onlyStage(solver, false, false, false, true);
  solver.step(0.01);
  EXPECT_NEAR(solver.grid().velocity_m_per_s[2](3, 4, 8), 0.05, 1e-15);
  EXPECT_NEAR(solver.grid().velocity_m_per_s[2](0, 7, 0), 0.05, 1e-15);
  EXPECT_LT(solver.maxDivergence_per_s(), 1e-12);
}

// The sampler returns a face's own value at the face, and reproduces a linear field in between.
TEST(Fluid3dStages, VelocitySamplerInterpolatesTrilinearly) {
  FluidParams3 p = smallBox(Boundaries3::allWalls(BoundaryType3::free_slip));
  FluidSolver3 solver(p);
  MacGrid3& g = solver.grid();
  for (int a = 0; a < 3; ++a) {
    Array3& u = g.velocity_m_per_s[a];
    for (int k = 0; k < u.nz(); ++k)
      for (int j = 0; j < u.ny(); ++j)
        for (int i = 0; i < u.nx(); ++i) {
          const std::array<double, 3> x = g.facePosition_m(a, i, j, k);
          u(i, j, k) = 1.0 + 2.0 * x[0] - 3.0 * x[1] + 0.5 * x[2] + a;
        }
  }
  VelocitySampler3 sampler;
  sampler.update(g);
  EXPECT_DOUBLE_EQ(sampler.velocity_m_per_s(g.facePosition_m(1, 3, 2, 5))[1], g.velocity_m_per_s[1](3, 2, 5));
  const std::array<double, 3> x{0.0213, 0.0377, 0.0461};  // inside, away from the walls' ghosts
  const std::array<double, 3> v = sampler.velocity_m_per_s(x);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(v[a], 1.0 + 2.0 * x[0] - 3.0 * x[1] + 0.5 * x[2] + a, 1e-14);
}

TEST(Fluid3dStages, BadParametersAreRefusedInWords) {
  FluidParams3 p;
  p.cells_y = 1;
  p.boundaries.axis[0].low = BoundaryType3::periodic;
  p.kinematic_viscosity_m2_per_s = -1.0;
  const std::string message = p.validate();
  EXPECT_NE(message.find("cells_y"), std::string::npos) << message;
  EXPECT_NE(message.find("periodic on one side"), std::string::npos) << message;
  EXPECT_NE(message.find("kinematic_viscosity"), std::string::npos) << message;
  EXPECT_THROW(FluidSolver3{p}, std::invalid_argument);
  FluidParams3 q;
  q.domain_z_m = 0.5;
  EXPECT_NE(q.validate().find("cubes"), std::string::npos);
  EXPECT_TRUE(FluidParams3{}.validate().empty());
}

}  // namespace
}  // namespace creaturelab::fluid3d
