#include "web/spiral_stage.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_set>

#include "core/rng.hpp"

namespace creaturelab::web {
namespace {

constexpr auto kJitterPurpose = core::purposeId("web.spiral_jitter");

class SpiralWeaver {
 public:
  SpiralWeaver(WebBuilder& web, const SpokeLayout& spokes)
      : web_(web), prm_(web.params()), radii_(spokes.radii), hub_(spokes.hub_centre_m),
        rng_(prm_.seed, kJitterPurpose), covered_(web.particleCount(), 0),
        started_(web.particleCount(), 0) {
    // Candidates of each radius (frame end first), fixed before any spiral mass is added: all but the
    // inner-frame mass and the spiral_free_masses masses at the hub end. The free zone's radius is the
    // farthest of those hub-end masses from the hub.
    const int free_masses = prm_.spiral_free_masses;
    for (const auto& r : radii_) {
      const int size = static_cast<int>(r.size());
      std::vector<int> c;
      for (int i = 1; i < size - free_masses; ++i) c.push_back(r[i]);
      for (int i = std::max(0, size - free_masses); i < size; ++i)
        free_zone_radius_m_ = std::max(free_zone_radius_m_, (web_.position(r[i]) - hub_).norm());
      candidates_.push_back(std::move(c));
    }
  }

  void initialSpiral() {
    if (radii_.empty()) return;
    for (int m : candidates_[0]) walk(0, m);
  }

  void processedSpiral() {
    const int n = static_cast<int>(radii_.size());
    for (;;) {
      int best = -1, best_count = prm_.spiral_density;
      for (int r = 0; r < n; ++r) {
        const int count = uncovered(r);
        if (count > best_count) best = r, best_count = count;
      }
      if (best < 0) return;
      for (int m : candidates_[best])
        if (!covered_[m] && !started_[m]) {
          started_[m] = 1;  // a walk that cannot leave m (no candidate clear of the hub) is not retried
          walk(best, m);
        }
    }
  }

  int segments() const { return segments_; }

 private:
  int uncovered(int r) const {
    return static_cast<int>(std::count_if(candidates_[r].begin(), candidates_[r].end(), [&](int m) { return !covered_[m] && !started_[m]; }));
  }

  // The strand from a to b keeps out of the free zone.
  bool clearOfHub(int a, int b) const {
    return distanceToSegment(hub_, web_.position(a), web_.position(b)) >= free_zone_radius_m_;
  }

  // Index in candidates_[r] of the next mass from `from`, or -1.
  int nextMass(int r, int from) {
    const auto& cand = candidates_[r];
    const Point2 x = web_.position(from);
    int best = -1;
    double best_d = 0;
    for (int i = 0; i < static_cast<int>(cand.size()); ++i) {
      if (!clearOfHub(from, cand[i])) continue;
      const double d = (web_.position(cand[i]) - x).norm();
      if (best < 0 || d < best_d) best = i, best_d = d;
    }
    if (best < 0) return -1;
    // Two draws per step, always consumed, so later steps do not depend on earlier outcomes' branches.
    const double u = rng_.nextUniform01(), side = rng_.nextUniform01();
    if (u < prm_.spiral_jitter) {
      const int j = best + (side < 0.5 ? -1 : 1);
      if (j >= 0 && j < static_cast<int>(cand.size()) && clearOfHub(from, cand[j])) return j;
    }
    return best;
  }

  void walk(int start, int from) {
    const int n = static_cast<int>(radii_.size());
    for (int k = 1; k <= n; ++k) {
      const int r = (start + k) % n;
      const int i = nextMass(r, from);
      if (i < 0) return;
      const int to = candidates_[r][i];
      if (to == from) continue;  // one radius only: nothing to join
      const auto key = pairKey(from, to);
      if (joined_.insert(key).second) {
        web_.layStrand(from, to, StrandType::spiral);
        ++segments_;
      }
      covered_[from] = covered_[to] = 1;
      from = to;
    }
  }

  static std::uint64_t pairKey(int a, int b) {
    const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
    return (hi << 32) | lo;
  }

  WebBuilder& web_;
  const WebParams& prm_;
  const std::vector<std::vector<int>>& radii_;
  Point2 hub_;
  double free_zone_radius_m_ = 0;  // no spiral strand comes closer to hub_
  core::Stream rng_;
  std::vector<std::vector<int>> candidates_;
  std::vector<char> covered_;  // per particle present before the spiral: a spiral strand ends at it
  std::vector<char> started_;  // a processed-spiral walk started from it
  std::unordered_set<std::uint64_t> joined_;
  int segments_ = 0;
};

}  // namespace

SpiralResult laySpiral(WebBuilder& web, const SpokeLayout& spokes) {
  SpiralWeaver weaver(web, spokes);
  weaver.initialSpiral();
  weaver.processedSpiral();
  return {weaver.segments()};
}

}  // namespace creaturelab::web
