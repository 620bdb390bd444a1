// Ceres lives in this translation unit only (DESIGN.md: Ceres headers compile slowly).
#include "fit/controller_fit.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <thread>

#include "core/text.hpp"

namespace creaturelab::fit {
namespace {

using Key = std::vector<std::uint64_t>;

// Evaluations are matched by the exact bits of x (resume reuses a run only for the very same point).
Key keyOf(const std::vector<double>& x) {
  Key k(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) std::memcpy(&k[i], &x[i], sizeof(double));
  return k;
}

int threadsFor(int jobs) {
  if (jobs > 0) return jobs;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// Runs f(0..count-1) on up to `jobs` threads; each index is done exactly once.
template <typename F>
void parallelFor(int count, int jobs, F&& f) {
  const int threads = std::min(threadsFor(jobs), count);
  if (threads <= 1) {
    for (int i = 0; i < count; ++i) f(i);
    return;
  }
  std::atomic<int> next{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      for (int i = next++; i < count; i = next++) f(i);
    });
  for (auto& th : pool) th.join();
}

Evaluation runOne(const ControllerSpec& spec, const kinds::Kind& kind, const std::vector<double>& x) {
  Evaluation e;
  e.x = x;
  e.cost = std::nan("");
  const auto t0 = std::chrono::steady_clock::now();
  const kinds::Params params = spec.paramsAt(x);
  if (std::string err = kind.validate(params); !err.empty()) {
    e.message = "invalid parameters: " + err;
    return e;
  }
  try {
    const kinds::Result r = kind.run(params);
    for (const auto& [name, m] : r.metrics) e.metrics[name] = m.value;
    e.cost = objectiveCost(spec.objective, e.metrics);
    e.ok = std::isfinite(e.cost);
    if (!e.ok) e.message = "the objective is not finite";
  } catch (const std::exception& ex) {
    e.message = ex.what();
  }
  e.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return e;
}

// The evaluations of one fit: this session's, the record's (resume) and the runs still to make.
class Evaluator {
 public:
  Evaluator(const ControllerSpec& spec, const kinds::Kind& kind, const ControllerFitOptions& options)
      : spec_(spec), kind_(kind), options_(options) {
    for (const auto& e : options.recorded) recorded_.emplace(keyOf(e.x), e);
  }

  // The evaluations of `xs`, in order; runs the missing ones in parallel. nullptr entries when the
  // run budget is spent or the fit was interrupted (the optimiser then sees a failed evaluation).
  std::vector<const Evaluation*> batch(const std::vector<std::vector<double>>& xs) {
    std::vector<std::vector<double>> to_run;
    std::vector<std::size_t> slots;  // where each new run goes in the evaluation list
    for (const auto& x : xs) {
      const Key k = keyOf(x);
      if (index_.count(k) || stopped()) continue;  // known, pending in this batch, or stopping
      if (static_cast<int>(evaluations_.size()) >= spec_.solver.max_runs) {
        budget_spent_ = true;
        continue;
      }
      if (auto it = recorded_.find(k); it != recorded_.end()) {
        index_[k] = evaluations_.size();
        evaluations_.push_back(it->second);
        ++reused_;
        continue;
      }
      if (options_.stop_after_new_runs > 0 && new_runs_ + int(to_run.size()) >= options_.stop_after_new_runs) {
        interrupted_ = true;
        continue;
      }
      // The slot is reserved now, so the list's order is that of the requests for any thread count.
      index_[k] = kPending;
      slots.push_back(evaluations_.size());
      evaluations_.emplace_back();
      to_run.push_back(x);
    }
    std::vector<Evaluation> done(to_run.size());
    parallelFor(static_cast<int>(to_run.size()), options_.jobs,
                [&](int i) { done[i] = runOne(spec_, kind_, to_run[i]); });
    for (std::size_t i = 0; i < done.size(); ++i) {
      index_[keyOf(done[i].x)] = slots[i];
      evaluations_[slots[i]] = std::move(done[i]);
    }
    new_runs_ += static_cast<int>(done.size());
    if (options_.on_batch && !done.empty()) options_.on_batch(state());

    std::vector<const Evaluation*> out;
    for (const auto& x : xs) out.push_back(find(x));
    return out;
  }

