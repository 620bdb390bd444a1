#pragma once
// The flesh of Lentine et al. 2010 §7.1-7.2 ("wrapped in flesh ... two-way coupled to the fluid")
// as the 3-D fluid's boundary: the flesh's vertices (flesh/flesh.hpp) are the immersed-boundary
// markers in place of the geoms' surfaces, moving with the flesh's own velocities; the fluid's force
// on each marker goes to its vertex as an external force (Flesh::externalForces_n), and so through
// the binding springs to the bones. The bones' interiors keep their own markers (interiorMarkers,
// RigidFluidParams3::interior_markers), moving with their bodies, so that the fluid inside the
// creature moves with it.
//
// The forcing is RigidFluidCoupling3's projected direct forcing (Taira & Colonius 2007), solved for
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
// there the staggered step is unstable.
// The regularisation: unlike a rigid surface, the flesh's vertices move with velocities of their own,
// with patterns on the scale of the vertex spacing (half a cell or less) that the kernel cannot resolve;
// the solve asks forces of them that grow as 1/forcing_regularisation, and handed back to the vertices
// these excite the same patterns. So the flesh needs a larger weight than a rigid body's 1e-3: an undamped
// flesh on a sphere in a still fluid (tests/unit/flesh_fluid_test.cpp) grows at 1e-3 and 1e-2 and decays
// at 3e-2, the markers then slipping by a few percent of their forcing.
//
// Momentum: the fluid receives dt Σ F at step n, the flesh's vertices and the bones −dt Σ F at step
// n + 1 (the vertices' share through the flesh's step, the interior markers' through applyReaction),
// and the binding passes momentum between flesh and bones to the flesh's linear solve's tolerance.
// Deterministic, no I/O.
#include <vector>

#include <Eigen/Core>

#include "coupling3d/forcing_cg3.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"
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
  std::vector<Vec3> body_force_n;
  std::vector<double> reaction;
};

class FleshFluidCoupling3 {
 public:
  /// The flesh of `data`'s model (FleshParams), placed on the skeleton at data's pose
  /// (data.kinematics() done), its vertices the fluid's markers; the fluid at rest. The flesh's
  /// longest edge is made at most marker_spacing_cells dx (FleshParams::max_edge_m, when larger or 0).
  /// Throws std::invalid_argument for unusable parameters (a forcing other than projected or off,
  /// viscosity_in_forcing) or a vertex outside the fluid box.
  FleshFluidCoupling3(const rigid::RigidData& data, const fluid3d::FluidParams3& fluid, const RigidFluidParams3& p,
                      const flesh::FleshParams& flesh);

  void advanceFluid(double dt_s);
  /// Adds the bones' reactions pending for this step (binding and interior markers) to data's applied forces.
  void applyReaction(rigid::RigidData& data) const;
  void forceFluid(const rigid::RigidData& data, double dt_s);
  /// The skeleton moved to data's pose without a step: every vertex moved rigidly with its body (its
  /// velocity relative to its anchor kept, turned with the body), the markers placed there.
  void placeMarkers(const rigid::RigidData& data);

  void save(FleshFluidState3& s) const;
  /// Back to s with the skeleton at data's pose (the pose s was saved at).
  void restore(const FleshFluidState3& s, const rigid::RigidData& data);

  /// Per body (world body 0 included), of the last forceFluid: the force (N) the fluid exerts on the
  /// body's flesh and interior.
  const std::vector<Vec3>& bodyForce_n() const { return body_force_n_; }
  /// Force on the fluid per marker (N): the flesh's vertices first, then the bones' interior markers.
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
  void projectedForcing(double dt_s);
  void reaction();

  RigidFluidParams3 p_;
  fluid3d::FluidSolver3 fluid_;
  flesh::Flesh flesh_;
  rigid::RigidData skeleton_;
  std::vector<SurfaceMarker3> interior_;
  Transfer3 transfer_;
  std::vector<double> mass_;  // direct-forcing mass: ρ (dA dx + dV) (kg)
  std::vector<Vec3> position_, velocity_, residual_, force_;
  forcing::ForcingWork3 work_;
  fluid3d::FaceField3 spread_;
  Eigen::VectorXd area_m2_;
  std::vector<Vec3> body_force_n_;
  std::vector<double> reaction_;  // generalised forces on the skeleton for the next MuJoCo step
  double cells_per_step_ = 0.0;
  int iterations_ = 0;
  double residual_m_per_s_ = 0.0;
};

}  // namespace creaturelab::coupling3d
