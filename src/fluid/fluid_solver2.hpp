#pragma once
// The 2-D incompressible fluid solver: Stam's stable fluids (Stam 1999) on a MAC grid
// (Griebel et al. 1998), for Eq. 1 of Rudolf & Mould 2009, §3.2:
//   ∂u/∂t = ν ∇²u − u·∇u − ∇p/ρ + F,   ∇·u = 0.
//
// One step is the operator split of Stam 1999 §2.2, as a fixed list of named stages (Jet's
// GridFluidSolver2::onAdvanceTimeStep; Box2D's solver stages):
//   1. external forces   u += dt (g + f/ρ)                          F of Eq. 1
//   2. advection         u ← u(x − trajectory), or explicit fluxes  −u·∇u
//   3. viscosity         (I − ν dt ∇²) u_new = u                     ν∇²u
//   4. projection        u ← u − (dt/ρ) ∇p with ∇·u = 0             −∇p/ρ, ∇·u = 0
//   5. tracers           passive particles move with the new velocity
// Each stage is a public method that can be called alone, each can be switched off
// (FluidStages), and advection, viscosity and pressure delegate to swappable sub-solvers.
// The solver owns its state, is deterministic (fixed loop orders; with FluidParams::threads > 1
// the stages share their loops among threads by index only, bitwise the same for any thread
// count: worker_pool.hpp), does no I/O and prints nothing.
//
// Accuracy: the split advects without the pressure and projects afterwards, which is first
// order in time whatever the advection scheme; with dt ∝ dx both schemes converge at first
// order on the Taylor–Green vortex (tests/physics/fluid_taylor_green_test.cpp), MacCormack
// with about a third of the semi-Lagrangian error and numerical viscosity.

#include <memory>
#include <stdexcept>
#include <vector>

#include "fluid/advection2.hpp"
#include "fluid/diffusion2.hpp"
#include "fluid/fluid_params.hpp"
#include "fluid/mac_grid2.hpp"
#include "fluid/pressure_solver2.hpp"
#include "fluid/staggered_sampler2.hpp"
#include "fluid/worker_pool.hpp"

namespace creaturelab::fluid {

/// Thrown when the velocity stops being finite or exceeds FluidParams::blowup_speed_m_per_s.
class FluidBlowUpError : public std::runtime_error {
 public:
  FluidBlowUpError(long step, double time_s, double dt_s, double max_speed_m_per_s, double limit_m_per_s,
                   double cfl_number);
  FluidBlowUpError(const std::string& message, long step, double time_s, double cfl_number)
      : std::runtime_error(message), step_(step), time_s_(time_s), cfl_number_(cfl_number) {}
  long step() const { return step_; }
  double time_s() const { return time_s_; }
  double cflNumber() const { return cfl_number_; }

 private:
  long step_;
  double time_s_;
  double cfl_number_;
};

/// Thrown before a step whose CFL number exceeds the stability bound of an explicit advection
/// scheme (FluidParams::advection = upwind2_rk2); a FluidBlowUpError, so callers that catch
/// blow-ups catch it too.
class FluidCflError final : public FluidBlowUpError {
 public:
  FluidCflError(long step, double time_s, double dt_s, double cfl_number, double bound);
  double bound() const { return bound_; }

 private:
  double bound_;
};

/// Per-step values, passed explicitly to every stage (never a global clock).
struct StepContext {
  long step_index = 0;  ///< 0 for the first step
  double time_s = 0.0;  ///< time at the start of the step
  double dt_s = 0.0;
};

/// Which stages step() runs. Tests switch stages off to check one against an analytic answer.
struct FluidStages {
  bool external_forces = true;
  bool advection = true;
  bool viscosity = true;
  bool pressure = true;
  bool tracers = true;
};

/// What one step did.
struct FluidStepReport {
  long steps_done = 0;  ///< steps completed, including this one
  double time_s = 0.0;  ///< time after the step
  double dt_s = 0.0;
  double cfl_number = 0.0;        ///< max(|u|, |v|) dt / dx of the velocity the step started from
  LinearSolveReport viscosity{};  ///< iterations 0 when the stage did not run
  LinearSolveReport pressure{};
  double max_divergence_per_s = 0.0;            ///< after the step
  double kinetic_energy_joule_per_m = 0.0;      ///< after the step
  double max_velocity_component_m_per_s = 0.0;  ///< after the step
};

class FluidSolver2 {
 public:
  /// Throws std::invalid_argument with FluidParams::validate()'s message if the parameters are
  /// unusable. Starts at rest at t = 0.
  explicit FluidSolver2(const FluidParams& params);