  const Evaluation* find(const std::vector<double>& x) const {
    auto it = index_.find(keyOf(x));
    return it == index_.end() || it->second == kPending ? nullptr : &evaluations_[it->second];
  }

  ControllerFitState state() const { return {&evaluations_, history_, new_runs_, reused_}; }
  void setHistory(const std::vector<IterationRecord>* h) { history_ = h; }
  bool stopped() const { return interrupted_ || budget_spent_; }
  bool interrupted() const { return interrupted_; }
  bool budgetSpent() const { return budget_spent_; }
  int newRuns() const { return new_runs_; }
  int reused() const { return reused_; }
  const std::vector<Evaluation>& all() const { return evaluations_; }

 private:
  const ControllerSpec& spec_;
  const kinds::Kind& kind_;
  const ControllerFitOptions& options_;
  static constexpr std::size_t kPending = static_cast<std::size_t>(-1);
  std::map<Key, Evaluation> recorded_;
  std::map<Key, std::size_t> index_;
  std::vector<Evaluation> evaluations_;
  const std::vector<IterationRecord>* history_ = nullptr;
  int new_runs_ = 0, reused_ = 0;
  bool interrupted_ = false, budget_spent_ = false;
};

// The 2n + 1 points of a central-difference gradient at x: x, then x + h⁺ e_i and x - h⁻ e_i.
struct Stencil {
  std::vector<std::vector<double>> points;
};

Stencil stencilAt(const ControllerSpec& spec, const std::vector<double>& x) {
  Stencil s;
  s.points.push_back(x);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const TunedParam& p = spec.tuned[i];
    auto plus = x, minus = x;
    plus[i] = std::min(x[i] + p.step, p.upper);
    minus[i] = std::max(x[i] - p.step, p.lower);
    s.points.push_back(plus);
    s.points.push_back(minus);
  }
  return s;
}

// ∂g/∂x_i from the stencil's evaluations: central when both sides ran, else one-sided from x
// (a run that fails on one side, e.g. a bell that crumples, need not end the fit). False, and
// `out` untouched, when neither side is usable. At a bound one side is x itself and the quotient is one-sided anyway.
template <typename G>
bool differenceQuotient(const Stencil& s, const std::vector<const Evaluation*>& r, std::size_t i, G&& g,
                        double& out) {
  const Evaluation *centre = r[0], *plus = r[1 + 2 * i], *minus = r[2 + 2 * i];
  const double hp = s.points[1 + 2 * i][i] - s.points[0][i], hm = s.points[0][i] - s.points[2 + 2 * i][i];
  const bool up = plus && plus->ok && hp > 0, down = minus && minus->ok && hm > 0;
  if (up && down) {
    out = (g(*plus) - g(*minus)) / (hp + hm);
  } else if (up) {
    out = (g(*plus) - g(*centre)) / hp;
  } else if (down) {
    out = (g(*centre) - g(*minus)) / hm;
  } else {
    return false;
  }
  return true;
}

double logistic(double z) { return 1.0 / (1.0 + std::exp(-z)); }

std::vector<double> toZ(const ControllerSpec& spec, const std::vector<double>& x) {
  std::vector<double> z(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const TunedParam& p = spec.tuned[i];
    const double u = (x[i] - p.lower) / (p.upper - p.lower);
    z[i] = std::log(u / (1 - u));
  }
  return z;
}

// x(z) of the logistic reparameterisation. A coordinate still at its start z maps to the start
// value itself (x(z(start)) can differ from start in the last bit), so the start run is the file's
// parameters exactly, and so are the untouched coordinates of each difference stencil there.
std::vector<double> toX(const ControllerSpec& spec, const double* z) {
  const std::vector<double> start = spec.start(), z0 = toZ(spec, start);
  std::vector<double> x(spec.tuned.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const TunedParam& p = spec.tuned[i];
    x[i] = z[i] == z0[i] ? start[i] : std::clamp(p.lower + (p.upper - p.lower) * logistic(z[i]), p.lower, p.upper);
  }
  return x;
}

// maximise: cost(z) = -metric(x(z)) / scale with its central-difference gradient in z.
//
// A run that fails (a bell that crumples) scores failed_cost = cost_start + max(|cost_start|, 1):
// finite and above the cost of every point a line search starts from (they only decrease), so
// the line search treats it as a step too far and backs off. Rejected: reporting the evaluation
// as invalid, which ends Ceres' Wolfe zoom phase and with it the whole solve.
class MaximiseFunction : public ceres::FirstOrderFunction {
 public:
  MaximiseFunction(const ControllerSpec& spec, Evaluator& evaluator, double start_cost)
      : spec_(spec), evaluator_(evaluator), failed_cost_(start_cost + std::max(std::fabs(start_cost), 1.0)) {}
  int NumParameters() const override { return static_cast<int>(spec_.tuned.size()); }

