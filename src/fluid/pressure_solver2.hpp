#pragma once
// Pressure projection: the −∇p/ρ term and ∇·u = 0 of Eq. 1 (Rudolf & Mould 2009, §3.2),
// by Chorin's projection as in Stam 1999 §2.2 ("project" step), on the MAC grid.
//
// Derivation. The projected velocity is u = u* − (dt/ρ) ∇p. Write q = p dt/ρ (m²/s). On
// a face between cells c and n (n on the +x or +y side), u_f = u*_f − (q_n − q_c)/dx. Requiring
// the flux sum of every cell to vanish gives, for each cell c,
//     Σ_{faces} (q_c − q_nb) = −dx · (u*_E − u*_W + v*_N − v*_S)      i.e.  A q = b,
// where the sum runs over the cell's neighbours inside the domain (coefficient 1), solid walls
// contribute nothing (no flux: ∂p/∂n = 0) and an open wall contributes 2 q_c (p = 0 on the
// wall, ghost q = −q_c half a cell beyond it). A is the symmetric graph Laplacian with those
// boundary terms: positive definite when a wall is open, otherwise singular with the constants
// as null space (p is defined up to a constant; we pick mean zero).
// After the update, dx · (flux sum of cell c) = (A q − b)_c: the residual IS the divergence left.

#include <memory>

#include "fluid/fluid_params.hpp"
#include "fluid/linear_solve.hpp"
#include "fluid/mac_grid2.hpp"
#include "fluid/worker_pool.hpp"

namespace creaturelab::fluid {

/// Swappable pressure stage (Jet's GridPressureSolver2 pattern).
class PressureSolver2 {
 public:
  virtual ~PressureSolver2() = default;
  /// Makes the grid's velocity divergence-free: solves A q = b (see above), subtracts ∇q and
  /// stores p = q ρ / dt in grid.pressure_pa. The grid's previous pressure is the warm start of
  /// iterative solvers. The report's residual is measured on the updated velocity.
  virtual LinearSolveReport project(MacGrid2& grid, const Walls& walls, double density_kg_per_m3, double dt_s) = 0;
  /// Threads for the stage (null: serial). Results are bitwise the same for any thread count.
  void setWorkers(WorkerPool* workers) { workers_ = workers; }

 protected:
  WorkerPool* workers_ = nullptr;
};

std::unique_ptr<PressureSolver2> makePressureSolver(const FluidParams& params);

// --- building blocks shared by the pressure solvers (and their tests) -------------------

/// b = −dx · (flux sum) per cell, nx × ny (units m²/s).
void projectionRhs(const MacGrid2& grid, Array2& b);
/// u ← u − factor · Δφ across every unknown face (interior faces and open-wall faces, with
/// ghost φ = −φ beyond an open wall): factor = 1/dx for φ = q, dt/(ρ dx) for φ = p.
/// With workers, threads share the rows (bitwise the same result).
void subtractGradient(MacGrid2& grid, const Walls& walls, const Array2& phi, double factor_per_m,
                       WorkerPool* workers = nullptr);
inline void subtractGradient(MacGrid2& grid, const Walls& walls, const Array2& q) {
  subtractGradient(grid, walls, q, 1.0 / grid.dx_m);
}
/// y = A x for the matrix above.
void applyPressureMatrix(const Walls& walls, const Array2& x, Array2& y);
/// Diagonal of A: number of neighbour cells + 2 per adjacent open wall.
void pressureMatrixDiagonal(const Walls& walls, int nx, int ny, Array2& diagonal);
/// max over cells of |dx · flux sum| = ‖A q − b‖∞ after the update.
double maxAbsCellFlux_m2_per_s(const MacGrid2& grid, WorkerPool* workers = nullptr);

}  // namespace creaturelab::fluid
