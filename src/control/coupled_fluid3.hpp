#pragma once
// The 3-D fluid as the controller's coupled fluid (coupled_fluid.hpp): coupling3d's
// RigidFluidCoupling3 (projected direct forcing, or Eq. 9's coupled solve, on surface markers; its
// forceFluid projects).
// A snapshot holds everything the coupling's next step reads (coupling3d::CouplingState3: the fluid's
// grid, the markers' positions, the forcing's warm start, the last reaction), so restore is exact and
// the controller keeps one copy per evaluation thread.
#include "control/coupled_fluid.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"

namespace creaturelab::control {

class CoupledFluid3 final : public CoupledFluid {
 public:
  CoupledFluid3(const rigid::RigidData& data, const fluid3d::FluidParams3& fluid,
                const coupling3d::RigidFluidParams3& p)
      : c_(data, fluid, p) {}
  void advanceFluid(double dt_s) override { c_.advanceFluid(dt_s); }
  /// Projected or off forcing only (the coupled solve changes data: forceAndCorrect).
  void forceAndProject(const rigid::RigidData& data, double dt_s) override { c_.forceFluid(data, dt_s); }
  /// Forcing3::coupled (Lentine et al. 2010 Eq. 9): the forcing solved with the bodies' velocities, the
  /// DOFs in held_dofs (the servo's prescribed ones) of infinite mass; data gets the fluid's impulse.
  bool coupledSolve() const override { return c_.params().forcing == coupling3d::Forcing3::coupled; }
  void forceAndCorrect(rigid::RigidData& data, double dt_s, const std::vector<int>& held_dofs) override {
    c_.setHeldDofs(held_dofs);
    c_.forceFluid(data, dt_s);
  }
  /// The last step's fluid force on the bodies, whatever the forcing (the controller's measurements).
  void applyFluidForce(rigid::RigidData& data) const override { c_.applyFluidForce(data); }
  void applyReaction(rigid::RigidData& data) const override { c_.applyReaction(data); }
  const std::vector<Vec3>& bodyForce_n() const override { return c_.bodyForce_n(); }
  int forcingIterations() const override { return c_.forcingIterations(); }
  void placeMarkers(const rigid::RigidData& data) override { c_.placeMarkers(data); }
  void save(std::unique_ptr<FluidSnapshot>& s) const override;
  void restore(const FluidSnapshot& s, const rigid::RigidData& data) override;
  bool exactSnapshot() const override { return true; }
  const coupling3d::RigidFluidCoupling3& coupling() const { return c_; }

 private:
  coupling3d::RigidFluidCoupling3 c_;
};

// Makes CoupledFluid3s; a single-threaded one's fluid takes one thread.
CoupledFluidFactory spatialFluid(const fluid3d::FluidParams3& fluid, const coupling3d::RigidFluidParams3& p);

}  // namespace creaturelab::control
