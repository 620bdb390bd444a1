#pragma once
// Trilinear interpolation of one face-centred velocity component (or any field stored like it),
// the 3-D form of fluid/staggered_sampler2.hpp.
//
// The component is copied into an array padded with one ghost layer on every side, filled by the
// ghost rules of stencil3.hpp (periodic sides wrap; walls mirror), so that sampling anywhere in the
// box is a branch-free trilinear interpolation. Positions are in cell units; along a periodic axis
// they wrap into [0, n), along a walled one they are clamped to [0, n]. Interpolation is written
// a + t (b − a), so a uniform field is reproduced exactly.

#include <array>
#include <cmath>

#include "fluid3d/mac_grid3.hpp"
#include "fluid3d/stencil3.hpp"

namespace creaturelab::fluid3d {

class PaddedComponent3 {
 public:
  /// Copies component a (array `values`, shaped like grid.velocity_m_per_s[a]) with its ghosts.
  void fill(int a, const MacGrid3& grid, const Array3& values, WorkerPool* pool);

  /// The stored value (i, j, k) of the component's array; indices −1 and extent reach the ghosts.
  double at(int i, int j, int k) const { return padded_.data()[(k + 1) * sz_ + (j + 1) * sy_ + (i + 1)]; }

  /// Value at position p (cell units).
  double sample(const std::array<double, 3>& p) const {
    double t[3];
    const double* c = locate(p, t);
    return interpolate(c, t);
  }
  /// The same, with the range [lo, hi] of the eight values interpolated.
  double sample(const std::array<double, 3>& p, double& lo, double& hi) const {
    double t[3];
    const double* c = locate(p, t);
    const double v[8] = {c[0], c[1], c[sy_], c[sy_ + 1], c[sz_], c[sz_ + 1], c[sz_ + sy_], c[sz_ + sy_ + 1]};
    lo = v[0], hi = v[0];
    for (double x : v) lo = x < lo ? x : lo, hi = x > hi ? x : hi;
    return interpolate(c, t);
  }

 private:
  const double* locate(const std::array<double, 3>& p, double* t) const {
    long offset = 0;
    const long strides[3] = {1, sy_, sz_};
    for (int d = 0; d < 3; ++d) {
      double X = p[d];
      if (periodic_[d]) {
        if (!(X >= 0.0 && X < n_[d])) {  // wrap (std::floor is a library call without SSE4.1)
          X -= n_[d] * std::floor(X / n_[d]);
          if (!(X >= 0.0 && X < n_[d])) X = 0.0;  // rounding of a tiny negative X, and NaN
        }
      } else {
        X = X > 0.0 ? X : 0.0;  // NaN lands on 0
        X = X < n_[d] ? X : n_[d];
      }
      const double s = X - shift_[d] + 1.0;
      int i0 = static_cast<int>(s);
      i0 = i0 < max_index_[d] ? i0 : max_index_[d];
      t[d] = s - i0;
      offset += i0 * strides[d];
    }
    return padded_.data() + offset;
  }
  double interpolate(const double* c, const double* t) const {
    auto lerp = [](double a, double b, double s) { return a + s * (b - a); };
    const double x00 = lerp(c[0], c[1], t[0]), x10 = lerp(c[sy_], c[sy_ + 1], t[0]);
    const double x01 = lerp(c[sz_], c[sz_ + 1], t[0]), x11 = lerp(c[sz_ + sy_], c[sz_ + sy_ + 1], t[0]);
    return lerp(lerp(x00, x10, t[1]), lerp(x01, x11, t[1]), t[2]);
  }

  Array3 padded_;
  long sy_ = 0, sz_ = 0;
  std::array<int, 3> n_{}, max_index_{};
  std::array<double, 3> shift_{};  // 0 along the component's own axis, ½ across it
  std::array<bool, 3> periodic_{};
  Stencil3 stencil_;
  int stencil_axis_ = -1;
};

}  // namespace creaturelab::fluid3d
