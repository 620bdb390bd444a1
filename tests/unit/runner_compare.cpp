// Regression baselines: JSON round trip, per-metric tolerances, NaN, missing and failed points.
#include "runner/compare.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using namespace creaturelab;
using runner::Baseline;
using runner::Comparison;
using runner::Row;
using runner::Table;
using runner::Tolerance;

Row row(int index, std::map<std::string, double> metrics, std::string status = "ok", std::string label = "") {
  Row r;
  r.index = index;
  r.label = std::move(label);
  r.status = std::move(status);
  r.metrics = std::move(metrics);
  return r;
}

Table runTable() {
  Table t{{}, {"a", "b"}, {}};
  t.rows.push_back(row(0, {{"a", 1.0}, {"b", 100.0}}, "ok", "first"));
  t.rows.push_back(row(1, {{"a", 2.0}, {"b", 0.0}}, "ok", "second"));
  return t;
}

Baseline baselineOf(const Table& t, std::map<std::string, Tolerance> tol = {}) {
  Baseline b;
  b.experiment = "experiments/oscillator/integrators.toml";
  b.overrides = {"params.end_time_s=2"};
  b.tolerances = std::move(tol);
  b.table = t;
  return b;
}

const runner::Difference& find(const Comparison& c, int point, const std::string& metric) {
  for (const auto& d : c.rows)
    if (d.point == point && d.metric == metric) return d;
  throw std::logic_error("no row for point " + std::to_string(point) + " " + metric);
}

// ---- JSON ----

TEST(RunnerCompare, BaselineJsonRoundTrip) {
  Table t = runTable();
  t.rows.push_back(row(2, {{"a", std::nan("")}, {"b", -3.25e-12}}, "failed", "third"));
  const Baseline b = baselineOf(t, {{"default", {1e-6, 1e-12}}, {"b", {0.01, 0.5}}});
  const std::string text = runner::baselineToJson(b).dump(2);
  const Baseline back = runner::baselineFromJson(nlohmann::json::parse(text), "b.json");
  EXPECT_EQ(back.experiment, b.experiment);
  EXPECT_EQ(back.overrides, b.overrides);
  ASSERT_EQ(back.tolerances.size(), 2u);
  EXPECT_EQ(back.tolerances.at("default").rtol, 1e-6);
  EXPECT_EQ(back.tolerances.at("default").atol, 1e-12);
  EXPECT_EQ(back.tolerances.at("b").rtol, 0.01);
  EXPECT_EQ(back.tolerances.at("b").atol, 0.5);
  ASSERT_EQ(back.table.rows.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back.table.rows[i].index, t.rows[i].index);
    EXPECT_EQ(back.table.rows[i].label, t.rows[i].label);
    EXPECT_EQ(back.table.rows[i].status, t.rows[i].status);
  }
  EXPECT_EQ(back.table.rows[0].metrics.at("a"), 1.0);
  EXPECT_EQ(back.table.rows[2].metrics.at("b"), -3.25e-12);  // bitwise, not rounded for display
  EXPECT_TRUE(std::isnan(back.table.rows[2].metrics.at("a")));
  // NaN is stored as the string "nan" (JSON has no NaN).
  EXPECT_NE(text.find("\"nan\""), std::string::npos);
  EXPECT_EQ(text.find("NaN"), std::string::npos);
  // A baseline compares clean against the table it was made from.
  EXPECT_TRUE(runner::compareTables(t, back).passed()) << runner::formatComparison(runner::compareTables(t, back), true);
}

TEST(RunnerCompare, RoundTripKeepsFullPrecision) {
  Table t{{}, {"x"}, {}};
  const double x = 0.1 + 0.2;  // 0.30000000000000004
  t.rows.push_back(row(0, {{"x", x}}));
  const Baseline back = runner::baselineFromJson(nlohmann::json::parse(runner::baselineToJson(baselineOf(t)).dump()), "-");
  EXPECT_EQ(back.table.rows[0].metrics.at("x"), x);
}

TEST(RunnerCompare, InfiniteMetricSurvivesTheRoundTrip) {
  Table t{{}, {"x"}, {}};
  t.rows.push_back(row(0, {{"x", std::numeric_limits<double>::infinity()}}));
  const Baseline back = runner::baselineFromJson(nlohmann::json::parse(runner::baselineToJson(baselineOf(t)).dump()), "-");
  const Comparison c = runner::compareTables(t, back);
  EXPECT_TRUE(c.passed()) << runner::formatComparison(c, true);
  EXPECT_TRUE(std::isinf(back.table.rows[0].metrics.at("x")));
}

