#pragma once
// Observables of the velocity gradient at cell centres: the vorticity ω = ∇ × u and the
// Q-criterion of Hunt, Wray & Moin 1988 (Center for Turbulence Research report CTR-S88, §2),
//   Q = ½ (‖Ω‖² − ‖S‖²),   S = ½ (G + Gᵀ),   Ω = ½ (G − Gᵀ),   G_ab = ∂u_a/∂x_b,
// positive where rotation dominates strain (vortex cores; solid-body rotation at rate Ω: Q = Ω²,
// ω = 2Ω). On the MAC grid ∂u_a/∂x_a at the centre is the difference of the cell's two faces; for
// b ≠ a the component is averaged onto the centres of the neighbouring cells along b and differenced
// centrally, with the ghost values of sampler3.hpp beyond the sides: second order inside, exact for
// a linear field away from the sides.

#include <array>

#include "fluid3d/mac_grid3.hpp"
#include "fluid3d/sampler3.hpp"

namespace creaturelab::fluid3d {

class FlowObservables3 {
 public:
  /// Recomputes the gradient from the grid's velocity (call after the grid changes).
  void update(const MacGrid3& grid);
  /// Velocity at the cell centres (m/s): the mean of each cell's two faces, component a.
  const Array3& cellVelocity_m_per_s(int a) const { return velocity_[a]; }
  /// Component a of ∇ × u at the cell centres (1/s).
  const Array3& vorticity_per_s(int a) const { return vorticity_[a]; }
  /// |∇ × u| at the cell centres (1/s).
  const Array3& vorticityMagnitude_per_s() const { return vorticity_magnitude_; }
  /// Q at the cell centres (1/s²).
  const Array3& q_per_s2() const { return q_; }

 private:
  std::array<PaddedComponent3, 3> padded_;
  std::array<Array3, 3> velocity_, vorticity_;
  Array3 vorticity_magnitude_, q_;
};

}  // namespace creaturelab::fluid3d
