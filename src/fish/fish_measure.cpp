#include "fish/fish_measure.hpp"

#include <cmath>

#include <Eigen/Core>

namespace creaturelab::fish {
namespace {
// The first frame at or after t_s (the last frame if none).
int frameAt(const FishRecord& rec, double t_s) {
  for (int f = 0; f < rec.frames(); ++f)
    if (rec.time_s[f] >= t_s - 1e-9) return f;
  return rec.frames() - 1;
}
double com(const FishRecord& rec, int f, int axis) { return rec.com_m[3 * f + axis]; }
// Horizontal centre-of-mass displacement from t0_s to t1_s.
Eigen::Vector2d travel(const FishRecord& rec, double t0_s, double t1_s) {
  const int a = frameAt(rec, t0_s), b = frameAt(rec, t1_s);
  return {com(rec, b, 0) - com(rec, a, 0), com(rec, b, 1) - com(rec, a, 1)};
}
// Signed angle from direction a to direction b (left, counter-clockwise, > 0), radians.
double turnedRad(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}
}  // namespace

SwimMeasures measureSwim(const FishRecord& rec, double body_length_m, double warmup_s, double window_s) {
  SwimMeasures m;
  const int last = rec.frames() - 1, start = frameAt(rec, warmup_s);
  const double span = rec.time_s[last] - rec.time_s[start];
  if (span > 0) {
    const double dx = com(rec, last, 0) - com(rec, start, 0), dy = com(rec, last, 1) - com(rec, start, 1);
    m.speed_m_per_s = std::hypot(dx, dy) / span;
    m.speed_body_lengths_per_s = m.speed_m_per_s / body_length_m;
  }
  m.forward_distance_m = com(rec, last, 0) - com(rec, 0, 0);
  m.lateral_drift_m = std::fabs(com(rec, last, 1) - com(rec, 0, 1));
  m.lateral_drift_fraction = m.forward_distance_m > 0 ? m.lateral_drift_m / m.forward_distance_m : std::nan("");
  m.com_travel_m = std::sqrt(std::pow(com(rec, last, 0) - com(rec, 0, 0), 2) +
                             std::pow(com(rec, last, 1) - com(rec, 0, 1), 2) +
                             std::pow(com(rec, last, 2) - com(rec, 0, 2), 2));
  m.vertical_drift_m = std::fabs(com(rec, last, 2) - com(rec, 0, 2));
  const double end = rec.time_s[last];
  if (window_s > 0 && warmup_s + window_s <= end - window_s) {
    const Eigen::Vector2d first = travel(rec, warmup_s, warmup_s + window_s), final = travel(rec, end - window_s, end);
    const Eigen::Vector2d settled = travel(rec, warmup_s, end), dir = first.normalized();
    m.settled_heading_change_deg = turnedRad(first, final) * 180.0 / M_PI;
    const double along = settled.dot(dir), side = dir.x() * settled.y() - dir.y() * settled.x();
    m.settled_lateral_drift_fraction = along > 0 ? std::fabs(side) / along : std::nan("");
  }
  return m;
}

TurnMeasures measureTurn(const FishRecord& rec, const std::vector<ScheduleItem>& schedule) {
  TurnMeasures m;
  for (const auto& item : schedule) {
    if (item.action != Action::left && item.action != Action::right) continue;
    const int a = frameAt(rec, item.start_s), b = frameAt(rec, item.start_s + item.duration_s);
    m.found = true;
    m.heading_change_deg = (rec.heading_rad[b] - rec.heading_rad[a]) * 180.0 / M_PI;
    for (int f = a + 1; f <= b; ++f) m.path_m += std::hypot(com(rec, f, 0) - com(rec, f - 1, 0), com(rec, f, 1) - com(rec, f - 1, 1));
    const double turned = std::fabs(rec.heading_rad[b] - rec.heading_rad[a]);
    m.radius_m = turned > 0 ? m.path_m / turned : std::nan("");
    break;
  }
  return m;
}

TravelTurn measureTravelTurn(const FishRecord& rec, const std::vector<ScheduleItem>& schedule, double window_s) {
  TravelTurn m;
  const ScheduleItem* item = nullptr;
  for (const auto& it : schedule)
    if (it.action != Action::swim) {
      item = &it;
      break;
    }
  if (!item) return m;
  const double end = rec.time_s.back(), item_end = item->start_s + item->duration_s;
  if (!(window_s > 0) || item->start_s < window_s || end + 1e-9 < item_end + window_s) return m;
  const Eigen::Vector2d before = travel(rec, item->start_s - window_s, item->start_s),
                        after = travel(rec, item_end, item_end + window_s);
  m.found = true;
  const double turned = turnedRad(before, after);
  m.heading_change_deg = turned * 180.0 / M_PI;
  const int a = frameAt(rec, item->start_s), b = frameAt(rec, item->start_s + item->duration_s);
  for (int f = a + 1; f <= b; ++f) m.path_m += std::hypot(com(rec, f, 0) - com(rec, f - 1, 0), com(rec, f, 1) - com(rec, f - 1, 1));
  m.radius_m = turned != 0 ? m.path_m / std::fabs(turned) : std::nan("");
  return m;
}

}  // namespace creaturelab::fish
