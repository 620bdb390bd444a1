#pragma once
// [[check]] evaluation over the sweep table (DESIGN.md): argmax, argmin, range, ratio, difference
// (numerator − denominator, with ratio's selections), monotonic, and order (observed order of
// convergence: log-log slope of a metric against an axis).
#include <string>
#include <vector>

#include "runner/experiment.hpp"
#include "runner/table.hpp"

namespace creaturelab::runner {

struct CheckOutcome {
  std::string name;
  std::string type;
  std::string expected;
  std::string got;
  bool passed = false;
  std::string known_deviation;  // from the spec: a failure is expected and does not fail the run
  bool counts() const { return passed || !known_deviation.empty(); }  // true when it does not fail the run
};

CheckOutcome evaluateCheck(const CheckSpec& check, const Table& table);
std::vector<CheckOutcome> evaluateChecks(const std::vector<CheckSpec>& checks, const Table& table);

// Before any point runs: every check's point selections (where, numerator, denominator, *_base)
// must match a point of the sweep; a key or value no point has is an ExperimentError naming the
// check, the key and the values the sweep does have.
void checkSelections(const Experiment& experiment, const std::vector<Point>& points);

// A plain-text table for the console.
std::string formatCheckTable(const std::vector<CheckOutcome>& outcomes);

}  // namespace creaturelab::runner
