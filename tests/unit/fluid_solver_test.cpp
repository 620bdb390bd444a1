// FluidSolver2 as a whole: time-step policy, blow-up detection, bitwise determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "fluid/diagnostics2.hpp"
#include "fluid/fluid_solver2.hpp"
#include "fluid/initial_conditions2.hpp"

namespace creaturelab::fluid {
namespace {

// FNV-1a over the bytes of the fields.
std::uint64_t hash_state(const FluidSolver2& solver) {
  std::uint64_t h = 1469598103934665603ULL;
  auto add = [&h](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k) h = (h ^ p[k]) * 1099511628211ULL;
  };
  const MacGrid2& g = solver.grid();
  add(g.u_m_per_s.data(), g.u_m_per_s.size() * sizeof(double));
  add(g.v_m_per_s.data(), g.v_m_per_s.size() * sizeof(double));
  add(g.pressure_pa.data(), g.pressure_pa.size() * sizeof(double));
  for (const Vec2& p : solver.tracers_m()) add(&p, sizeof p);
  const double t = solver.time_s();
  add(&t, sizeof t);
  return h;
}

FluidParams vortex_box(AdvectionScheme scheme, PressureSolverType pressure) {
  FluidParams params;
  params.cells_x = params.cells_y = 32;
  params.domain_width_m = params.domain_height_m = 0.4;
  params.kinematic_viscosity_m2_per_s = 1e-4;
  params.advection = scheme;
  params.pressure_solver = pressure;
  params.walls.bottom.type = WallType::no_slip;
  params.walls.top.type = WallType::moving;
  params.walls.top.tangential_velocity_m_per_s = 0.01;
  return params;
}

std::uint64_t run_and_hash(const FluidParams& params, int steps) {
  FluidSolver2 solver(params);
  setVortexPair(solver.grid(), VortexPair{});
  solver.makeDivergenceFree();
  solver.tracers_m() = {{0.1, 0.2}, {0.3, 0.35}};
  solver.forceDensity_n_per_m3().y.fill(0.5);
  for (int s = 0; s < steps; ++s) solver.step();
  return hash_state(solver);
}

// Runs are bitwise deterministic (hash of every field after the same steps).
TEST(FluidSolver, RunsAreBitwiseDeterministic) {
  for (AdvectionScheme scheme : {AdvectionScheme::semi_lagrangian, AdvectionScheme::maccormack}) {
    for (PressureSolverType pressure : {PressureSolverType::fast_direct, PressureSolverType::pcg}) {
      const FluidParams params = vortex_box(scheme, pressure);
      const std::uint64_t first = run_and_hash(params, 12);
      // A second solver, interleaved with a third one, must not see any shared state.
      FluidSolver2 other(vortex_box(AdvectionScheme::maccormack, PressureSolverType::pcg));
      setTaylorGreen(other.grid(), TaylorGreenVortex{0.02});
      other.step();
      const std::uint64_t second = run_and_hash(params, 12);
      EXPECT_EQ(first, second) << to_string(scheme) << ", " << to_string(pressure);
    }
  }
}

TEST(FluidSolver, AdaptiveStepFollowsTheCflCondition) {
  FluidParams params;
  params.cells_x = params.cells_y = 16;
  params.domain_width_m = params.domain_height_m = 1.6;  // dx = 0.1 m
  params.cfl_safety_factor = 0.5;
  params.max_step_s = 0.2;
  FluidSolver2 solver(params);
  EXPECT_DOUBLE_EQ(solver.nextTimeStep_s(), 0.2);  // at rest: the maximum step
  solver.grid().v_m_per_s(3, 4) = -2.0;
  EXPECT_DOUBLE_EQ(solver.nextTimeStep_s(), 0.5 * 0.1 / 2.0);
  const FluidStepReport report = solver.step();
  EXPECT_DOUBLE_EQ(report.dt_s, 0.025);
  EXPECT_DOUBLE_EQ(report.cfl_number, 0.5);
  EXPECT_EQ(report.steps_done, 1);
  EXPECT_LE(report.max_divergence_per_s, 1e-10 * 2.0 / 0.1);

  params.time_step_policy = TimeStepPolicy::fixed;
  params.fixed_step_s = 0.003;
  FluidSolver2 fixed(params);
  fixed.grid().v_m_per_s(3, 4) = -2.0;
  EXPECT_DOUBLE_EQ(fixed.nextTimeStep_s(), 0.003);
  EXPECT_THROW(fixed.step(0.0), std::invalid_argument);
  EXPECT_THROW(fixed.step(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

// Non-finite or runaway velocity throws an error naming the step, the time and the CFL number.
TEST(FluidSolver, BlowUpIsReportedWithStepTimeAndCfl) {
  FluidParams params;
  params.cells_x = params.cells_y = 16;
  params.blowup_speed_m_per_s = 10.0;
  FluidSolver2 solver(params);
  solver.step(0.01);
  // A sheared force (10⁴ m/s² in water on the lower half): a uniform one would be balanced by
  // pressure alone.
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i <= 16; ++i) solver.forceDensity_n_per_m3().x(i, j) = 1e7;
  try {
    solver.step(0.01);
    FAIL() << "expected FluidBlowUpError";
  } catch (const FluidBlowUpError& error) {
    EXPECT_EQ(error.step(), 2);
    EXPECT_DOUBLE_EQ(error.time_s(), 0.02);
    EXPECT_GT(error.cflNumber(), 1.0);
    const std::string message = error.what();
    EXPECT_NE(message.find("blew up at step 2 (t = 0.02 s"), std::string::npos) << message;
    EXPECT_NE(message.find("above blowup_speed_m_per_s = 10"), std::string::npos) << message;
    EXPECT_NE(message.find("CFL number"), std::string::npos) << message;
  }

  FluidSolver2 nan_solver(params);
  nan_solver.forceDensity_n_per_m3().y(3, 3) = std::numeric_limits<double>::quiet_NaN();
  try {
    nan_solver.step(0.01);
    FAIL() << "expected FluidBlowUpError";
  } catch (const FluidBlowUpError& error) {
    EXPECT_EQ(error.step(), 1);
    EXPECT_TRUE(std::isinf(error.cflNumber()));
    EXPECT_NE(std::string(error.what()).find("is inf m/s"), std::string::npos) << error.what();
  }
}

// upwind2_rk2 is explicit: a step above its CFL bound (½) is refused before it starts, with the
// CFL number and the bound in the message; a step just below it runs and stays bounded.
TEST(FluidSolver, ExplicitAdvectionRefusesAStepAboveItsCflBound) {
  FluidParams params;
  params.cells_x = params.cells_y = 32;
  params.advection = AdvectionScheme::upwind2_rk2;
  params.time_step_policy = TimeStepPolicy::fixed;
  FluidSolver2 solver(params);
  VortexPair pair;
  pair.circulation_m2_per_s = 2e-3;
  setVortexPair(solver.grid(), pair);
  solver.makeDivergenceFree();
  const double speed = maxVelocityComponent_m_per_s(solver.grid());
  const double dx = solver.grid().dx_m;
  const double ke0 = solver.kineticEnergy_joule_per_m();
  for (int s = 0; s < 100; ++s) solver.step(0.49 * dx / maxVelocityComponent_m_per_s(solver.grid()));
  EXPECT_LT(solver.kineticEnergy_joule_per_m(), ke0);
  EXPECT_LT(maxVelocityComponent_m_per_s(solver.grid()), speed);
  try {
    solver.step(0.6 * dx / maxVelocityComponent_m_per_s(solver.grid()));
    FAIL() << "expected FluidCflError";
  } catch (const FluidCflError& error) {
    EXPECT_EQ(error.step(), 100);
    EXPECT_NEAR(error.cflNumber(), 0.6, 1e-9);
    EXPECT_EQ(error.bound(), 0.5);
    const std::string message = error.what();
    EXPECT_NE(message.find("has CFL number 0.6, above the stability bound 0.5"), std::string::npos) << message;
  }
  EXPECT_EQ(solver.stepsDone(), 100);  // nothing of the refused step was done
}

TEST(FluidSolver, InitialConditionsBecomeDivergenceFree) {
  FluidParams params;
  params.cells_x = params.cells_y = 32;
  FluidSolver2 solver(params);
  setShearLayer(solver.grid(), ShearLayer{});
  const LinearSolveReport report = solver.makeDivergenceFree();
  EXPECT_TRUE(report.converged);
  const double u_max = maxVelocityComponent_m_per_s(solver.grid());
  EXPECT_GT(u_max, 0.005);
  EXPECT_LE(solver.maxDivergence_per_s(), 1e-10 * u_max / solver.grid().dx_m);
  EXPECT_EQ(maxAbs(solver.grid().pressure_pa), 0.0);
  EXPECT_EQ(solver.grid().u_m_per_s(0, 7), 0.0);  // free-slip walls: no normal flow

  setVortexPair(solver.grid(), VortexPair{});
  solver.makeDivergenceFree();
  Array2 omega;
  vorticityAtCentres(solver.grid(), solver.walls(), omega);
  // The pair heading down: counter-clockwise core on the right, clockwise on the left.
  EXPECT_GT(omega(19, 19), 0.0);
  EXPECT_LT(omega(12, 19), 0.0);
}

// FluidParams::force_stage: a step is the stages in its order, and the order matters when a local
// force sits in a moving flow (the increment is carried by −u·∇u only when added first).
TEST(FluidSolver, ForceStageOrdersTheForceAroundTheAdvection) {
  const double dt = 0.05;
  Array2 u_after[2];
  for (ForceStage stage : {ForceStage::before_advection, ForceStage::after_advection}) {
    FluidParams params = vortex_box(AdvectionScheme::maccormack, PressureSolverType::fast_direct);
    params.force_stage = stage;
    FluidSolver2 whole(params), staged(params);
    for (FluidSolver2* solver : {&whole, &staged}) {
      setVortexPair(solver->grid(), VortexPair{});
      solver->makeDivergenceFree();
      for (int j = 12; j < 18; ++j)
        for (int i = 14; i < 18; ++i) solver->forceDensity_n_per_m3().x(i, j) = 20.0;
    }
    whole.step(dt);
    const StepContext context{0, 0.0, dt};
    if (stage == ForceStage::before_advection) staged.applyExternalForces(context);
    staged.advectVelocity(context);
    if (stage == ForceStage::after_advection) staged.applyExternalForces(context);
    staged.applyViscosity(context);
    staged.project(context);
    EXPECT_EQ(whole.grid().u_m_per_s, staged.grid().u_m_per_s) << to_string(stage);
    EXPECT_EQ(whole.grid().v_m_per_s, staged.grid().v_m_per_s) << to_string(stage);
    u_after[stage == ForceStage::after_advection] = whole.grid().u_m_per_s;
  }
  double largest_difference = 0.0;
  for (int j = 0; j < u_after[0].ny(); ++j)
    for (int i = 0; i < u_after[0].nx(); ++i)
      largest_difference = std::max(largest_difference, std::abs(u_after[1](i, j) - u_after[0](i, j)));
  EXPECT_GT(largest_difference, 1e-7) << largest_difference;  // zero if the order were ignored
}

TEST(FluidParams, ForceStageNamesRoundTrip) {
  for (ForceStage stage : {ForceStage::before_advection, ForceStage::after_advection})
    EXPECT_EQ(parseForceStage(to_string(stage)), stage);
  EXPECT_FALSE(parseForceStage("after").has_value());
}

}  // namespace
}  // namespace creaturelab::fluid
