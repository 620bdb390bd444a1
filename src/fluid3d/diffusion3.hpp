#pragma once
// The viscous term ν∇²u, per velocity component with the ghost values of stencil3.hpp, integrated
// over dt by backward Euler (Stam 1999 §2.2), Crank–Nicolson or explicit Euler; α = ν dt / dx²:
//   backward Euler   (1 + 6α) u − α Σ_nb f u_nb = u^n
//   Crank–Nicolson   (1 + 3α) u − ½α Σ_nb f u_nb = (1 − 3α) u^n + ½α Σ_nb f u^n_nb
//   explicit         u = (1 − 6α) u^n + α Σ_nb f u^n_nb        (stable for α ≤ 1/6)
// The implicit systems are symmetric positive definite with spectrum in [1, 1 + 12α]
// (Gershgorin): conjugate gradients preconditioned by the diagonal (Jacobi) converge in a
// number of iterations that grows like √α.

#include <array>

#include "fluid3d/fluid_params3.hpp"
#include "fluid3d/mac_grid3.hpp"
#include "fluid3d/pressure_solver3.hpp"
#include "fluid3d/stencil3.hpp"

namespace creaturelab::fluid3d {

class ViscositySolver3 {
 public:
  ViscositySolver3(ViscosityScheme3 scheme, double tolerance, int max_iterations)
      : scheme_(scheme), tolerance_(tolerance), max_iterations_(max_iterations) {}
  /// Applies ν∇² over dt_s to the grid's velocity; the report is the worst component's.
  SolveReport3 diffuse(MacGrid3& grid, double viscosity_m2_per_s, double dt_s);
  void setWorkers(WorkerPool* workers) { workers_ = workers; }

 private:
  SolveReport3 solveComponent(int a, double diag, double off, const Array3& b, Array3& x);

  ViscosityScheme3 scheme_;
  double tolerance_;
  int max_iterations_;
  WorkerPool* workers_ = nullptr;
  std::array<Stencil3, 3> stencils_;
  std::array<int, 3> cells_{};
  Boundaries3 sides_{};
  bool ready_ = false;
  Array3 b_, r_, z_, s_, as_, inv_diag_;
  std::vector<double> per_slab_;
};

}  // namespace creaturelab::fluid3d
