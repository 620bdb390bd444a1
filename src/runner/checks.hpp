#pragma once
// [[check]] evaluation over the sweep table (DESIGN.md): argmax, argmin, range, ratio, monotonic,
// and order (observed order of convergence: log-log slope of a metric against an axis).
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
};

CheckOutcome evaluateCheck(const CheckSpec& check, const Table& table);
std::vector<CheckOutcome> evaluateChecks(const std::vector<CheckSpec>& checks, const Table& table);

// A plain-text table for the console.
std::string formatCheckTable(const std::vector<CheckOutcome>& outcomes);

}  // namespace creaturelab::runner
