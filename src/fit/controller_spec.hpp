#pragma once
// A controller-fit file (experiments/fit/*.toml): which kind runs, its base parameters, which
// parameters to tune within which bounds, the objective and the optimiser's budget.
//
//   kind = "jellyfish"                     # the kind whose run() is the objective (default jellyfish)
//   title = "..."
//   [params]                               # overrides of the kind's defaults, as in an experiment file
//   cells = 50
//   [objective]
//   type = "maximise"                      # maximise | target
//   metric = "distance_per_cycle_m"        # a metric of the kind
//   scale = 0.001                          # maximise: cost = -metric / scale
//   # target: residuals ((metric - target) / tolerance, least / least_scale), bounded least squares
//   # target = 0.004, tolerance = 0.0005, least = "muscle_work_j", least_scale = 2e-4
//   [solver]
//   max_iterations = 6                     # optimiser iterations
//   max_runs = 200                         # kind runs, new and recorded together
//   function_tolerance = 1e-3              # stop when |Δcost| / |cost| < this
//   gradient_tolerance = 1e-6              # stop when max |∂cost/∂z| < this
//   [[tune]]                               # one per tuned parameter: a real parameter of the kind
//   name = "stagger"
//   start = 0.5                            # default: the [params] / default value
//   min = 0.05                             # lower < start < upper, inside the kind's range
//   max = 0.95
//   step = 0.02                            # central-difference half step, in the parameter's unit
//
// Errors (FitError) name the file, the key and what was expected, with a close match for an
// unknown parameter or metric, before any run.
#include <string>
#include <utility>
#include <vector>

#include "fit/fit_error.hpp"
#include "kinds/kind.hpp"

namespace creaturelab::fit {

struct TunedParam {
  std::string name;
  std::string unit;
  double start = 0, lower = 0, upper = 0;
  double step = 0;  // > 0; at most a quarter of (upper - lower)
};

enum class ObjectiveType { maximise, target };

struct ObjectiveSpec {
  ObjectiveType type = ObjectiveType::maximise;
  std::string metric = "distance_per_cycle_m";
  double scale = 1.0;       // maximise
  double target = 0;        // target
  double tolerance = 1.0;   // target: the metric's residual unit
  std::string least;        // target: a metric to keep small ("" = none)
  double least_scale = 1.0;
};

struct ControllerSolverOptions {
  int max_iterations = 6;
  int max_runs = 200;
  double function_tolerance = 1e-3;
  double gradient_tolerance = 1e-6;
  double parameter_tolerance = 1e-4;
};

struct ControllerSpec {
  std::string path, stem, title, kind = "jellyfish";
  std::vector<std::pair<std::string, kinds::Value>> overrides;  // [params] as given, file order
  kinds::Params base;                                           // every parameter, resolved
  std::vector<TunedParam> tuned;
  ObjectiveSpec objective;
  ControllerSolverOptions solver;
  std::string source_text;  // the file as read (its SHA-256 guards a resume)

  /// The base parameters with the tuned ones set to x.
  kinds::Params paramsAt(const std::vector<double>& x) const;
  std::vector<double> start() const;
};

/// Parses and checks the file against the kind found in `registry`. Throws FitError.
ControllerSpec loadControllerSpec(const std::string& path, const kinds::Registry& registry);
ControllerSpec loadControllerSpecText(const std::string& text, const std::string& path,
                                      const kinds::Registry& registry);

}  // namespace creaturelab::fit
