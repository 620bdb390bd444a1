#pragma once
// Two-way coupling of MuJoCo's planar rigid bodies with the 2-D fluid by direct forcing on
// outline markers (Lentine et al. 2010 §4.2, §6;
// the immersed-boundary transfer of src/ib, Peskin 2002). The fluid lives in the creature's x-z
// plane: fluid (x, y) = world (x - origin_x, z - origin_z), per metre of depth; the bodies are
// depth_m deep along y.
//
// One coupled step of dt, in the caller's order (coupled_step.hpp names it):
//   1. advanceFluid   fluid external forces, inflow, advection with u^n, viscosity -> u~
//                     (§6 steps 2 and 5 without the pressure)
//   2. (solid)        the caller steps MuJoCo from x^n to x^{n+1}, with the fluid's reaction of
//                     the previous step applied (applyReaction): §6 step 3
//   3. forceFluid     markers at x^{n+1} with the solid's effective velocity V = (x^{n+1} - x^n)/dt
//                     (§6 step 4's velocity); direct forcing (Uhlmann 2005, J. Comput. Phys. 209)
//                     iterated (multi-direct forcing, Wang, Fan & Luo 2008, Int. J. Numer. Meth.
//                     Fluids 56): G_k += rho dA_k (V_k - I u~)_k / dt, u~ += dt S G / rho, with
//                     dA_k = (marker's outline length) x dx; the body gets -G_k depth_m
//   4. project        pressure projection -> u^{n+1} (§6 step 7), then projection_rounds - 1
//                     further rounds of forcing sweeps and projection (the leak the projection
//                     puts back at the markers taken out again)
// Where this differs from §6 and why: the paper solves the coupled system of Eq. 9 (solid
// velocity and pressure together, [25]); here the solid feels the fluid force of the previous
// step (explicit, staggered). For joints the servo prescribes (the controlled and kinematic ones,
// §2.2: targets reached "irrespective of all external forces") the lag changes only the measured
// torque; for passive bodies lighter than the fluid they displace a staggered scheme is unstable
// (added mass), which the run detects as a blow-up (exit 3) rather than hides. The paper's
// leak-proof advection velocity (§6 step 4) is not built: advection uses u^n and the forcing
// happens before the projection, which moves the velocity at the markers again by the pressure
// gradient (hence the extra rounds); the leak that leaves is measured (tests/unit/coupling_test.cpp) and bounded.
//
// Momentum: the spread forces keep the kernel's partition of unity and zero first moment
// (transfer.hpp), so the fluid's momentum and angular momentum change by exactly dt sum G_k and
// dt sum X_k x G_k, and the bodies get the negatives (to round-off; tested).
#include <stdexcept>
#include <string>
#include <vector>

#include "coupling/inflow.hpp"
#include "coupling/mouth.hpp"
#include "coupling/outline.hpp"
#include "fluid/fluid_solver2.hpp"
#include "ib/kernel.hpp"
#include "ib/transfer.hpp"

namespace creaturelab::coupling {

// How the markers force the fluid. sweeps: multi-direct forcing before the projection (cheap,
// leaks: the projection moves the markers' velocity again); projected: the forces solved so that
// the projected velocity meets the markers (one projection per CG iteration; what leaks is the
// CG tolerance and the kernel's width).
enum class Forcing { sweeps, projected };

// The projected forcing's CG preconditioner. mass: the direct-forcing mass rho dA_k / dt per marker
// (a diagonal); gram: the forcing operator without the projection, dt/(rho dx^2) G + eps D (G the
// stencils' Gram matrix, transfer.hpp), factored once per step. Markers half a cell apart share
// most of their 4 x 4 stencils, which the diagonal ignores.
enum class ForcingPreconditioner { mass, gram };

struct RigidFluidParams {
  Forcing forcing = Forcing::projected;
  ib::Kernel kernel = ib::Kernel::peskin4;
  // Outline markers per cell of fluid: spacing = marker_spacing_cells dx. At most 1: farther apart,
  // fluid slips between neighbours that the kernel no longer joins (measured leak; validate()).
  double marker_spacing_cells = 0.5;
  int forcing_iterations = 3;      // multi-direct forcing sweeps per step (1 = Uhlmann's)
  // Rounds of (forcing sweeps, projection) per step: the projection moves the velocity at the
  // markers again, each further round takes that leak back out (a fast direct solve each).
  int projection_rounds = 2;
  double forcing_relaxation = 1.0;  // factor on each sweep's correction (over-relaxation > 1)
  // projected: CG stops when every marker's velocity is met to this fraction of the largest speed.
  double forcing_tolerance = 1e-3;
  int max_forcing_iterations = 50;
  ForcingPreconditioner forcing_preconditioner = ForcingPreconditioner::mass;
  // projected: Tikhonov weight on the marker forces (relative to the direct-forcing mass), which
  // damps forces that do not reach the fluid (see projectedForcing); it lets the markers slip by
  // about this fraction of their forcing.
  double forcing_regularisation = 1e-3;
  double depth_m = 1.0;            // bodies' extent along y (the fluid is per metre of depth)
  double origin_x_m = 0.0;         // world x of the fluid box's left wall
  double origin_z_m = 0.0;         // world z of its floor
  // The coupled stability limit: no marker may move more than this many cells in one step (it
  // would jump over the fluid it should push, and the explicit reaction lags by a step).
  double max_marker_cells_per_step = 1.0;
  InflowParams inflow;
  // The swimmer's mouth (mouth.hpp, §7.2): markers after the outlines' whose velocity carries a flux.
  MouthParams mouth;