TEST(RunnerCompare, MalformedBaselineNamesTheFile) {
  for (const char* text : {R"({"points": []})", R"({"experiment": "e.toml"})",
                           R"({"experiment": "e.toml", "points": [{"index": 0}]})",
                           R"({"experiment": "e.toml", "points": [{"index": 0, "metrics": {"a": "x"}}]})"}) {
    try {
      runner::baselineFromJson(nlohmann::json::parse(text), "results/baselines/bad.json");
      ADD_FAILURE() << "no error for " << text;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("results/baselines/bad.json: not a creaturelab baseline"), std::string::npos)
          << e.what();
    }
  }
}

TEST(RunnerCompare, MissingOptionalFieldsTakeDefaults) {
  const Baseline b = runner::baselineFromJson(
      nlohmann::json::parse(R"({"experiment": "e.toml", "points": [{"index": 4, "metrics": {"a": 1.5}}]})"), "-");
  EXPECT_TRUE(b.overrides.empty());
  EXPECT_TRUE(b.tolerances.empty());
  ASSERT_EQ(b.table.rows.size(), 1u);
  EXPECT_EQ(b.table.rows[0].index, 4);
  EXPECT_EQ(b.table.rows[0].status, "ok");
  EXPECT_EQ(b.table.rows[0].label, "");
}

// ---- tolerances ----

TEST(RunnerCompare, ToleranceLookup) {
  const Baseline none = baselineOf(runTable());
  EXPECT_EQ(none.toleranceFor("a").rtol, 1e-9);  // built-in default
  EXPECT_EQ(none.toleranceFor("a").atol, 0.0);
  const Baseline b = baselineOf(runTable(), {{"default", {1e-3, 0}}, {"b", {0, 1e-6}}});
  EXPECT_EQ(b.toleranceFor("a").rtol, 1e-3);
  EXPECT_EQ(b.toleranceFor("b").rtol, 0.0);
  EXPECT_EQ(b.toleranceFor("b").atol, 1e-6);
}

TEST(RunnerCompare, RelativeTolerance) {
  const Baseline b = baselineOf(runTable(), {{"default", {1e-3, 0}}});
  Table run = runTable();
  run.rows[0].metrics["b"] = 100.0 * (1 + 0.9e-3);
  Comparison c = runner::compareTables(run, b);
  EXPECT_TRUE(c.passed()) << runner::formatComparison(c, false);
  EXPECT_TRUE(find(c, 0, "b").within);
  EXPECT_EQ(find(c, 0, "b").got, run.rows[0].metrics["b"]);
  EXPECT_EQ(find(c, 0, "b").expected, 100.0);
  run.rows[0].metrics["b"] = 100.0 * (1 - 1.1e-3);
  c = runner::compareTables(run, b);
  EXPECT_FALSE(c.passed());
  EXPECT_FALSE(find(c, 0, "b").within);
  EXPECT_TRUE(find(c, 0, "a").within);
  // rtol alone does not cover an expected zero...
  run = runTable();
  run.rows[1].metrics["b"] = 1e-15;
  EXPECT_FALSE(runner::compareTables(run, b).passed());
}

TEST(RunnerCompare, AbsoluteTolerance) {
  // ...atol does.
  const Baseline b = baselineOf(runTable(), {{"default", {1e-9, 0}}, {"b", {0, 1e-12}}});
  Table run = runTable();
  run.rows[1].metrics["b"] = 0.9e-12;
  EXPECT_TRUE(runner::compareTables(run, b).passed());
  run.rows[1].metrics["b"] = -1.1e-12;
  const Comparison c = runner::compareTables(run, b);
  EXPECT_FALSE(c.passed());
  EXPECT_EQ(find(c, 1, "b").tolerance.atol, 1e-12);
}

TEST(RunnerCompare, ToleranceIsAtolPlusRtolTimesExpected) {
  const Baseline b = baselineOf(runTable(), {{"default", {0.01, 0.5}}});
  Table run = runTable();
  run.rows[0].metrics["b"] = 101.49;  // 0.5 + 0.01 * 100 = 1.5
  EXPECT_TRUE(runner::compareTables(run, b).passed());
  run.rows[0].metrics["b"] = 101.51;
  EXPECT_FALSE(runner::compareTables(run, b).passed());
}

// ---- NaN ----

