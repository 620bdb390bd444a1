#include "runner/cost.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>

namespace creaturelab::runner {
namespace {

std::string format(double x, const char* unit = "") {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g%s", x, unit);
  return buf;
}

std::string gb(double bytes) { return format(bytes / 1e9, " GB"); }

std::string pointName(const Point& p) {
  return "point " + std::to_string(p.index) + (p.label.empty() ? "" : " (" + p.label + ")");
}

}  // namespace

void checkCost(const Experiment& experiment, const kinds::Kind& kind, const std::vector<Point>& points,
               const CostLimits& limits) {
  std::vector<double> memory;
  const Point* largest = nullptr;
  double largest_bytes = 0;
  std::string largest_detail;
  for (const auto& p : points) {
    const kinds::CostEstimate cost = kind.estimateCost(p.params);
    if (!limits.allow_long && cost.steps > kMaxStepsWithoutAllowLong)
      throw ExperimentError(experiment.path + ": " + pointName(p) + " would take about " + format(cost.steps) +
                            " time steps (" + cost.detail + "), more than " + format(kMaxStepsWithoutAllowLong) +
                            ": give params.dt_s, choose another integrator, or pass --allow-long to run it anyway");
    if (cost.memory_bytes > largest_bytes) {
      largest = &p;
      largest_bytes = cost.memory_bytes;
      largest_detail = cost.detail;
    }
    memory.push_back(cost.memory_bytes);
  }
  if (limits.memory.bytes <= 0) return;
  // The largest points may run at the same time: the sum of the --jobs largest estimates.
  const size_t at_once = std::min(memory.size(), size_t(std::max(1, limits.concurrent_points)));
  std::partial_sort(memory.begin(), memory.begin() + at_once, memory.end(), std::greater<>());
  double points_bytes = 0;
  for (size_t i = 0; i < at_once; ++i) points_bytes += memory[i];
  const double runner_bytes = kRunnerBytesPerPoint * double(points.size());
  const double need = points_bytes + runner_bytes;
  if (need <= limits.memory.bytes) return;
  std::string why;
  if (largest && memory[0] > 0) {
    why = pointName(*largest) + " needs about " + gb(memory[0]) + " (" + largest_detail + ")";
    if (at_once > 1) why += "; " + std::to_string(at_once) + " points at once (--jobs) need about " + gb(points_bytes);
    if (runner_bytes > 1e8)
      why += "; the runner's tables for " + std::to_string(points.size()) + " points about " + gb(runner_bytes);
  } else {
    why = "the runner's tables for " + std::to_string(points.size()) + " points need about " + gb(runner_bytes);
  }
  throw ExperimentError(experiment.path + ": the run would need about " + gb(need) + " of memory but " +
                        gb(limits.memory.bytes) + " is available (" + limits.memory.source + "): " + why +
                        ". Refused before it starts: use fewer cells or stored frames, a smaller sweep, or fewer --jobs");
}

}  // namespace creaturelab::runner