  // "" when usable in this fluid, else what is wrong.
  std::string validate(const fluid::FluidParams& fluid) const;
};

// A step beyond the coupled stability limit, or a body leaving the fluid box, during a run.
class CouplingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Everything of the coupling that decides the next step, for snapshots (§4.3: each perturbation
// has its own copy of the fluid state).
struct CouplingState {
  fluid::MacGrid2 grid;
  std::vector<fluid::Vec2> previous_m, marker_force_n_per_m;
  std::vector<Vec3> body_force_n, body_torque_n_m, body_point_m;
  double time_s = 0;
};

class RigidFluidCoupling {
 public:
  // Markers from the model's outlines at data's pose (data.kinematics() done); the fluid at rest,
  // or filled with the stream. Throws std::invalid_argument for unusable parameters, a geom
  // without an outline, or a body outside the fluid box (named).
  RigidFluidCoupling(const rigid::RigidData& data, const fluid::FluidParams& fluid, const RigidFluidParams& p);

  // Moves the markers to data's pose without a step (the pose set before the first step); throws
  // std::invalid_argument when a body is then outside the fluid box.
  void placeMarkers(const rigid::RigidData& data);

  void advanceFluid(double dt_s);
  void forceFluid(const rigid::RigidData& data, double dt_s);
  fluid::LinearSolveReport project(double dt_s);
  // Adds the last forceFluid's reaction on every moving body to data's applied forces.
  void applyReaction(rigid::RigidData& data) const;

  // Per body (world body 0 included: the static scenery's share), of the last forceFluid.
  const std::vector<Vec3>& bodyForce_n() const { return body_force_n_; }
  const std::vector<Vec3>& bodyTorque_n_m() const { return body_torque_n_m_; }  // about bodyPoint_m
  const std::vector<Vec3>& bodyPoint_m() const { return body_point_m_; }
  // Force on the fluid per marker (N per metre of depth) of the last forceFluid.
  const std::vector<fluid::Vec2>& markerForce_n_per_m() const { return force_; }
  const std::vector<fluid::Vec2>& markerPosition_m() const { return previous_; }  // fluid frame
  const std::vector<OutlineMarker>& markers() const { return markers_; }
  // Markers from this index on are the mouth's (mouth.hpp); markers().size() when there is none.
  std::size_t mouthBegin() const { return mouth_begin_; }
  // Largest marker displacement of the last step, cells.
  double markerCellsPerStep() const { return cells_per_step_; }
  // Forcing::projected: CG iterations and the largest marker velocity miss of the last step.
  int forcingIterations() const { return iterations_; }
  double forcingResidual_m_per_s() const { return forcing_residual_m_per_s_; }

  fluid::FluidSolver2& fluid() { return fluid_; }
  const fluid::FluidSolver2& fluid() const { return fluid_; }
  const RigidFluidParams& params() const { return p_; }

  void save(CouplingState& s) const;
  void restore(const CouplingState& s);

 private:
  void place(const rigid::RigidData& data, std::vector<fluid::Vec2>& out) const;
  void locate(const std::vector<fluid::Vec2>& x);
  void sweeps(double dt_s);
  void projectedForcing(double dt_s);
  void reaction(const rigid::RigidData& data);
  void sumReaction();
  void addMouthFlux(const rigid::RigidData& data);

  RigidFluidParams p_;
  fluid::FluidSolver2 fluid_;
  std::vector<OutlineMarker> markers_;
  ib::Transfer transfer_;
  std::vector<fluid::Vec2> previous_, current_, velocity_, sampled_, sweep_, force_, z_, direction_, applied_;
  fluid::MacGrid2 work_;
  Eigen::SparseMatrix<double> gram_;  // the gram preconditioner's A0 (scratch of projectedForcing)
  Eigen::VectorXd packed_;            // its right-hand side and solution, 2 k + component
  int iterations_ = 0;
  double forcing_residual_m_per_s_ = 0;
  fluid::FaceVectorField2 spread_;
  std::vector<Vec3> body_force_n_, body_torque_n_m_, body_point_m_;
  double cells_per_step_ = 0;
  double time_s_ = 0;
  std::size_t mouth_begin_ = 0;
};

}  // namespace creaturelab::coupling
