// Ceres lives in this translation unit only (DESIGN.md: Ceres headers compile slowly).
#include "fit/spline_fit.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>

#include "core/text.hpp"
#include "jellyfish/contraction_curve.hpp"

namespace creaturelab::fit {
namespace {

using core::formatNumber;

// One sample's weighted residual sqrt(w) (c(φ; v, m) - y). Parameter blocks: the K knot values,
// the K knot tangents. Knot phases are constants (hermiteCurve<T> takes them as doubles).
struct SampleResidual {
  std::span<const double> phases;
  double phase = 0, value = 0, sqrt_weight = 1;

  template <typename T>
  bool operator()(T const* const* blocks, T* residual) const {
    residual[0] = sqrt_weight * (jellyfish::hermiteCurve<T>(phases, blocks[0], blocks[1], phase) - value);
    return true;
  }
};

// The dynamic cost function evaluates Jets of this many partials per pass (2K unknowns at most 12).
constexpr int kStride = 4;

// Phase-nearest sample's value: a start for each knot value.
double nearestValue(const std::vector<double>& sample_phase, const Profile& p, double knot_phase) {
  double best_d = 2, best = p.value.front();
  for (int i = 0; i < p.size(); ++i) {
    if (!(p.weightAt(i) > 0)) continue;
    double d = std::fabs(sample_phase[i] - knot_phase);
    d = std::min(d, 1 - d);
    if (d < best_d) best_d = d, best = p.value[i];
  }
  return best;
}

std::string listNumbers(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ", ") + formatNumber(x);
  return s;
}

}  // namespace

bool parseLoss(const std::string& text, Loss& out) {
  if (text == "none") return out = Loss::none, true;
  if (text == "huber") return out = Loss::huber, true;
  if (text == "cauchy") return out = Loss::cauchy, true;
  return false;
}

std::string lossName(Loss loss) {
  switch (loss) {
    case Loss::huber: return "huber";
    case Loss::cauchy: return "cauchy";
    default: return "none";
  }
}

std::vector<double> evenPhases(int count) {
  std::vector<double> out;
  for (int k = 0; k < count; ++k) out.push_back(double(k) / count);
  return out;
}

std::string SplineFitOptions::validate() const {
  const int k = static_cast<int>(knot_phases.size());
  if (k < 1 || k > kMaxKnots)
    return "the curve needs 1 to " + std::to_string(kMaxKnots) + " knots (the jellyfish kind's knot0_* .. knot" +
           std::to_string(kMaxKnots - 1) + "_*), got " + std::to_string(k);
  for (int i = 0; i < k; ++i) {
    if (!(knot_phases[i] >= 0 && knot_phases[i] < 1))
      return "knot phase " + formatNumber(knot_phases[i]) + " is outside [0, 1)";
    if (i > 0 && !(knot_phases[i] > knot_phases[i - 1]))
      return "knot phases must increase: " + listNumbers(knot_phases);
  }
  if (!(std::isfinite(period_s) && period_s > 0)) return "the period must be > 0 s, got " + formatNumber(period_s);
  if (!std::isfinite(phase_origin_s)) return "the phase origin must be finite";
  if (!(std::isfinite(lower_value) && std::isfinite(upper_value) && lower_value < upper_value))
    return "value bounds must be finite with lower < upper, got [" + formatNumber(lower_value) + ", " +
           formatNumber(upper_value) + "]";
  if (!start_values.empty()) {
    if (static_cast<int>(start_values.size()) != k)
      return std::to_string(start_values.size()) + " start values for " + std::to_string(k) + " knots";
    for (int i = 0; i < k; ++i)
      if (!(start_values[i] >= lower_value && start_values[i] <= upper_value))
        return "the bounds [" + formatNumber(lower_value) + ", " + formatNumber(upper_value) +
               "] exclude the start value " + formatNumber(start_values[i]) + " of knot " + std::to_string(i);
  }
  if (!start_tangents.empty() && static_cast<int>(start_tangents.size()) != k)
    return std::to_string(start_tangents.size()) + " start tangents for " + std::to_string(k) + " knots";
  for (double t : start_tangents)
    if (!std::isfinite(t)) return "start tangents must be finite";
  if (loss != Loss::none && !(std::isfinite(loss_scale) && loss_scale > 0))
    return "the loss scale must be > 0, got " + formatNumber(loss_scale);
  if (max_iterations < 1) return "max_iterations must be >= 1";
  return "";
}

double SplineFitResult::curve(double phase) const {
  return jellyfish::hermiteCurve<double>(phases, values.data(), tangents.data(), phase);
}

