// The inflow wall (WallType::inflow, boundary2.hpp): a prescribed flux that every stage keeps.
// A held band of faces beside an open floor lost flux to the projection, by an amount
// that depended on the step; these tests pin what the wall must do instead.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fluid/boundary2.hpp"
#include "fluid/diagnostics2.hpp"
#include "fluid/fluid_solver2.hpp"
#include "fluid/staggered_sampler2.hpp"

namespace creaturelab::fluid {
namespace {

constexpr double kInflow = 0.4;  // m/s

// A vertical channel: fluid enters through the floor, leaves through the open top.
FluidParams channel(AdvectionScheme scheme, PressureSolverType pressure, ViscositySolverType viscosity) {
  FluidParams p;
  p.cells_x = 12;
  p.cells_y = 16;
  p.domain_width_m = 0.6;
  p.domain_height_m = 0.8;
  p.walls.bottom.type = WallType::inflow;
  p.walls.bottom.inflow_m_per_s = kInflow;
  p.walls.top.type = WallType::open;
  p.kinematic_viscosity_m2_per_s = 1e-3;
  p.advection = scheme;
  p.pressure_solver = pressure;
  p.pressure_tolerance = 1e-13;
  p.viscosity_solver = viscosity;
  p.viscosity_tolerance = 1e-13;
  p.time_step_policy = TimeStepPolicy::fixed;
  p.fixed_step_s = 0.02;  // CFL 0.4 at the inflow speed (upwind2_rk2's bound is 0.5)
  return p;
}

std::string name(const FluidParams& p) {
  return std::string(to_string(p.advection)) + ", " + std::string(to_string(p.pressure_solver)) + ", " +
         std::string(to_string(p.viscosity_solver));
}

// From rest, the first projection makes the uniform stream v = U (the only divergence-free field
// with this flux in a free-slip channel), and every stage then keeps it: advection, viscosity
// (the wall's face enters the viscous stencil) and the projection.
TEST(InflowWall, ChannelFromRestBecomesAndStaysTheUniformStream) {
  for (AdvectionScheme scheme :
       {AdvectionScheme::semi_lagrangian, AdvectionScheme::maccormack, AdvectionScheme::upwind2_rk2}) {
    for (PressureSolverType pressure : {PressureSolverType::fast_direct, PressureSolverType::pcg}) {
      for (ViscositySolverType viscosity : {ViscositySolverType::iterative, ViscositySolverType::fast_direct}) {
        const FluidParams params = channel(scheme, pressure, viscosity);
        FluidSolver2 solver(params);
        for (int s = 0; s < 6; ++s) solver.step();
        const MacGrid2& g = solver.grid();
        for (int i = 0; i < g.nx; ++i) EXPECT_EQ(g.v_m_per_s(i, 0), kInflow) << name(params);
        EXPECT_NEAR(maxAbs(g.u_m_per_s), 0.0, 1e-10) << name(params);
        for (int j = 0; j <= g.ny; ++j)
          for (int i = 0; i < g.nx; ++i)
            ASSERT_NEAR(g.v_m_per_s(i, j), kInflow, 1e-10) << name(params) << " " << i << "," << j;
      }
    }
  }
}

// Viscosity alone: the wall's face is a neighbour of the first row of faces, so the uniform stream
// is a fixed point of the implicit step only if the wall's speed enters its stencil.
TEST(InflowWall, ViscosityAloneKeepsTheUniformStream) {
  for (ViscositySolverType viscosity : {ViscositySolverType::iterative, ViscositySolverType::fast_direct}) {
    FluidParams params = channel(AdvectionScheme::maccormack, PressureSolverType::fast_direct, viscosity);
    params.kinematic_viscosity_m2_per_s = 0.05;  // α = ν dt / dx² = 0.4
    FluidSolver2 solver(params);
    solver.stages() = FluidStages{false, false, true, false, false};
    solver.grid().v_m_per_s.fill(kInflow);
    solver.step();
    const MacGrid2& g = solver.grid();
    for (int j = 0; j <= g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        ASSERT_NEAR(g.v_m_per_s(i, j), kInflow, 1e-11) << name(params) << " " << i << "," << j;
  }
}

// The projection keeps the wall's flux whatever the interior: a arbitrary field projected leaves the
// floor faces at U and sends exactly the inflow out through the open top.
TEST(InflowWall, ProjectionKeepsTheFluxOfARandomField) {
  FluidParams params = channel(AdvectionScheme::maccormack, PressureSolverType::fast_direct,
                               ViscositySolverType::fast_direct);
  params.walls.left.type = WallType::no_slip;
  FluidSolver2 solver(params);
  MacGrid2& g = solver.grid();
  // An arbitrary field, far from divergence free.
  for (std::size_t k = 0; k < g.u_m_per_s.size(); ++k) g.u_m_per_s.data()[k] = std::sin(1.7 * double(k));
  for (std::size_t k = 0; k < g.v_m_per_s.size(); ++k) g.v_m_per_s.data()[k] = std::cos(2.3 * double(k));
  enforceWallNormalVelocity(g, solver.walls());
  solver.project({0, 0.0, 0.01});
  double in = 0.0, out = 0.0;
  for (int i = 0; i < g.nx; ++i) {
    EXPECT_EQ(g.v_m_per_s(i, 0), kInflow);
    in += g.v_m_per_s(i, 0) * g.dx_m;
    out += g.v_m_per_s(i, g.ny) * g.dx_m;
  }
  EXPECT_NEAR(out, in, 1e-12);
  EXPECT_LT(maxDivergence_per_s(g), 1e-9);
}

// An inflow wall on the right (its speed points into the domain: −x there) with an open left.
TEST(InflowWall, HighSideWallPointsIntoTheDomain) {
  FluidParams params = channel(AdvectionScheme::maccormack, PressureSolverType::fast_direct,
                               ViscositySolverType::fast_direct);
  params.walls.bottom = {};
  params.walls.top = {};
  params.walls.right.type = WallType::inflow;
  params.walls.right.inflow_m_per_s = kInflow;
  params.walls.left.type = WallType::open;
  FluidSolver2 solver(params);
  for (int s = 0; s < 4; ++s) solver.step();
  const MacGrid2& g = solver.grid();
  for (int j = 0; j < g.ny; ++j) {
    EXPECT_EQ(g.u_m_per_s(g.nx, j), -kInflow);
    EXPECT_NEAR(g.u_m_per_s(0, j), -kInflow, 1e-10);
  }
}

TEST(InflowWall, TangentialGhostHoldsTheWallsTangentialSpeed) {
  MacGrid2 grid(4, 4, 1.0);
  grid.u_m_per_s.fill(2.0);
  Walls walls;
  walls.bottom.type = WallType::inflow;
  walls.bottom.inflow_m_per_s = 1.0;
  walls.bottom.tangential_velocity_m_per_s = -0.5;
  walls.top.type = WallType::open;
  StaggeredComponent2 u;
  u.assign(FaceAxis::x, grid.u_m_per_s, walls);
  EXPECT_DOUBLE_EQ(u.sample(2.0, 0.0), -0.5);
}

TEST(InflowWall, ValidationNamesWhatIsWrong) {
  FluidParams closed;
  closed.walls.bottom.type = WallType::inflow;
  closed.walls.bottom.inflow_m_per_s = 1.0;
  EXPECT_NE(closed.validate().find("needs an open wall"), std::string::npos) << closed.validate();

  FluidParams stray;
  stray.walls.top.type = WallType::open;
  stray.walls.left.inflow_m_per_s = 1.0;
  EXPECT_NE(stray.validate().find("walls.left.inflow_m_per_s"), std::string::npos) << stray.validate();

  EXPECT_EQ(parseWallType("inflow"), WallType::inflow);
  EXPECT_EQ(to_string(WallType::inflow), "inflow");
}

}  // namespace
}  // namespace creaturelab::fluid
