// FluidParams::validate() messages and enum names.
#include "fluid/fluid_params.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "fluid/fluid_solver2.hpp"

namespace creaturelab::fluid {
namespace {

TEST(FluidParams, DefaultsAreValid) { EXPECT_EQ(FluidParams{}.validate(), ""); }

TEST(FluidParams, TooFewCellsNamesTheKeyAndTheValue) {
  FluidParams params;
  params.cells_x = 1;
  const std::string message = params.validate();
  EXPECT_NE(message.find("cells_x must be between 2 and"), std::string::npos) << message;
  EXPECT_NE(message.find("(got 1)"), std::string::npos) << message;
}

TEST(FluidParams, NonSquareCellsSuggestAFix) {
  FluidParams params;
  params.domain_width_m = 0.4;
  params.domain_height_m = 0.3;
  params.cells_x = 100;
  params.cells_y = 100;
  const std::string message = params.validate();
  EXPECT_NE(message.find("cells must be square"), std::string::npos) << message;
  EXPECT_NE(message.find("cells_y = 75"), std::string::npos) << message;
}

TEST(FluidParams, PhysicalQuantitiesMustBeFiniteAndPositive) {
  FluidParams params;
  params.density_kg_per_m3 = 0.0;
  params.kinematic_viscosity_m2_per_s = -1.0;
  params.domain_width_m = std::numeric_limits<double>::quiet_NaN();
  const std::string message = params.validate();
  EXPECT_NE(message.find("density_kg_per_m3 must be a positive number of kg/m^3 (got 0)"), std::string::npos)
      << message;
  EXPECT_NE(message.find("kinematic_viscosity_m2_per_s must be zero or a positive number"), std::string::npos)
      << message;
  EXPECT_NE(message.find("domain_width_m must be a positive number of metres (got nan)"), std::string::npos) << message;
  // Problems are joined into one message, one sentence each.
  EXPECT_NE(message.find("; "), std::string::npos);
}

TEST(FluidParams, TangentialVelocityNeedsAMovingWall) {
  FluidParams params;
  params.walls.top.tangential_velocity_m_per_s = 1.0;
  const std::string message = params.validate();
  EXPECT_NE(message.find("walls.top.tangential_velocity_m_per_s = 1 has no effect on a free_slip wall"),
            std::string::npos)
      << message;
  params.walls.top.type = WallType::moving;
  EXPECT_EQ(params.validate(), "");
}

TEST(FluidParams, SolverSettingsAreChecked) {
  FluidParams params;
  params.pressure_tolerance = 0.0;
  params.viscosity_max_iterations = 0;
  params.cfl_safety_factor = -0.5;
  params.max_step_s = 0.0;
  params.blowup_speed_m_per_s = std::numeric_limits<double>::infinity();
  params.threads = 0;
  const std::string message = params.validate();
  EXPECT_NE(message.find("pressure_tolerance must lie between 0 and 1"), std::string::npos) << message;
  EXPECT_NE(message.find("viscosity_max_iterations must be at least 1 (got 0)"), std::string::npos) << message;
  EXPECT_NE(message.find("cfl_safety_factor must be above 0 and at most 10 (got -0.5"), std::string::npos) << message;
  EXPECT_NE(message.find("max_step_s must be a positive number of seconds (got 0)"), std::string::npos) << message;
  EXPECT_NE(message.find("blowup_speed_m_per_s must be a positive number of m/s (got inf)"), std::string::npos)
      << message;
  EXPECT_NE(message.find("threads must be between 1 and 16 (got 0)"), std::string::npos) << message;
}

TEST(FluidParams, SolverRefusesInvalidParameters) {
  FluidParams params;
  params.cells_y = 0;
  try {
    FluidSolver2 solver(params);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("invalid fluid parameters: cells_y must be between 2"), std::string::npos)
        << error.what();
  }
}

// The explicit scheme's stability bound is a bad input when the adaptive step would exceed it.
TEST(FluidParams, AdaptiveStepAboveTheExplicitSchemesBoundIsRefused) {
  FluidParams params;
  params.advection = AdvectionScheme::upwind2_rk2;
  EXPECT_EQ(params.validate(), "");  // the default safety factor 0.5 is at the bound
  params.cfl_safety_factor = 0.8;
  EXPECT_NE(params.validate().find("cfl_safety_factor 0.8 is above the stability bound 0.5 of advection = upwind2_rk2"),
            std::string::npos)
      << params.validate();
  params.time_step_policy = TimeStepPolicy::fixed;  // checked at step time instead
  EXPECT_EQ(params.validate(), "");
}

TEST(FluidParams, EnumNamesRoundTrip) {
  for (WallType t : {WallType::free_slip, WallType::no_slip, WallType::moving, WallType::open}) {
    EXPECT_EQ(parseWallType(to_string(t)), t);
  }
  for (AdvectionScheme s :
       {AdvectionScheme::semi_lagrangian, AdvectionScheme::maccormack, AdvectionScheme::upwind2_rk2}) {
    EXPECT_EQ(parseAdvectionScheme(to_string(s)), s);
  }
  for (PressureSolverType s : {PressureSolverType::fast_direct, PressureSolverType::pcg}) {
    EXPECT_EQ(parsePressureSolverType(to_string(s)), s);
  }
  for (TimeStepPolicy p : {TimeStepPolicy::cfl_adaptive, TimeStepPolicy::fixed}) {
    EXPECT_EQ(parseTimeStepPolicy(to_string(p)), p);
  }
  for (ViscositySolverType s : {ViscositySolverType::iterative, ViscositySolverType::fast_direct}) {
    EXPECT_EQ(parseViscositySolverType(to_string(s)), s);
  }
  EXPECT_FALSE(parseViscositySolverType("direct").has_value());
  EXPECT_FALSE(parseWallType("freeslip").has_value());
}

}  // namespace
}  // namespace creaturelab::fluid
