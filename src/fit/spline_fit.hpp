#pragma once
// Fitting the jellyfish's periodic cubic Hermite contraction curve (Rudolf & Mould 2009,
// An Interactive Fluid Model of Jellyfish for Animation, §3.3; jellyfish/contraction_curve.hpp) to a measured
// profile: knot values and tangents at fixed knot phases, by bounded (robust) nonlinear least
// squares with Ceres.
//
// Model. A sample (t_i, y_i, w_i) sits at phase φ_i = wrap((t_i - t_0) / P) and the curve is
// c(φ; v, m) = Σ_k (basis of knot k at φ) (v_k, m_k): the Hermite curve is linear in the knot
// values v and tangents m (d value / d phase). The fit minimises
//     ½ Σ_i ρ( w_i (c(φ_i; v, m) - y_i)² )        subject to  lower <= v_k <= upper,
// with ρ the identity, Huber's or Cauchy's loss of scale s (Ceres' HuberLoss / CauchyLoss:
// ρ(r²) = r² for |r| <= s, 2 s |r| - s² beyond; ρ(r²) = s² log(1 + r²/s²)). Tangents are free.
// The residuals are differentiated by Ceres' autodiff through hermiteCurve<Jet>; without a loss
// the problem is linear and the trust-region solver converges to machine precision.
//
// Uncertainty. The covariance of (v, m) is σ̂² (JᵀJ)⁻¹ (ceres::Covariance, dense SVD), J the
// Jacobian of the weighted (and, with a loss, robustified) residuals at the solution and
// σ̂² = Σ w_i r_i² / (n - 2K) the residual variance of unit weight (Gauss-Markov; weights are
// relative, the noise level is estimated from the data). With a loss the covariance is the
// usual first-order approximation. A value held at a bound is flagged: its σ is that of the
// unconstrained problem there and overstates what the data allow.
#include <string>
#include <vector>

#include "fit/fit_error.hpp"
#include "fit/profile.hpp"

namespace creaturelab::fit {

enum class Loss { none, huber, cauchy };
/// "none" | "huber" | "cauchy"; false if unknown.
bool parseLoss(const std::string& text, Loss& out);
std::string lossName(Loss loss);

struct SplineFitOptions {
  std::vector<double> knot_phases = {0.0, 0.25, 0.5, 0.75};  // strictly increasing, in [0, 1)
  double period_s = 0;        // > 0
  double phase_origin_s = 0;  // time at phase 0 (a jellyfish run's t = 0)
  double lower_value = 0.56;  // bounds on the knot values (§3.3: the curve lies in [0.56, 1])
  double upper_value = 1.0;
  // Start. Empty: each value is the data interpolated at the knot's phase, clamped into the
  // bounds, and each tangent is 0. Given: one per knot, inside the bounds.
  std::vector<double> start_values, start_tangents;
  Loss loss = Loss::none;
  double loss_scale = 0.01;  // in value units: residuals beyond it count less (huber, cauchy)
  int max_iterations = 200;

  /// Up to this many knots (the jellyfish kind's knot0_* .. knot5_*).
  static constexpr int kMaxKnots = 6;

  /// "" if usable, else what is wrong in words a user understands.
  std::string validate() const;
};

/// Knot phases evenly spaced from 0: k / count.
std::vector<double> evenPhases(int count);

struct SplineFitResult {
  std::vector<double> phases, values, tangents;
  std::vector<double> start_values, start_tangents;
  std::vector<double> value_sigma, tangent_sigma;  // sqrt of the covariance's diagonal
  std::vector<bool> value_at_bound;                // |v - bound| <= 1e-12
  // Covariance of (v_0..v_{K-1}, m_0..m_{K-1}), row-major 2K x 2K. Empty if it could not be
  // computed (rank-deficient Jacobian); then covariance_message says why.
  std::vector<double> covariance;
  std::string covariance_message;
  double residual_rms = 0;           // sqrt(mean (c(φ_i) - y_i)²) over samples of positive weight
  double weighted_residual_rms = 0;  // sqrt(Σ w r² / Σ w)
  double sigma_unit_weight = 0;      // σ̂ above
  int samples = 0;                   // of positive weight
  bool converged = false;
  int iterations = 0;
  std::string solver_report;  // Ceres' BriefReport()

  double curve(double phase) const;  // the fitted curve (wrapped phase)
};

/// Checks the options and the profile (checkSamples, checkCoverage, start inside the bounds) and
/// throws FitError with the first problem before any fitting; then fits.
SplineFitResult fitSpline(const Profile& profile, const SplineFitOptions& options);

}  // namespace creaturelab::fit
