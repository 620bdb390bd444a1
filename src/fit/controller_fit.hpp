#pragma once
// Tuning controller parameters (stagger, knot values, frequency, ...) of a kind for an objective
// computed from its metrics. Each objective evaluation is one deterministic run of the
// kind (kinds::Kind::run); derivatives are central differences, one parameter at a time, as in
// Lentine et al. 2010 (Creature Control in a Fluid Environment, §2.1: "make a change in one
// direction, evaluate the objective function, then make the same change in the opposite
// direction ... the difference ... divided by twice the magnitude of the change"), and, as the
// paper notes, "inherently parallelizable": the 2n + 1 runs of one gradient run on `jobs` threads.
//
// Two forms (Ceres, controller_fit.cpp):
//  - maximise: cost(z) = -metric(x(z)) / scale minimised by Ceres' GradientProblem with LBFGS,
//    unconstrained in z; the bounds are kept by the logistic reparameterisation
//        x_i = lower_i + (upper_i - lower_i) σ(z_i),   σ(z) = 1 / (1 + e^-z),
//    ∂cost/∂z_i = ∂cost/∂x_i (upper_i - lower_i) σ(z_i)(1 - σ(z_i)). (LBFGS is unconstrained in
//    Ceres; rejected: clamping x, which leaves a zero gradient along the clamped direction.)
//  - target: residuals r = ((metric - target) / tolerance, least / least_scale), ½|r|² minimised by
//    Ceres' trust-region solver (Levenberg-Marquardt), which keeps the bounds on x itself.
// The difference quotient at x uses steps h⁺ = min(h, upper - x), h⁻ = min(h, x - lower):
//     ∂f/∂x_i ≈ (f(x + h⁺ e_i) - f(x - h⁻ e_i)) / (h⁺ + h⁻)
// so no run leaves the bounds (one-sided only at a bound itself). When the run on one side fails
// (a bell that crumples, invalid parameters), the one-sided quotient from x on the other is used;
// when both fail, that derivative is 0 for the step. A failed run at a point the optimiser tries
// scores a finite penalty (maximise: cost_start + max(|cost_start|, 1); target: an invalid step,
// which the trust region rejects), so the search backs off instead of stopping.
//
// Determinism: every run is a pure function of its parameters and each batch's results are placed
// by index, so the fit is bitwise the same for any `jobs`. Resume: evaluations are looked up by
// the exact bits of x; a fit restarted with the evaluations of an interrupted one retraces the
// same path from the record and runs only what is missing.
//
// The fit does no I/O: `on_batch` receives the state after every batch so that the caller can
// record it (controller_record.hpp).
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "fit/controller_spec.hpp"
#include "kinds/kind.hpp"

namespace creaturelab::fit {

struct Evaluation {
  std::vector<double> x;                  // the tuned parameters, in ControllerSpec::tuned order
  bool ok = false;                        // false: the run failed or its parameters were invalid
  std::string message;                    // why it failed
  std::map<std::string, double> metrics;  // the kind's metrics (empty when it failed)
  double cost = 0;                        // the objective's cost (NaN when it failed)
  double wall_s = 0;                      // time of the run (provenance, not compared)
};

// One optimiser iteration (Ceres' IterationSummary) at the current point x.
struct IterationRecord {
  int iteration = 0;
  bool accepted = true;  // the step of this iteration was taken
  double cost = 0;       // at x
  double objective = 0;  // the metric (maximise) or the cost (target) at x
  double gradient_max_norm = 0;
  double step_norm = 0;
  int evaluations = 0;  // distinct evaluations so far (new and recorded)
  std::vector<double> x;
};

struct ControllerFitState {
  const std::vector<Evaluation>* evaluations = nullptr;  // every distinct evaluation, in order of first use
  const std::vector<IterationRecord>* history = nullptr;
  int new_runs = 0;     // runs made by this process
  int reused_runs = 0;  // evaluations served from the record
};

struct ControllerFitOptions {
  int jobs = 0;  // threads for the runs of one batch; 0 = the cores
  std::vector<Evaluation> recorded;  // evaluations of an earlier, interrupted fit (resume)
  std::function<void(const ControllerFitState&)> on_batch;      // after each batch of runs
  std::function<void(const IterationRecord&)> on_iteration;     // after each optimiser iteration
  int stop_after_new_runs = 0;  // > 0: stop (FitInterrupted) once this many new runs are made (tests)
};

struct ControllerFitResult {
  std::vector<double> x_start, x_fitted;
  Evaluation start, fitted;
  std::vector<Evaluation> evaluations;
  std::vector<IterationRecord> history;
  int new_runs = 0, reused_runs = 0;
  bool converged = false;
  std::string termination;  // Ceres' message
  std::string solver_report;
};

/// Thrown when ControllerFitOptions::stop_after_new_runs is reached.
class FitInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The cost of one evaluation's metrics under the spec's objective (NaN if a metric is missing).
double objectiveCost(const ObjectiveSpec& objective, const std::map<std::string, double>& metrics);
/// The residuals of the target form (empty for maximise).
std::vector<double> objectiveResiduals(const ObjectiveSpec& objective, const std::map<std::string, double>& metrics);

/// Runs the fit. Throws FitError when the start point itself cannot be evaluated.
ControllerFitResult fitController(const ControllerSpec& spec, const kinds::Kind& kind,
                                  const ControllerFitOptions& options);

/// Runs the kind once at x (no cache), e.g. to store the start and fitted trajectories. Both
/// points run on their own threads when `jobs` > 1.
std::vector<kinds::Result> runPoints(const ControllerSpec& spec, const kinds::Kind& kind,
                                     const std::vector<std::vector<double>>& xs, int jobs);

}  // namespace creaturelab::fit
