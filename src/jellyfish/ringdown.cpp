#include "jellyfish/ringdown.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Dense>

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

namespace {

// Sum of squared residuals of the linear least-squares fit for one (ω, σ); the time is measured
// from the first sample.
double fitResidual(std::span<const double> t, std::span<const double> d, double omega, double sigma) {
  const Eigen::Index n = static_cast<Eigen::Index>(t.size());
  Eigen::MatrixXd a(n, 4);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double s = t[i] - t[0];
    const double decay = std::exp(-sigma * s);
    a(i, 0) = decay * std::cos(omega * s);
    a(i, 1) = decay * std::sin(omega * s);
    a(i, 2) = 1.0;
    a(i, 3) = s;
    b[i] = d[i];
  }
  const Eigen::VectorXd x = a.colPivHouseholderQr().solve(b);
  return (a * x - b).squaredNorm();
}

}  // namespace

DampedFit fitDampedOscillation(std::span<const double> t, std::span<const double> d) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  DampedFit out{nan, nan, nan, nan};
  if (t.size() < 8 || t.size() != d.size()) return out;
  double mean = 0;
  for (double v : d) mean += v;
  mean /= double(d.size());
  double variance = 0;
  for (double v : d) variance += (v - mean) * (v - mean);
  if (!(variance > 0) || !std::isfinite(variance)) return out;
  const double span_s = t.back() - t.front();
  const double sample_s = span_s / double(t.size() - 1);
  // Grid in log f_d and in ζ (σ = ζ ω / sqrt(1 − ζ²)); then two finer grids about the best.
  double log_f_lo = std::log(2.0 / span_s), log_f_hi = std::log(0.2 / sample_s);
  if (!(log_f_hi > log_f_lo)) return out;
  double zeta_lo = 0.0, zeta_hi = 0.8;
  int nf = 240, nz = 33;
  double best = std::numeric_limits<double>::infinity(), best_log_f = 0, best_zeta = 0;
  for (int level = 0; level < 3; ++level) {
    const double df = (log_f_hi - log_f_lo) / (nf - 1), dz = (zeta_hi - zeta_lo) / (nz - 1);
    for (int i = 0; i < nf; ++i)
      for (int j = 0; j < nz; ++j) {
        const double log_f = log_f_lo + i * df, zeta = zeta_lo + j * dz;
        const double omega = 2.0 * M_PI * std::exp(log_f);
        const double sigma = zeta * omega / std::sqrt(1.0 - zeta * zeta);
        const double r = fitResidual(t, d, omega, sigma);
        if (r < best) best = r, best_log_f = log_f, best_zeta = zeta;
      }
    log_f_lo = best_log_f - 2 * df, log_f_hi = best_log_f + 2 * df;
    zeta_lo = std::max(0.0, best_zeta - 2 * dz), zeta_hi = std::min(0.95, best_zeta + 2 * dz);
    nf = nz = 21;
  }
  out.damped_hz = std::exp(best_log_f);
  out.damping_ratio = best_zeta;
  out.natural_hz = out.damped_hz / std::sqrt(1.0 - best_zeta * best_zeta);
  out.residual_fraction = std::sqrt(best / variance);
  return out;
}

}  // namespace creaturelab::jellyfish
