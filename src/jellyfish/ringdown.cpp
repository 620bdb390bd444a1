#include "jellyfish/ringdown.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace creaturelab::jellyfish {

Ringdown measureRingdown(std::span<const double> t, std::span<const double> d, double relative_floor,
                         int max_half_periods) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Ringdown out{0, nan, nan, nan};
  // Hysteresis: a half period ends when the signal, having crossed zero, passes ±h on the other
  // side; the crossing's time is the last zero crossing before that. h follows the decay: a
  // fraction of the last half period's extremum (of the starting deviation at first), so that
  // small beats of higher modes about zero add no crossings while the ring itself still does.
  double h = relative_floor * std::abs(d.empty() ? 0.0 : d[0]);
  std::vector<double> crossings;
  std::vector<double> extrema;  // |d| largest within each half period between counted crossings
  int side = 0;                 // sign of the current half period, 0 before the signal leaves ±h
  double last_zero_s = nan, peak = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (i > 0 && (d[i - 1] < 0) != (d[i] < 0) && d[i - 1] != d[i])
      last_zero_s = t[i - 1] + (t[i] - t[i - 1]) * d[i - 1] / (d[i - 1] - d[i]);
    const int now = d[i] > h ? 1 : d[i] < -h ? -1 : 0;
    if (now != 0 && now != side) {
      if (side != 0) {
        if (!crossings.empty()) extrema.push_back(peak);
        crossings.push_back(last_zero_s);
        if (static_cast<int>(crossings.size()) > max_half_periods) break;
        h = relative_floor * peak;
      }
      side = now;
      peak = 0;
    }
    peak = std::max(peak, std::abs(d[i]));
  }
  if (static_cast<int>(crossings.size()) > max_half_periods + 1) crossings.resize(max_half_periods + 1);
  out.half_periods = crossings.size() >= 2 ? static_cast<int>(crossings.size()) - 1 : 0;
  if (out.half_periods < 2) return out;
  const double half_period_s = (crossings.back() - crossings.front()) / out.half_periods;
  out.damped_hz = 1.0 / (2.0 * half_period_s);
  if (extrema.size() < 2) return out;
  // Mean decrement per half period over the extrema of the counted half periods.
  const double per_half = std::log(extrema.front() / extrema.back()) / double(extrema.size() - 1);
  const double delta = 2.0 * per_half;
  out.damping_ratio = delta / std::sqrt(4.0 * M_PI * M_PI + delta * delta);
  out.natural_hz = out.damped_hz / std::sqrt(1.0 - out.damping_ratio * out.damping_ratio);
  return out;
}

}  // namespace creaturelab::jellyfish
