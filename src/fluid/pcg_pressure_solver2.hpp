#pragma once
// Pressure projection by conjugate gradients preconditioned with modified incomplete Cholesky,
// MIC(0) (Bridson, "Fluid Simulation for Computer Graphics", 2nd ed. 2015, ch. 5; Bridson &
// Müller-Fischer, SIGGRAPH 2007 course notes). The general solver: it needs nothing of the
// domain but the matrix, so it keeps working once obstacles or variable density arrive.

#include "fluid/pressure_solver2.hpp"

namespace creaturelab::fluid {

class PcgPressureSolver2 final : public PressureSolver2 {
 public:
  /// Stopping rule, with s = dx · max|u*| the velocity scale of the field being projected:
  ///   ‖b − A q‖∞ ≤ max(tolerance · min(‖b‖∞, s), 1e-14 · s).
  /// Since ‖b − A q‖∞ = dx² max|∇·u| after the update, this guarantees both a relative
  /// residual ≤ tolerance and max|∇·u| ≤ tolerance · max|u*| / dx; the 1e-14 floor is the
  /// round-off level of the divergence and only binds for fields already divergence-free.
  PcgPressureSolver2(double tolerance = 1e-10, int max_iterations = 5000)
      : tolerance_(tolerance), max_iterations_(max_iterations) {}

  LinearSolveReport project(MacGrid2& grid, const Walls& walls, double density_kg_per_m3, double dt_s) override;

  /// Solves A q = b (A from pressure_solver2.hpp) from the initial guess q (or from zero, if
  /// that is closer) with the stopping rule above; velocity_scale_m2_per_s = 0 drops the
  /// velocity terms (plain relative residual). In a closed box the mean of b is removed first
  /// and q is returned with mean zero.
  LinearSolveReport solve(const Walls& walls, const Array2& b, Array2& q, double velocity_scale_m2_per_s = 0.0);

  /// MIC(0) tuning (Bridson): τ blends modified (1) and plain (0) incomplete Cholesky; a
  /// pivot below σ · A_cc falls back to A_cc.
  static constexpr double kTau = 0.97;
  static constexpr double kSigma = 0.25;

 private:
  void factor(const Walls& walls, int nx, int ny);
  void applyPreconditioner(const Array2& r, Array2& z) const;

  double tolerance_;
  int max_iterations_;
  bool factored_ = false;
  Walls factored_walls_{};
  Array2 diagonal_, precon_;
  Array2 rhs_, b_, q_, r_, z_, s_, as_;
};

}  // namespace creaturelab::fluid
