#pragma once
// Points that should never start: before any point runs, each point's cost is estimated (the
// kind's CostEstimate: the steps its solver will take) and a point above the limit is refused
// with the estimate printed, unless the user says it is meant (--allow-long). This catches, e.g.,
// explicit Euler at dt_s = "auto", which picks a step of 1.25e-7 s: a 13-minute point.
#include <vector>

#include "kinds/kind.hpp"
#include "runner/experiment.hpp"

namespace creaturelab::runner {

// Above this many time steps a point is refused without --allow-long. RK4 at the automatic step
// takes 2e4-4e4 steps for the webs in experiments/web and 2.8e5 for tests/cli/strand_slow.toml;
// the explicit-Euler strand of issue 19 takes 1.2e8 (13 minutes), so 1e7 is about a minute.
inline constexpr double kMaxStepsWithoutAllowLong = 1e7;

// Throws ExperimentError naming the first point above the limit, its estimate and how it was made.
void checkCost(const Experiment& experiment, const kinds::Kind& kind, const std::vector<Point>& points,
               bool allow_long);

}  // namespace creaturelab::runner
