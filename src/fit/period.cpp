#include "fit/period.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace creaturelab::fit {
namespace {

// x(t) by linear interpolation between the samples (t inside [t_0, t_n]).
double interpolate(const Profile& p, double t) {
  const auto it = std::upper_bound(p.time_s.begin(), p.time_s.end(), t);
  if (it == p.time_s.begin()) return p.value.front();
  if (it == p.time_s.end()) return p.value.back();
  const auto i = static_cast<std::size_t>(it - p.time_s.begin());
  const double t0 = p.time_s[i - 1], t1 = p.time_s[i];
  const double s = (t - t0) / (t1 - t0);
  return (1 - s) * p.value[i - 1] + s * p.value[i];
}

// d(τ): mean squared difference between the signal and itself shifted by τ.
double difference(const Profile& p, double lag_s) {
  const double end = p.time_s.back();
  double sum = 0;
  int count = 0;
  for (int i = 0; i < p.size() && p.time_s[i] + lag_s <= end; ++i) {
    const double e = interpolate(p, p.time_s[i] + lag_s) - p.value[i];
    sum += e * e;
    ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

}  // namespace

PeriodDetection detectPeriod(const Profile& p, const PeriodOptions& options) {
  PeriodDetection out;
  if (p.size() < 8) {
    out.error = "too few samples (" + std::to_string(p.size()) + ") to detect a period; give --period";
    return out;
  }
  std::vector<double> steps;
  for (int i = 1; i < p.size(); ++i) steps.push_back(p.time_s[i] - p.time_s[i - 1]);
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  const double dt = steps[steps.size() / 2];
  const double span = p.time_s.back() - p.time_s.front();
  const int lags = static_cast<int>(std::floor(0.5 * span / dt));
  if (lags < 3) {
    out.error = "detecting the period needs at least two periods of samples; give --period";
    return out;
  }
  double mean = 0, variance = 0;
  for (double v : p.value) mean += v;
  mean /= p.size();
  for (double v : p.value) variance += (v - mean) * (v - mean);
  variance /= p.size();
  if (!(variance > 0)) {
    out.error = "the signal is constant: no period to detect";
    return out;
  }

  // d and the cumulative-mean-normalised d' at the lags j dt, j = 1..lags (§II.C).
  std::vector<double> d(lags + 1, 0.0), dn(lags + 1, 1.0);
  double running = 0;
  for (int j = 1; j <= lags; ++j) {
    d[j] = difference(p, j * dt);
    running += d[j];
    dn[j] = running > 0 ? d[j] * j / running : 1.0;
  }
  int best = -1;
  for (int j = 2; j <= lags && best < 0; ++j)
    if (dn[j] < options.threshold) {
      while (j < lags && dn[j + 1] < dn[j]) ++j;
      best = j;
    }
  if (best < 0) {
    best = static_cast<int>(std::min_element(dn.begin() + 2, dn.end()) - dn.begin());
    if (!(dn[best] < 0.5)) {
      out.error = "no period found within half the span of the samples (detection needs at least two periods); give --period";
      return out;
    }
  }

  // Golden-section search for the minimum of d between the neighbouring lags (§II.E refines by
  // parabolic interpolation; golden section is exact to the tolerance for any shape of the dip).
  const double phi = (std::sqrt(5.0) - 1) / 2;
  double a = (best - 1) * dt, b = std::min(best + 1, lags) * dt;
  double c = b - phi * (b - a), e = a + phi * (b - a);
  double fc = difference(p, c), fe = difference(p, e);
  for (int it = 0; it < 100 && b - a > 1e-12 * b; ++it) {
    if (fc < fe) {
      b = e, e = c, fe = fc;
      c = b - phi * (b - a), fc = difference(p, c);
    } else {
      a = c, c = e, fc = fe;
      e = a + phi * (b - a), fe = difference(p, e);
    }
  }
  out.period_s = 0.5 * (a + b);
  out.mismatch = difference(p, out.period_s) / (2 * variance);
  return out;
}

}  // namespace creaturelab::fit
