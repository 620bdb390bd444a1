#pragma once
// Points that should never start. Before any point runs, each point's cost is estimated (the
// kind's CostEstimate) and the run is refused, with the estimate printed, when
//  - a point would take more than kMaxStepsWithoutAllowLong time steps, unless --allow-long: e.g.
//    explicit Euler at dt_s = "auto" picks a step of 1.25e-7 s, a 13-minute point;
//  - the points running at once (--jobs), plus the runner's own tables, would need more memory
//    than the machine gives this process: refused rather than killed by the kernel half-way.
#include <vector>

#include "kinds/kind.hpp"
#include "runner/experiment.hpp"
#include "runner/memory.hpp"

namespace creaturelab::runner {

// RK4 at the automatic step takes 2e4-4e4 steps for the webs in experiments/web and 2.8e5 for
// tests/cli/strand_slow.toml; the explicit-Euler strand takes 1.2e8 (13 minutes), so
// 1e7 is about a minute.
inline constexpr double kMaxStepsWithoutAllowLong = 1e7;
// The runner's own memory per point (its parameters, its row of the index), measured: a dry run
// of 1e6 oscillator points peaks at 1.5 GB, a real run of 1e5 points at 371 MB.
inline constexpr double kRunnerBytesPerPoint = 4096;

struct CostLimits {
  bool allow_long = false;
  int concurrent_points = 1;  // points computed at once by this process (--jobs)
  MemoryBudget memory;        // bytes = 0: unknown, not checked
};

// Throws ExperimentError naming the point, the estimate and how it was made, and what to change.
void checkCost(const Experiment& experiment, const kinds::Kind& kind, const std::vector<Point>& points,
               const CostLimits& limits);

}  // namespace creaturelab::runner
