#pragma once
// Velocity self-advection, the u·∇u term of Eq. 5 (Lentine et al. 2010 §4.1: "the typical
// semi-Lagrangian scheme"), by tracing each face sample back along the flow (Stam 1999 §2.2), the
// schemes of the 2-D solver (fluid/advection2.hpp) with trilinear interpolation.

#include <limits>
#include <memory>

#include "fluid3d/fluid_params3.hpp"
#include "fluid3d/mac_grid3.hpp"
#include "fluid3d/sampler3.hpp"

namespace creaturelab::fluid3d {

class AdvectionSolver3 {
 public:
  virtual ~AdvectionSolver3() = default;
  /// Transports the grid's velocity along itself for dt_s into `out` (shaped like the velocity);
  /// known normal faces (solid walls, inflow sides) hold their values. The grid is not modified.
  virtual void advect(const MacGrid3& grid, double dt_s, FaceField3& out) = 0;
  /// Largest max-component CFL number (max|u_a| dt / dx) the scheme is stable at.
  virtual double maxStableCfl() const { return std::numeric_limits<double>::infinity(); }
  void setWorkers(WorkerPool* workers) { workers_ = workers; }

 protected:
  /// Pads the three components of `field` for sampling.
  void padAll(const MacGrid3& grid, const FaceField3& field, std::array<PaddedComponent3, 3>& padded);
  WorkerPool* workers_ = nullptr;
};

/// Stam 1999 §2.2 with a midpoint (RK2) backtrace and trilinear interpolation:
///   x_mid = x − ½ dt u(x),   x_back = x − dt u(x_mid),   u^{n+1}(x) = u^n(x_back).
/// Unconditionally stable and monotone; its interpolation adds a numerical viscosity of order |u| dx.
class SemiLagrangianAdvection3 final : public AdvectionSolver3 {
 public:
  void advect(const MacGrid3& grid, double dt_s, FaceField3& out) override;

 private:
  std::array<PaddedComponent3, 3> velocity_;
};

/// MacCormack in the unconditionally stable form of Selle, Fedkiw, Kim, Liu & Osher 2008:
///   φ̂ = A(φ),  φ̃ = A_reversed(φ̂),  φ^{n+1} = φ̂ + ½ (φ − φ̃),
/// clamped to the range of the eight values the forward step interpolated (their limiter).
class MacCormackAdvection3 final : public AdvectionSolver3 {
 public:
  void advect(const MacGrid3& grid, double dt_s, FaceField3& out) override;

 private:
  std::array<PaddedComponent3, 3> velocity_, forward_;
  FaceField3 lo_, hi_;
  std::array<FaceField3, 3> ahead_;  // coordinate d of the forward trace's end, cell units
};

std::unique_ptr<AdvectionSolver3> makeAdvectionSolver(AdvectionScheme3 scheme);

}  // namespace creaturelab::fluid3d
