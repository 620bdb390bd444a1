#pragma once
// Swappable pressure stage of the 3-D solver (Jet's GridPressureSolver pattern): solves the
// projection A q = b of pressure_operator3.hpp, subtracts ∇q and stores p = q ρ / dt.

#include <memory>
#include <vector>

#include "fluid3d/fluid_params3.hpp"
#include "fluid3d/mac_grid3.hpp"
#include "fluid3d/parallel3.hpp"

namespace creaturelab::fluid3d {

/// Outcome of a linear solve (iterative or direct).
struct SolveReport3 {
  int iterations = 0;              ///< 0 for direct solves
  double relative_residual = 0.0;  ///< ‖b − A x‖∞ / ‖b‖∞ at exit (0 when b = 0)
  bool converged = true;
};

class PressureSolver3 {
 public:
  virtual ~PressureSolver3() = default;
  /// Makes the grid's velocity divergence-free and leaves the pressure in grid.pressure_pa; with
  /// `increment`, the projection's pressure is added to grid.pressure_pa instead (incremental scheme).
  SolveReport3 project(MacGrid3& grid, double density_kg_per_m3, double dt_s, bool increment = false);
  /// Solves A q = b; q holds the initial guess of iterative solvers. In a closed box b must have
  /// mean zero (project() removes it) and q comes back with mean zero.
  virtual SolveReport3 solve(const std::array<int, 3>& cells, const Boundaries3& sides, const Array3& b,
                             Array3& q) = 0;
  void setWorkers(WorkerPool* workers) { workers_ = workers; }

 protected:
  WorkerPool* workers_ = nullptr;

 private:
  Array3 rhs_, q_;
};

std::unique_ptr<PressureSolver3> makePressureSolver(const FluidParams3& params);

}  // namespace creaturelab::fluid3d
