#pragma once
// The number of points of a sweep (cases × the product of the axes' lengths), counted before the
// points are expanded, in arithmetic that cannot wrap: four axes of 65,536 values are 2^64 points,
// which a size_t product turns into 0 (an empty sweep).
#include <cstddef>

#include "runner/experiment.hpp"

namespace creaturelab::runner {

inline constexpr std::size_t kMaxSweepPoints = 1000000;

// Throws ExperimentError naming the file when the sweep has more than kMaxSweepPoints points.
std::size_t sweepPointCount(const Experiment& experiment);

}  // namespace creaturelab::runner
