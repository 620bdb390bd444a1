// Parameters declared once (kinds/describe.hpp): the schema, the reading of resolved parameters, the
// way back and the range check all come from one describe(); a kind built on it lists its struct's
// in-class defaults and reads them back unchanged.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "kinds/describe.hpp"
#include "kinds/fish.hpp"
#include "kinds/fluid.hpp"
#include "kinds/oscillator.hpp"
#include "kinds/strand.hpp"

namespace sample {

enum class Scheme { plain, fancy };
inline std::string to_string(Scheme s) { return s == Scheme::plain ? "plain" : "fancy"; }
enum class Law { linear, quadratic };

struct Sample {
  double dt_s = 0.01;
  int cells = 10;
  bool record = true;
  std::string mode = "b";
  std::string note = "hi";
  Scheme scheme = Scheme::fancy;
  Law law = Law::linear;
  creaturelab::kinds::RealOrAuto step_s;

  template <class V>
  void describe(V& v) {
    v.real("dt_s", dt_s, "s", 1e-6, 1, "time step");
    v.integer("cells", cells, 2, 100, "cells per side");
    v.boolean("record", record, "record frames");
    v.choice("mode", mode, {"a", "b"}, "a or b");
    v.text("note", note, "", "free text");
    v.choice("scheme", scheme, {Scheme::plain, Scheme::fancy}, "spelled by to_string");
    v.choice("law", law, {{"linear", Law::linear}, {"quadratic", Law::quadratic}}, "spelled here");
    v.realOrAuto("step_s", step_s, "s", 1e-9, 10, "a step or auto");
  }
};

}  // namespace sample

