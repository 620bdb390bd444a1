// Experiment files (DESIGN.md "Experiment files"): parsing, sweeps, cases, overrides,
// and the user errors that must name the file, the key, a close match and what was expected.
#include "runner/experiment.hpp"
#include "runner/checks.hpp"
#include "runner/cost.hpp"
#include "test_registry.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace creaturelab;
using runner::Experiment;
using runner::ExperimentError;
using runner::Point;
using kinds::Value;

using creaturelab::testing::registry;

Experiment load(const std::string& text, const std::vector<std::string>& overrides = {},
                const std::string& path = "exp/test.toml") {
  return runner::loadExperimentText(text, path, overrides, registry());
}

std::vector<Point> points(const Experiment& e) { return runner::expandPoints(e, *registry().find(e.kind)); }

// The message of the ExperimentError that loading (and expanding) `text` throws; "" (and a test
// failure) when nothing is thrown.
std::string errorOf(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    const Experiment e = load(text, overrides);
    points(e);
  } catch (const ExperimentError& err) {
    return err.what();
  }
  ADD_FAILURE() << "no ExperimentError for:\n" << text;
  return "";
}

double real(const Value& v) { return std::get<double>(v); }
std::int64_t integer(const Value& v) { return std::get<std::int64_t>(v); }
const std::string& text(const Value& v) { return std::get<std::string>(v); }

// ---- parsing ----

TEST(RunnerExperiment, ParamsOverrideDefaultsAndTheRestAreFilled) {
  const Experiment e = load(R"(
kind = "strand"
title = "a strand"
[params]
n_springs = 20
mass_kg = 2e-8
end_time_s = 3          # an integer literal is a fine real
integrator = "symplectic_euler"
)");
  EXPECT_EQ(e.kind, "strand");
  EXPECT_EQ(e.title, "a strand");
  EXPECT_EQ(e.stem, "test");
  EXPECT_EQ(e.path, "exp/test.toml");
  EXPECT_EQ(e.params.size(), 4u);  // only the overrides
  const auto pts = points(e);
  ASSERT_EQ(pts.size(), 1u);
  const auto& p = pts[0].params;
  EXPECT_EQ(pts[0].index, 0);
  EXPECT_EQ(pts[0].label, "");
  EXPECT_EQ(integer(p.at("n_springs")), 20);
  EXPECT_EQ(real(p.at("mass_kg")), 2e-8);
  ASSERT_TRUE(std::holds_alternative<double>(p.at("end_time_s")));
  EXPECT_EQ(real(p.at("end_time_s")), 3.0);
  EXPECT_EQ(text(p.at("integrator")), "symplectic_euler");
  // Defaults for everything else, and every declared parameter present.
  EXPECT_EQ(real(p.at("spring_k_n_per_m")), 0.01);
  EXPECT_EQ(real(p.at("rest_length_m")), 0.003);
  EXPECT_EQ(text(p.at("layout")), "overextended");
  EXPECT_EQ(text(p.at("dt_s")), "auto");
  EXPECT_EQ(std::get<bool>(p.at("provot")), false);
  EXPECT_EQ(p.size(), registry().find("strand")->params().size());
}

TEST(RunnerExperiment, TitleDefaultsToTheFileStem) {
  const Experiment e = load("kind = \"oscillator\"\n", {}, "some/dir/my_experiment.toml");
  EXPECT_EQ(e.stem, "my_experiment");
  EXPECT_EQ(e.title, "my_experiment");
  EXPECT_TRUE(e.axes.empty());
  EXPECT_TRUE(e.cases.empty());
  EXPECT_EQ(points(e).size(), 1u);
}

TEST(RunnerExperiment, SweepListKeepsValuesAndCoercesIntegersToReals) {
  const Experiment e = load(R"(
kind = "oscillator"
[sweep]
dt_s = [0.01, 0.005, 1]
)");
  ASSERT_EQ(e.axes.size(), 1u);
  EXPECT_EQ(e.axes[0].name, "dt_s");
  ASSERT_EQ(e.axes[0].values.size(), 3u);
  EXPECT_EQ(real(e.axes[0].values[0]), 0.01);
  EXPECT_EQ(real(e.axes[0].values[1]), 0.005);
  EXPECT_EQ(real(e.axes[0].values[2]), 1.0);
}

TEST(RunnerExperiment, RangeIncludesStopAndGivesExactDecimals) {
  const Experiment e = load(R"(
kind = "oscillator"
[sweep]
dt_s = "0.1:0.5:0.1"
)");
  ASSERT_EQ(e.axes.size(), 1u);
  const auto& v = e.axes[0].values;
  ASSERT_EQ(v.size(), 5u);
  // Bitwise equal to the decimal literals (0.1 + 2*0.1 would be 0.30000000000000004).
  EXPECT_EQ(real(v[0]), 0.1);
  EXPECT_EQ(real(v[1]), 0.2);
  EXPECT_EQ(real(v[2]), 0.3);
  EXPECT_EQ(real(v[3]), 0.4);
  EXPECT_EQ(real(v[4]), 0.5);
}

TEST(RunnerExperiment, RangeAsInTheDesignCard) {
  // DESIGN.md's "0.3:1.5:0.1": 13 values, (1.5 - 0.3) / 0.1 = 11.999999999999998 in doubles.
  const Experiment e = load(R"(
kind = "strand"
[sweep]
overextension = "0.3:1.5:0.1"
)");
  const auto& v = e.axes.at(0).values;
  ASSERT_EQ(v.size(), 13u);
  const double expected[] = {0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5};
  for (size_t i = 0; i < v.size(); ++i) EXPECT_EQ(real(v[i]), expected[i]) << "value " << i;
}