  bool Evaluate(const double* z, double* cost, double* gradient) const override {
    const std::vector<double> x = toX(spec_, z);
    const Stencil s = gradient ? stencilAt(spec_, x) : Stencil{{x}};
    const auto results = evaluator_.batch(s.points);
    if (!results[0]) return false;  // out of runs or interrupted: the callback ends the solve
    *cost = results[0]->ok ? results[0]->cost : failed_cost_;
    if (!gradient) return true;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const TunedParam& p = spec_.tuned[i];
      double dcost_dx = 0;  // kept 0 when neither side ran: the parameter holds still this step
      if (results[0]->ok) differenceQuotient(s, results, i, [](const Evaluation& e) { return e.cost; }, dcost_dx);
      const double sig = logistic(z[i]);
      gradient[i] = dcost_dx * (p.upper - p.lower) * sig * (1 - sig);
    }
    return true;
  }

 private:
  const ControllerSpec& spec_;
  Evaluator& evaluator_;
  double failed_cost_;
};

// target: residuals ((metric - target) / tolerance[, least / least_scale]) with a central-difference
// Jacobian in x; the bounds are Ceres' own (trust region).
class TargetCost : public ceres::CostFunction {
 public:
  TargetCost(const ControllerSpec& spec, Evaluator& evaluator) : spec_(spec), evaluator_(evaluator) {
    set_num_residuals(spec.objective.least.empty() ? 1 : 2);
    mutable_parameter_block_sizes()->push_back(static_cast<int>(spec.tuned.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const int n = static_cast<int>(spec_.tuned.size()), m = num_residuals();
    const std::vector<double> x(parameters[0], parameters[0] + n);
    const bool want_jacobian = jacobians && jacobians[0];
    const Stencil s = want_jacobian ? stencilAt(spec_, x) : Stencil{{x}};
    const auto results = evaluator_.batch(s.points);
    if (!results[0] || !results[0]->ok) return false;
    const auto r0 = objectiveResiduals(spec_.objective, results[0]->metrics);
    for (int j = 0; j < m; ++j) residuals[j] = r0[j];
    if (!want_jacobian) return true;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < m; ++j) {
        const auto residual = [&](const Evaluation& e) { return objectiveResiduals(spec_.objective, e.metrics)[j]; };
        jacobians[0][j * n + i] = 0;  // kept 0 when neither side ran: the parameter holds still this step
        differenceQuotient(s, results, std::size_t(i), residual, jacobians[0][j * n + i]);
      }
    return true;
  }

 private:
  const ControllerSpec& spec_;
  Evaluator& evaluator_;
};

// Records one row of history per optimiser iteration (the state is updated every iteration).
class HistoryCallback : public ceres::IterationCallback {
 public:
  HistoryCallback(const ControllerSpec& spec, const Evaluator& evaluator, const double* parameters, bool logistic,
                  std::vector<IterationRecord>& history, const std::function<void(const IterationRecord&)>& notify)
      : spec_(spec), evaluator_(evaluator), parameters_(parameters), logistic_(logistic), history_(history),
        notify_(notify) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    IterationRecord r;
    r.iteration = summary.iteration;
    r.accepted = summary.iteration == 0 || summary.step_is_successful;  // iteration 0 is the start
    r.gradient_max_norm = summary.gradient_max_norm;
    r.step_norm = summary.step_norm;
    r.evaluations = static_cast<int>(evaluator_.all().size());
    const std::size_t n = spec_.tuned.size();
    r.x = logistic_ ? toX(spec_, parameters_) : std::vector<double>(parameters_, parameters_ + n);
    // The cost at the current point (a rejected trust-region step reports the candidate's).
    const Evaluation* e = evaluator_.find(r.x);
    r.cost = e && e->ok ? e->cost : summary.cost;
    r.objective = r.cost;
    if (spec_.objective.type == ObjectiveType::maximise && e && e->metrics.count(spec_.objective.metric))
      r.objective = e->metrics.at(spec_.objective.metric);
    history_.push_back(r);
    if (notify_) notify_(r);
    // Out of runs (or interrupted): stop here rather than let every later iteration fail.
    return evaluator_.stopped() ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  const ControllerSpec& spec_;
  const Evaluator& evaluator_;
  const double* parameters_;
  bool logistic_;
  std::vector<IterationRecord>& history_;
  const std::function<void(const IterationRecord&)>& notify_;
};

}  // namespace

