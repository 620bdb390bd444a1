#pragma once
// Pressure projection by conjugate gradients preconditioned with a multigrid V-cycle
// (multigrid3.hpp): the general solver, whose iterations stay about flat as the grid is refined.

#include "fluid3d/multigrid3.hpp"
#include "fluid3d/pressure_solver3.hpp"

namespace creaturelab::fluid3d {

class MgPcgPressureSolver3 final : public PressureSolver3 {
 public:
  /// Stops at ‖b − A q‖∞ ≤ tolerance · ‖b‖∞ (= dx² max|∇·u| after the update).
  explicit MgPcgPressureSolver3(double tolerance = 1e-10, int max_iterations = 500)
      : tolerance_(tolerance), max_iterations_(max_iterations) {}
  SolveReport3 solve(const std::array<int, 3>& cells, const Boundaries3& sides, const Array3& b, Array3& q) override;
  int multigridLevels() const { return preconditioner_.levels(); }

 private:
  double tolerance_;
  int max_iterations_;
  Stencil3 stencil_;
  std::array<int, 3> stencil_cells_{};
  Boundaries3 stencil_sides_{};
  MultigridPreconditioner3 preconditioner_;
  Array3 r_, z_, s_, as_;
  std::vector<double> per_slab_;
};

}  // namespace creaturelab::fluid3d