TEST(RunnerExperiment, RangeStopOffTheGridIsNotIncluded) {
  const Experiment e = load("kind = \"strand\"\n[sweep]\noverextension = \"0:1:0.3\"\n");
  const auto& v = e.axes.at(0).values;
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(real(v[3]), 0.9);
}

TEST(RunnerExperiment, RangeOfOneValueAndOverAnIntegerParameter) {
  const Experiment one = load("kind = \"strand\"\n[sweep]\noverextension = \"2:2:1\"\n");
  ASSERT_EQ(one.axes.at(0).values.size(), 1u);
  EXPECT_EQ(real(one.axes.at(0).values[0]), 2.0);

  const Experiment ints = load("kind = \"strand\"\n[sweep]\nn_springs = \"10:30:10\"\n");
  const auto& v = ints.axes.at(0).values;
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(integer(v[0]), 10);
  EXPECT_EQ(integer(v[1]), 20);
  EXPECT_EQ(integer(v[2]), 30);
}

TEST(RunnerExperiment, SweepIsTheProductWithTheLastAxisFastest) {
  // toml++ iterates keys in sorted order: the axes are dt_s, then integrator, whatever the file order.
  const Experiment e = load(R"(
kind = "oscillator"
[sweep]
integrator = ["rk4", "euler"]
dt_s = [0.01, 0.02, 0.03]
)");
  ASSERT_EQ(e.axes.size(), 2u);
  EXPECT_EQ(e.axes[0].name, "dt_s");
  EXPECT_EQ(e.axes[1].name, "integrator");
  EXPECT_EQ(runner::sweepColumns(e), (std::vector<std::string>{"dt_s", "integrator"}));
  const auto pts = points(e);
  ASSERT_EQ(pts.size(), 6u);
  const double dt[] = {0.01, 0.01, 0.02, 0.02, 0.03, 0.03};
  const char* integ[] = {"rk4", "euler", "rk4", "euler", "rk4", "euler"};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(pts[i].index, i);
    EXPECT_EQ(real(pts[i].params.at("dt_s")), dt[i]) << "point " << i;
    EXPECT_EQ(text(pts[i].params.at("integrator")), integ[i]) << "point " << i;
    EXPECT_EQ(real(pts[i].params.at("end_time_s")), 10.0);  // default
  }
}

TEST(RunnerExperiment, CasesAreOuterAndCombineWithTheSweep) {
  const Experiment e = load(R"(
kind = "strand"
[params]
n_springs = 10
[sweep]
spring_k_n_per_m = [0.01, 0.02]
[[case]]
label = "rest"
layout = "rest"
overextension = 0.0
[[case]]
label = "stretched"
overextension = 1.5
provot = true
[[case]]
overextension = 2.5
)");
  ASSERT_EQ(e.cases.size(), 3u);
  EXPECT_EQ(e.cases[2].label, "case 2");  // an unlabelled case gets its position
  // Case keys (first appearance; toml++ gives each case's keys alphabetically), then the axes.
  EXPECT_EQ(runner::sweepColumns(e),
            (std::vector<std::string>{"layout", "overextension", "provot", "spring_k_n_per_m"}));
  const auto pts = points(e);
  ASSERT_EQ(pts.size(), 6u);
  const char* labels[] = {"rest", "rest", "stretched", "stretched", "case 2", "case 2"};
  const double ovx[] = {0.0, 0.0, 1.5, 1.5, 2.5, 2.5};
  const double k[] = {0.01, 0.02, 0.01, 0.02, 0.01, 0.02};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(pts[i].index, i);
    EXPECT_EQ(pts[i].label, labels[i]);
    EXPECT_EQ(real(pts[i].params.at("overextension")), ovx[i]) << "point " << i;
    EXPECT_EQ(real(pts[i].params.at("spring_k_n_per_m")), k[i]) << "point " << i;
    EXPECT_EQ(integer(pts[i].params.at("n_springs")), 10);  // [params] under every case
  }
  // A key a case does not set keeps the [params] value or the default.
  EXPECT_EQ(text(pts[0].params.at("layout")), "rest");
  EXPECT_EQ(text(pts[2].params.at("layout")), "overextended");
  EXPECT_EQ(std::get<bool>(pts[2].params.at("provot")), true);
  EXPECT_EQ(std::get<bool>(pts[4].params.at("provot")), false);
}

TEST(RunnerExperiment, CaseOverridesParams) {
  const Experiment e = load(R"(
kind = "strand"
[params]
overextension = 0.5
[[case]]
label = "a"
[[case]]
label = "b"
overextension = 2.0
)");
  const auto pts = points(e);
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(real(pts[0].params.at("overextension")), 0.5);
  EXPECT_EQ(real(pts[1].params.at("overextension")), 2.0);
}

