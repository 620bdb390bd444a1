#pragma once
// Regression baselines (results/baselines/*.json): scalar metrics per point with per-metric
// tolerances, and the comparison of a run against one (`creaturelab compare RUN BASELINE`).
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "runner/table.hpp"

namespace creaturelab::runner {

// |got - expected| <= atol + rtol * |expected|
struct Tolerance {
  double rtol = 1e-9;
  double atol = 0;
};

struct Baseline {
  std::string experiment;              // the experiment file, relative to the repository
  std::vector<std::string> overrides;  // dotted.key=value, as on the command line
  std::map<std::string, Tolerance> tolerances;  // per metric; "default" for the rest
  Table table;                          // label, status and metrics per point

  Tolerance toleranceFor(const std::string& metric) const;
};

nlohmann::json baselineToJson(const Baseline& baseline);
Baseline baselineFromJson(const nlohmann::json& j, const std::string& source);  // throws std::runtime_error

struct Difference {
  int point = 0;
  std::string label, metric;
  double got = 0, expected = 0;
  Tolerance tolerance;
  bool within = false;
  std::string note;  // "point failed", "missing", ...
};

struct Comparison {
  std::vector<Difference> rows;
  bool passed() const;
};

Comparison compareTables(const Table& run, const Baseline& baseline);
std::string formatComparison(const Comparison& c, bool only_failures);

}  // namespace creaturelab::runner
