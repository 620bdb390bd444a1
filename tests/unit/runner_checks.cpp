// [[check]] evaluation over hand-built sweep tables: argmax, argmin, range, ratio, monotonic,
// point selections, failed and missing points.
#include "runner/checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace {

using namespace creaturelab;
using runner::CheckOutcome;
using runner::CheckSpec;
using runner::Row;
using runner::Table;
using kinds::Value;

Row row(int index, std::map<std::string, Value> columns, std::map<std::string, double> metrics,
        std::string status = "ok", std::string message = "", std::string label = "") {
  Row r;
  r.index = index;
  r.label = std::move(label);
  r.status = std::move(status);
  r.message = std::move(message);
  r.columns = std::move(columns);
  r.metrics = std::move(metrics);
  return r;
}

// distance_m over contraction_hz, peaked at 0.7 Hz.
Table frequencyTable() {
  Table t{{"contraction_hz"}, {"distance_m"}, {}};
  const double hz[] = {0.5, 0.6, 0.7, 0.8, 0.9};
  const double d[] = {1.0, 1.5, 2.0, 1.8, 1.2};
  for (int i = 0; i < 5; ++i) t.rows.push_back(row(i, {{"contraction_hz", hz[i]}}, {{"distance_m", d[i]}}));
  return t;
}

// max_abs_error_m over integrator x dt_s.
Table integratorTable() {
  Table t{{"dt_s", "integrator"}, {"max_abs_error_m"}, {}};
  const char* names[] = {"euler", "rk4", "implicit_euler"};
  const double err[] = {1e-1, 1e-8, 1e-2};
  int i = 0;
  for (double dt : {0.01, 0.02})
    for (int n = 0; n < 3; ++n) {
      const double scale = dt == 0.01 ? 1.0 : (n == 1 ? 16.0 : 2.0);
      t.rows.push_back(row(i++, {{"dt_s", dt}, {"integrator", std::string(names[n])}},
                           {{"max_abs_error_m", err[n] * scale}}));
    }
  return t;
}

CheckSpec spec(std::string type, std::string metric, std::string axis = "") {
  CheckSpec c;
  c.name = type + " check";
  c.type = std::move(type);
  c.metric = std::move(metric);
  c.axis = std::move(axis);
  return c;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// ---- argmax / argmin ----

TEST(RunnerChecks, ArgmaxOnANumericAxis) {
  CheckSpec c = spec("argmax", "distance_m", "contraction_hz");
  c.expect_lo = 0.6;
  c.expect_hi = 0.8;
  const CheckOutcome o = runner::evaluateCheck(c, frequencyTable());
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.name, "argmax check");
  EXPECT_EQ(o.type, "argmax");
  EXPECT_EQ(o.got, "contraction_hz=0.7 (distance_m=2)");
  EXPECT_EQ(o.expected, "contraction_hz in [0.6, 0.8]");
}

// An argmax relative to another point's metric: a driven response's peak frequency against the
// natural frequency a pluck measured (experiments/jellyfish/frequency.toml).
TEST(RunnerChecks, ArgmaxRelativeToAnotherPointsMetric) {
  Table t{{"protocol", "contraction_hz"}, {"stroke_amplitude", "natural_hz"}, {}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  t.rows.push_back(row(0, {{"protocol", std::string("pluck")}, {"contraction_hz", 1.0}},
                       {{"stroke_amplitude", 0.1}, {"natural_hz", 0.75}}));
  const double hz[] = {0.5, 0.7, 0.9};
  const double amp[] = {0.2, 0.4, 0.3};
  for (int i = 0; i < 3; ++i)
    t.rows.push_back(row(i + 1, {{"protocol", std::string("drive")}, {"contraction_hz", hz[i]}},
                         {{"stroke_amplitude", amp[i]}, {"natural_hz", nan}}));
  CheckSpec c = spec("argmax", "stroke_amplitude", "contraction_hz");
  c.where = {{"protocol", Value(std::string("drive"))}};
  c.relative_to = {{"protocol", Value(std::string("pluck"))}};
  c.relative_metric = "natural_hz";
  c.expect_lo = 0.9;
  c.expect_hi = 1.1;
  CheckOutcome o = runner::evaluateCheck(c, t);
  EXPECT_TRUE(o.passed) << o.got;  // 0.7 / 0.75 = 0.933
  EXPECT_TRUE(contains(o.got, "0.933333 x natural_hz 0.75")) << o.got;
  EXPECT_EQ(o.expected, "contraction_hz / natural_hz(protocol=\"pluck\") in [0.9, 1.1]");
  c.expect_lo = 0.95;
  EXPECT_FALSE(runner::evaluateCheck(c, t).passed);
  // A reference without a finite metric fails with the reason.
  c.relative_to = {{"protocol", Value(std::string("drive"))}};
  o = runner::evaluateCheck(c, t);
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.got, "has no finite natural_hz")) << o.got;
}

TEST(RunnerChecks, ArgmaxBoundsAreInclusiveAndAWrongExpectationFails) {
  CheckSpec c = spec("argmax", "distance_m", "contraction_hz");
  c.expect_lo = 0.7;
  c.expect_hi = 0.7;
  EXPECT_TRUE(runner::evaluateCheck(c, frequencyTable()).passed);
  c.expect_lo = 0.8;
  c.expect_hi = 1.0;
  const CheckOutcome o = runner::evaluateCheck(c, frequencyTable());
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.got, "contraction_hz=0.7")) << o.got;
}

