#pragma once
// Two-way coupling of MuJoCo bodies with the 3-D fluid (Lentine et al. 2010 §4.2, §6) by projected
// direct forcing on markers spread over the geoms' surfaces (surface_markers3.hpp), transferred by
// the tensor-product kernels of transfer3.hpp: the 2-D coupling of coupling/rigid_fluid_coupling.hpp
// (Forcing::projected) with a third axis. World and fluid axes agree; the fluid box's corner sits
// at the world point `origin_m`.
//
// One coupled step of dt, in the caller's order:
//   1. advanceFluid   external forces, advection with u^n, viscosity -> u~ (the fluid's stages
//                     1-3, each as the fluid's FluidStages3 switches; §6 steps 2 and 5; viscosity
//                     moves into step 3 with RigidFluidParams3::viscosity_in_forcing)
//   2. (solid)        the caller steps MuJoCo from x^n to x^{n+1} with the reaction of the previous
//                     step applied (applyReaction; §6 step 3; nothing with Forcing3::coupled), or sets
//                     a kinematic pose, and then
//                     updates the kinematics (MuJoCo's step leaves the poses of the step's start)
//   3. forceFluid     markers at x^{n+1} with the solid's effective velocity V = (x^{n+1} − x^n)/dt
//                     (§6 step 4's velocity); marker forces F solved so that the projected velocity
//                     meets them, I P (u~ + dt S F/ρ) = V (Taira & Colonius 2007, J. Comput. Phys.
//                     225, the immersed-boundary projection), by preconditioned conjugate gradients
//                     with one fluid projection per iteration; u^{n+1} = P (u~ + dt S F/ρ); each
//                     marker's body gets −F (the reaction, applied at the next step: staggered)
// Where this differs from §6: the paper solves solid velocities and pressure together (Eq. 9);
// Forcing3::projected lets the solid feel the previous step's fluid force (explicit), which is
// unstable for free bodies not several times denser than the fluid: the reaction includes the force
// that accelerates the fluid the body carries (inside it and within the kernel's reach) and its added
// mass.
//
// Forcing3::coupled is Eq. 9 in the symmetric positive definite form its text points to
// (Robinson-Mosher, Schroeder & Fedkiw, J. Comput. Phys. 2011): the marker forces F are the unknowns,
// the bodies answer them within the step. Step 2 then steps MuJoCo without the fluid's force (applyReaction
// adds nothing) to x*, v*; step 3 solves, with J the markers' velocity Jacobian in the generalised
// velocities and A = M + h D MuJoCo's Euler matrix on the DOFs not held (solid_mobility3.hpp),
//   (I P S dt/ρ + dt J A⁻¹ Jᵀ + ε D) F = J v* − I P u~      (P → P H P with viscosity_in_forcing)
// by the same conjugate gradients (a sum of SPD operators), so the fluid at the markers and the bodies
// there agree after the step, then sets u^{n+1} = P (u~ + dt S F/ρ) and v^{n+1} = v* − dt A⁻¹ Jᵀ F, and
// moves the positions by dt (v^{n+1} − v*) as MuJoCo's Euler step would have. Where it differs from Eq. 9:
// the interface is the markers' kernel-smoothed one, not cut cells; the markers, their Jacobian and A are
// at x*, the step's end before the fluid's impulse (lagged by dt Δv: first order); held joints (a servo,
// a kinematic pose) have infinite mass as §6's kinematic bodies, their velocity in the right-hand side;
// no contacts or post-stabilisation inside the solve. Momentum fluid + bodies is kept in each step.
//
// Momentum: the transfer keeps the kernels' partition of unity and zero first moment, so the fluid
// receives exactly dt Σ F_k (and, away from walls, dt Σ X_k × F_k) and the bodies the negatives.

#include <stdexcept>
#include <string>
#include <vector>

#include "coupling3d/forcing_cg3.hpp"
#include "coupling3d/solid_mobility3.hpp"
#include "coupling3d/surface_markers3.hpp"
#include "coupling3d/transfer3.hpp"
#include "fluid3d/fluid_solver3.hpp"