TEST(RunnerExperiment, ChecksAreParsed) {
  const Experiment e = load(R"(
kind = "oscillator"
[sweep]
integrator = ["rk4", "euler"]
dt_s = [0.01, 0.02]
[[check]]
name = "best"
type = "argmin"
metric = "max_abs_error_m"
axis = "integrator"
expect = "rk4"
[[check]]
name = "mono"
type = "monotonic"
metric = "max_abs_error_m"
axis = "dt_s"
direction = "decreasing"
strict = false
where = { integrator = "rk4" }
[[check]]
name = "ratio"
type = "ratio"
metric = "max_abs_error_m"
numerator = { integrator = "rk4", dt_s = 0.02 }
denominator = { integrator = "rk4", dt_s = 0.01 }
expect = [12, 20.5]
)");
  ASSERT_EQ(e.checks.size(), 3u);
  const auto& a = e.checks[0];
  EXPECT_EQ(a.type, "argmin");
  ASSERT_TRUE(a.expect_choice.has_value());
  EXPECT_EQ(*a.expect_choice, "rk4");
  const auto& m = e.checks[1];
  EXPECT_EQ(m.direction, "decreasing");
  EXPECT_FALSE(m.strict);
  ASSERT_EQ(m.where.size(), 1u);
  EXPECT_EQ(m.where[0].first, "integrator");
  EXPECT_EQ(text(m.where[0].second), "rk4");
  const auto& r = e.checks[2];
  EXPECT_EQ(r.expect_lo, 12.0);
  EXPECT_EQ(r.expect_hi, 20.5);
  EXPECT_EQ(r.numerator.size(), 2u);
  EXPECT_EQ(r.denominator.size(), 2u);
  EXPECT_TRUE(e.checks[0].strict);  // default
}

TEST(RunnerExperiment, CheckAxisMayBeACaseKey) {
  EXPECT_NO_THROW(load(R"(
kind = "strand"
[[case]]
overextension = 0.75
[[case]]
overextension = 1.5
[[check]]
name = "sag falls"
type = "monotonic"
metric = "mid_sag_m"
axis = "overextension"
direction = "decreasing"
where = { label = "case 0" }
)"));
}

TEST(RunnerExperiment, OutputTable) {
  const Experiment e = load("kind = \"oscillator\"\n[output]\ndir = \"somewhere\"\nlagrangian = false\n");
  EXPECT_EQ(e.output.dir, "somewhere");
  EXPECT_FALSE(e.output.lagrangian);
  const Experiment d = load("kind = \"oscillator\"\n");
  EXPECT_EQ(d.output.dir, "");
  EXPECT_TRUE(d.output.lagrangian);
}

// ---- command-line overrides ----

const char* kStrand = R"(
kind = "strand"
[params]
n_springs = 20
[sweep]
spring_k_n_per_m = [0.01, 0.02]
)";

TEST(RunnerExperiment, OverrideReplacesAParam) {
  const Experiment e = load(kStrand, {"params.n_springs=3"});
  EXPECT_EQ(integer(e.params.at("n_springs")), 3);
  EXPECT_EQ(e.overrides, (std::vector<std::string>{"params.n_springs=3"}));
  EXPECT_NE(e.resolved_json.find("\"n_springs\":3"), std::string::npos) << e.resolved_json;
}

TEST(RunnerExperiment, OverrideAddsAParamWithoutAParamsTable) {
  const Experiment e = load("kind = \"oscillator\"\n", {"params.end_time_s=3"});
  EXPECT_EQ(real(e.params.at("end_time_s")), 3.0);
}

TEST(RunnerExperiment, OverrideReplacesASweepAxis) {
  const Experiment e = load(kStrand, {"sweep.spring_k_n_per_m=[1,2]"});
  ASSERT_EQ(e.axes.size(), 1u);
  ASSERT_EQ(e.axes[0].values.size(), 2u);
  EXPECT_EQ(real(e.axes[0].values[0]), 1.0);
  EXPECT_EQ(real(e.axes[0].values[1]), 2.0);
}

TEST(RunnerExperiment, OverrideAddsASweepAxisAsARange) {
  const Experiment e = load(kStrand, {"sweep.overextension=0.5:1.5:0.5"});
  ASSERT_EQ(e.axes.size(), 2u);
  EXPECT_EQ(e.axes[0].name, "overextension");
  EXPECT_EQ(e.axes[0].values.size(), 3u);
  EXPECT_EQ(points(e).size(), 6u);
}

TEST(RunnerExperiment, OverrideTakesBareWordsAsStrings) {
  const Experiment e = load(kStrand, {"params.integrator=rk4", "params.layout=rest", "params.dt_s=auto"});
  EXPECT_EQ(text(e.params.at("integrator")), "rk4");
  EXPECT_EQ(text(e.params.at("layout")), "rest");
  EXPECT_EQ(text(e.params.at("dt_s")), "auto");
  const Experiment q = load(kStrand, {"params.integrator=\"implicit_euler\"", "params.provot=true"});
  EXPECT_EQ(text(q.params.at("integrator")), "implicit_euler");
  EXPECT_EQ(std::get<bool>(q.params.at("provot")), true);
}

TEST(RunnerExperiment, OverridesApplyInOrderLastWins) {
  const Experiment e = load(kStrand, {"params.n_springs=3", "params.n_springs=4"});
  EXPECT_EQ(integer(e.params.at("n_springs")), 4);
}