TEST(RunnerChecks, ArgminOnANumericAxis) {
  CheckSpec c = spec("argmin", "distance_m", "contraction_hz");
  c.expect_lo = 0.45;
  c.expect_hi = 0.55;
  const CheckOutcome o = runner::evaluateCheck(c, frequencyTable());
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.got, "contraction_hz=0.5 (distance_m=1)");
}

TEST(RunnerChecks, ArgminOnAStringAxis) {
  CheckSpec c = spec("argmin", "max_abs_error_m", "integrator");
  c.expect_choice = "rk4";
  CheckOutcome o = runner::evaluateCheck(c, integratorTable());
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.expected, "integrator=\"rk4\"");
  EXPECT_TRUE(contains(o.got, "integrator=\"rk4\"")) << o.got;
  c.expect_choice = "euler";
  o = runner::evaluateCheck(c, integratorTable());
  EXPECT_FALSE(o.passed);
}

TEST(RunnerChecks, ArgmaxOnAStringAxis) {
  CheckSpec c = spec("argmax", "max_abs_error_m", "integrator");
  c.expect_choice = "euler";
  EXPECT_TRUE(runner::evaluateCheck(c, integratorTable()).passed);
  c.where = {{"dt_s", 0.02}};
  c.expect_choice = "euler";
  EXPECT_TRUE(runner::evaluateCheck(c, integratorTable()).passed);
}

TEST(RunnerChecks, NumericExpectationOnAStringAxisFailsCleanly) {
  CheckSpec c = spec("argmin", "max_abs_error_m", "integrator");
  c.expect_lo = 0;
  c.expect_hi = 1;
  EXPECT_FALSE(runner::evaluateCheck(c, integratorTable()).passed);
}

TEST(RunnerChecks, ArgminWithAWhereFilter) {
  CheckSpec c = spec("argmin", "max_abs_error_m", "dt_s");
  c.where = {{"integrator", std::string("rk4")}};
  c.expect_lo = 0.01;
  c.expect_hi = 0.01;
  EXPECT_TRUE(runner::evaluateCheck(c, integratorTable()).passed);
}

// ---- range ----

TEST(RunnerChecks, RangeOverEverySelectedPoint) {
  CheckSpec c = spec("range", "distance_m");
  c.expect_lo = 1.0;  // inclusive at both ends
  c.expect_hi = 2.0;
  CheckOutcome o = runner::evaluateCheck(c, frequencyTable());
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.expected, "distance_m in [1, 2]");
  EXPECT_EQ(o.got, "[1, 2] over 5 points");
  c.expect_hi = 1.9;
  o = runner::evaluateCheck(c, frequencyTable());
  EXPECT_FALSE(o.passed);
}

TEST(RunnerChecks, RangeWithAWhereFilterOnOnePoint) {
  CheckSpec c = spec("range", "distance_m");
  c.where = {{"contraction_hz", 0.9}};
  c.expect_lo = 1.1;
  c.expect_hi = 1.3;
  const CheckOutcome o = runner::evaluateCheck(c, frequencyTable());
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.got, "1.2");
}

TEST(RunnerChecks, WhereMatchesNumbersWhateverTheirStoredType) {
  Table t{{"n_springs"}, {"m"}, {}};
  t.rows.push_back(row(0, {{"n_springs", std::int64_t(10)}}, {{"m", 1.0}}));
  t.rows.push_back(row(1, {{"n_springs", std::int64_t(20)}}, {{"m", 5.0}}));
  CheckSpec c = spec("range", "m");
  c.where = {{"n_springs", 10.0}};  // a TOML float selecting an integer column
  c.expect_lo = 0;
  c.expect_hi = 2;
  EXPECT_TRUE(runner::evaluateCheck(c, t).passed);
}

TEST(RunnerChecks, WhereSelectsByBooleanAndLabel) {
  Table t{{"provot"}, {"m"}, {}};
  t.rows.push_back(row(0, {{"provot", false}}, {{"m", 1.0}}, "ok", "", "rest"));
  t.rows.push_back(row(1, {{"provot", true}}, {{"m", 9.0}}, "ok", "", "provot"));
  CheckSpec c = spec("range", "m");
  c.expect_lo = 0;
  c.expect_hi = 2;
  c.where = {{"provot", false}};
  EXPECT_TRUE(runner::evaluateCheck(c, t).passed);
  c.where = {{"label", std::string("provot")}};
  EXPECT_FALSE(runner::evaluateCheck(c, t).passed);
  c.where = {{"label", std::string("rest")}};
  EXPECT_TRUE(runner::evaluateCheck(c, t).passed);
}

TEST(RunnerChecks, NoMatchingPointFails) {
  CheckSpec c = spec("range", "distance_m");
  c.where = {{"contraction_hz", 5.0}};
  c.expect_lo = 0;
  c.expect_hi = 10;
  const CheckOutcome o = runner::evaluateCheck(c, frequencyTable());
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.got, "no point matches contraction_hz=5")) << o.got;
}

// ---- ratio ----