namespace creaturelab::coupling3d {

/// How the markers force the fluid: projected (the forces solved through the projection, the bodies
/// feel them one step later), coupled (the forces and the bodies' velocities solved together, the
/// bodies feel them in the same step: Eq. 9 below), or off (the bodies do not touch the fluid: a
/// breaking switch for tests).
enum class Forcing3 { projected, coupled, off };

/// A mouth (Lentine et al. 2010 §7.2, the swimmer's flux through its mouth; the 3-D form of
/// coupling/mouth.hpp): a disc of markers fixed in a geom's frame, just outside its surface, whose
/// velocity is the geom's plus the flux speed along the disc's outward normal. Fluid is pushed across
/// the disc and returns round its rim, like an actuator disc; the force it takes goes into the fluid as
/// at any marker and its reaction onto the geom's body, so the jet's thrust is the momentum the fluid
/// receives. Keep the disc the kernel's half-width (2 cells for peskin4) outside the surface: closer, the
/// surface markers' no-slip and the disc's flux constrain the same fluid and the fluid across the disc
/// falls short of the flux.
struct Mouth3 {
  int geom = -1;
  Vec3 centre_geom_m{};           ///< the disc's centre in the geom's frame (m)
  Vec3 normal_geom{0.0, 0.0, -1.0};  ///< outward (expelling) normal in the geom's frame; normalised
  double radius_m = 0.0;
};

struct RigidFluidParams3 {
  Forcing3 forcing = Forcing3::projected;
  ib::Kernel kernel = ib::Kernel::peskin4;
  /// Surface markers per cell: no two neighbours farther apart than marker_spacing_cells dx. At most
  /// 1: farther apart, fluid slips between markers the kernel no longer joins.
  double marker_spacing_cells = 0.5;
  /// Surface markers moved this many cells (dx) inward along their facet's normal, the retracted Lagrangian
  /// grid of Breugem 2012 (J. Comput. Phys. 231, 4469; r_d = 0.3 dx for his 3-point kernel; Höfler &
  /// Schwarzer 2000, Phys. Rev. E 61, 7146): the kernel spreads each marker's forcing about 2 cells on
  /// either side, so a body forced on its surface drags and carries fluid like one about 0.8 cells larger.
  /// 1 cancels that for the Stokes drag with peskin4, the default regularisation and interior markers
  /// (chosen on one sphere array, checked on others); it removes only part of the excess added mass.
  /// 0 (default): markers on the surface. In [0, 2).
  double marker_retraction_cells = 0.0;
  /// Also markers inside each primitive geom, on a lattice of one cell at least the kernel's half-width
  /// (2 cells for peskin4) below the surface (interiorMarkers): the fluid inside then moves with the
  /// body instead of lagging it (the kernel constrains only the averaged velocity at the surface markers).
  bool interior_markers = true;
  /// CG stops when every marker's velocity is met to this fraction of the largest speed (markers' or fluid's).
  double forcing_tolerance = 1e-4;
  int max_forcing_iterations = 100;
  /// Tikhonov weight on the marker forces relative to the direct-forcing mass ρ dV / dt (dV = dA dx on
  /// the surface, the lattice cell inside; times 1 + 6 ν dt/dx² with viscosity_in_forcing): damps forces
  /// the fluid cannot feel (markers closer than the kernel resolves); the markers slip by about this
  /// fraction of their forcing.
  double forcing_regularisation = 1e-3;
  Vec3 origin_m{0.0, 0.0, 0.0};  ///< world position of the fluid box's corner (0, 0, 0)
  /// Solve the forces through the viscous step too: advanceFluid leaves viscosity out and forceFluid
  /// sets u^{n+1} = P H P (u~ + dt S F/ρ), H the fluid's viscous solve, F from I P H P S F dt/ρ (+ ε D F)
  /// = V − I P H P u~ (Taira & Colonius 2007's operator with the viscous solve done exactly). Then a
  /// steady state is the discrete steady Stokes (or Navier–Stokes) solution whatever dt; without it the
  /// viscous step smooths the forced velocity after the forcing, an error of order ν dt / dx² at the
  /// markers, negligible for water on centimetre cells but not in the Stokes regime. Costs a viscous
  /// solve and a second projection per CG iteration.
  bool viscosity_in_forcing = false;
  /// Coupled stability limit: no marker may move more than this many cells in one step.
  double max_marker_cells_per_step = 1.0;
  /// Forcing3::coupled: joints whose DOFs the caller prescribes (a servo, a kinematic pose): the fluid's
  /// impulse does not move them (infinite mass in the solve); their bodies' markers still move with them.
  std::vector<std::string> held_joints;
  /// Mouths, their markers spaced like the surface's (marker_spacing_cells); flux set by setMouthFlux.
  std::vector<Mouth3> mouths;

  /// "" when usable with this fluid, else what is wrong.
  std::string validate(const fluid3d::FluidParams3& fluid) const;
};

/// A step beyond the coupled stability limit, or a body leaving the fluid box, during a run.
class CouplingError3 : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Everything a coupled step reads besides the bodies (RigidFluidCoupling3::save, restore): the fluid's
/// grid, the markers' last positions, the forcing's warm start (the last forces), the last reaction and
/// the mouths' fluxes. (The fluid's external force density is the caller's: no step changes it.)
struct CouplingState3 {
  fluid3d::MacGrid3 grid;
  std::vector<Vec3> positions_m, forces_n, body_force_n, body_torque_n_m, body_point_m;
  std::vector<double> mouth_flux_m_per_s;
};

class RigidFluidCoupling3 {
 public:
  /// Markers on every geom's surface at data's pose (data.kinematics() done); the fluid at rest.
  /// Throws std::invalid_argument for unusable parameters or a body outside the fluid box (named).
  RigidFluidCoupling3(const rigid::RigidData& data, const fluid3d::FluidParams3& fluid, const RigidFluidParams3& p);

