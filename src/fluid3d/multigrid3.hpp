#pragma once
// A geometric multigrid V-cycle for the pressure matrix A of pressure_operator3.hpp, used as the
// preconditioner of conjugate gradients (Tatebe 1993, "The multigrid preconditioned conjugate
// gradient method"; Trottenberg, Oosterlee & Schüller 2001, "Multigrid", on
// cell-centred grids).
//
// Levels halve every axis while all are even and at least 4 cells long. Restriction sums the 8
// children (Pᵀ), prolongation injects the parent's value (P, constant interpolation). The coarse
// operator is the same matrix on the coarse grid, A_2h; Galerkin's Pᵀ A P is exactly 4 A_2h (each
// coarse face carries 4 fine faces; an open side's ghost term likewise), and the correction
// x += P A_2h⁻¹ (Pᵀ r / 2) weighs it twice Galerkin's, which is the Laplacian rediscretised at 2h:
// constant interpolation under-corrects smooth errors, and Galerkin's weight lets the PCG
// iterations grow with the grid where this one keeps them flat (tests/unit/fluid3d_pressure_test.cpp).
// Smoother: damped Jacobi, ω = 6/7, the same number of sweeps before and after the coarse
// correction, started from zero; the coarsest level gets a fixed number of sweeps. Every step is
// linear and self-adjoint, so the V-cycle is a fixed symmetric positive definite operator, as CG
// requires. (Gauss–Seidel was rejected: its symmetric form needs a reversed post-sweep and
// serialises the sweep.)

#include <array>
#include <vector>

#include "fluid3d/stencil3.hpp"

namespace creaturelab::fluid3d {

class MultigridPreconditioner3 {
 public:
  static constexpr double kOmega = 6.0 / 7.0;
  static constexpr int kSweeps = 2;         ///< before and after each coarse correction
  static constexpr int kCoarsestSweeps = 16;
  static constexpr double kCoarseWeight = 0.5;  ///< b_c = kCoarseWeight · Pᵀ r

  /// (Re)builds the levels unless built for these cells and sides.
  void prepare(const std::array<int, 3>& cells, const Boundaries3& sides);
  /// z = M⁻¹ r (one V-cycle from zero).
  void apply(const Array3& r, Array3& z, WorkerPool* pool);
  int levels() const { return static_cast<int>(levels_.size()); }

 private:
  struct Level {
    std::array<int, 3> n{};
    Stencil3 stencil;
    Array3 inv_diag, x, b, r;
  };
  void vcycle(int l, WorkerPool* pool);
  void jacobi(Level& level, int sweeps, bool from_zero, WorkerPool* pool);

  std::array<int, 3> cells_{};
  Boundaries3 sides_{};
  bool ready_ = false;
  std::vector<Level> levels_;
};

}  // namespace creaturelab::fluid3d
