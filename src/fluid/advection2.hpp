#pragma once
// Velocity self-advection, the −u·∇u term of Eq. 1 (Rudolf & Mould 2009, §3.2), solved by
// tracing each face sample back along the flow (Stam 1999 §2.2, "method of characteristics").

#include <limits>
#include <memory>
#include <vector>

#include "fluid/fluid_params.hpp"
#include "fluid/mac_grid2.hpp"
#include "fluid/staggered_sampler2.hpp"
#include "fluid/worker_pool.hpp"

namespace creaturelab::fluid {

/// Swappable advection stage (Jet's AdvectionSolver2 pattern).
class AdvectionSolver2 {
 public:
  virtual ~AdvectionSolver2() = default;
  /// Transports the grid's velocity along itself for dt_s. Writes u_out ((nx+1) × ny) and
  /// v_out (nx × (ny+1)); normal velocity on solid walls is zero. The grid is not modified.
  virtual void advectVelocity(const MacGrid2& grid, const Walls& walls, double dt_s, Array2& u_out, Array2& v_out) = 0;
  /// Largest CFL number (max velocity component · dt / dx) the scheme is stable at.
  virtual double maxStableCfl() const { return std::numeric_limits<double>::infinity(); }
  /// Threads for the stage (null: serial). Results are bitwise the same for any thread count.
  void setWorkers(WorkerPool* workers) { workers_ = workers; }

 protected:
  WorkerPool* workers_ = nullptr;
};

/// Stam 1999 §2.2 with linear interpolation: u^{n+1}(x) = u^n(x − Δ), where the displacement Δ
/// comes from a second-order (midpoint, RK2) backtrace:
///   x_mid = x − ½ dt u^n(x),   x_back = x − dt u^n(x_mid),   u^{n+1}(x) = u^n(x_back).
/// Unconditionally stable and monotone; first order in space–time, its interpolation adds a
/// numerical viscosity of order |u| dx (measured in tests/physics/fluid_taylor_green_test.cpp).
class SemiLagrangianAdvection2 final : public AdvectionSolver2 {
 public:
  void advectVelocity(const MacGrid2& grid, const Walls& walls, double dt_s, Array2& u_out, Array2& v_out) override;

 private:
  StaggeredComponent2 u_;
  StaggeredComponent2 v_;
  std::vector<double> scratch_;
};

/// MacCormack advection in the unconditionally stable form of Selle, Fedkiw, Kim, Liu & Osher
/// 2008 ("An unconditionally stable MacCormack method", J. Sci. Comput. 35):
///   φ̂ = A(φ)  (semi-Lagrangian forward),  φ̃ = A_reversed(φ̂)  (backward, −dt),
///   φ^{n+1} = φ̂ + ½ (φ − φ̃),
/// then clamped to the range of the four values the forward step interpolated, which
/// keeps the scheme stable and free of new extrema (their limiter). Rejected alternative: BFECC (Kim et al.
/// 2005) needs three semi-Lagrangian passes instead of two for the same order.
class MacCormackAdvection2 final : public AdvectionSolver2 {
 public:
  void advectVelocity(const MacGrid2& grid, const Walls& walls, double dt_s, Array2& u_out, Array2& v_out) override;

 private:
  StaggeredComponent2 u_, v_;          // the advecting velocity u^n
  StaggeredComponent2 u_hat_, v_hat_;  // forward results, written padded for the backward pass
  Array2 u_lo_, u_hi_, v_lo_, v_hi_;  // the forward step's interpolation bounds
  std::vector<double> scratch_;
};

std::unique_ptr<AdvectionSolver2> makeAdvectionSolver(AdvectionScheme scheme);

}  // namespace creaturelab::fluid
