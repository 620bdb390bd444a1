#pragma once
// The flesh of Lentine et al. 2010 §7.1-7.2 ("wrapped in flesh ... two-way coupled to the fluid")
// as the 3-D fluid's boundary: the flesh's vertices (flesh/flesh.hpp) are the immersed-boundary
// markers in place of the geoms' surfaces, moving with the flesh's own velocities; the fluid's force
// on each marker goes to its vertex as an external force (Flesh::externalForces_n), and so through
// the binding springs to the bones. The bones' interiors keep their own markers (interiorMarkers,
// RigidFluidParams3::interior_markers), moving with their bodies, so that the fluid inside the
// creature moves with it.
//
// Forcing3::projected is RigidFluidCoupling3's projected direct forcing (Taira & Colonius 2007), solved for
// the markers' forces F with I P (u~ + dt S F/ρ) = V. A coupled step of dt, in the caller's order:
//   1. advanceFluid   the fluid's stages to u~, then the flesh's backward Euler step against the
//                     skeleton as forceFluid last saw it, with the fluid's last reaction −F on its
//                     vertices; the binding's reactions on the bones kept for applyReaction
//   2. (solid)        the caller clears the applied forces, applyReaction, MuJoCo's step, kinematics
//   3. forceFluid     markers at the flesh's vertices (velocity: the flesh's) and inside the bones
//                     (velocity: their bodies' at the point); F solved; u^{n+1} = P (u~ + dt S F/ρ)
// So the flesh feels the fluid one step late (staggered, as the bodies do in RigidFluidCoupling3).
// That is stable when the flesh is much heavier than the fluid its markers drag: a vertex of area A
// carries ρ_flesh t A against the fluid's ρ A dx within the kernel's reach, a ratio of about 1e-2 for
// the flyer's 1 cm of flesh at 1050 kg/m^3 in air on 0.125 m cells (the added-mass amplification of
// the staggered step, −m_a/m per step; Causin, Gerbeau & Nobile 2005). In water the ratio is near 1:
// there the staggered step is unstable (Forcing3::coupled below is not).
// The regularisation: unlike a rigid surface, the flesh's vertices move with velocities of their own,
// with patterns on the scale of the vertex spacing (half a cell or less) that the kernel cannot resolve;
// the solve asks forces of them that grow as 1/forcing_regularisation, and handed back to the vertices
// these excite the same patterns. So the staggered flesh needs a larger weight than a rigid body's 1e-3: an
// undamped flesh on a sphere in a still fluid (tests/unit/flesh_fluid_test.cpp) grows at 1e-3 and 1e-2 and
// decays at 3e-2, the markers then slipping by a few percent of their forcing at every step, so that a flow's
// forces depend on the step. Forcing3::coupled answers the vertices' motion within the solve and runs the
// flyer's flesh in air at the rigid body's 1e-3.
//
// Momentum: the fluid receives dt Σ F at step n, the flesh's vertices and the bones −dt Σ F at step
// n + 1 (the vertices' share through the flesh's step, the interior markers' through applyReaction),
// and the binding passes momentum between flesh and bones to the flesh's linear solve's tolerance.
//
// Forcing3::coupled: the flesh in the coupled solve, stable for flesh as dense as the water. Lentine et al.
// 2010 §5 Eq. 9 in its symmetric positive definite form (Robinson-Mosher, Schroeder & Fedkiw 2011), as
// RigidFluidCoupling3's coupled forcing, with the flesh's backward Euler step (flesh.hpp: flesh and skeleton
// in one SPD system K y = b, y = (dv, du)) as the markers' mobility. With G the markers' velocity in y (a
// vertex's dv; an interior marker's J_b du at its arm) the forces −F on the markers add −h Gᵀ F to b, so
//   (I P S dt/ρ + h G K⁻¹ Gᵀ + ε D) F = G y0 + V* − I P u~,   y0 = K⁻¹ b0,
// V* the interior markers' velocity after MuJoCo's step without these forces (the vertices': v0), solved by
// the same conjugate gradients with K factorised once per step (sparse LDLT: an exact inner solve per outer
// iteration, so the operator is a fixed SPD one) and the preconditioner 1 / (dt/(ρ dV) + h/K_ii). Then
// y = K⁻¹ (b0 − h Gᵀ F): the flesh steps with it and the bones' free DOFs get du (velocities += du, positions
// += h du, as MuJoCo's Euler step would have with the forces). A step of dt, in the caller's order:
//   1. advanceFluid   the fluid's stages to u~ only
//   2. (solid)        MuJoCo's step from the pose forceFluid last saw, without the flesh's and fluid's forces
//                     (applyReaction adds nothing), kinematics
//   3. forceFluid     (non-const data) K at the step's start, the markers where y0 takes them (vertices at
//                     x0 + h (v0 + dv0), interior markers at data's pose), F solved, the flesh stepped and
//                     data corrected; the DOFs of held_joints or setHeldDofs (a servo) have infinite mass
// So fluid, flesh and bones take dt Σ F and −dt Σ F within the step (momentum to K's round-off, whatever the
// CG's tolerance). Where it differs from Eq. 9: the interface is the markers' kernel-smoothed one; the markers
// and K are at the step's start or y0's end, not at the corrected end (lagged: first order); the flesh's
// binding sees the skeleton's velocity at the step's start plus du, not MuJoCo's own change over the step
// (as in the staggered step). Needs the flesh's implicit_skeleton.
//
// Mouths (RigidFluidParams3::mouths, Lentine et al. 2010 §7.2): their discs of markers ride with their geoms'
// bodies as the interior markers do, their velocity the body's plus the flux along the disc's normal.
// Deterministic, no I/O.
#include <vector>