TEST(RunnerChecks, RatioOfTwoSelectedPoints) {
  CheckSpec c = spec("ratio", "max_abs_error_m");
  c.numerator = {{"integrator", std::string("rk4")}, {"dt_s", 0.02}};
  c.denominator = {{"integrator", std::string("rk4")}, {"dt_s", 0.01}};
  c.expect_lo = 12;
  c.expect_hi = 20;
  CheckOutcome o = runner::evaluateCheck(c, integratorTable());
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.got, "16");
  EXPECT_EQ(o.expected, "max_abs_error_m ratio in [12, 20]");
  c.expect_lo = 1;
  c.expect_hi = 3;
  o = runner::evaluateCheck(c, integratorTable());
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(o.got, "16");
}

TEST(RunnerChecks, RatioAcrossMetricsEachRelativeToItsBase) {
  // Spring-constant experiment: each family's elongation when its own k is cut, relative to the
  // original web; outer grows x3, inner x2, so the ratio of the relative growths is 1.5.
  Table t{{"case"}, {"outer", "inner"}, {}};
  t.rows.push_back(row(0, {{"case", std::string("original")}}, {{"outer", 2.0}, {"inner", 5.0}}));
  t.rows.push_back(row(1, {{"case", std::string("cut outer")}}, {{"outer", 6.0}, {"inner", 5.0}}));
  t.rows.push_back(row(2, {{"case", std::string("cut inner")}}, {{"outer", 2.0}, {"inner", 10.0}}));
  CheckSpec c = spec("ratio", "outer");
  c.numerator_metric = "outer";
  c.denominator_metric = "inner";
  c.numerator = {{"case", std::string("cut outer")}};
  c.denominator = {{"case", std::string("cut inner")}};
  c.expect_lo = 1.4;
  c.expect_hi = 1.6;
  EXPECT_FALSE(runner::evaluateCheck(c, t).passed);  // absolute: 6 / 10 = 0.6
  EXPECT_EQ(runner::evaluateCheck(c, t).got, "0.6");
  c.numerator_base = {{"case", std::string("original")}};
  c.denominator_base = {{"case", std::string("original")}};
  const CheckOutcome o = runner::evaluateCheck(c, t);  // (6 / 2) / (10 / 5) = 1.5
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.got, "1.5");
  c.numerator_base = {{"case", std::string("nowhere")}};
  EXPECT_FALSE(runner::evaluateCheck(c, t).passed);
}

TEST(RunnerChecks, RatioOverADifferenceOfTwoPointsTakesTheSlopesSign) {
  // A derivative (per rad) against the finite difference of a force between two poses 0.5 rad apart:
  // 3 N/rad against 2.5 - 1 = 1.5 N gives 2 /rad; the same derivative against a falling force, -2.
  Table t{{"case"}, {"force", "derivative"}, {}};
  t.rows.push_back(row(0, {{"case", std::string("low")}}, {{"force", 1.0}, {"derivative", 0.0}}));
  t.rows.push_back(row(1, {{"case", std::string("high")}}, {{"force", 2.5}, {"derivative", 0.0}}));
  t.rows.push_back(row(2, {{"case", std::string("gradient")}}, {{"force", 0.0}, {"derivative", 3.0}}));
  CheckSpec c = spec("ratio", "force");
  c.numerator_metric = "derivative";
  c.denominator_metric = "force";
  c.numerator = {{"case", std::string("gradient")}};
  c.denominator = {{"case", std::string("high")}};
  c.denominator_base = {{"case", std::string("low")}};
  c.expect_lo = 1.5;
  c.expect_hi = 2.5;
  EXPECT_FALSE(runner::evaluateCheck(c, t).passed);  // relative by ratio: 3 / (2.5 / 1) = 1.2
  c.base_difference = true;
  CheckOutcome o = runner::evaluateCheck(c, t);
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.got, "2");
  EXPECT_TRUE(contains(o.expected, "each less its base")) << o.expected;
  std::swap(c.denominator, c.denominator_base);  // the force falls from low to high
  o = runner::evaluateCheck(c, t);
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(o.got, "-2");
}

TEST(RunnerChecks, RatioSelectionsMustEachPickOnePoint) {
  CheckSpec c = spec("ratio", "max_abs_error_m");
  c.numerator = {{"integrator", std::string("rk4")}};  // two points
  c.denominator = {{"integrator", std::string("rk4")}, {"dt_s", 0.01}};
  c.expect_lo = 0;
  c.expect_hi = 100;
  const CheckOutcome o = runner::evaluateCheck(c, integratorTable());
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.got, "must each select one point (got 2 and 1)")) << o.got;
}

TEST(RunnerChecks, DifferenceOfTwoSelectedPointsTakesANegativeReference) {
  // A creature that rises 0.6 cm a cycle with its controller and sinks 0.007 cm without: the
  // ratio is negative, the difference says what the comparison means.
  Table t{{"case"}, {"rise"}, {}};
  t.rows.push_back(row(0, {{"case", std::string("controller")}}, {{"rise", 0.006}}));
  t.rows.push_back(row(1, {{"case", std::string("off")}}, {{"rise", -0.00007}}));
  CheckSpec c = spec("difference", "rise");
  c.numerator = {{"case", std::string("controller")}};
  c.denominator = {{"case", std::string("off")}};
  c.expect_lo = 0.001;
  c.expect_hi = 1;
  CheckOutcome o = runner::evaluateCheck(c, t);
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.got, "0.00607");
  EXPECT_EQ(o.expected, "rise difference in [0.001, 1]");
  std::swap(c.numerator, c.denominator);
  o = runner::evaluateCheck(c, t);
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(o.got, "-0.00607");
}

