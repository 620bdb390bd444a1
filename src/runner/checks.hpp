#pragma once
// [[check]] evaluation over the sweep table (DESIGN.md): argmax, argmin, range, ratio, difference
// (numerator − denominator, with ratio's selections), monotonic, and order (observed order of
// convergence: log-log slope of a metric against an axis). A range, ratio or difference check with
// `uncertainty = "<metric>"` (each point's standard error of its value) is pass, fail or inconclusive.
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
  // With the spec's uncertainty: the value's 95% interval holds a bound of the window, so the run
  // decides nothing (passed is false; the exit code is as for a pass).
  bool inconclusive = false;
  // true when it does not fail the run
  bool counts() const { return passed || inconclusive || !known_deviation.empty(); }
};

// The half-width of a two-sided 95% Student-t interval: t(0.975, dof) x standard_error; 0 for a zero
// standard error, NaN when the error is not a finite number >= 0 or dof is not > 0 (one sample).
double intervalHalfWidth(double standard_error, double dof);
// Welch-Satterthwaite: the degrees of freedom of the quadrature sum of two independent errors.
double welchDegreesOfFreedom(double error_a, double dof_a, double error_b, double dof_b);
// A value with a standard error and its degrees of freedom against the window [lo, hi]: the 95% interval
// (intervalHalfWidth) wholly inside passes, wholly outside fails, one that holds a bound (or no interval)
// is inconclusive.
enum class Verdict { pass, fail, inconclusive };
Verdict intervalVerdict(double value, double standard_error, double dof, double lo, double hi);

CheckOutcome evaluateCheck(const CheckSpec& check, const Table& table);
std::vector<CheckOutcome> evaluateChecks(const std::vector<CheckSpec>& checks, const Table& table);

// Before any point runs: every check's point selections (where, numerator, denominator, *_base)
// must match a point of the sweep; a key or value no point has is an ExperimentError naming the
// check, the key and the values the sweep does have.
void checkSelections(const Experiment& experiment, const std::vector<Point>& points);

// A plain-text table for the console.
std::string formatCheckTable(const std::vector<CheckOutcome>& outcomes);

}  // namespace creaturelab::runner