#include <Eigen/Core>

#include "coupling3d/forcing_cg3.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"
#include "coupling3d/solid_mobility3.hpp"
#include "coupling3d/surface_markers3.hpp"
#include "coupling3d/transfer3.hpp"
#include "flesh/flesh.hpp"
#include "fluid3d/fluid_solver3.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::coupling3d {

/// What a FleshFluidCoupling3 restores to continue bitwise as it would have: the fluid's grid, the
/// flesh's state, the last marker forces (the next flesh step's load and the forcing's warm start)
/// and the skeleton's reaction pending from the last flesh step.
struct FleshFluidState3 {
  fluid3d::MacGrid3 grid;
  Eigen::Matrix3Xd flesh_x_m, flesh_v_m_per_s;
  std::vector<Vec3> force_n;
  std::vector<Vec3> body_force_n, bone_force_n;
  std::vector<double> reaction;
  std::vector<double> mouth_flux_m_per_s;
};

class FleshFluidCoupling3 {
 public:
  /// The flesh of `data`'s model (FleshParams), placed on the skeleton at data's pose
  /// (data.kinematics() done), its vertices the fluid's markers; the fluid at rest. The flesh's
  /// longest edge is made at most marker_spacing_cells dx (FleshParams::max_edge_m, when larger or 0).
  /// Throws std::invalid_argument for unusable parameters (viscosity_in_forcing, the coupled forcing
  /// without the flesh's implicit_skeleton, a held joint the model lacks) or a vertex outside the fluid box.
  FleshFluidCoupling3(const rigid::RigidData& data, const fluid3d::FluidParams3& fluid, const RigidFluidParams3& p,
                      const flesh::FleshParams& flesh);

  void advanceFluid(double dt_s);
  /// Adds the bones' reactions pending for this step (binding and interior markers) to data's applied forces
  /// (nothing with Forcing3::coupled: forceFluid gave them to the bones in its own step).
  void applyReaction(rigid::RigidData& data) const;
  /// Adds the generalised forces the last step's flesh and fluid exerted on the bones to data's applied
  /// forces, whatever the forcing (for measurements: the actuator torques that hold the joints under them).
  void applyFluidForce(rigid::RigidData& data) const;
  /// Projected or off forcing (throws std::logic_error for coupled: it changes data).
  void forceFluid(const rigid::RigidData& data, double dt_s);
  /// Forcing3::coupled: the flesh's step and the marker forces solved together (above); data (MuJoCo's step
  /// without the flesh's and the fluid's forces) gets their impulse on its free DOFs. Other forcings: as the
  /// const overload.
  void forceFluid(rigid::RigidData& data, double dt_s);
  /// Forcing3::coupled: the DOFs (MuJoCo's qvel indices) the caller prescribes from the next forceFluid on, in
  /// place of held_joints'; throws std::invalid_argument for an index out of range.
  void setHeldDofs(const std::vector<int>& dofs);
  /// The flux speed (m/s, + expels along the normal) of mouth `mouth` (RigidFluidParams3::mouths) from the next
  /// forceFluid on.
  void setMouthFlux(std::size_t mouth, double flux_m_per_s);
  /// The skeleton moved to data's pose without a step: every vertex moved rigidly with its body (its
  /// velocity relative to its anchor kept, turned with the body), the markers placed there.
  void placeMarkers(const rigid::RigidData& data);