TEST(RunnerChecks, RatioOverZeroFails) {
  Table t{{"x"}, {"m"}, {}};
  t.rows.push_back(row(0, {{"x", 1.0}}, {{"m", 1.0}}));
  t.rows.push_back(row(1, {{"x", 2.0}}, {{"m", 0.0}}));
  CheckSpec c = spec("ratio", "m");
  c.numerator = {{"x", 1.0}};
  c.denominator = {{"x", 2.0}};
  c.expect_lo = 0;
  c.expect_hi = std::numeric_limits<double>::max();
  EXPECT_FALSE(runner::evaluateCheck(c, t).passed);
}

// ---- monotonic ----

Table series(const std::vector<double>& axis, const std::vector<double>& values) {
  Table t{{"x"}, {"m"}, {}};
  for (size_t i = 0; i < axis.size(); ++i) t.rows.push_back(row(int(i), {{"x", axis[i]}}, {{"m", values[i]}}));
  return t;
}

CheckSpec monotonic(std::string direction, bool strict) {
  CheckSpec c = spec("monotonic", "m", "x");
  c.direction = std::move(direction);
  c.strict = strict;
  return c;
}

TEST(RunnerChecks, MonotonicIncreasingStrict) {
  const CheckOutcome o = runner::evaluateCheck(monotonic("increasing", true), series({1, 2, 3}, {1, 2, 4}));
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.expected, "m strictly increasing in x");
  EXPECT_EQ(o.got, "1, 2, 4");
  EXPECT_FALSE(runner::evaluateCheck(monotonic("increasing", true), series({1, 2, 3}, {1, 3, 2})).passed);
  EXPECT_FALSE(runner::evaluateCheck(monotonic("decreasing", true), series({1, 2, 3}, {1, 2, 4})).passed);
}

TEST(RunnerChecks, MonotonicTiesPassOnlyWhenNotStrict) {
  const Table flat = series({1, 2, 3}, {1, 1, 2});
  EXPECT_FALSE(runner::evaluateCheck(monotonic("increasing", true), flat).passed);
  const CheckOutcome o = runner::evaluateCheck(monotonic("increasing", false), flat);
  EXPECT_TRUE(o.passed);
  EXPECT_EQ(o.expected, "m increasing in x");
  const Table down = series({1, 2, 3}, {3, 3, 1});
  EXPECT_FALSE(runner::evaluateCheck(monotonic("decreasing", true), down).passed);
  EXPECT_TRUE(runner::evaluateCheck(monotonic("decreasing", false), down).passed);
}

TEST(RunnerChecks, MonotonicDecreasing) {
  EXPECT_TRUE(runner::evaluateCheck(monotonic("decreasing", true), series({0, 0.75, 1.5, 2.5}, {9, 4, 2, 1})).passed);
  EXPECT_FALSE(runner::evaluateCheck(monotonic("decreasing", true), series({0, 0.75, 1.5, 2.5}, {9, 4, 5, 1})).passed);
}

TEST(RunnerChecks, MonotonicSortsByTheAxisNotTheRowOrder) {
  // Rows in the order cases listed them; the axis decides.
  const Table t = series({2.5, 0.75, 1.5}, {1, 4, 2});
  const CheckOutcome o = runner::evaluateCheck(monotonic("decreasing", true), t);
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.got, "4, 2, 1");
  EXPECT_FALSE(runner::evaluateCheck(monotonic("increasing", true), t).passed);
}

TEST(RunnerChecks, MonotonicWithWhereFilters) {
  // rk4 rises with dt; implicit Euler does not (in this made-up table), so only a filter passes.
  Table t = integratorTable();
  t.rows[5].metrics["max_abs_error_m"] = 1e-3;  // implicit_euler at dt 0.02 below its dt 0.01 value
  CheckSpec c = spec("monotonic", "max_abs_error_m", "dt_s");
  c.where = {{"integrator", std::string("rk4")}};
  EXPECT_TRUE(runner::evaluateCheck(c, t).passed);
  c.where = {{"integrator", std::string("implicit_euler")}};
  EXPECT_FALSE(runner::evaluateCheck(c, t).passed);
}

TEST(RunnerChecks, MonotonicNeedsTwoPoints) {
  const CheckOutcome o = runner::evaluateCheck(monotonic("increasing", true), series({1}, {1}));
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(o.got, "fewer than 2 points");
}

TEST(RunnerChecks, MonotonicOnAnIntegerAxis) {
  Table t{{"n"}, {"m"}, {}};
  for (int i = 0; i < 4; ++i) t.rows.push_back(row(i, {{"n", std::int64_t(10 * (4 - i))}}, {{"m", double(i)}}));
  CheckSpec c = spec("monotonic", "m", "n");
  c.direction = "decreasing";
  EXPECT_TRUE(runner::evaluateCheck(c, t).passed);
}

