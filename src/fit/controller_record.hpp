#pragma once
// The record of a controller fit (file I/O): DIR/controller_fit.h5, rewritten as a whole (.tmp,
// then renamed) after every batch of runs, so the file that exists is always whole and an
// interrupted fit loses at most the batch in flight.
//
//   /                    attrs: title, kind, spec_path, spec_sha256, objective_type, objective_metric,
//                        complete (false until the fit ends), new_runs, reused_runs, converged,
//                        termination, solver_report, and the caller's provenance attributes
//   /tuned/{name, unit, lower, upper, step, start}
//   /evaluations/x            (N, n) every distinct evaluation, in order of first use
//   /evaluations/{ok, cost, message, wall_s}, /evaluations/metrics/<metric>   (N)
//   /history/{iteration, accepted, cost, objective, gradient_max_norm, step_norm, evaluations},
//   /history/x (iterations, n)          one row per optimiser iteration, at its current point
// and, once complete:
//   /result/{x_start, x_fitted}, /result/start_metrics/<m>, /result/fitted_metrics/<m>
//   /start/timeseries/<name>, /fitted/timeseries/<name>      the two runs again, whole
//   /start/curve/{phase, aperture, apex}, /fitted/curve/...  jellyfish only: the muscle factor
//                                                            of the aperture and apex springs
// DIR/params.toml: the fitted `[params]` (the file's [params] and the tuned values).
#include <map>
#include <string>
#include <vector>

#include "fit/controller_fit.hpp"
#include "fit/controller_spec.hpp"
#include "kinds/result.hpp"

namespace creaturelab::fit {

std::string recordPath(const std::string& dir);  // DIR/controller_fit.h5

struct ControllerRecordInfo {
  std::map<std::string, std::string> attributes;  // provenance
};

/// While the fit runs: evaluations and history so far.
void writeControllerRecord(const std::string& dir, const ControllerSpec& spec, const ControllerFitState& state,
                           const ControllerRecordInfo& info);

/// When it is done: everything, with the two whole runs (start, fitted).
void writeControllerResult(const std::string& dir, const ControllerSpec& spec, const ControllerFitResult& result,
                           const kinds::Result& start_run, const kinds::Result& fitted_run,
                           const ControllerRecordInfo& info);

/// The evaluations of an earlier fit of the same file. Throws FitError when the record belongs to
/// another file (its spec_sha256 differs) or cannot be read.
std::vector<Evaluation> readControllerEvaluations(const std::string& dir, const ControllerSpec& spec);

/// The params.toml text of a fit.
std::string controllerParamsFragment(const ControllerSpec& spec, const std::vector<double>& x);

}  // namespace creaturelab::fit
