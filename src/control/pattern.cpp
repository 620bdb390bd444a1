#include "control/pattern.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace creaturelab::control {

namespace {
// Index of the table segment [k, k+1] holding t; -1 before the first point, n-1 after the last.
int segment(const std::vector<double>& time_s, double t) {
  if (t < time_s.front()) return -1;
  return int(std::upper_bound(time_s.begin(), time_s.end(), t) - time_s.begin()) - 1;
}
}  // namespace

double Pattern::angle(double t, double hold_rad) const {
  switch (kind) {
    case Kind::hold: return hold_rad;
    case Kind::sine: return mean_rad + amplitude_rad * std::sin(2 * std::numbers::pi * frequency_hz * t + phase_rad);
    case Kind::table: {
      const int k = segment(time_s, t);
      if (k < 0) return angle_rad.front();
      if (k >= int(time_s.size()) - 1) return angle_rad.back();
      const double a = (t - time_s[k]) / (time_s[k + 1] - time_s[k]);
      return angle_rad[k] + a * (angle_rad[k + 1] - angle_rad[k]);
    }
  }
  return hold_rad;
}

double Pattern::rate(double t) const {
  switch (kind) {
    case Kind::hold: return 0;
    case Kind::sine: {
      const double w = 2 * std::numbers::pi * frequency_hz;
      return amplitude_rad * w * std::cos(w * t + phase_rad);
    }
    case Kind::table: {
      const int k = segment(time_s, t);
      if (k < 0 || k >= int(time_s.size()) - 1) return 0;
      return (angle_rad[k + 1] - angle_rad[k]) / (time_s[k + 1] - time_s[k]);
    }
  }
  return 0;
}

std::string Pattern::validate() const {
  const Pattern& p = *this;
  auto finite = [](double x) { return std::isfinite(x); };
  switch (p.kind) {
    case Pattern::Kind::hold: return "";
    case Pattern::Kind::sine:
      if (!finite(p.mean_rad) || !finite(p.amplitude_rad) || !finite(p.frequency_hz) || !finite(p.phase_rad))
        return "sine: a parameter is not a finite number";
      if (p.frequency_hz < 0) return "sine: the frequency must not be negative";
      return "";
    case Pattern::Kind::table:
      if (p.time_s.empty()) return "table: no (time, angle) points";
      if (p.time_s.size() != p.angle_rad.size()) return "table: times and angles differ in number";
      for (std::size_t k = 0; k < p.time_s.size(); ++k) {
        if (!finite(p.time_s[k]) || !finite(p.angle_rad[k])) return "table: a value is not a finite number";
        if (k > 0 && !(p.time_s[k] > p.time_s[k - 1])) return "table: times must increase";
      }
      return "";
  }
  return "";
}

}  // namespace creaturelab::control