// ---- order (observed order of convergence: -slope of log metric against log axis) ----

TEST(RunnerChecks, OrderOfAPowerLaw) {
  // error = 3 * cells^-2 exactly: order 2.
  Table t{{"cells"}, {"error"}, {}};
  int i = 0;
  for (std::int64_t n : {16, 32, 64, 128})
    t.rows.push_back(row(i++, {{"cells", n}}, {{"error", 3.0 / double(n * n)}}));
  CheckSpec c = spec("order", "error", "cells");
  c.expect_lo = 1.9;
  c.expect_hi = 2.1;
  CheckOutcome o = runner::evaluateCheck(c, t);
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.got, "2 over 4 points");
  c.expect_lo = 0.9;
  c.expect_hi = 1.1;  // first order expected, second order found
  o = runner::evaluateCheck(c, t);
  EXPECT_FALSE(o.passed);
}

TEST(RunnerChecks, OrderNeedsTwoDistinctPositiveAxisValues) {
  CheckSpec c = spec("order", "m", "x");
  c.expect_lo = -10;
  c.expect_hi = 10;
  EXPECT_FALSE(runner::evaluateCheck(c, series({4}, {1})).passed);
  EXPECT_FALSE(runner::evaluateCheck(c, series({4, 4}, {1, 2})).passed);
  EXPECT_FALSE(runner::evaluateCheck(c, series({0, 4}, {1, 2})).passed);
  EXPECT_FALSE(runner::evaluateCheck(c, series({1, 4}, {0, 2})).passed);  // log(0)
}

// ---- failed, missing and non-finite points ----

TEST(RunnerChecks, AFailedPointFailsTheCheckWithItsMessage) {
  Table t = frequencyTable();
  t.rows[3].status = "failed";
  t.rows[3].message = "simulation diverged at step 16 (t = 8 s)";
  t.rows[3].metrics["distance_m"] = std::nan("");
  for (const std::string type : {"argmax", "argmin", "range", "monotonic"}) {
    CheckSpec c = spec(type, "distance_m", type == "range" ? "" : "contraction_hz");
    c.expect_lo = 0;
    c.expect_hi = 10;
    const CheckOutcome o = runner::evaluateCheck(c, t);
    EXPECT_FALSE(o.passed) << type;
    EXPECT_EQ(o.got, "point 3 failed: simulation diverged at step 16 (t = 8 s)") << type;
  }
  CheckSpec r = spec("ratio", "distance_m");
  r.numerator = {{"contraction_hz", 0.8}};
  r.denominator = {{"contraction_hz", 0.5}};
  r.expect_lo = 0;
  r.expect_hi = 10;
  const CheckOutcome o = runner::evaluateCheck(r, t);
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.got, "point 3 failed: simulation diverged")) << o.got;
}

TEST(RunnerChecks, AFailedPointOutsideTheSelectionDoesNotMatter) {
  Table t = frequencyTable();
  t.rows[4].status = "failed";
  t.rows[4].message = "diverged";
  CheckSpec c = spec("range", "distance_m");
  c.where = {{"contraction_hz", 0.7}};
  c.expect_lo = 1.9;
  c.expect_hi = 2.1;
  EXPECT_TRUE(runner::evaluateCheck(c, t).passed);
}

TEST(RunnerChecks, AMissingPointFailsTheCheck) {
  Table t = frequencyTable();
  t.rows[1].status = "missing";
  CheckSpec c = spec("argmax", "distance_m", "contraction_hz");
  c.expect_lo = 0.6;
  c.expect_hi = 0.8;
  const CheckOutcome o = runner::evaluateCheck(c, t);
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(o.got, "point 1 missing");
}

TEST(RunnerChecks, ANonFiniteMetricFailsTheCheck) {
  Table t = frequencyTable();
  t.rows[2].metrics["distance_m"] = std::nan("");  // e.g. a strand that never settled
  CheckSpec c = spec("range", "distance_m");
  c.expect_lo = 0;
  c.expect_hi = 10;
  const CheckOutcome o = runner::evaluateCheck(c, t);
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(o.got, "point 2 has no finite distance_m");
  t.rows[2].metrics.erase("distance_m");
  EXPECT_FALSE(runner::evaluateCheck(c, t).passed);
}

// ---- several checks, the console table ----

TEST(RunnerChecks, EvaluateChecksKeepsOrderAndTheTableMarksFailures) {
  CheckSpec pass = spec("argmax", "distance_m", "contraction_hz");
  pass.name = "peak near 0.7 Hz";
  pass.expect_lo = 0.6;
  pass.expect_hi = 0.8;
  CheckSpec fail = monotonic("increasing", true);  // must fail: distance rises then falls
  fail.name = "distance rises";
  fail.metric = "distance_m";
  fail.axis = "contraction_hz";
  const auto outcomes = runner::evaluateChecks({pass, fail}, frequencyTable());
  ASSERT_EQ(outcomes.size(), 2u);
  EXPECT_TRUE(outcomes[0].passed);
  EXPECT_FALSE(outcomes[1].passed);
  EXPECT_EQ(outcomes[1].got, "1, 1.5, 2, 1.8, 1.2");
  const std::string table = runner::formatCheckTable(outcomes);
  EXPECT_TRUE(contains(table, "peak near 0.7 Hz")) << table;
  EXPECT_TRUE(contains(table, "ok")) << table;
  const auto line = table.substr(table.find("distance rises"));
  EXPECT_TRUE(contains(line.substr(0, line.find('\n')), "FAIL")) << table;
}

}  // namespace

