#pragma once
// The velocity anywhere in the box by trilinear interpolation of the three face components
// (sampler3.hpp's ghost rules), for observers such as immersed bodies' markers and tracers.

#include <array>

#include "fluid3d/mac_grid3.hpp"
#include "fluid3d/sampler3.hpp"

namespace creaturelab::fluid3d {

class VelocitySampler3 {
 public:
  /// Takes a copy of the grid's velocity (call again after the grid changes).
  void update(const MacGrid3& grid, WorkerPool* pool = nullptr) {
    for (int a = 0; a < 3; ++a) components_[a].fill(a, grid, grid.velocity_m_per_s[a], pool);
    per_dx_ = 1.0 / grid.dx_m;
  }
  /// Velocity (m/s) at x_m (metres); positions outside a walled axis are clamped to the box,
  /// along a periodic axis they wrap.
  std::array<double, 3> velocity_m_per_s(const std::array<double, 3>& x_m) const {
    const std::array<double, 3> p{x_m[0] * per_dx_, x_m[1] * per_dx_, x_m[2] * per_dx_};
    return {components_[0].sample(p), components_[1].sample(p), components_[2].sample(p)};
  }

 private:
  std::array<PaddedComponent3, 3> components_;
  double per_dx_ = 0.0;
};

}  // namespace creaturelab::fluid3d