TEST(RunnerExperiment, OverrideErrors) {
  std::string m = errorOf(kStrand, {"params.n_springs"});
  EXPECT_NE(m.find("dotted.key=value"), std::string::npos) << m;
  m = errorOf(kStrand, {"=3"});
  EXPECT_NE(m.find("dotted.key=value"), std::string::npos) << m;
  m = errorOf(kStrand, {"kind.x=1"});
  EXPECT_NE(m.find("'kind' is not a table"), std::string::npos) << m;
  m = errorOf(kStrand, {"params.n_sprigns=3"});
  EXPECT_NE(m.find("unknown parameter 'n_sprigns'"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'n_springs'"), std::string::npos) << m;
  m = errorOf(kStrand, {"params.n_springs=many"});
  EXPECT_NE(m.find("params.n_springs"), std::string::npos) << m;
  EXPECT_NE(m.find("expected an integer"), std::string::npos) << m;
  m = errorOf(kStrand, {"params.integrator=rk5"});
  EXPECT_NE(m.find("\"rk4\""), std::string::npos) << m;  // lists the choices
  m = errorOf(kStrand, {"sweeps.n_springs=[1]"});
  EXPECT_NE(m.find("unknown key 'sweeps'"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'sweep'"), std::string::npos) << m;
}

// ---- errors: each names the file, the key and what was expected ----

TEST(RunnerExperimentError, MalformedTomlNamesFileAndLine) {
  const std::string m = errorOf("kind = \"strand\"\n[params\nn_springs = 3\n");
  EXPECT_EQ(m.rfind("exp/test.toml:2:", 0), 0u) << m;
  EXPECT_NE(m.find("malformed TOML"), std::string::npos) << m;

  const std::string m2 = errorOf("kind = \"strand\"\n\n\n[params]\nn_springs = = 3\n");
  EXPECT_EQ(m2.rfind("exp/test.toml:5:", 0), 0u) << m2;
}

TEST(RunnerExperimentError, MissingFileIsNamed) {
  try {
    runner::loadExperiment("/nonexistent/dir/nope.toml", {}, registry());
    FAIL() << "no error";
  } catch (const ExperimentError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/nope.toml"), std::string::npos) << e.what();
  }
}

TEST(RunnerExperimentError, UnknownParamNamesItAndTheLine) {
  const std::string m = errorOf("kind = \"strand\"\n[params]\nn_spring = 3\n");
  EXPECT_EQ(m.rfind("exp/test.toml:3: params.n_spring:", 0), 0u) << m;
  EXPECT_NE(m.find("unknown parameter 'n_spring' for kind 'strand'"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'n_springs'"), std::string::npos) << m;
}

TEST(RunnerExperimentError, UnknownParamSuggestsTheNameWithItsUnit) {
  // Users drop the unit suffix: "spring_k" must lead to "spring_k_n_per_m" (the issue's example).
  const std::string m = errorOf("kind = \"strand\"\n[params]\nspring_k = 0.01\n");
  EXPECT_NE(m.find("unknown parameter 'spring_k'"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'spring_k_n_per_m'"), std::string::npos) << m;
}

TEST(RunnerExperimentError, UnknownSweepAndCaseKeys) {
  std::string m = errorOf("kind = \"oscillator\"\n[sweep]\nintegrater = [\"rk4\"]\n");
  EXPECT_NE(m.find("sweep.integrater"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'integrator'"), std::string::npos) << m;
  m = errorOf("kind = \"oscillator\"\n[[case]]\nlabel = \"x\"\nmass_gk = 1.0\n");
  EXPECT_NE(m.find("case[0].mass_gk"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'mass_kg'"), std::string::npos) << m;
}

TEST(RunnerExperimentError, UnknownTopLevelCheckAndOutputKeys) {
  std::string m = errorOf("kind = \"oscillator\"\ntitel = \"x\"\n");
  EXPECT_NE(m.find("unknown key 'titel'"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'title'"), std::string::npos) << m;
  EXPECT_NE(m.find("exp/test.toml:2"), std::string::npos) << m;
  m = errorOf(R"(kind = "oscillator"
[sweep]
dt_s = [0.01, 0.02]
[[check]]
name = "c"
type = "range"
metrik = "max_abs_error_m"
expect = [0, 1]
)");
  EXPECT_NE(m.find("unknown key 'metrik'"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'metric'"), std::string::npos) << m;
  m = errorOf("kind = \"oscillator\"\n[output]\ndri = \"x\"\n");
  EXPECT_NE(m.find("unknown key 'dri'"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'dir'"), std::string::npos) << m;
}

TEST(RunnerExperimentError, WrongTypes) {
  std::string m = errorOf("kind = \"strand\"\n[params]\nn_springs = \"ten\"\n");
  EXPECT_EQ(m.rfind("exp/test.toml:3: params.n_springs: got \"ten\", expected an integer", 0), 0u) << m;
  m = errorOf("kind = \"strand\"\n[params]\nn_springs = 2.5\n");
  EXPECT_NE(m.find("expected an integer"), std::string::npos) << m;
  m = errorOf("kind = \"strand\"\n[params]\nmass_kg = \"heavy\"\n");
  EXPECT_NE(m.find("params.mass_kg: got \"heavy\", expected a number"), std::string::npos) << m;
  m = errorOf("kind = \"strand\"\n[params]\nprovot = 1\n");
  EXPECT_NE(m.find("expected true or false"), std::string::npos) << m;
  m = errorOf("kind = \"strand\"\n[params]\nlayout = \"sideways\"\n");
  EXPECT_NE(m.find("expected one of \"rest\" | \"overextended\""), std::string::npos) << m;
  m = errorOf("kind = \"strand\"\n[params]\nmass_kg = [1, 2]\n");
  EXPECT_NE(m.find("params.mass_kg: expected a number"), std::string::npos) << m;
  m = errorOf("kind = \"strand\"\nparams = 3\n");
  EXPECT_NE(m.find("expected a table [params]"), std::string::npos) << m;
  m = errorOf("kind = \"oscillator\"\n[params]\ndt_s = \"soon\"\n");
  EXPECT_NE(m.find("a number or \"auto\""), std::string::npos) << m;
  m = errorOf("kind = \"oscillator\"\n[sweep]\ndt_s = 0.01\n");
  EXPECT_NE(m.find("expected a list [a, b, ...] or a range"), std::string::npos) << m;
  m = errorOf("kind = \"oscillator\"\n[sweep]\ndt_s = [0.01, \"x\"]\n");
  EXPECT_NE(m.find("sweep.dt_s"), std::string::npos) << m;
  EXPECT_NE(m.find("got \"x\""), std::string::npos) << m;
}

TEST(RunnerExperimentError, ValuesOutOfRange) {
  std::string m = errorOf("kind = \"strand\"\n[params]\nmass_kg = 2.0\n");
  EXPECT_EQ(m.rfind("exp/test.toml:3: params.mass_kg: got 2, expected a value in [1e-15, 1]", 0), 0u) << m;
  m = errorOf("kind = \"strand\"\n[params]\nn_springs = -1\n");
  EXPECT_NE(m.find("got -1, expected a value in [0, 1e+05]"), std::string::npos) << m;
  m = errorOf("kind = \"strand\"\n[sweep]\noverextension = [1.0, 9.0]\n");
  EXPECT_NE(m.find("sweep.overextension: got 9"), std::string::npos) << m;
  m = errorOf("kind = \"strand\"\n[sweep]\noverextension = \"4:6:1\"\n");  // 6 is above the maximum 5
  EXPECT_NE(m.find("sweep.overextension: got 6"), std::string::npos) << m;
  m = errorOf("kind = \"strand\"\n[[case]]\noverextension = 7\n");
  EXPECT_NE(m.find("case[0].overextension: got 7"), std::string::npos) << m;
}

TEST(RunnerExperimentError, UnknownOrMissingKind) {
  std::string m = errorOf("kind = \"strnd\"\n");
  EXPECT_NE(m.find("unknown kind 'strnd'"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'strand'"), std::string::npos) << m;
  EXPECT_NE(m.find("exp/test.toml:1"), std::string::npos) << m;
  m = errorOf("title = \"no kind\"\n");
  EXPECT_NE(m.find("kind: missing"), std::string::npos) << m;
  m = errorOf("kind = 3\n");
  EXPECT_NE(m.find("kind"), std::string::npos) << m;
}

TEST(RunnerExperimentError, EmptySweepList) {
  const std::string m = errorOf("kind = \"oscillator\"\n[sweep]\ndt_s = []\n");
  EXPECT_EQ(m.rfind("exp/test.toml:3: sweep.dt_s: empty sweep axis", 0), 0u) << m;
  const std::string o = errorOf("kind = \"oscillator\"\n", {"sweep.dt_s=[]"});
  EXPECT_NE(o.find("sweep.dt_s: empty sweep axis"), std::string::npos) << o;
}

TEST(RunnerExperimentError, EmptyReversedOrMalformedRange) {
  for (const char* r : {"1:0.5:0.1", "0.1:0.5:0", "0.1:0.5:-0.1"}) {
    const std::string m = errorOf(std::string("kind = \"oscillator\"\n[sweep]\ndt_s = \"") + r + "\"\n");
    EXPECT_NE(m.find("sweep.dt_s: range \"" + std::string(r) + "\" is empty"), std::string::npos) << m;
  }
  std::string m = errorOf("kind = \"oscillator\"\n[sweep]\ndt_s = \"a:b:c\"\n");
  EXPECT_NE(m.find("is not start:stop:step"), std::string::npos) << m;
  m = errorOf("kind = \"oscillator\"\n[sweep]\ndt_s = \"0.1:0.2:0.1x\"\n");
  EXPECT_NE(m.find("is not start:stop:step"), std::string::npos) << m;
  m = errorOf("kind = \"oscillator\"\n[sweep]\ndt_s = \"0.001:1000:0.001\"\n");
  EXPECT_NE(m.find("at most 100000"), std::string::npos) << m;
}

TEST(RunnerExperimentError, CheckNamingAnUnknownMetric) {
  const std::string m = errorOf(R"(kind = "strand"
[sweep]
overextension = [1.0, 2.0]
[[check]]
name = "sag"
type = "monotonic"
metric = "mid_sag"
axis = "overextension"
)");
  EXPECT_NE(m.find("check[0].metric: 'mid_sag' is not a metric of kind 'strand'"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'mid_sag_m'"), std::string::npos) << m;
  EXPECT_NE(m.find("exp/test.toml:7"), std::string::npos) << m;
}

TEST(RunnerExperimentError, CheckNamingAnAxisThatIsNotSwept) {
  const std::string m = errorOf(R"(kind = "strand"
[sweep]
overextension = [1.0, 2.0]
[[check]]
name = "sag"
type = "argmax"
metric = "mid_sag_m"
axis = "overextensio"
expect = [0, 1]
)");
  EXPECT_NE(m.find("check 'sag': axis 'overextensio' is not swept"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'overextension'"), std::string::npos) << m;

  const std::string w = errorOf(R"(kind = "strand"
[sweep]
overextension = [1.0, 2.0]
[[check]]
name = "sag"
type = "range"
metric = "mid_sag_m"
where = { provot = false }
expect = [0, 1]
)");
  EXPECT_NE(w.find("selection key 'provot' is not a swept column"), std::string::npos) << w;
}

TEST(RunnerExperimentError, MalformedChecks) {
  const std::string head = "kind = \"strand\"\n[sweep]\noverextension = [1.0, 2.0]\n[[check]]\nname = \"c\"\n"
                           "metric = \"mid_sag_m\"\n";
  std::string m = errorOf(head + "type = \"argmaks\"\naxis = \"overextension\"\nexpect = [0, 1]\n");
  EXPECT_NE(m.find("'argmaks' is not one of argmax"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'argmax'"), std::string::npos) << m;
  m = errorOf(head + "type = \"argmax\"\nexpect = [0, 1]\n");
  EXPECT_NE(m.find("needs an axis"), std::string::npos) << m;
  m = errorOf(head + "type = \"range\"\n");
  EXPECT_NE(m.find("needs expect = [low, high]"), std::string::npos) << m;
  m = errorOf(head + "type = \"range\"\nexpect = [2, 1]\n");
  EXPECT_NE(m.find("low is above high"), std::string::npos) << m;
  m = errorOf(head + "type = \"difference\"\nexpect = [0, 1]\nnumerator = { overextension = 1.0 }\n");
  EXPECT_NE(m.find("a difference check needs numerator = {...} and denominator = {...}"), std::string::npos) << m;
  m = errorOf(head + "type = \"range\"\nexpect = \"high\"\n");
  EXPECT_NE(m.find("check[0].expect: expected [low, high]"), std::string::npos) << m;
  m = errorOf(head + "type = \"ratio\"\nexpect = [0, 1]\nnumerator = { overextension = 1.0 }\n");
  EXPECT_NE(m.find("needs numerator = {...} and denominator = {...}"), std::string::npos) << m;
  m = errorOf(head + "type = \"monotonic\"\naxis = \"overextension\"\ndirection = \"up\"\n");
  EXPECT_NE(m.find("expected \"increasing\" or \"decreasing\""), std::string::npos) << m;
  m = errorOf("kind = \"strand\"\n[[check]]\ntype = \"range\"\nmetric = \"mid_sag_m\"\nexpect = [0, 1]\n");
  EXPECT_NE(m.find("check[0]: needs a name"), std::string::npos) << m;
}

TEST(RunnerExperimentError, BadExpectIsQuotedOnOneLine) {
  const std::string m = errorOf("kind = \"strand\"\n[sweep]\noverextension = [1.0, 2.0]\n[[check]]\nname = \"c\"\n"
                                "metric = \"mid_sag_m\"\ntype = \"range\"\nexpect = [1, 2, 3]\n");
  EXPECT_NE(m.find("check[0].expect: expected [low, high], got ["), std::string::npos) << m;
  // The CLI prints one "error:" line.
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  EXPECT_NE(m.find("got [1, 2, 3]"), std::string::npos) << m;
}

TEST(RunnerExperimentError, CaseKeyAlsoSwept) {
  const std::string m = errorOf(R"(kind = "strand"
[sweep]
overextension = [1.0, 2.0]
[[case]]
label = "a"
overextension = 0.5
)");
  EXPECT_NE(m.find("case[0].overextension: is also a [sweep] axis"), std::string::npos) << m;
  EXPECT_NE(m.find("exp/test.toml:6"), std::string::npos) << m;
  // The same when the axis comes from an override.
  const std::string o = errorOf("kind = \"strand\"\n[[case]]\noverextension = 0.5\n", {"sweep.overextension=[1]"});
  EXPECT_NE(o.find("is also a [sweep] axis"), std::string::npos) << o;
}

TEST(RunnerExperimentError, StrandSpanAndSpringCountBothSet) {
  std::string m = errorOf("kind = \"strand\"\n[params]\nspan_m = 0.3\nn_springs = 10\n");
  EXPECT_NE(m.find("exp/test.toml: point 0: set span_m or n_springs, not both"), std::string::npos) << m;
  // Split between [params] and a case: the message names the point and its label.
  m = errorOf(R"(kind = "strand"
[params]
n_springs = 10
[[case]]
label = "ok"
[[case]]
label = "spanned"
span_m = 0.2
)");
  EXPECT_NE(m.find("point 1 (spanned): set span_m or n_springs"), std::string::npos) << m;
  // Either one alone is fine.
  EXPECT_NO_THROW(points(load("kind = \"strand\"\n[params]\nspan_m = 0.3\n")));
}

TEST(RunnerExperimentError, OscillatorStepLongerThanTheRun) {
  const std::string m = errorOf("kind = \"oscillator\"\n[params]\nend_time_s = 1.0\ndt_s = 2.0\n");
  EXPECT_NE(m.find("longer than end_time_s"), std::string::npos) << m;
}

TEST(RunnerExperiment, ShippedExperimentsLoadAndExpand) {
  // Every claim and study file in the repository (and the reproduce list's entries) is valid.
  // experiments/fit/ holds controller-fit specifications (`creaturelab fit controller`), another
  // format, read by src/fit and tested there (fit_controller_test.cpp, ShippedFitFilesLoad).
  // Paths inside experiment files (charlotte.toml's image_file) are relative to the repository
  // root, where the README runs them from.
  const std::filesystem::path here = std::filesystem::current_path();
  std::filesystem::current_path(CREATURELAB_TEST_SOURCE_DIR);
  struct Restore {
    std::filesystem::path dir;
    ~Restore() { std::filesystem::current_path(dir); }
  } restore{here};
  int n = 0;
  std::vector<std::filesystem::path> shipped;
  for (const char* top : {"experiments", "studies"})
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(std::filesystem::path(CREATURELAB_TEST_SOURCE_DIR) / top))
      shipped.push_back(entry.path());
  for (const std::filesystem::path& path : shipped) {
    const auto entry = std::filesystem::directory_entry(path);
    if (entry.path().extension() != ".toml") continue;
    if (entry.path().parent_path().filename() == "fit") continue;
    if (entry.path().filename().string().rfind("reproduce", 0) == 0) {
      // The reproduce lists: each entry (a path, or {file, set = overrides}) loads with its overrides.
      const toml::table list = toml::parse_file(entry.path().string());
      const auto* files = list["experiments"].as_array();
      ASSERT_NE(files, nullptr) << entry.path();
      for (auto&& f : *files) {
        std::string file = f.value_or(std::string());
        std::vector<std::string> set;
        if (const auto* t = f.as_table()) {
          file = (*t)["file"].value_or(std::string());
          if (const auto* a = (*t)["set"].as_array())
            for (auto&& v : *a) set.push_back(v.value_or(std::string()));
        }
        try {
          EXPECT_FALSE(points(runner::loadExperiment(file, set, registry())).empty()) << entry.path() << ": " << file;
        } catch (const ExperimentError& err) {
          ADD_FAILURE() << entry.path() << ": " << err.what();
        }
      }
      continue;
    }
    ++n;
    try {
      EXPECT_FALSE(points(runner::loadExperiment(entry.path().string(), {}, registry())).empty()) << entry.path();
    } catch (const ExperimentError& err) {
      ADD_FAILURE() << err.what();
    }
  }
  EXPECT_GE(n, 40);  // every claim and study: a broken walk of the folders fails here
}

TEST(RunnerExperiment, JellyfishDefaultsAreTheSettingItsConvergenceStudyMeasures) {
  // The convergence study's "2/3 mm" case is the kind's default setting; a default that drifts from it
  // (a dropped or changed default, or a case that pins another value) would leave the study measuring
  // another setting than the one `creaturelab run` gives.
  const std::filesystem::path file =
      std::filesystem::path(CREATURELAB_TEST_SOURCE_DIR) / "studies/jellyfish/convergence.toml";
  const std::vector<Point> study = points(runner::loadExperiment(file.string(), {}, registry()));
  int compared = 0;
  for (const Point& p : study) {
    if (p.label != "2/3 mm") continue;
    const double hz = std::get<double>(p.params.at("contraction_hz"));
    const std::vector<Point> plain =
        points(load("kind = \"jellyfish\"\n[params]\ncontraction_hz = " + std::to_string(hz) + "\n"));
    ASSERT_EQ(plain.size(), 1u);
    for (const auto& [name, value] : p.params)
      EXPECT_EQ(plain[0].params.at(name), value) << name << " at " << hz << " Hz";
    ++compared;
  }
  EXPECT_EQ(compared, 4);
}

}  // namespace

TEST(RunnerExperiment, KnownDeviationIsReadAndMustSayWhy) {
  const std::string base = R"(kind = "oscillator"
[sweep]
dt_s = [0.01, 0.02]
[[check]]
name = "c"
type = "range"
metric = "max_abs_error_m"
expect = [0, 1]
)";
  const Experiment e = load(base + "known_deviation = \"see the note\"\n");
  ASSERT_EQ(e.checks.size(), 1u);
  EXPECT_EQ(e.checks[0].known_deviation, "see the note");
  EXPECT_EQ(load(base).checks[0].known_deviation, "");
  std::string m = errorOf(base + "known_deviation = \"\"\n");
  EXPECT_NE(m.find("known_deviation"), std::string::npos) << m;
  m = errorOf(base + "known_deviation = true\n");
  EXPECT_NE(m.find("expected a non-empty string"), std::string::npos) << m;
}

TEST(RunnerExperiment, UncertaintyNamesAMetricOfARangeRatioOrDifferenceAndItsSamples) {
  const std::string head = "kind = \"control_fluid\"\n[sweep]\ncells = [32, 64]\n[[check]]\nname = \"c\"\n";
  const std::string range = head + "type = \"range\"\nmetric = \"mean_up_force_n\"\nexpect = [0, 1]\n";
  const std::string counted = "samples = \"force_cycles\"\n";
  const Experiment e = load(range + "uncertainty = \"mean_up_force_n_stderr\"\n" + counted);
  EXPECT_EQ(e.checks[0].uncertainty, "mean_up_force_n_stderr");
  EXPECT_EQ(e.checks[0].samples, "force_cycles");
  // The samples parameter joins the table's columns, so that the check can be judged from the table alone.
  EXPECT_EQ(runner::sweepColumns(e), (std::vector<std::string>{"cells", "force_cycles"}));
  EXPECT_EQ(load(range).checks[0].uncertainty, "");
  std::string m = errorOf(range + "uncertainty = \"mean_up_force_n_sterr\"\n" + counted);
  EXPECT_NE(m.find("check[0].uncertainty"), std::string::npos) << m;
  EXPECT_NE(m.find("mean_up_force_n_stderr"), std::string::npos) << m;  // the close match
  m = errorOf(head + "type = \"monotonic\"\nmetric = \"mean_up_force_n\"\naxis = \"cells\"\n"
                     "uncertainty = \"mean_up_force_n_stderr\"\n" + counted);
  EXPECT_NE(m.find("belongs to range, ratio and difference checks"), std::string::npos) << m;
  m = errorOf(head + "type = \"ratio\"\nmetric = \"mean_up_force_n\"\nnumerator_metric = \"mean_up_force_n_stderr\"\n"
                     "numerator = { cells = 32 }\ndenominator = { cells = 64 }\nexpect = [0, 1]\n"
                     "uncertainty = \"mean_up_force_n_stderr\"\n" + counted);
  EXPECT_NE(m.find("one metric's standard error"), std::string::npos) << m;
  // The samples: required beside uncertainty, an integer parameter, and nowhere else.
  m = errorOf(range + "uncertainty = \"mean_up_force_n_stderr\"\n");
  EXPECT_NE(m.find("uncertainty needs samples"), std::string::npos) << m;
  m = errorOf(range + "uncertainty = \"mean_up_force_n_stderr\"\nsamples = \"force_cycle\"\n");
  EXPECT_NE(m.find("check[0].samples"), std::string::npos) << m;
  EXPECT_NE(m.find("force_cycles"), std::string::npos) << m;  // the close match
  m = errorOf(range + "uncertainty = \"mean_up_force_n_stderr\"\nsamples = \"flap_period_s\"\n");
  EXPECT_NE(m.find("integer parameter"), std::string::npos) << m;
  m = errorOf(range + counted);
  EXPECT_NE(m.find("belongs to a check with uncertainty"), std::string::npos) << m;
}

TEST(RunnerExperiment, BaseRelationIsRatioOrDifferenceBesideABase) {
  const std::string ratio = "kind = \"oscillator\"\n[sweep]\ndt_s = [0.01, 0.02]\n[[check]]\nname = \"c\"\n"
                            "type = \"ratio\"\nmetric = \"max_abs_error_m\"\nnumerator = { dt_s = 0.01 }\n"
                            "denominator = { dt_s = 0.02 }\nexpect = [0, 1]\n";
  const std::string based = ratio + "denominator_base = { dt_s = 0.01 }\n";
  EXPECT_FALSE(load(based).checks[0].base_difference);
  EXPECT_TRUE(load(based + "base_relation = \"difference\"\n").checks[0].base_difference);
  EXPECT_FALSE(load(based + "base_relation = \"ratio\"\n").checks[0].base_difference);
  std::string m = errorOf(based + "base_relation = \"minus\"\n");
  EXPECT_NE(m.find("check[0].base_relation"), std::string::npos) << m;
  EXPECT_NE(m.find("\"ratio\" or \"difference\""), std::string::npos) << m;
  m = errorOf(ratio + "base_relation = \"difference\"\n");
  EXPECT_NE(m.find("belongs to a check with numerator_base or denominator_base"), std::string::npos) << m;
}

// ---- input that should never start ----

TEST(RunnerExperimentError, DuplicateCaseLabelsAreRefused) {
  const std::string m = errorOf(
      "kind = \"strand\"\n[[case]]\nlabel = \"a\"\noverextension = 1.0\n[[case]]\nlabel = \"a\"\noverextension = 1.5\n");
  EXPECT_NE(m.find("case[1].label"), std::string::npos) << m;
  EXPECT_NE(m.find("\"a\" is already the label of case[0]"), std::string::npos) << m;
}

// The message of the ExperimentError that checking `text`'s selections against its points throws.
static std::string selectionErrorOf(const std::string& text) {
  const Experiment e = load(text);
  try {
    runner::checkSelections(e, points(e));
  } catch (const ExperimentError& err) {
    return err.what();
  }
  return "";
}

TEST(RunnerExperimentError, SelectionsMustMatchAPointBeforeTheRun) {
  const std::string sweep = "kind = \"oscillator\"\n[sweep]\ndt_s = [0.01, 0.02]\n"
                            "[[check]]\nname = \"c\"\ntype = \"range\"\nmetric = \"max_abs_error_m\"\nexpect = [0, 1]\n";
  EXPECT_EQ(selectionErrorOf(sweep + "where = { dt_s = 0.02 }\n"), "");
  std::string m = selectionErrorOf(sweep + "where = { dt_s = 0.03 }\n");
  EXPECT_NE(m.find("check 'c': where = {dt_s=0.03}: no point has dt_s = 0.03 (dt_s takes 0.01, 0.02)"),
            std::string::npos) << m;
  m = selectionErrorOf(sweep + "where = { label = \"x\" }\n");
  EXPECT_NE(m.find("no point has label = \"x\" (the file has no [[case]] labels)"), std::string::npos) << m;
}

TEST(RunnerExperimentError, ExplicitEulerAtAnAutomaticStepIsRefusedUnlessAllowed) {
  const Experiment e = load("kind = \"strand\"\n[params]\nintegrator = \"euler\"\n");
  const kinds::Kind& kind = *registry().find(e.kind);
  const auto ps = points(e);
  const kinds::CostEstimate cost = kind.estimateCost(ps[0].params);
  EXPECT_NEAR(cost.steps, 1.2e8, 1e6);  // dt = 1.25e-7 s over 15 s
  runner::CostLimits limits;
  try {
    runner::checkCost(e, kind, ps, limits);
    ADD_FAILURE() << "no refusal";
  } catch (const ExperimentError& err) {
    EXPECT_NE(std::string(err.what()).find("--allow-long"), std::string::npos) << err.what();
  }
  limits.allow_long = true;
  EXPECT_NO_THROW(runner::checkCost(e, kind, ps, limits));
  // RK4 at its automatic step: far below the limit.
  const Experiment rk4 = load("kind = \"strand\"\n");
  EXPECT_LT(kind.estimateCost(points(rk4)[0].params).steps, 1e6);
}

TEST(RunnerExperimentError, AGridThatCannotFitInMemoryIsRefused) {
  const Experiment e = load("kind = \"fluid\"\n[params]\ncells = 1024\n");
  const kinds::Kind& kind = *registry().find(e.kind);
  const auto ps = points(e);
  const double need = kind.estimateCost(ps[0].params).memory_bytes;
  EXPECT_GT(need, 0.7e9);  // measured: 1024^2 cells with 11-12 stored frames peak at 660-692 MB
  runner::CostLimits limits;
  limits.memory = {need * 1.01, "a test budget"};
  EXPECT_NO_THROW(runner::checkCost(e, kind, ps, limits));
  limits.memory = {need * 0.99, "a test budget"};
  try {
    runner::checkCost(e, kind, ps, limits);
    ADD_FAILURE() << "no refusal";
  } catch (const ExperimentError& err) {
    EXPECT_NE(std::string(err.what()).find("(a test budget)"), std::string::npos) << err.what();
  }
}