// ---- known deviations: still evaluated and printed, but a failure does not fail the run ----

TEST(RunnerChecks, AKnownDeviationIsEvaluatedPrintedAndDoesNotCount) {
  CheckSpec c = spec("argmax", "distance_m", "contraction_hz");
  c.expect_lo = 1.0;
  c.expect_hi = 1.5;
  c.known_deviation = "the model peaks at 0.7 Hz, not above";
  const CheckOutcome failed = runner::evaluateCheck(c, frequencyTable());
  EXPECT_FALSE(failed.passed);
  EXPECT_TRUE(failed.counts());
  const std::string table = runner::formatCheckTable({failed});
  EXPECT_TRUE(contains(table, "KNOWN ")) << table;
  EXPECT_TRUE(contains(table, "fails as expected")) << table;
  EXPECT_TRUE(contains(table, "the model peaks at 0.7 Hz, not above")) << table;
  EXPECT_FALSE(contains(table, "FAIL")) << table;

  c.expect_lo = 0.6;
  c.expect_hi = 0.8;
  const CheckOutcome passed = runner::evaluateCheck(c, frequencyTable());
  EXPECT_TRUE(passed.passed);
  EXPECT_TRUE(contains(runner::formatCheckTable({passed}), "marked as a known deviation but passed")) << passed.got;
}

TEST(RunnerChecks, AnOrdinaryFailureStillCounts) {
  CheckSpec c = spec("argmax", "distance_m", "contraction_hz");
  c.expect_lo = 1.0;
  c.expect_hi = 1.5;
  const CheckOutcome o = runner::evaluateCheck(c, frequencyTable());
  EXPECT_FALSE(o.counts());
  EXPECT_TRUE(contains(runner::formatCheckTable({o}), "FAIL")) << o.got;
}

// ---- uncertainty: the value's 95% Student-t interval decides pass, fail or inconclusive ----

TEST(RunnerChecks, IntervalHalfWidthIsStudentsT) {
  // t(0.975) from the tables: 12.706 at 1 dof, 2.571 at 5, 2.228 at 10, 1.960 for many.
  EXPECT_NEAR(runner::intervalHalfWidth(1.0, 1), 12.7062, 1e-4);
  EXPECT_NEAR(runner::intervalHalfWidth(1.0, 5), 2.5706, 1e-4);
  EXPECT_NEAR(runner::intervalHalfWidth(0.5, 10), 0.5 * 2.2281, 1e-4);
  EXPECT_NEAR(runner::intervalHalfWidth(1.0, 1e6), 1.9600, 1e-4);
  EXPECT_EQ(runner::intervalHalfWidth(0.0, std::nan("")), 0.0);  // no scatter: no interval needed
  EXPECT_TRUE(std::isnan(runner::intervalHalfWidth(1.0, 0)));    // one sample: no spread to judge by
  EXPECT_TRUE(std::isnan(runner::intervalHalfWidth(1.0, std::nan(""))));
  EXPECT_TRUE(std::isnan(runner::intervalHalfWidth(-1.0, 5)));
}

TEST(RunnerChecks, WelchDegreesOfFreedom) {
  EXPECT_DOUBLE_EQ(runner::welchDegreesOfFreedom(1, 5, 1, 5), 10);       // equal errors: the sum of both
  EXPECT_DOUBLE_EQ(runner::welchDegreesOfFreedom(1, 5, 2, 5), 25 / 3.4);  // the larger error dominates
  EXPECT_DOUBLE_EQ(runner::welchDegreesOfFreedom(1, 5, 0, 1), 5);         // an exact side adds nothing
  EXPECT_DOUBLE_EQ(runner::welchDegreesOfFreedom(-1, 5, 1, 5), 10);
}

