#include "fluid3d/fast_transform1.hpp"

#include <cmath>
#include <numbers>
#include <utility>

namespace creaturelab::fluid3d {

bool FastTransform1::applies(int n, const AxisBoundary3& sides) {
  const bool power_of_two = n >= 2 && (n & (n - 1)) == 0;
  const bool solid = sides.low != BoundaryType3::open && sides.high != BoundaryType3::open;
  return power_of_two && (sides.periodic() || solid);
}

FastTransform1::FastTransform1(int n, const AxisBoundary3& sides) : n_(n), periodic_(sides.periodic()) {
  const double pi = std::numbers::pi;
  int bits = 0;
  while ((1 << bits) < n) ++bits;
  bit_reverse_.resize(n);
  for (int t = 0; t < n; ++t) {
    int r = 0;
    for (int b = 0; b < bits; ++b) r |= ((t >> b) & 1) << (bits - 1 - b);
    bit_reverse_[t] = r;
  }
  cos_.resize(n / 2), sin_.resize(n / 2);
  for (int t = 0; t < n / 2; ++t) cos_[t] = std::cos(2.0 * pi * t / n), sin_[t] = std::sin(2.0 * pi * t / n);
  shift_cos_.resize(n), shift_sin_.resize(n);
  for (int k = 0; k < n; ++k) shift_cos_[k] = std::cos(pi * k / (2.0 * n)), shift_sin_[k] = std::sin(pi * k / (2.0 * n));
}

void FastTransform1::fft(double* re, double* im, bool inverse) const {
  const int n = n_;
  for (int t = 0; t < n; ++t) {
    const int r = bit_reverse_[t];
    if (r > t) std::swap(re[t], re[r]), std::swap(im[t], im[r]);
  }
  const double sign = inverse ? 1.0 : -1.0;
  for (int len = 2; len <= n; len *= 2) {
    const int half = len / 2, step = n / len;
    for (int start = 0; start < n; start += len)
      for (int t = 0; t < half; ++t) {
        const double wr = cos_[t * step], wi = sign * sin_[t * step];
        const int a = start + t, b = a + half;
        const double xr = wr * re[b] - wi * im[b], xi = wr * im[b] + wi * re[b];
        re[b] = re[a] - xr, im[b] = im[a] - xi;
        re[a] += xr, im[a] += xi;
      }
  }
}

void FastTransform1::forward(const double* line, double* c, double* work) const {
  const int n = n_;
  double* re = work;
  double* im = work + n;
  if (periodic_) {
    for (int j = 0; j < n; ++j) re[j] = line[j], im[j] = 0.0;
    fft(re, im, false);
    const double s0 = 1.0 / std::sqrt(static_cast<double>(n)), s = std::sqrt(2.0 / n);
    c[0] = s0 * re[0];
    for (int f = 1; 2 * f < n; ++f) c[2 * f - 1] = s * re[f], c[2 * f] = -s * im[f];
    if (n % 2 == 0) c[n - 1] = s0 * re[n / 2];
    return;
  }
  // DCT-II (Makhoul): v = even samples ascending, odd samples descending; C_k = Re(e^{−iπk/2n} V_k).
  for (int j = 0; j < n / 2; ++j) re[j] = line[2 * j], re[n - 1 - j] = line[2 * j + 1];
  for (int j = 0; j < n; ++j) im[j] = 0.0;
  fft(re, im, false);
  const double s0 = 1.0 / std::sqrt(static_cast<double>(n)), s = std::sqrt(2.0 / n);
  for (int k = 0; k < n; ++k) {
    const double value = shift_cos_[k] * re[k] + shift_sin_[k] * im[k];
    c[k] = (k == 0 ? s0 : s) * value;
  }
}

void FastTransform1::inverse(const double* c, double* line, double* work) const {
  const int n = n_;
  double* re = work;
  double* im = work + n;
  if (periodic_) {
    // x_j = Σ_f Y_f e^{+2πi f j / n}, Y_0 = c_0/√n, Y_f = ½√(2/n) (c_cos − i c_sin), Y_{n−f} = conj Y_f.
    const double s0 = 1.0 / std::sqrt(static_cast<double>(n)), h = 0.5 * std::sqrt(2.0 / n);
    re[0] = s0 * c[0], im[0] = 0.0;
    for (int f = 1; 2 * f < n; ++f) {
      re[f] = h * c[2 * f - 1], im[f] = -h * c[2 * f];
      re[n - f] = re[f], im[n - f] = -im[f];
    }
    if (n % 2 == 0) re[n / 2] = s0 * c[n - 1], im[n / 2] = 0.0;
    fft(re, im, true);
    for (int j = 0; j < n; ++j) line[j] = re[j];
    return;
  }
  // DCT-III: with a_k the weighted coefficients (a_0 = c_0/√n, a_k = ½√(2/n) c_k, a_n = 0),
  // V_k = e^{iπk/2n} (a_k − i a_{n−k}), v = Σ_k V_k e^{+2πi k j/n}, then undo the reordering.
  const double s0 = 1.0 / std::sqrt(static_cast<double>(n)), h = 0.5 * std::sqrt(2.0 / n);
  auto a = [&](int k) { return k == 0 ? s0 * c[0] : k == n ? 0.0 : h * c[k]; };
  for (int k = 0; k < n; ++k) {
    const double ar = a(k), ai = -a(n - k);
    re[k] = shift_cos_[k] * ar - shift_sin_[k] * ai;
    im[k] = shift_cos_[k] * ai + shift_sin_[k] * ar;
  }
  fft(re, im, true);
  for (int j = 0; j < n / 2; ++j) line[2 * j] = re[j], line[2 * j + 1] = re[n - 1 - j];
}

}  // namespace creaturelab::fluid3d