double objectiveCost(const ObjectiveSpec& o, const std::map<std::string, double>& metrics) {
  if (o.type == ObjectiveType::maximise) {
    auto it = metrics.find(o.metric);
    return it == metrics.end() ? std::nan("") : -it->second / o.scale;
  }
  const auto r = objectiveResiduals(o, metrics);
  double c = 0;
  for (double v : r) c += 0.5 * v * v;
  return r.empty() ? std::nan("") : c;
}

std::vector<double> objectiveResiduals(const ObjectiveSpec& o, const std::map<std::string, double>& metrics) {
  if (o.type != ObjectiveType::target) return {};
  auto it = metrics.find(o.metric);
  if (it == metrics.end()) return {};
  std::vector<double> r = {(it->second - o.target) / o.tolerance};
  if (!o.least.empty()) {
    auto jt = metrics.find(o.least);
    if (jt == metrics.end()) return {};
    r.push_back(jt->second / o.least_scale);
  }
  return r;
}

ControllerFitResult fitController(const ControllerSpec& spec, const kinds::Kind& kind,
                                  const ControllerFitOptions& options) {
  ControllerFitResult out;
  Evaluator evaluator(spec, kind, options);
  evaluator.setHistory(&out.history);
  const bool maximise = spec.objective.type == ObjectiveType::maximise;

  // The start, evaluated first: a start that cannot run is a user error, before any optimisation.
  std::vector<double> z = toZ(spec, spec.start());
  std::vector<double> x = maximise ? toX(spec, z.data()) : spec.start();
  out.x_start = x;
  const Evaluation* first = evaluator.batch({x})[0];
  if (first && !first->ok) throw FitError("the start point cannot be evaluated: " + first->message);

  if (maximise) {
    ceres::GradientProblem problem(new MaximiseFunction(spec, evaluator, first ? first->cost : 0.0));
    ceres::GradientProblemSolver::Options o;
    o.line_search_direction_type = ceres::LBFGS;
    o.max_num_iterations = spec.solver.max_iterations;
    o.function_tolerance = spec.solver.function_tolerance;
    o.gradient_tolerance = spec.solver.gradient_tolerance;
    o.parameter_tolerance = spec.solver.parameter_tolerance;
    o.logging_type = ceres::SILENT;
    o.update_state_every_iteration = true;
    HistoryCallback history(spec, evaluator, z.data(), true, out.history, options.on_iteration);
    o.callbacks.push_back(&history);
    ceres::GradientProblemSolver::Summary summary;
    ceres::Solve(o, problem, z.data(), &summary);
    out.converged = summary.termination_type == ceres::CONVERGENCE;
    out.termination = summary.message;
    out.solver_report = summary.BriefReport();
    out.x_fitted = toX(spec, z.data());
  } else {
    ceres::Problem problem;
    problem.AddResidualBlock(new TargetCost(spec, evaluator), nullptr, x.data());
    for (std::size_t i = 0; i < x.size(); ++i) {
      problem.SetParameterLowerBound(x.data(), int(i), spec.tuned[i].lower);
      problem.SetParameterUpperBound(x.data(), int(i), spec.tuned[i].upper);
    }
    ceres::Solver::Options o;
    o.linear_solver_type = ceres::DENSE_QR;
    o.max_num_iterations = spec.solver.max_iterations;
    o.function_tolerance = spec.solver.function_tolerance;
    o.gradient_tolerance = spec.solver.gradient_tolerance;
    o.parameter_tolerance = spec.solver.parameter_tolerance;
    o.num_threads = 1;
    o.logging_type = ceres::SILENT;
    o.update_state_every_iteration = true;
    // With bounds, Ceres follows each trust-region step by a projected Armijo line search; with
    // bisection it asks for costs only (one run per trial) instead of gradients (2n + 1 runs).
    o.line_search_interpolation_type = ceres::BISECTION;
    o.max_num_line_search_step_size_iterations = 4;
    HistoryCallback history(spec, evaluator, x.data(), false, out.history, options.on_iteration);
    o.callbacks.push_back(&history);
    ceres::Solver::Summary summary;
    ceres::Solve(o, &problem, &summary);
    out.converged = summary.termination_type == ceres::CONVERGENCE;
    out.termination = summary.message;
    out.solver_report = summary.BriefReport();
    out.x_fitted = x;
  }
  if (evaluator.interrupted())
    throw FitInterrupted("stopped after " + std::to_string(evaluator.newRuns()) + " new runs (as asked)");
  if (evaluator.budgetSpent()) out.termination = "run budget spent (solver.max_runs); " + out.termination;

  // Ceres returns the last accepted point; it was evaluated on the way (else evaluate it now).
  const Evaluation* fitted = evaluator.find(out.x_fitted);
  if (!fitted) {
    Evaluation e = runOne(spec, kind, out.x_fitted);
    out.fitted = e;
  } else {
    out.fitted = *fitted;
  }
  out.start = *evaluator.find(out.x_start);
  out.evaluations = evaluator.all();
  out.new_runs = evaluator.newRuns();
  out.reused_runs = evaluator.reused();
  return out;
}

std::vector<kinds::Result> runPoints(const ControllerSpec& spec, const kinds::Kind& kind,
                                     const std::vector<std::vector<double>>& xs, int jobs) {
  std::vector<kinds::Result> out(xs.size());
  std::vector<std::string> errors(xs.size());
  parallelFor(static_cast<int>(xs.size()), jobs, [&](int i) {
    try {
      out[i] = kind.run(spec.paramsAt(xs[i]));
    } catch (const kinds::RunFailure& e) {
      out[i] = e.partial();
    } catch (const std::exception& e) {
      errors[i] = e.what();
    }
  });
  for (const auto& e : errors)
    if (!e.empty()) throw FitError("re-running a point failed: " + e);
  return out;
}

}  // namespace creaturelab::fit