TEST(RunnerChecks, IntervalVerdictAgainstAWindow) {
  using runner::Verdict;
  const double many = 1e6;  // t = 1.96
  EXPECT_EQ(runner::intervalVerdict(1.5, 0.1, many, 1.0, 2.0), Verdict::pass);           // [1.30, 1.70] inside
  EXPECT_EQ(runner::intervalVerdict(1.1, 0.05, many, 1.0, 2.0), Verdict::pass);          // [1.002, 1.198]
  EXPECT_EQ(runner::intervalVerdict(1.1, 0.06, many, 1.0, 2.0), Verdict::inconclusive);  // [0.982, 1.218] holds 1
  EXPECT_EQ(runner::intervalVerdict(1.9, 0.1, many, 1.0, 2.0), Verdict::inconclusive);   // holds 2
  EXPECT_EQ(runner::intervalVerdict(0.9, 0.1, many, 1.0, 2.0), Verdict::inconclusive);   // below, but holds 1
  EXPECT_EQ(runner::intervalVerdict(0.7, 0.1, many, 1.0, 2.0), Verdict::fail);           // [0.50, 0.90] wholly below
  EXPECT_EQ(runner::intervalVerdict(2.5, 0.2, many, 1.0, 2.0), Verdict::fail);           // [2.11, 2.89] wholly above
  EXPECT_EQ(runner::intervalVerdict(1.5, 0.0, 0, 1.0, 2.0), Verdict::pass);              // no scatter: the value decides
  EXPECT_EQ(runner::intervalVerdict(0.5, 0.0, 0, 1.0, 2.0), Verdict::fail);
  EXPECT_EQ(runner::intervalVerdict(1.5, std::nan(""), many, 1.0, 2.0), Verdict::inconclusive);  // no standard error
  EXPECT_EQ(runner::intervalVerdict(1.5, -0.1, many, 1.0, 2.0), Verdict::inconclusive);
  EXPECT_EQ(runner::intervalVerdict(std::nan(""), 0.1, many, 1.0, 2.0), Verdict::fail);
  EXPECT_EQ(runner::intervalVerdict(1.1, 0.2, many, 1.0, 1e9), Verdict::inconclusive);  // a one-sided bound
  EXPECT_EQ(runner::intervalVerdict(1.5, 0.2, many, 1.0, 1e9), Verdict::pass);
  // Few samples widen the interval: six flaps (5 dof) give [0.986, 2.014], which holds 1; two samples
  // (1 dof) hold it by far; one sample has no spread to judge by.
  EXPECT_EQ(runner::intervalVerdict(1.5, 0.2, 5, 1.0, 1e9), Verdict::inconclusive);
  EXPECT_EQ(runner::intervalVerdict(1.6, 0.2, 5, 1.0, 1e9), Verdict::pass);
  EXPECT_EQ(runner::intervalVerdict(3.0, 0.2, 1, 1.0, 1e9), Verdict::inconclusive);
  EXPECT_EQ(runner::intervalVerdict(0.1, 0.02, 0, 1.0, 1e9), Verdict::inconclusive);
}

// Two labelled points, each with a mean force, its standard error and the flaps behind it.
Table forceTable(double controlled, double controlled_se, double held, double held_se, std::int64_t flaps = 1000000,
                 std::int64_t held_flaps = 0) {
  Table t{{"flaps"}, {"force_n", "force_n_stderr"}, {}};
  t.rows.push_back(row(0, {{"flaps", flaps}}, {{"force_n", controlled}, {"force_n_stderr", controlled_se}}, "ok", "",
                       "controlled"));
  t.rows.push_back(row(1, {{"flaps", held_flaps > 0 ? held_flaps : flaps}}, {{"force_n", held}, {"force_n_stderr", held_se}},
                       "ok", "", "held"));
  return t;
}

CheckSpec forceRatio(std::string type = "ratio") {
  CheckSpec c = spec(std::move(type), "force_n");
  c.numerator = {{"label", std::string("controlled")}};
  c.denominator = {{"label", std::string("held")}};
  c.expect_lo = 1.0;
  c.expect_hi = 1e9;
  c.uncertainty = "force_n_stderr";
  c.samples = "flaps";
  return c;
}

TEST(RunnerChecks, ARatioWhoseIntervalHoldsTheBoundIsInconclusiveAndDoesNotCount) {
  // 9.73 +- 0.14 over 9.50 +- 1.30: 1.024 +- 0.141 (relative errors in quadrature); with many flaps
  // t = 1.96, [0.748, 1.300] holds 1.
  const CheckOutcome o = runner::evaluateCheck(forceRatio(), forceTable(9.73, 0.14, 9.50, 1.30));
  EXPECT_FALSE(o.passed) << o.got;
  EXPECT_TRUE(o.inconclusive) << o.got;
  EXPECT_TRUE(o.counts());
  EXPECT_EQ(o.got, "1.02421 +- 0.140928 (95%, 1.02211e+06 dof: [0.747997, 1.30042])");
  const std::string table = runner::formatCheckTable({o});
  EXPECT_TRUE(contains(table, "  inconclusive  ")) << table;
  EXPECT_TRUE(contains(table, "inconclusive: 'ratio check'")) << table;
  EXPECT_FALSE(contains(table, "FAIL")) << table;
  EXPECT_FALSE(contains(table, "ok ")) << table;
}

TEST(RunnerChecks, ARatioWithSmallErrorsPassesOrFails) {
  CheckOutcome o = runner::evaluateCheck(forceRatio(), forceTable(10.4, 0.05, 10.0, 0.05));  // 1.04 +- 0.0072
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_FALSE(o.inconclusive);
  EXPECT_TRUE(contains(runner::formatCheckTable({o}), "ok    ")) << runner::formatCheckTable({o});
  o = runner::evaluateCheck(forceRatio(), forceTable(9.0, 0.05, 10.0, 0.05));  // 0.9 +- 0.0067
  EXPECT_FALSE(o.passed) << o.got;
  EXPECT_FALSE(o.inconclusive);
  EXPECT_FALSE(o.counts());
  // Without the uncertainty the same values decide alone.
  CheckSpec plain = forceRatio();
  plain.uncertainty.clear();
  o = runner::evaluateCheck(plain, forceTable(9.73, 0.14, 9.50, 1.30));
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_EQ(o.got, "1.02421");
}

