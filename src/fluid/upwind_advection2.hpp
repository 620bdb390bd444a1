#pragma once
// Eulerian, conservative, second-order upwind-biased advection of the MAC velocity: the −u·∇u
// term of Eq. 1 (Rudolf & Mould 2009, §3.2) in flux form −∇·(u ⊗ u), which equals it for a
// divergence-free advecting field.
//
// Why a third scheme: the jellyfish runs at CFL 0.03–0.1, where a semi-Lagrangian step pays an
// interpolation error every step whatever its length (numerical viscosity ∝ dx²/dt) and costs
// scattered gathers; an explicit Eulerian scheme's error per unit time does not grow as dt
// shrinks, and its loops are contiguous and vectorised.
//
// Space: finite volumes on each component's own staggered cell (Harlow & Welch 1965; Griebel
// et al. 1998 ch. 3 use the same control volumes with a donor-cell blend). The advecting
// velocity on a control-volume face is the mean of the two nearest samples of the component
// normal to it; the advected value there is Fromm's reconstruction (van Leer 1977; MUSCL with
// κ = 0, unlimited), from the upwind side:
//   q_{i+½} = q_i + ¼ (q_{i+1} − q_{i−1})        if the advecting velocity is ≥ 0,
//   q_{i+½} = q_{i+1} − ¼ (q_{i+2} − q_i)         otherwise;
// second order in space, no limiter (it would clip smooth extrema to first order). Walls by two
// ghost layers: tangential components mirrored as in boundary2.hpp, normal components odd
// about a solid wall (u·n = 0 there) and constant across an open one.
// Time: Heun / SSP-RK2 (Shu & Osher 1988): u¹ = uⁿ + dt L(uⁿ), uⁿ⁺¹ = ½ uⁿ + ½ (u¹ + dt L(u¹)).
// Stability (linear von Neumann analysis of Fromm + RK2 with constant advecting velocity,
// amplification |1 + z + z²/2| ≤ 1): CFL |a| dt/dx ≤ 1 in 1-D; in 2-D the worst case is the
// diagonal, |u| dt/dx + |v| dt/dx ≤ 1, i.e. max-component CFL ≤ ½ (kUpwind2Rk2MaxCfl in
// fluid_params.hpp). FluidSolver2 refuses a step above it.
#include <vector>

#include "fluid/advection2.hpp"

namespace creaturelab::fluid {

/// One velocity component with two ghost layers on every side, filled from the walls.
class GhostedComponent2 {
 public:
  /// Shapes the storage for the component on kAxis faces of an nx × ny grid.
  void prepare(FaceAxis axis, int nx, int ny);
  /// Interior row j of the component (its own indices), writable.
  double* row(int j) { return data_.data() + static_cast<long>(j + kGhost) * stride_ + kGhost; }
  const double* row(int j) const { return data_.data() + static_cast<long>(j + kGhost) * stride_ + kGhost; }
  long stride() const { return stride_; }
  /// Solid walls' normal faces zeroed, then the ghost layers filled.
  void finish(const Walls& walls);

  static constexpr int kGhost = 2;

 private:
  FaceAxis axis_ = FaceAxis::x;
  int nx_ = 0, ny_ = 0;  // the component's own extents ((nx + 1) × ny for u)
  long stride_ = 0;
  std::vector<double> data_;
};

/// Fromm-upwind fluxes in conservative form with Heun (SSP-RK2) time stepping; see above.
class Upwind2Rk2Advection2 final : public AdvectionSolver2 {
 public:
  void advectVelocity(const MacGrid2& grid, const Walls& walls, double dt_s, Array2& u_out, Array2& v_out) override;
  double maxStableCfl() const override;

 private:
  GhostedComponent2 u0_, v0_;  // uⁿ
  GhostedComponent2 u1_, v1_;  // the Euler predictor u¹
  std::vector<double> scratch_;
};

}  // namespace creaturelab::fluid