SplineFitResult fitSpline(const Profile& profile, const SplineFitOptions& o) {
  if (std::string e = o.validate(); !e.empty()) throw FitError(e);
  if (std::string e = checkSamples(profile); !e.empty()) throw FitError(e);
  if (std::string e = checkCoverage(profile, o.period_s, o.phase_origin_s, o.knot_phases); !e.empty())
    throw FitError(e);

  const int k = static_cast<int>(o.knot_phases.size());
  std::vector<double> sample_phase(profile.size());
  for (int i = 0; i < profile.size(); ++i)
    sample_phase[i] = jellyfish::wrapPhase((profile.time_s[i] - o.phase_origin_s) / o.period_s);

  SplineFitResult out;
  out.phases = o.knot_phases;
  out.start_values = o.start_values;
  if (out.start_values.empty())
    for (double ph : o.knot_phases)
      out.start_values.push_back(std::clamp(nearestValue(sample_phase, profile, ph), o.lower_value, o.upper_value));
  out.start_tangents = o.start_tangents.empty() ? std::vector<double>(k, 0.0) : o.start_tangents;
  out.values = out.start_values;
  out.tangents = out.start_tangents;

  // --- the problem: one residual block per sample of positive weight
  ceres::Problem problem;
  double* v = out.values.data();
  double* m = out.tangents.data();
  for (int i = 0; i < profile.size(); ++i) {
    const double w = profile.weightAt(i);
    if (!(w > 0)) continue;
    auto* cost = new ceres::DynamicAutoDiffCostFunction<SampleResidual, kStride>(
        new SampleResidual{std::span<const double>(out.phases), sample_phase[i], profile.value[i], std::sqrt(w)});
    cost->AddParameterBlock(k);
    cost->AddParameterBlock(k);
    cost->SetNumResiduals(1);
    ceres::LossFunction* loss = nullptr;
    if (o.loss == Loss::huber) loss = new ceres::HuberLoss(o.loss_scale);
    if (o.loss == Loss::cauchy) loss = new ceres::CauchyLoss(o.loss_scale);
    problem.AddResidualBlock(cost, loss, v, m);
    ++out.samples;
  }
  for (int i = 0; i < k; ++i) {
    problem.SetParameterLowerBound(v, i, o.lower_value);
    problem.SetParameterUpperBound(v, i, o.upper_value);
  }

  // --- solve. Tolerances at rounding level: the noiseless problem is recovered to ~1e-12.
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = o.max_iterations;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-14;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  out.iterations = static_cast<int>(summary.iterations.size());
  out.solver_report = summary.BriefReport();

  // --- residuals
  double sum2 = 0, wsum2 = 0, wsum = 0;
  for (int i = 0; i < profile.size(); ++i) {
    const double w = profile.weightAt(i);
    if (!(w > 0)) continue;
    const double r = out.curve(sample_phase[i]) - profile.value[i];
    sum2 += r * r;
    wsum2 += w * r * r;
    wsum += w;
  }
  out.residual_rms = std::sqrt(sum2 / out.samples);
  out.weighted_residual_rms = std::sqrt(wsum2 / wsum);
  const int dof = out.samples - 2 * k;
  out.sigma_unit_weight = dof > 0 ? std::sqrt(wsum2 / dof) : 0.0;

  for (int i = 0; i < k; ++i)
    out.value_at_bound.push_back(std::fabs(out.values[i] - o.lower_value) <= 1e-10 ||
                                 std::fabs(out.values[i] - o.upper_value) <= 1e-10);

  // --- covariance σ̂² (JᵀJ)⁻¹
  ceres::Covariance::Options copt;
  copt.algorithm_type = ceres::DENSE_SVD;
  copt.num_threads = 1;
  ceres::Covariance covariance(copt);
  const std::vector<std::pair<const double*, const double*>> blocks = {{v, v}, {v, m}, {m, m}};
  if (dof <= 0) {
    out.covariance_message = "no degrees of freedom left for the noise level (samples <= 2 x knots)";
  } else if (!covariance.Compute(blocks, &problem)) {
    out.covariance_message = "the Jacobian is rank-deficient at the solution: the data do not determine every knot";
  } else {
    out.covariance.assign(4 * k * k, 0.0);
    covariance.GetCovarianceMatrix({v, m}, out.covariance.data());
    const double s2 = out.sigma_unit_weight * out.sigma_unit_weight;
    for (double& c : out.covariance) c *= s2;
    for (int i = 0; i < k; ++i) {
      out.value_sigma.push_back(std::sqrt(out.covariance[i * 2 * k + i]));
      out.tangent_sigma.push_back(std::sqrt(out.covariance[(k + i) * 2 * k + k + i]));
    }
  }
  if (out.value_sigma.empty()) {
    out.value_sigma.assign(k, std::nan(""));
    out.tangent_sigma.assign(k, std::nan(""));
  }
  return out;
}

}  // namespace creaturelab::fit
