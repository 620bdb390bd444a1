#pragma once
// The 3-D fluid's momentum, for the momentum-balance tests of the couplings in a periodic box.
#include <cstddef>

#include <Eigen/Core>

#include "fluid3d/fluid_solver3.hpp"

namespace creaturelab::coupling3d {

// ρ dx³ Σ u over every face of a periodic box (kg m/s).
inline Eigen::Vector3d fluidMomentum(const fluid3d::FluidSolver3& f) {
  const fluid3d::MacGrid3& g = f.grid();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int a = 0; a < 3; ++a) {
    for (std::size_t t = 0; t < g.velocity_m_per_s[a].size(); ++t) p[a] += g.velocity_m_per_s[a].data()[t];
    p[a] *= f.params().density_kg_per_m3 * g.cellVolume_m3();
  }
  return p;
}

}  // namespace creaturelab::coupling3d
