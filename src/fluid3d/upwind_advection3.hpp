#pragma once
// Eulerian, conservative, second-order upwind-biased advection of the MAC velocity, the 2-D
// solver's upwind2_rk2 scheme (fluid/upwind_advection2.hpp) with a third axis: −u·∇u in flux form
// −∇·(u ⊗ u), equal to it for a divergence-free advecting field.
//
// Space: finite volumes on each component's own staggered cell (Harlow & Welch 1965). The
// advecting velocity on a control-volume face is the mean of the two nearest samples of the
// component normal to it; the advected value there is Fromm's reconstruction (van Leer 1977; MUSCL
// with κ = 0, unlimited) from the upwind side:
//   q_{i+½} = q_i + ¼ (q_{i+1} − q_{i−1})   if the advecting velocity is ≥ 0,
//   q_{i+½} = q_{i+1} − ¼ (q_{i+2} − q_i)    otherwise.
// Walls by two ghost layers: tangential components mirrored (stencil3.hpp's factors), normal
// components odd about a solid wall's value (u·n = 0 there, or an inflow side's speed U:
// ghost = 2U − mirror) and constant across an open side; periodic sides wrap.
// Time: Heun / SSP-RK2 (Shu & Osher 1988): u¹ = uⁿ + dt L(uⁿ), uⁿ⁺¹ = ½ uⁿ + ½ (u¹ + dt L(u¹)).
// Stability (linear von Neumann analysis with a constant advecting velocity): the worst case is the
// diagonal, (|u| + |v| + |w|) dt/dx ≤ 1, i.e. a max-component CFL number ≤ ⅓ (maxStableCfl());
// FluidSolver3 refuses a step above it.

#include "fluid3d/advection3.hpp"

namespace creaturelab::fluid3d {

/// One component with two ghost layers on every side.
class GhostedComponent3 {
 public:
  static constexpr int kGhost = 2;
  /// Copies component a (shaped like grid.velocity_m_per_s[a]) and fills its ghosts.
  void fill(int a, const MacGrid3& grid, const Array3& values);
  /// Value (i, j, k), each index from −2 to extent + 1.
  double at(int i, int j, int k) const {
    return data_.data()[(static_cast<long>(k + kGhost) * ey_ + (j + kGhost)) * ex_ + (i + kGhost)];
  }

 private:
  double& ref(int i, int j, int k) {
    return data_.data()[(static_cast<long>(k + kGhost) * ey_ + (j + kGhost)) * ex_ + (i + kGhost)];
  }
  long ex_ = 0, ey_ = 0;
  Array3 data_;
};

class Upwind2Rk2Advection3 final : public AdvectionSolver3 {
 public:
  void advect(const MacGrid3& grid, double dt_s, FaceField3& out) override;
  double maxStableCfl() const override { return 1.0 / 3.0; }

 private:
  /// out = q − (dt/dx) Σ_b ΔF_b, with F from `state` (advected and advecting), or for the corrector
  /// out = ½ (uⁿ + q − (dt/dx) Σ_b ΔF_b).
  void stage(const MacGrid3& grid, const std::array<GhostedComponent3, 3>& state, double c, bool corrector,
             FaceField3& out);
  std::array<GhostedComponent3, 3> ghosted_;
  FaceField3 predictor_;
};

}  // namespace creaturelab::fluid3d
