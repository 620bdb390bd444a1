#pragma once
// Implicit viscosity solved directly (an option: FluidParams::viscosity_solver = fast_direct).
//
// The backward-Euler step of diffusion2.hpp, (I − α ∇²_h) x = b with α = ν dt / dx², is for
// each velocity component a shifted Kronecker sum: α (σ I + T_x ⊗ I + I ⊗ T_y) with σ = 1/α,
// where T_x, T_y are the 1-D second differences of the component's unknown faces
// (diffusion_operator2.hpp). Its ends: along the component's own axis a solid wall's normal face
// is a known zero one cell beyond the last unknown (end entry 2), an open wall leaves ∂u/∂n = 0
// (entry 1); across, a free-slip/open ghost equals the face (entry 1), a no-slip/moving ghost is
// 2U − x (entry 3, U in the right-hand side). The fast solver of the pressure (Schumann & Sweet
// 1988; fast_pressure_solver2.hpp) transforms along the "across" axis (a DCT by FFT when both
// walls there are free-slip/open, else a dense eigenbasis) and runs Thomas along the other, so
// the step is exact to round-off for any α, where the iterative solver's work grows with α
// (Richardson sweeps for 10 α ≤ 0.1, then Chebyshev or CG with cond ≤ 1 + 8 α).
//
// Cost (tests/bench/bench_fluid.cpp): two transforms per component, so at water's α (10⁻³ ..
// 0.05 on the paper's and the bench's grids) it is slower than the 2–4 Richardson sweeps of the
// iterative solver; it pays for viscous flows (large α), where the iteration needs many sweeps.
// Not bitwise the iterative solver's result: the two agree to the viscosity tolerance.

#include "fluid/diffusion2.hpp"
#include "fluid/diffusion_operator2.hpp"
#include "fluid/fast_pressure_solver2.hpp"

namespace creaturelab::fluid {

class FastDiffusion2 final : public DiffusionSolver2 {
 public:
  /// `tolerance` only judges the report: converged when ‖b − A x‖∞ ≤ tolerance · ‖b‖∞.
  explicit FastDiffusion2(double tolerance) : tolerance_(tolerance) {}

  /// The transform method of the last solve of each component (tests).
  FastPressureSolver2::Method uMethod() const { return u_work_.solver.method(); }
  FastPressureSolver2::Method vMethod() const { return v_work_.solver.method(); }

 private:
  /// Reports 0 iterations and the residual ‖b − A x‖∞ / ‖b‖∞ (round-off).
  LinearSolveReport diffuseComponent(FaceAxis axis, Array2& x, const Walls& walls, double alpha) override {
    return solveComponent(axis, x, walls, alpha, axis == FaceAxis::x ? u_work_ : v_work_);
  }
  struct Workspace {
    DiffusionBlock2 block;
    Array2 b, q, ap;  // b and q on the unknown block only; ap on the component's array
    std::vector<double> row_dots;
    FastPressureSolver2 solver;
  };
  LinearSolveReport solveComponent(FaceAxis axis, Array2& x, const Walls& walls, double alpha, Workspace& work);
  double tolerance_;
  Workspace u_work_, v_work_;
};

/// The operator σ I + T_x ⊗ I + I ⊗ T_y of a component's block (see above), σ = 1/α.
KroneckerOperator2 diffusionOperator(const DiffusionBlock2& block, int nx, int ny, double alpha);

}  // namespace creaturelab::fluid
