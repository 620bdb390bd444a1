#pragma once
// An experiment file (DESIGN.md "Experiment files"), parsed and checked against its kind's schema.
//
// `base = "<path>"` (relative to the naming file's folder) starts the file from another experiment
// file; bases chain. The merge: tables ([params], [sweep], [output], nested tables) merge key by
// key, recursively; every other value of the file replaces the base's: scalars (kind, title,
// description), sweep lists, and the [[case]] and [[check]] lists as a whole. A file without its
// own list inherits the base's; an empty list (case = [], check = []) clears it. Overrides apply
// after the merge. A missing base, a base that is not a string and a cycle are ExperimentErrors
// naming the chain ("a.toml -> b.toml: base file not found"); a bad key read from a base names
// the base file. See docs/experiments.md.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinds/kind.hpp"

namespace creaturelab::runner {

using kinds::Params;
using kinds::Value;

// A user error in an experiment file or an override: the message names the file, the key
// (with a close match) and what was expected. The CLI prints it and exits with code 2.
class ExperimentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SweepAxis {
  std::string name;
  std::vector<Value> values;
};

struct Case {
  std::string label;
  Params values;  // in file order is not kept: std::map sorts, which keeps /sweep columns stable
  std::vector<std::string> keys;  // file order, for the /sweep columns
};

using Where = std::vector<std::pair<std::string, Value>>;

struct CheckSpec {
  std::string name;
  std::string type;    // argmax | argmin | range | ratio | difference | monotonic | order
  std::string metric;
  std::string axis;    // argmax, argmin, monotonic, order
  double expect_lo = 0, expect_hi = 0;        // numeric expectations
  std::optional<std::string> expect_choice;  // argmax/argmin over a string axis
  std::string direction = "increasing";     // monotonic
  bool strict = true;                        // monotonic
  Where where, numerator, denominator;       // point selections
  std::string numerator_metric, denominator_metric;  // ratio: "" = metric
  Where numerator_base, denominator_base;  // ratio, difference: each side relative to its metric at this point
  // How a side is relative to its base: false, metric(side) / metric(base); true (base_relation =
  // "difference"), metric(side) - metric(base), e.g. a finite-difference slope between two poses.
  bool base_difference = false;
  // argmax/argmin: the expectation is on axis value / mean of relative_metric over the points
  // relative_to selects (e.g. a driven response's peak frequency over a pluck's natural_hz).
  Where relative_to;
  std::string relative_metric;
  // A paper claim the model is known not to reproduce, with the reason (its data and
  // mechanism). The check is still evaluated and printed (KNOWN instead of FAIL) but a failure
  // does not change the exit code; if it passes the table says so.
  std::string known_deviation;
  // range, ratio, difference: the metric holding each point's standard error of `metric`; the value's 95%
  // Student-t interval (the error propagated through the ratio or difference, Welch's degrees of freedom)
  // decides pass, fail or inconclusive.
  std::string uncertainty;
  // With uncertainty: the integer parameter counting the independent samples behind each point's standard
  // error (n; n - 1 degrees of freedom), e.g. the flaps whose means it is the scatter of.
  std::string samples;
};

struct OutputOptions {
  std::string dir;          // "" = results/runs/<file stem>
  bool lagrangian = true;   // write /lagrangian tracks
};

struct Experiment {
  std::string path;   // as given
  std::string stem;   // file name without .toml (the file's own, not its base's)
  std::string kind;
  std::string title;
  Params params;      // [params] overrides only
  std::vector<SweepAxis> axes;
  std::vector<Case> cases;
  std::vector<CheckSpec> checks;
  OutputOptions output;
  std::string resolved_json;  // the experiment after overrides, as JSON (provenance)
  // The file as read, so a run folder can re-check itself; with a base, the merged document
  // (without `base`), so the run folder never needs the base file.
  std::string source_text;
  std::vector<std::string> overrides;
};

// Parses `path`, applies command-line overrides ("params.x=3", "sweep.y=[1,2]"), and checks every
// key and value against the kind. Throws ExperimentError.
Experiment loadExperiment(const std::string& path, const std::vector<std::string>& overrides,
                          const kinds::Registry& registry);
// The same from the file's text (`path` is used in messages and for the stem).
Experiment loadExperimentText(const std::string& text, const std::string& path,
                              const std::vector<std::string>& overrides, const kinds::Registry& registry);

// One point of the sweep: cases (outer) × sweep axes (last axis fastest).
struct Point {
  int index = 0;
  std::string label;   // the case label, "" without cases
  Params params;       // every parameter of the kind, resolved
};

// The /sweep columns: case keys (first appearance order), then sweep axes, then the checks' samples
// parameters.
std::vector<std::string> sweepColumns(const Experiment& experiment);

// Expands and validates every point (ranges, the kind's cross checks). Throws ExperimentError.
std::vector<Point> expandPoints(const Experiment& experiment, const kinds::Kind& kind);

}  // namespace creaturelab::runner