namespace {

using namespace creaturelab::kinds;
namespace fluid = creaturelab::fluid;

TEST(Describe, SchemaListsEachFieldOnceWithItsInClassDefault) {
  const std::vector<ParamSpec> specs = schemaOf<sample::Sample>();
  ASSERT_EQ(specs.size(), 8u);
  EXPECT_EQ(specs[0].name, "dt_s");
  EXPECT_EQ(specs[0].type, ParamType::Real);
  EXPECT_EQ(std::get<double>(specs[0].default_value), 0.01);
  EXPECT_EQ(specs[0].unit, "s");
  EXPECT_EQ(specs[0].min, 1e-6);
  EXPECT_EQ(specs[0].max, 1.0);
  EXPECT_EQ(specs[0].doc, "time step");
  EXPECT_EQ(specs[1].type, ParamType::Integer);
  EXPECT_EQ(std::get<std::int64_t>(specs[1].default_value), 10);
  EXPECT_EQ(specs[1].max, 100.0);
  EXPECT_EQ(std::get<bool>(specs[2].default_value), true);
  EXPECT_EQ(specs[3].type, ParamType::Choice);
  EXPECT_EQ(specs[3].choices, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(specs[4].type, ParamType::Text);
  EXPECT_EQ(std::get<std::string>(specs[5].default_value), "fancy");
  EXPECT_EQ(specs[5].choices, (std::vector<std::string>{"plain", "fancy"}));
  EXPECT_EQ(std::get<std::string>(specs[6].default_value), "linear");
  EXPECT_EQ(specs[6].choices, (std::vector<std::string>{"linear", "quadratic"}));
  EXPECT_EQ(specs[7].type, ParamType::RealOrAuto);
  EXPECT_EQ(std::get<std::string>(specs[7].default_value), "auto");

  sample::Sample fixed;  // another struct's defaults (a kind composing other defaults)
  fixed.step_s = {false, 0.5};
  EXPECT_EQ(std::get<double>(schemaOf(fixed)[7].default_value), 0.5);
}

TEST(Describe, ReadsResolvedParamsIntoTheFieldsAndBack) {
  Params p = paramsOf(sample::Sample{});
  p["dt_s"] = 0.25;
  p["cells"] = std::int64_t(42);
  p["record"] = false;
  p["mode"] = std::string("a");
  p["scheme"] = std::string("plain");
  p["law"] = std::string("quadratic");
  p["step_s"] = 2.0;
  const sample::Sample s = readParams<sample::Sample>(p);
  EXPECT_EQ(s.dt_s, 0.25);
  EXPECT_EQ(s.cells, 42);
  EXPECT_FALSE(s.record);
  EXPECT_EQ(s.mode, "a");
  EXPECT_EQ(s.scheme, sample::Scheme::plain);
  EXPECT_EQ(s.law, sample::Law::quadratic);
  EXPECT_FALSE(s.step_s.is_auto);
  EXPECT_EQ(s.step_s.value, 2.0);
  EXPECT_EQ(paramsOf(s), p);
  EXPECT_TRUE(readParams<sample::Sample>(paramsOf(sample::Sample{})).step_s.is_auto);
}

TEST(Describe, AMissingOrMistypedNameIsAProgrammingError) {
  Params p = paramsOf(sample::Sample{});
  p.erase("cells");
  EXPECT_THROW(readParams<sample::Sample>(p), std::logic_error);
  p = paramsOf(sample::Sample{});
  p["dt_s"] = std::string("fast");
  EXPECT_THROW(readParams<sample::Sample>(p), std::logic_error);
}

TEST(Describe, RangeProblemsNameEachFieldOutsideItsDescribedRange) {
  EXPECT_EQ(rangeProblems(sample::Sample{}), "");
  sample::Sample s;
  s.dt_s = 2;
  s.cells = 1;
  s.mode = "c";
  EXPECT_EQ(rangeProblems(s),
            "dt_s: got 2, expected a value in [1e-06, 1]; cells: got 1, expected a value in [2, 100]; "
            "mode: got \"c\", expected one of \"a\" | \"b\"");
}

TEST(DescribedKind, OscillatorListsItsStructsDefaultsAndValidatesThroughIt) {
  const OscillatorKind kind;
  const Params defaults = withDefaults(kind, {});
  EXPECT_EQ(defaults, paramsOf(OscillatorParams{}));
  EXPECT_EQ(kind.params().size(), 8u);
  EXPECT_EQ(kind.validate(defaults), "");
  Params p = defaults;
  p["dt_s"] = 5.0;
  p["end_time_s"] = 1.0;
  EXPECT_EQ(kind.validate(p), "dt_s (5 s) is longer than end_time_s (1 s)");
  p["mass_kg"] = -1.0;  // values the runner did not check: the ranges first
  EXPECT_EQ(kind.validate(p), "mass_kg: got -1, expected a value in [1e-12, 1e+06]");
}

TEST(DescribedKind, FluidReadsIntoTheSolversStructAndValidatesThroughIt) {
  const FluidKind kind;
  const fluid::FluidParams solver = readParams<FluidKindParams>(withDefaults(kind, {})).solverParams();
  const fluid::FluidParams plain;  // the solver's in-class defaults are the kind's
  EXPECT_EQ(solver.domain_height_m, plain.domain_height_m);
  EXPECT_EQ(solver.cells_y, plain.cells_y);
  EXPECT_EQ(solver.kinematic_viscosity_m2_per_s, plain.kinematic_viscosity_m2_per_s);
  EXPECT_EQ(solver.time_step_policy, fluid::TimeStepPolicy::cfl_adaptive);

  Params p = withDefaults(kind, {});
  p["domain_m"] = 0.2;
  p["cells"] = std::int64_t(32);
  p["wall_top"] = std::string("moving");
  p["wall_top_velocity_m_per_s"] = 0.5;
  p["advection"] = std::string("maccormack");
  p["dt_s"] = 0.001;
  const fluid::FluidParams f = readParams<FluidKindParams>(p).solverParams();
  EXPECT_EQ(f.domain_width_m, 0.2);
  EXPECT_EQ(f.domain_height_m, 0.2);
  EXPECT_EQ(f.cells_x, 32);
  EXPECT_EQ(f.cells_y, 32);
  EXPECT_EQ(f.walls.top.type, fluid::WallType::moving);
  EXPECT_EQ(f.walls.top.tangential_velocity_m_per_s, 0.5);
  EXPECT_EQ(f.walls.left.type, fluid::WallType::free_slip);
  EXPECT_EQ(f.advection, fluid::AdvectionScheme::maccormack);
  EXPECT_EQ(f.time_step_policy, fluid::TimeStepPolicy::fixed);
  EXPECT_EQ(f.fixed_step_s, 0.001);
  EXPECT_EQ(kind.validate(p), "");

  p["wall_left_velocity_m_per_s"] = 0.25;  // the solver's own cross-field rule, through the kind
  EXPECT_EQ(kind.validate(p),
            "walls.left.tangential_velocity_m_per_s = 0.25 has no effect on a free_slip wall; set walls.left.type = "
            "moving (or inflow) or the velocity to 0");
}

TEST(DescribedKind, FishBuildsItsRunFromTheFishStructsDefaults) {
  const FishKind kind;
  const FishSetup s = readParams<FishKindParams>(withDefaults(kind, {})).setup();
  namespace fish = creaturelab::fish;
  EXPECT_EQ(s.solver.dt_s, fish::SolverParams{}.dt_s);
  EXPECT_EQ(s.solver.water.law, fish::WaterLaw::quadratic);
  EXPECT_EQ(s.units.stiffness_cross_n_per_m, fish::UnitParams{}.stiffness_cross_n_per_m);
  EXPECT_EQ(s.geometry.body_length_m, fish::FishGeometry{}.body_length_m);
  EXPECT_EQ(s.motor.turn_rate, fish::MotorParams{}.turn_rate);
  EXPECT_EQ(s.schedule.size(), 1u);

  Params p = withDefaults(kind, {});
  p["shape"] = std::string("reimplementation");
  p["body_length_m"] = 1.5;
  p["swim_amplitude"] = 0.5;
  p["swim_rate"] = 0.01;
  p["water_law"] = std::string("linear");
  const FishSetup r = readParams<FishKindParams>(p).setup();
  EXPECT_EQ(r.geometry.body_length_m, 1.5);
  EXPECT_EQ(r.geometry.ring_station, fish::reimplementationGeometry().ring_station);
  EXPECT_EQ(r.motor.swim.amplitude_posterior, 0.5);  // one command for both segments
  EXPECT_EQ(r.motor.swim.rate_posterior, 0.01);
  EXPECT_EQ(r.solver.water.law, fish::WaterLaw::linear);

  p["schedule"] = std::string("swim 3; hover 2");
  EXPECT_NE(kind.validate(p).find("schedule: "), std::string::npos);
  p = withDefaults(kind, {});
  p["stable_lo_s"] = 1.0;
  p["stable_hi_s"] = 0.5;
  EXPECT_EQ(kind.validate(p), "stable_lo_s must be below stable_hi_s");
}

TEST(DescribedKind, StrandReadsProvotsOwnStructAndValidatesThroughIt) {
  const StrandKind kind;
  Params p = withDefaults(kind, {});
  EXPECT_EQ(p, paramsOf(StrandParams{}));
  p["provot"] = true;
  p["provot_passes"] = std::int64_t(3);
  const StrandParams q = readParams<StrandParams>(p);
  EXPECT_TRUE(q.provot.enabled);
  EXPECT_EQ(q.provot.passes, 3);
  EXPECT_EQ(q.provot.tolerance, creaturelab::springs::ProvotOptions{}.tolerance);  // not described: stays
  EXPECT_EQ(kind.validate(p), "");
  p["span_m"] = 0.1;
  p["n_springs"] = std::int64_t(10);
  EXPECT_EQ(kind.validate(p), "set span_m or n_springs, not both (the other follows from the placement length)");
}

}  // namespace
