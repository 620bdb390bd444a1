#pragma once
// Settling time: how long a web takes to come to rest (thesis §5.1: "a settling time for the
// system being around 5 to 10 seconds"), measured from kinetic energy.
#include <optional>
#include <vector>

namespace creaturelab::springs {

// Earliest time after which kinetic energy stays below fraction * (its peak over the series).
// With i the last sample at or above the threshold, the crossing is interpolated linearly between
// samples i and i+1. std::nullopt if the last sample is still at or above the threshold (never
// settled within the run) or the series is empty; t_s.front() if the energy is zero throughout.
// t_s must be increasing and as long as ke_j (std::invalid_argument otherwise).
std::optional<double> settlingTime(const std::vector<double>& t_s, const std::vector<double>& ke_j, double fraction);

// The same answer, fed one sample at a time without storing the series (simulate() feeds it every
// substep). The last sample at or above fraction * running peak is also the last one at or above
// fraction * final peak: a later peak is itself such a sample.
class SettlingTracker {
 public:
  explicit SettlingTracker(double fraction) : fraction_(fraction) {}
  void add(double t_s, double ke_j);
  double peak() const { return peak_; }
  std::optional<double> settlingTime() const;

 private:
  double fraction_;
  long count_ = 0;
  double first_t_s_ = 0;
  double peak_ = 0;
  bool have_above_ = false;
  double above_t_s_ = 0, above_ke_j_ = 0;    // last sample at or above threshold
  bool have_after_ = false;
  double after_t_s_ = 0, after_ke_j_ = 0;    // the sample right after it
};

}  // namespace creaturelab::springs
