#pragma once
// The 3-D fluid as the controller's coupled fluid (coupled_fluid.hpp): coupling3d's
// RigidFluidCoupling3 (projected direct forcing on surface markers; its forceFluid projects).
// A snapshot holds the fluid's grid (velocity and pressure); restore places the markers at the
// restored pose. The last step's reaction and the forcing's warm start are the coupling's own and
// not restored (exactSnapshot false): the controller then keeps one copy per derivative evaluation.
#include "control/coupled_fluid.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"

namespace creaturelab::control {

class CoupledFluid3 final : public CoupledFluid {
 public:
  CoupledFluid3(const rigid::RigidData& data, const fluid3d::FluidParams3& fluid,
                const coupling3d::RigidFluidParams3& p)
      : c_(data, fluid, p) {}
  void advanceFluid(double dt_s) override { c_.advanceFluid(dt_s); }
  void forceAndProject(const rigid::RigidData& data, double dt_s) override { c_.forceFluid(data, dt_s); }
  void applyReaction(rigid::RigidData& data) const override { c_.applyReaction(data); }
  const std::vector<Vec3>& bodyForce_n() const override { return c_.bodyForce_n(); }
  int forcingIterations() const override { return c_.forcingIterations(); }
  void placeMarkers(const rigid::RigidData& data) override { c_.placeMarkers(data); }
  void save(std::unique_ptr<FluidSnapshot>& s) const override;
  void restore(const FluidSnapshot& s, const rigid::RigidData& data) override;
  bool exactSnapshot() const override { return false; }
  const coupling3d::RigidFluidCoupling3& coupling() const { return c_; }

 private:
  coupling3d::RigidFluidCoupling3 c_;
};

// Makes CoupledFluid3s; a single-threaded one's fluid takes one thread.
CoupledFluidFactory spatialFluid(const fluid3d::FluidParams3& fluid, const coupling3d::RigidFluidParams3& p);

}  // namespace creaturelab::control