  /// One time step of the size chosen by the time-step policy.
  FluidStepReport step();
  /// One time step of dt_s (> 0). Throws FluidBlowUpError if the velocity blows up.
  FluidStepReport step(double dt_s);
  /// The policy's next step: fixed_step_s, or min(max_step_s, cfl_safety_factor dx / max(|u|, |v|)).
  double nextTimeStep_s() const;

  // --- the stages (Stam 1999 §2.2), each callable alone -------------------------------
  /// u += dt (g + f/ρ) on every face that is not a solid wall's (f: forceDensity_n_per_m3()).
  void applyExternalForces(const StepContext& context);
  /// −u·∇u by the advection sub-solver (semi-Lagrangian, MacCormack or Eulerian upwind2_rk2).
  void advectVelocity(const StepContext& context);
  /// ν∇²u implicitly by the diffusion sub-solver; does nothing when ν = 0.
  LinearSolveReport applyViscosity(const StepContext& context);
  /// Pressure projection by the pressure sub-solver; leaves the pressure in grid().pressure_pa.
  LinearSolveReport project(const StepContext& context);
  /// Moves the tracers with the current velocity.
  void advectTracers(const StepContext& context);

  /// For initial conditions: zero normal velocity on solid walls, project onto divergence-free
  /// fields, and reset the pressure to zero.
  LinearSolveReport makeDivergenceFree();

  // --- state ------------------------------------------------------------------------------
  const FluidParams& params() const { return params_; }
  const Walls& walls() const { return params_.walls; }
  MacGrid2& grid() { return grid_; }
  const MacGrid2& grid() const { return grid_; }
  /// External force density on the faces, N/m³ (force per unit volume; per unit area in 2-D
  /// per metre of depth). The immersed boundary spreads its forces here before each step;
  /// it stays until changed. Values on solid walls' normal faces are ignored.
  FaceVectorField2& forceDensity_n_per_m3() { return force_density_; }
  const FaceVectorField2& forceDensity_n_per_m3() const { return force_density_; }
  std::vector<Vec2>& tracers_m() { return tracers_; }
  const std::vector<Vec2>& tracers_m() const { return tracers_; }
  double time_s() const { return time_s_; }
  long stepsDone() const { return steps_done_; }
  FluidStages& stages() { return stages_; }

  /// The new sub-solver shares the solver's threads (FluidParams::threads).
  void setAdvectionSolver(std::unique_ptr<AdvectionSolver2> solver) {
    advection_ = std::move(solver);
    advection_->setWorkers(workers_.get());
  }
  void setDiffusionSolver(std::unique_ptr<DiffusionSolver2> solver) {
    diffusion_ = std::move(solver);
    diffusion_->setWorkers(workers_.get());
  }
  void setPressureSolver(std::unique_ptr<PressureSolver2> solver) {
    pressure_ = std::move(solver);
    pressure_->setWorkers(workers_.get());
  }

  // --- observables of the current state -------------------------------------------------
  double kineticEnergy_joule_per_m() const;
  double maxDivergence_per_s() const;
  double cflNumber(double dt_s) const;

 private:
  double timeStepFor(double max_velocity_component_m_per_s) const;
  FluidStepReport runStep(double dt_s, double start_speed_m_per_s);

  FluidParams params_;
  std::unique_ptr<WorkerPool> workers_;  // null with one thread
  MacGrid2 grid_;
  FaceVectorField2 force_density_;
  std::vector<Vec2> tracers_;
  FluidStages stages_{};
  double time_s_ = 0.0;
  long steps_done_ = 0;
  std::unique_ptr<AdvectionSolver2> advection_;
  std::unique_ptr<DiffusionSolver2> diffusion_;
  std::unique_ptr<PressureSolver2> pressure_;
  Array2 u_scratch_, v_scratch_;
  std::vector<double> row_energies_;  // scratch of summarize_flow
  VelocitySampler2 sampler_;
};

}  // namespace creaturelab::fluid