  void save(FleshFluidState3& s) const;
  /// Back to s with the skeleton at data's pose (the pose s was saved at).
  void restore(const FleshFluidState3& s, const rigid::RigidData& data);

  /// Per body (world body 0 included), of the last forceFluid: the force (N) the fluid exerts on the
  /// body's flesh and interior.
  const std::vector<Vec3>& bodyForce_n() const { return body_force_n_; }
  /// Per body (world body 0 included), of the last step: the force (N) on the body's bone, the reaction of its
  /// flesh's binding springs at the step's end (flesh.hpp's f_i(t + h), negated) plus the fluid's force on its
  /// interior and mouth markers; with the forcing projected or off, the reaction the bones take in the step after
  /// advanceFluid. It differs from bodyForce_n by the flesh's own rate of change of momentum.
  const std::vector<Vec3>& boneForce_n() const { return bone_force_n_; }
  /// Force on the fluid per marker (N): the flesh's vertices first, then the bones' interior markers, then the
  /// mouths'.
  const std::vector<Vec3>& markerForce_n() const { return force_; }
  const std::vector<Vec3>& markerPosition_m() const { return position_; }  ///< fluid frame
  int surfaceMarkers() const { return flesh_.vertices(); }
  int markers() const { return int(position_.size()); }
  double markerCellsPerStep() const { return cells_per_step_; }
  int forcingIterations() const { return iterations_; }
  double forcingResidual_m_per_s() const { return residual_m_per_s_; }

  const flesh::Flesh& flesh() const { return flesh_; }
  flesh::Flesh& flesh() { return flesh_; }
  fluid3d::FluidSolver3& fluid() { return fluid_; }
  const fluid3d::FluidSolver3& fluid() const { return fluid_; }
  /// The skeleton as forceFluid or placeMarkers last saw it (kinematics done).
  const rigid::RigidData& skeleton() const { return skeleton_; }
  const RigidFluidParams3& params() const { return p_; }

 private:
  void sync(const rigid::RigidData& data);
  void place(double dt_s, bool step);  // markers at the flesh and bones; with step, their velocities and the check
  void placeInterior(const rigid::RigidData& bodies, int nv, std::vector<Vec3>& now);
  void checkMoved(const std::vector<Vec3>& now, double dt_s);
  void projectedForcing(double dt_s);
  void reaction();
  void boneForces();  // bone_force_n_ from the flesh's binding forces and the interior markers' force_
  void coupledStep(rigid::RigidData& data, double dt_s);
  void placeCoupled(const rigid::RigidData& data, double dt_s);
  void toSystem(const std::vector<Vec3>& f, Eigen::VectorXd& b) const;   // b = Gᵀ f
  void fromSystem(const Eigen::VectorXd& y, std::vector<Vec3>& v) const; // v = G y
  void solidResponse(const std::vector<Vec3>& f, std::vector<Vec3>& out, double dt_s);

  RigidFluidParams3 p_;
  fluid3d::FluidSolver3 fluid_;
  flesh::Flesh flesh_;
  rigid::RigidData skeleton_;
  std::vector<SurfaceMarker3> interior_;  // the bones' markers: inside the geoms, then the mouths' discs
  std::vector<int> mouth_of_;             // per bone marker: its mouth, −1 for none
  std::vector<double> mouth_flux_m_per_s_;
  Transfer3 transfer_;
  std::vector<double> mass_;  // direct-forcing mass: ρ (dA dx + dV) (kg)
  std::vector<Vec3> position_, velocity_, residual_, force_;
  forcing::ForcingWork3 work_;
  fluid3d::FaceField3 spread_;
  Eigen::VectorXd area_m2_;
  std::vector<Vec3> body_force_n_, bone_force_n_;
  std::vector<double> reaction_;  // generalised forces on the skeleton for the next MuJoCo step
  // Forcing3::coupled: held DOFs, the applier of the bones' velocity change (no DOF held), each marker's
  // arm from its body's centre of mass at the step's start (interior markers), the preconditioner's
  // weights, the flesh system's vectors.
  std::vector<int> held_dofs_;
  SolidMobility3 mover_;
  std::vector<Vec3> arm_, solid_, weight_;
  Eigen::VectorXd system_b_, system_y_;
  double cells_per_step_ = 0.0;
  int iterations_ = 0;
  double residual_m_per_s_ = 0.0;
};

}  // namespace creaturelab::coupling3d