  /// Moves the markers to data's pose without a step; throws std::invalid_argument when a body is
  /// then outside the fluid box.
  void placeMarkers(const rigid::RigidData& data);

  void advanceFluid(double dt_s);
  /// Step 3 (above). With Forcing3::coupled, data (after the solid's step without the fluid's force)
  /// gets the fluid's impulse: its velocities and positions are corrected and its kinematics updated.
  void forceFluid(rigid::RigidData& data, double dt_s);
  /// The same for projected or off forcing (throws std::logic_error for coupled: it changes data).
  void forceFluid(const rigid::RigidData& data, double dt_s);
  /// Adds the last forceFluid's reaction on every moving body to data's applied forces (nothing with
  /// Forcing3::coupled: forceFluid applied it in its own step).
  void applyReaction(rigid::RigidData& data) const;
  /// Adds the last forceFluid's force on every moving body to data's applied forces, whatever the forcing
  /// (for measurements: e.g. the actuator torques that hold the joints under it).
  void applyFluidForce(rigid::RigidData& data) const;

  /// Forcing3::coupled: the DOFs (MuJoCo's qvel indices) the caller prescribes from the next forceFluid on,
  /// in place of held_joints' (a controller whose servo holds a different set in each evaluation).
  void setHeldDofs(const std::vector<int>& dofs) { mobility_.setHeldDofs(dofs); }

  /// The flux speed (m/s, + expels along the normal) of mouth `mouth` from the next forceFluid on.
  void setMouthFlux(std::size_t mouth, double flux_m_per_s);

  /// Copies everything the next step reads into s (reusing its storage), and back: restore, then the
  /// same steps from the same bodies' state give bitwise the same results. restore throws
  /// std::invalid_argument for a state of another coupling (other grid or markers).
  void save(CouplingState3& s) const;
  void restore(const CouplingState3& s);

  /// Per body (world body 0 included: the static geoms' share), of the last forceFluid: the force
  /// (N) the fluid exerts, and its torque (N m) about bodyPoint_m (the body's centre of mass).
  const std::vector<Vec3>& bodyForce_n() const { return body_force_n_; }
  const std::vector<Vec3>& bodyTorque_n_m() const { return body_torque_n_m_; }
  const std::vector<Vec3>& bodyPoint_m() const { return body_point_m_; }
  /// Force on the fluid per marker (N) and marker positions (fluid frame, m), of the last forceFluid.
  const std::vector<Vec3>& markerForce_n() const { return force_; }
  const std::vector<Vec3>& markerPosition_m() const { return previous_; }
  const std::vector<SurfaceMarker3>& markers() const { return markers_; }
  /// Largest marker displacement of the last step, cells.
  double markerCellsPerStep() const { return cells_per_step_; }
  /// CG iterations and the largest marker velocity miss (m/s) of the last forceFluid.
  int forcingIterations() const { return iterations_; }
  double forcingResidual_m_per_s() const { return residual_m_per_s_; }

  fluid3d::FluidSolver3& fluid() { return fluid_; }
  const fluid3d::FluidSolver3& fluid() const { return fluid_; }
  const RigidFluidParams3& params() const { return p_; }

 private:
  void place(const rigid::RigidData& data, std::vector<Vec3>& out) const;
  void force(const rigid::RigidData& data, double dt_s);
  void markerVelocities(const rigid::RigidData& data, double dt_s);
  void projectedForcing(double dt_s);
  void solidResponse(const std::vector<Vec3>& f, std::vector<Vec3>& out, double dt_s);
  Vec3 markerArm(std::size_t k) const;
  /// The fluid's response to a velocity change, in place: P, or P H P with viscosity_in_forcing.
  void respond(fluid3d::FaceField3& velocity, double dt_s);
  void reaction(const rigid::RigidData& data);

  RigidFluidParams3 p_;
  fluid3d::FluidSolver3 fluid_;
  std::vector<SurfaceMarker3> markers_;
  Transfer3 transfer_;
  std::vector<double> mass_;  // direct-forcing mass times dt: ρ (dA dx + dV) (kg)
  std::vector<Vec3> previous_, current_, velocity_, residual_, force_;
  forcing::ForcingWork3 work_;
  fluid3d::FaceField3 spread_;
  std::vector<Vec3> body_force_n_, body_torque_n_m_, body_point_m_;
  SolidMobility3 mobility_;
  std::vector<int> mouth_of_;  // per marker: its mouth, −1 for none
  std::vector<double> mouth_flux_m_per_s_;
  std::vector<Vec3> solid_, wrench_force_, wrench_torque_, body_linear_, body_angular_;
  std::vector<double> dv_;
  double cells_per_step_ = 0.0;
  int iterations_ = 0;
  double residual_m_per_s_ = 0.0;
};

}  // namespace creaturelab::coupling3d
