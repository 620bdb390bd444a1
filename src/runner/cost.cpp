#include "runner/cost.hpp"

#include <cstdio>

namespace creaturelab::runner {

void checkCost(const Experiment& experiment, const kinds::Kind& kind, const std::vector<Point>& points,
               bool allow_long) {
  if (allow_long) return;
  for (const auto& p : points) {
    const kinds::CostEstimate cost = kind.estimateCost(p.params);
    if (!(cost.steps > kMaxStepsWithoutAllowLong)) continue;
    char steps[64], limit[64];
    std::snprintf(steps, sizeof steps, "%.3g", cost.steps);
    std::snprintf(limit, sizeof limit, "%.3g", kMaxStepsWithoutAllowLong);
    throw ExperimentError(experiment.path + ": point " + std::to_string(p.index) +
                          (p.label.empty() ? "" : " (" + p.label + ")") + " would take about " + steps +
                          " time steps (" + cost.detail + "), more than " + limit +
                          ": give params.dt_s, choose another integrator, or pass --allow-long to run it anyway");
  }
}

}  // namespace creaturelab::runner
