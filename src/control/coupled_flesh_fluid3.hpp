#pragma once
// The 3-D fluid with the creature wrapped in flesh (Lentine et al. 2010 §7.1, Fig. 13) as the
// controller's coupled fluid (coupled_fluid.hpp): coupling3d's FleshFluidCoupling3, whose markers are
// the flesh's vertices, by projected forcing or in the coupled solve. The fluid's force per body is the force on
// that body's flesh and interior.
// A snapshot holds the fluid's grid, the flesh's state, the last marker forces and the skeleton's
// pending reaction, so restore continues bitwise as the saved run would (exactSnapshot true); the
// derivative evaluations' placed poses carry the flesh rigidly with their bodies.
#include "control/coupled_fluid.hpp"
#include "coupling3d/flesh_fluid_coupling3.hpp"

namespace creaturelab::control {

class CoupledFleshFluid3 final : public CoupledFluid {
 public:
  CoupledFleshFluid3(const rigid::RigidData& data, const fluid3d::FluidParams3& fluid,
                     const coupling3d::RigidFluidParams3& p, const flesh::FleshParams& flesh)
      : c_(data, fluid, p, flesh) {}
  void advanceFluid(double dt_s) override { c_.advanceFluid(dt_s); }
  /// Projected or off forcing only (the coupled solve changes data: forceAndCorrect).
  void forceAndProject(const rigid::RigidData& data, double dt_s) override { c_.forceFluid(data, dt_s); }
  /// Forcing3::coupled (Lentine et al. 2010 Eq. 9 with the flesh's backward Euler step as its mobility): the
  /// flesh's step and the forcing solved together, the DOFs in held_dofs of infinite mass; data gets the
  /// flesh's and fluid's impulse.
  bool coupledSolve() const override { return c_.params().forcing == coupling3d::Forcing3::coupled; }
  void forceAndCorrect(rigid::RigidData& data, double dt_s, const std::vector<int>& held_dofs) override {
    c_.setHeldDofs(held_dofs);
    c_.forceFluid(data, dt_s);
  }
  void applyReaction(rigid::RigidData& data) const override { c_.applyReaction(data); }
  /// The last step's flesh and fluid forces on the bones, whatever the forcing (the controller's measurements).
  void applyFluidForce(rigid::RigidData& data) const override { c_.applyFluidForce(data); }
  const std::vector<Vec3>& bodyForce_n() const override { return c_.bodyForce_n(); }
  int forcingIterations() const override { return c_.forcingIterations(); }
  void placeMarkers(const rigid::RigidData& data) override { c_.placeMarkers(data); }
  void save(std::unique_ptr<FluidSnapshot>& s) const override;
  void restore(const FluidSnapshot& s, const rigid::RigidData& data) override;
  bool exactSnapshot() const override { return true; }
  const coupling3d::FleshFluidCoupling3& coupling() const { return c_; }

 private:
  coupling3d::FleshFluidCoupling3 c_;
};

// Makes CoupledFleshFluid3s; a single-threaded one's fluid takes one thread.
CoupledFluidFactory fleshFluid(const fluid3d::FluidParams3& fluid, const coupling3d::RigidFluidParams3& p,
                               const flesh::FleshParams& flesh);

}  // namespace creaturelab::control
