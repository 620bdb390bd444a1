#include "springs/settling.hpp"

#include <stdexcept>

namespace creaturelab::springs {

void SettlingTracker::add(double t_s, double ke_j) {
  if (count_++ == 0) first_t_s_ = t_s;
  if (ke_j > peak_) peak_ = ke_j;
  if (ke_j > 0 && ke_j >= fraction_ * peak_) {
    have_above_ = true;
    above_t_s_ = t_s;
    above_ke_j_ = ke_j;
    have_after_ = false;
  } else if (have_above_ && !have_after_) {
    have_after_ = true;
    after_t_s_ = t_s;
    after_ke_j_ = ke_j;
  }
}

std::optional<double> SettlingTracker::settlingTime() const {
  if (count_ == 0) return std::nullopt;
  if (!have_above_) return first_t_s_;  // no kinetic energy at all: at rest from the start
  if (!have_after_) return std::nullopt;  // still above the threshold at the last sample
  // Linear interpolation of the downward crossing of fraction * peak between the two samples.
  const double threshold = fraction_ * peak_;
  const double w = (above_ke_j_ - threshold) / (above_ke_j_ - after_ke_j_);
  return above_t_s_ + w * (after_t_s_ - above_t_s_);
}

std::optional<double> settlingTime(const std::vector<double>& t_s, const std::vector<double>& ke_j, double fraction) {
  if (t_s.size() != ke_j.size()) throw std::invalid_argument("settlingTime: time and energy series differ in length");
  SettlingTracker tracker(fraction);
  for (size_t i = 0; i < t_s.size(); ++i) {
    if (i > 0 && !(t_s[i] > t_s[i - 1])) throw std::invalid_argument("settlingTime: times must increase");
    tracker.add(t_s[i], ke_j[i]);
  }
  return tracker.settlingTime();
}

}  // namespace creaturelab::springs
