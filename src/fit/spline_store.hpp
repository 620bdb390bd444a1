#pragma once
// Writing a spline fit (file I/O): DIR/spline_fit.h5 and DIR/params.toml.
//
// spline_fit.h5 (written as .tmp, renamed when whole):
//   /                   attrs: data_source, period_s, period_source, phase_origin_s, loss, loss_scale,
//                       lower_value, upper_value, knots, samples, converged, iterations, solver_report,
//                       covariance_message, and the caller's provenance attributes
//   /knots/{phase, value, tangent, value_sigma, tangent_sigma, value_at_bound, start_value, start_tangent}
//   /covariance         (2K, 2K) of (value_0..value_{K-1}, tangent_0..tangent_{K-1}); attr order
//   /residual_rms, /weighted_residual_rms, /sigma_unit_weight   scalars
//   /data/{time_s, phase, value, weight, fitted, residual}      the samples beside the fitted curve
//   /curve/{phase, value}                                        the fitted curve over one period
// params.toml: the `[params]` fragment of the fitted curve for the jellyfish kind.
#include <map>
#include <string>

#include "fit/profile.hpp"
#include "fit/spline_fit.hpp"

namespace creaturelab::fit {

struct SplineFitContext {
  std::string data_source;    // what was read
  std::string period_source;  // "--period", "contraction_hz attribute", "detected (YIN)"
  std::map<std::string, std::string> attributes;  // provenance etc., written on the root
};

/// The params.toml text of a fit.
std::string splineParamsFragment(const SplineFitResult& result, const SplineFitContext& context);

/// Writes both files into `dir` (created if missing).
void writeSplineFit(const std::string& dir, const Profile& profile, const SplineFitOptions& options,
                    const SplineFitResult& result, const SplineFitContext& context);

}  // namespace creaturelab::fit