TEST(RunnerChecks, ARatioOfFewFlapsTakesStudentsTWithWelchsDegreesOfFreedom) {
  // 1.30 +- 0.115 (6.26% a side) from two flaps a side: 2 s.e. would clear 1 ([1.07, 1.53]); Welch
  // gives 2 dof (t = 4.30), so the interval holds 1.
  const Table two = forceTable(1.3 * 10, 0.0626 * 13, 10, 0.0626 * 10, 2);
  CheckOutcome o = runner::evaluateCheck(forceRatio(), two);
  EXPECT_TRUE(o.inconclusive) << o.got;
  EXPECT_TRUE(contains(o.got, "(95%, 2 dof: [")) << o.got;
  // Six a side: 10 dof, t = 2.23: [1.044, 1.556] clears it.
  o = runner::evaluateCheck(forceRatio(), forceTable(1.3 * 10, 0.0626 * 13, 10, 0.0626 * 10, 6));
  EXPECT_TRUE(o.passed) << o.got;
  EXPECT_TRUE(contains(o.got, "(95%, 10 dof: [1.04")) << o.got;
  // Unequal counts, six and two: (2 e^2)^2 / (e^4 / 5 + e^4 / 1) = 3.3 dof.
  o = runner::evaluateCheck(forceRatio(), forceTable(1.3 * 10, 0.0626 * 13, 10, 0.0626 * 10, 6, 2));
  EXPECT_TRUE(contains(o.got, "(95%, 3.3 dof: [")) << o.got;
  // A point of one sample has no interval.
  o = runner::evaluateCheck(forceRatio(), forceTable(13, 0.1, 10, 0.1, 1));
  EXPECT_TRUE(o.inconclusive) << o.got;
  EXPECT_TRUE(contains(o.got, "(no interval: 0 dof)")) << o.got;
}

TEST(RunnerChecks, ADifferenceAddsItsErrorsInQuadrature) {
  CheckSpec c = forceRatio("difference");
  c.expect_lo = 0.0;
  // 0.5 +- hypot(0.3, 0.4) = 0.5: [-0.48, 1.48] holds 0.
  CheckOutcome o = runner::evaluateCheck(c, forceTable(10.5, 0.3, 10.0, 0.4));
  EXPECT_TRUE(o.inconclusive) << o.got;
  EXPECT_TRUE(contains(o.got, "0.5 +- 0.5")) << o.got;
  o = runner::evaluateCheck(c, forceTable(12.0, 0.3, 10.0, 0.4));  // 2 +- 0.5
  EXPECT_TRUE(o.passed) << o.got;
}

TEST(RunnerChecks, ARangeOverPointsWithErrors) {
  CheckSpec c = spec("range", "force_n");
  c.expect_lo = 9.0;
  c.expect_hi = 11.0;
  c.uncertainty = "force_n_stderr";
  c.samples = "flaps";
  EXPECT_TRUE(runner::evaluateCheck(c, forceTable(10.0, 0.1, 10.5, 0.2)).passed);
  const CheckOutcome inconclusive = runner::evaluateCheck(c, forceTable(10.0, 0.1, 10.5, 0.3));  // [9.91, 11.09]
  EXPECT_TRUE(inconclusive.inconclusive) << inconclusive.got;
  EXPECT_TRUE(contains(inconclusive.got, "standard errors up to 0.3")) << inconclusive.got;
  const CheckOutcome failed = runner::evaluateCheck(c, forceTable(10.0, 0.6, 12.0, 0.3));  // one wholly above
  EXPECT_FALSE(failed.passed);
  EXPECT_FALSE(failed.inconclusive);
  c.where = {{"label", std::string("held")}};
  const CheckOutcome one = runner::evaluateCheck(c, forceTable(10.0, 0.1, 10.5, 0.3, 5));
  EXPECT_TRUE(one.inconclusive) << one.got;
  EXPECT_TRUE(contains(one.got, "10.5 +- 0.3 (95%, 4 dof: [9.66707, 11.3329])")) << one.got;  // t(4) = 2.776
  EXPECT_TRUE(runner::evaluateCheck(c, forceTable(10.0, 0.1, 10.5, 0.17, 5)).passed);  // [10.03, 10.97]
}

TEST(RunnerChecks, AMissingOrNonFiniteStandardErrorIsInconclusive) {
  CheckOutcome o = runner::evaluateCheck(forceRatio(), forceTable(12.0, std::nan(""), 10.0, 0.1));
  EXPECT_TRUE(o.inconclusive) << o.got;
  EXPECT_TRUE(contains(o.got, "1.2 +- nan")) << o.got;
  CheckSpec c = forceRatio();
  c.uncertainty = "no_such_metric";
  o = runner::evaluateCheck(c, forceTable(12.0, 0.1, 10.0, 0.1));
  EXPECT_TRUE(o.inconclusive) << o.got;
}

TEST(RunnerChecks, AKnownDeviationThatIsInconclusiveIsPrintedInconclusive) {
  CheckSpec c = forceRatio();
  c.known_deviation = "the model's ratio sits at 1";
  const CheckOutcome o = runner::evaluateCheck(c, forceTable(9.73, 0.14, 9.50, 1.30));
  const std::string table = runner::formatCheckTable({o});
  EXPECT_TRUE(contains(table, "  inconclusive  ")) << table;
  EXPECT_FALSE(contains(table, "KNOWN")) << table;
}
