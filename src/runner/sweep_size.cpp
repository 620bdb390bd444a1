#include "runner/sweep_size.hpp"

#include <string>

namespace creaturelab::runner {

std::size_t sweepPointCount(const Experiment& e) {
  std::size_t count = e.cases.empty() ? 1 : e.cases.size();
  std::string axes;
  for (const auto& a : e.axes) {
    axes += (axes.empty() ? "" : " x ") + std::to_string(a.values.size()) + " " + a.name;
    // count * n > limit, asked without forming the product
    if (!a.values.empty() && count > kMaxSweepPoints / a.values.size())
      throw ExperimentError(e.path + ": the sweep has more than " + std::to_string(kMaxSweepPoints) + " points (" +
                            (e.cases.empty() ? "" : std::to_string(e.cases.size()) + " cases x ") + axes +
                            (&a == &e.axes.back() ? "" : " x ...") + ")");
    count *= a.values.size();
  }
  return count;
}

}  // namespace creaturelab::runner
