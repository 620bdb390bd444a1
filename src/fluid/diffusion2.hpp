#pragma once
// Viscosity, the ν∇²u term of Eq. 1 (Rudolf & Mould 2009, §3.2), integrated implicitly
// (backward Euler, Stam 1999 §2.2: "diffuse" step), hence stable for any ν dt / dx².

#include <memory>
#include <vector>

#include "fluid/diffusion_operator2.hpp"
#include "fluid/fluid_params.hpp"
#include "fluid/linear_solve.hpp"
#include "fluid/mac_grid2.hpp"
#include "fluid/worker_pool.hpp"
#include "fluid/staggered_sampler2.hpp"

namespace creaturelab::fluid {

/// Swappable viscosity stage.
class DiffusionSolver2 {
 public:
  virtual ~DiffusionSolver2() = default;
  /// Replaces the velocity u by the solution of (I − ν dt ∇²) u_new = u, with the walls'
  /// conditions; solid-wall normal velocity stays zero. Reports the worse of the two components.
  /// With ViscosityScheme::crank_nicolson, u is first replaced by (I + ½ν dt ∇²) u (with the
  /// walls' terms) and the system solved is (I − ½ν dt ∇²) u_new = that.
  LinearSolveReport diffuseVelocity(MacGrid2& grid, const Walls& walls, double kinematic_viscosity_m2_per_s,
                                     double dt_s, ViscosityScheme scheme = ViscosityScheme::backward_euler);
  /// Threads for the stage (null: serial). Results are bitwise the same for any thread count.
  void setWorkers(WorkerPool* workers) { workers_ = workers; }

 protected:
  /// One component (u: FaceAxis::x, v: FaceAxis::y) with α = ν dt / dx² > 0.
  virtual LinearSolveReport diffuseComponent(FaceAxis axis, Array2& x, const Walls& walls, double alpha) = 0;
  WorkerPool* workers_ = nullptr;

 private:
  // x ← (I + β ∇²) x + β · wall terms = 2x − A_β x + β · wall terms on the unknown block, so that
  // the solve's right-hand side x + β · wall terms is Crank–Nicolson's.
  void explicitHalf(FaceAxis axis, Array2& x, const Walls& walls, double beta);
  DiffusionBlock2 explicit_u_, explicit_v_;
  Array2 explicit_ax_;
  std::vector<double> explicit_dots_;
};

/// Backward-Euler diffusion solved per component by an iteration.
///
/// For a face value x with the 5-point Laplacian, α = ν dt / dx²:
///   (1 + α d) x − α Σ_{unknown neighbours} x_n = x^n + α Σ_{moving-wall ghosts} 2 U_wall,
/// where d counts neighbours: 1 for each face neighbour (unknown, or a solid wall's normal
/// face, which is zero), 0 for a free-slip/open ghost (ghost = x) and 2 for a no-slip/moving
/// ghost (ghost = 2U − x). The matrix is symmetric positive definite with its spectrum in
/// [1, 1 + α g], g ≤ 8 (DiffusionBlock2::max_row_sum). Stops when ‖b − A x‖∞ ≤ tolerance · ‖b‖∞;
/// starts from x^n. When 10 α ≤ kSweepContraction (water: α ~ 1e-3) up to kMaxSweeps
/// Richardson sweeps x ← x + (b − A x), one pass each, run first and usually meet the
/// tolerance alone. What they leave is finished by Chebyshev's semi-iteration, one pass per
/// sweep, while α g ≤ kChebyshevSpread (the jellyfish: α g = 0.1–0.5), else by conjugate
/// gradients, whose adaptivity wins on wide spectra (it ends in at most n iterations on n
/// unknowns, where Chebyshev needs ~ √(α g) · ln(1/tolerance) / 2). The report counts sweeps +
/// iterations.
class ImplicitDiffusion2 final : public DiffusionSolver2 {
 public:
  ImplicitDiffusion2(double tolerance, int max_iterations) : tolerance_(tolerance), max_iterations_(max_iterations) {}

  static constexpr double kSweepContraction = 0.1;  ///< largest error factor per sweep allowed
  static constexpr int kMaxSweeps = 8;
  /// Largest α g (κ − 1) solved by Chebyshev's semi-iteration rather than CG.
  static constexpr double kChebyshevSpread = 64.0;

 private:
  LinearSolveReport diffuseComponent(FaceAxis axis, Array2& x, const Walls& walls, double alpha) override {
    return solveComponent(axis, x, walls, alpha, axis == FaceAxis::x ? u_work_ : v_work_);
  }
  // Scratch of one component, kept between steps (allocated once per shape and walls).
  struct Workspace {
    DiffusionBlock2 block;
    Array2 b, r, p, ap;
    std::vector<double> row_dots, row_rr;  // per-row partial inner products
  };
  LinearSolveReport solveComponent(FaceAxis axis, Array2& x, const Walls& walls, double alpha, Workspace& work);
  // A x = w.b from x to ‖b − A x‖∞ ≤ target in at most `budget` iterations; the report's
  // residual is relative to b_norm.
  LinearSolveReport chebyshev(Array2& x, double alpha, double target, double b_norm, int budget, Workspace& w);
  LinearSolveReport conjugateGradients(Array2& x, double alpha, double target, double b_norm, int budget,
                                        Workspace& w);
  double tolerance_;
  int max_iterations_;
  Workspace u_work_, v_work_;
};

}  // namespace creaturelab::fluid
