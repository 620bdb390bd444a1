#pragma once
// The 3-D incompressible fluid solver: Eqs. 5–8 of Lentine, Gräfe & Fedkiw 2010 (§4.1) with a
// viscous term, by Stam's stable fluids (Stam 1999) on a MAC grid (mac_grid3.hpp).
//
// One step is a fixed list of named stages (the 2-D solver's, fluid/fluid_solver2.hpp):
//   1. external forces   u += dt (g + f/ρ)                          f of Eq. 5
//   2. advection         u ← u(x − trajectory)                      u·∇u (Eq. 5's u* step)
//   3. viscosity         (I − ν dt ∇²) u_new = u, or CN / explicit   ν∇²u
//   4. projection        u ← u − (dt/ρ) ∇p with ∇·u = 0             Eqs. 7–8
// Each stage is a public method, each can be switched off (FluidStages3), and advection, viscosity
// and pressure are swappable sub-solvers. Deterministic for any FluidParams3::threads (loops are
// cut by slab index only: parallel3.hpp); no I/O.
//
// With ProjectionScheme3::incremental a stage between 2 and 3 subtracts (dt/ρ) ∇pⁿ (applyPressureGradient)
// and stage 4 finds the pressure's increment (Guermond, Minev & Shen 2006 §3.2).
//
// Accuracy: the split is first order in time (advection without the pressure, then the
// projection); in space the operators are second order (tests/physics/fluid3d_abc_test.cpp).

#include <memory>
#include <stdexcept>

#include "fluid3d/advection3.hpp"
#include "fluid3d/diffusion3.hpp"
#include "fluid3d/fluid_params3.hpp"
#include "fluid3d/mac_grid3.hpp"
#include "fluid3d/pressure_solver3.hpp"

namespace creaturelab::fluid3d {

/// Thrown when the velocity stops being finite or exceeds FluidParams3::blowup_speed_m_per_s.
class FluidBlowUpError3 : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct FluidStages3 {
  bool external_forces = true;
  bool advection = true;
  bool viscosity = true;
  bool pressure = true;
};

struct FluidStepReport3 {
  long steps_done = 0;
  double time_s = 0.0;  ///< after the step
  double dt_s = 0.0;
  double cfl_number = 0.0;  ///< max|u component| dt / dx at the step's start
  SolveReport3 viscosity{};
  SolveReport3 pressure{};
};

class FluidSolver3 {
 public:
  /// Throws std::invalid_argument with FluidParams3::validate()'s message. Starts at rest at t = 0.
  explicit FluidSolver3(const FluidParams3& params);
  ~FluidSolver3();

  /// One step of the policy's size, or of dt_s (> 0). Throws FluidBlowUpError3 when the velocity blows
  /// up, or before a step whose CFL number exceeds the advection scheme's stability bound.
  FluidStepReport3 step();
  FluidStepReport3 step(double dt_s);
  /// fixed_step_s, or min(max_step_s, min(cfl_safety_factor, the scheme's bound) dx / max|u component|).
  double nextTimeStep_s() const;

  // --- the stages, each callable alone
  void applyExternalForces(double dt_s);
  void advectVelocity(double dt_s);
  SolveReport3 applyViscosity(double dt_s);
  /// The projection; with the incremental scheme it adds its pressure to the previous one.
  SolveReport3 project(double dt_s);
  /// The incremental scheme's predictor term: u −= (dt/ρ) ∇p with the grid's (previous) pressure.
  void applyPressureGradient(double dt_s);
  /// For initial conditions: zero normal velocity on solid walls and project (pressure reset to zero).
  SolveReport3 makeDivergenceFree();

  // --- state
  const FluidParams3& params() const { return params_; }
  MacGrid3& grid() { return grid_; }
  const MacGrid3& grid() const { return grid_; }
  /// External force density on the faces, N/m³; stays until changed.
  FaceField3& forceDensity_n_per_m3() { return force_density_; }
  FluidStages3& stages() { return stages_; }
  double time_s() const { return time_s_; }
  long stepsDone() const { return steps_done_; }
  void setPressureSolver(std::unique_ptr<PressureSolver3> solver);
  void setAdvectionSolver(std::unique_ptr<AdvectionSolver3> solver);

  // --- observables
  /// ½ ρ Σ u² dx³ over the faces (a wall's faces weigh ½).
  double kineticEnergy_joule() const;
  double maxDivergence_per_s() const;
  double maxVelocityComponent_m_per_s() const;

 private:
  FluidParams3 params_;
  std::unique_ptr<WorkerPool> workers_;
  MacGrid3 grid_;
  FaceField3 force_density_, scratch_;
  FluidStages3 stages_{};
  double time_s_ = 0.0;
  long steps_done_ = 0;
  std::unique_ptr<AdvectionSolver3> advection_;
  std::unique_ptr<ViscositySolver3> viscosity_;
  std::unique_ptr<PressureSolver3> pressure_;
};

}  // namespace creaturelab::fluid3d
