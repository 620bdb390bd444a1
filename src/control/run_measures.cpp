#include "control/run_measures.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace creaturelab::control {

std::vector<double>& SeriesSet::add(const std::string& name, const std::string& unit) {
  series_.push_back({name, unit, {}});
  return series_.back().values;
}

double tailMean(const std::vector<double>& v, int tail) {
  double sum = 0;
  for (int k = int(v.size()) - tail; k < int(v.size()); ++k) sum += v[k] / tail;
  return sum;
}

double lineAngleDeg(const Vec3& a, const Vec3& b) {
  auto norm = [](const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
  const double c = std::abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (norm(a) * norm(b));
  return std::acos(std::min(1.0, c)) * 180.0 / std::numbers::pi;
}

double meanLineAngleDeg(const std::vector<Vec3>& lines, const Vec3& reference) {
  Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
  for (const auto& l : lines) {
    const Eigen::Vector3d u = Eigen::Vector3d(l[0], l[1], l[2]).normalized();
    t += u * u.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(t);
  const Eigen::Vector3d axis = eig.eigenvectors().col(2);  // eigenvalues ascending
  return lineAngleDeg({axis[0], axis[1], axis[2]}, reference);
}

double convergedFrame(const std::vector<std::vector<double>>& angles_deg, double tol_deg, int tail) {
  long first = 0;
  for (const auto& a : angles_deg) {
    const int n = int(a.size());
    const int t = std::min(tail, n);
    double mean = 0;
    for (int k = n - t; k < n; ++k) mean += a[k] / t;
    long f = n;
    while (f > 0 && std::abs(a[f - 1] - mean) <= tol_deg) --f;
    first = std::max(first, f == n ? long(n) + 1 : f + 1);
  }
  return double(first);
}

namespace {
// The mean of K cycles' means m_k and its standard error sqrt(sum (m_k - mean)^2 / (K - 1)) / sqrt(K);
// the error NaN for K < 2.
PhaseMean meanOfCycleMeans(const std::vector<double>& means) {
  const double cycles = double(means.size());
  PhaseMean out;
  for (double m : means) out.mean += m / cycles;
  if (means.size() < 2) return {out.mean, std::numeric_limits<double>::quiet_NaN()};
  double squares = 0;
  for (double m : means) squares += (m - out.mean) * (m - out.mean);
  out.standard_error = std::sqrt(squares / (cycles - 1) / cycles);
  return out;
}
}  // namespace

double lastCyclesMean(const std::vector<double>& v, int frames_per_cycle, int cycles) {
  const long n = long(frames_per_cycle) * cycles;
  if (n < 1 || n > long(v.size())) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0;
  for (long k = long(v.size()) - n; k < long(v.size()); ++k) sum += v[k];
  return sum / double(n);
}

double lastCyclesStandardError(const std::vector<double>& v, int frames_per_cycle, int cycles) {
  const long n = long(frames_per_cycle) * cycles;
  if (cycles < 2 || frames_per_cycle < 1 || n > long(v.size())) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> means;
  for (long k = long(v.size()) - n; k < long(v.size()); k += frames_per_cycle) {
    double sum = 0;
    for (long j = k; j < k + frames_per_cycle; ++j) sum += v[j];
    means.push_back(sum / double(frames_per_cycle));
  }
  return meanOfCycleMeans(means).standard_error;
}

PhaseMean lastCyclesPhaseMean(const std::vector<double>& v, const std::vector<double>& sense, double sign,
                              int frames_per_cycle, int cycles) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const long n = long(frames_per_cycle) * cycles;
  if (n < 1 || n > long(v.size()) || sense.size() != v.size()) return {nan, nan};
  std::vector<double> means;  // each cycle's mean over its frames of the phase
  for (long k = long(v.size()) - n; k < long(v.size()); k += frames_per_cycle) {
    double sum = 0;
    long count = 0;
    for (long j = k; j < k + frames_per_cycle; ++j)
      if (sense[j] * sign > 0) sum += v[j], ++count;
    if (count == 0) return {nan, nan};
    means.push_back(sum / double(count));
  }
  return meanOfCycleMeans(means);
}

}  // namespace creaturelab::control