TEST(RunnerCompare, NanMatchesOnlyNan) {
  Table base = runTable();
  base.rows[0].metrics["a"] = std::nan("");  // e.g. settling_time_s of a strand that never settled
  const Baseline b = baselineOf(base, {{"default", {1, 1}}});  // even a huge tolerance
  Table run = runTable();
  run.rows[0].metrics["a"] = std::nan("");
  EXPECT_TRUE(runner::compareTables(run, b).passed());
  run.rows[0].metrics["a"] = 1.0;
  Comparison c = runner::compareTables(run, b);
  EXPECT_FALSE(c.passed());
  EXPECT_FALSE(find(c, 0, "a").within);
  run = runTable();
  run.rows[1].metrics["b"] = std::nan("");  // baseline finite, run NaN
  c = runner::compareTables(run, baselineOf(runTable(), {{"default", {1, 1}}}));
  EXPECT_FALSE(c.passed());
  EXPECT_FALSE(find(c, 1, "b").within);
}

// ---- missing and failed points ----

TEST(RunnerCompare, APointMissingFromTheRunIsOutside) {
  Table run = runTable();
  run.rows.pop_back();
  Comparison c = runner::compareTables(run, baselineOf(runTable()));
  EXPECT_FALSE(c.passed());
  EXPECT_FALSE(find(c, 1, "a").within);
  EXPECT_EQ(find(c, 1, "a").note, "point missing from the run");
  EXPECT_TRUE(find(c, 0, "a").within);

  run = runTable();
  run.rows[1].status = "missing";  // in the index but never run
  c = runner::compareTables(run, baselineOf(runTable()));
  EXPECT_FALSE(c.passed());
  EXPECT_EQ(find(c, 1, "b").note, "point missing from the run");
}

TEST(RunnerCompare, AMetricMissingFromTheRunIsOutside) {
  Table run = runTable();
  run.rows[0].metrics.erase("b");
  const Comparison c = runner::compareTables(run, baselineOf(runTable()));
  EXPECT_FALSE(c.passed());
  EXPECT_EQ(find(c, 0, "b").note, "metric missing from the run");
}

TEST(RunnerCompare, AFailedPointIsOutsideAnOkBaseline) {
  Table run = runTable();
  run.rows[0].status = "failed";
  const Comparison c = runner::compareTables(run, baselineOf(runTable()));
  EXPECT_FALSE(c.passed());
  EXPECT_EQ(find(c, 0, "a").note, "status failed, baseline ok");
  const std::string text = runner::formatComparison(c, true);
  EXPECT_NE(text.find("OUTSIDE status failed, baseline ok"), std::string::npos) << text;
}

TEST(RunnerCompare, AFailureRecordedInTheBaselineMatchesAFailedRun) {
  Table base = runTable();
  base.rows[1].status = "failed";
  base.rows[1].metrics = {{"a", std::nan("")}, {"b", std::nan("")}};
  Table run = base;
  EXPECT_TRUE(runner::compareTables(run, baselineOf(base)).passed());
  run.rows[1] = runTable().rows[1];  // now it finishes: a change the baseline should flag
  EXPECT_FALSE(runner::compareTables(run, baselineOf(base)).passed());
}

TEST(RunnerCompare, ExtraRunPointsAreIgnored) {
  Table run = runTable();
  run.rows.push_back(row(2, {{"a", 9.0}, {"b", 9.0}}));
  EXPECT_TRUE(runner::compareTables(run, baselineOf(runTable())).passed());
}

// ---- the printed table ----

TEST(RunnerCompare, FormatShowsOnlyFailuresOrEverything) {
  const Baseline b = baselineOf(runTable(), {{"default", {1e-6, 0}}});
  EXPECT_NE(runner::formatComparison(runner::compareTables(runTable(), b), true).find("(all 4 values within tolerance)"),
            std::string::npos);
  Table run = runTable();
  run.rows[1].metrics["a"] = 2.5;
  const Comparison c = runner::compareTables(run, b);
  EXPECT_EQ(c.rows.size(), 4u);
  const std::string failures = runner::formatComparison(c, true);
  EXPECT_NE(failures.find("OUTSIDE"), std::string::npos) << failures;
  EXPECT_NE(failures.find("second"), std::string::npos) << failures;
  EXPECT_EQ(failures.find("first"), std::string::npos) << failures;
  const std::string all = runner::formatComparison(c, false);
  EXPECT_NE(all.find("first"), std::string::npos) << all;
  EXPECT_NE(all.find(" ok"), std::string::npos) << all;
}

}  // namespace
