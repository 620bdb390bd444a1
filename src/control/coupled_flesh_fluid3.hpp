#pragma once
// The 3-D fluid with the creature wrapped in flesh (Lentine et al. 2010 §7.1, Fig. 13) as the
// controller's coupled fluid (coupled_fluid.hpp): coupling3d's FleshFluidCoupling3, whose markers are
// the flesh's vertices, by projected forcing or in the coupled solve. The fluid's force per body is the force on
// that body's flesh and interior.
// A snapshot holds the fluid's grid, the flesh's state, the last marker forces and the skeleton's
// pending reaction, so restore continues bitwise as the saved run would (exactSnapshot true); the
// derivative evaluations' placed poses carry the flesh rigidly with their bodies.
#include <vector>

#include "control/coupled_fluid.hpp"
#include "coupling/mouth.hpp"
#include "coupling3d/flesh_fluid_coupling3.hpp"

namespace creaturelab::control {

// The mouths' flux following phases (Lentine et al. 2010 §7.2, as swimmer_run3.hpp's SwimmerFluid3 sets it):
// at each coupled step every mouth takes flux_m_per_s[phase] (m/s, + expels) of the phase the step's middle
// is in, a function of the bodies' time alone (a restored evaluation sees the frame's flux). Empty: no flux.
struct MouthPhases3 {
  coupling::PhaseSchedule schedule;
  std::vector<double> flux_m_per_s;
};

class CoupledFleshFluid3 final : public CoupledFluid {
 public:
  CoupledFleshFluid3(const rigid::RigidData& data, const fluid3d::FluidParams3& fluid,
                     const coupling3d::RigidFluidParams3& p, const flesh::FleshParams& flesh, MouthPhases3 mouths = {})
      : c_(data, fluid, p, flesh), mouths_(std::move(mouths)) {}
  void advanceFluid(double dt_s) override { c_.advanceFluid(dt_s); }
  /// Projected or off forcing only (the coupled solve changes data: forceAndCorrect).
  void forceAndProject(const rigid::RigidData& data, double dt_s) override {
    setFlux(data.time_s(), dt_s);
    c_.forceFluid(data, dt_s);
  }
  /// Forcing3::coupled (Lentine et al. 2010 Eq. 9 with the flesh's backward Euler step as its mobility): the
  /// flesh's step and the forcing solved together, the DOFs in held_dofs of infinite mass; data gets the
  /// flesh's and fluid's impulse.
  bool coupledSolve() const override { return c_.params().forcing == coupling3d::Forcing3::coupled; }
  void forceAndCorrect(rigid::RigidData& data, double dt_s, const std::vector<int>& held_dofs) override {
    setFlux(data.time_s(), dt_s);
    c_.setHeldDofs(held_dofs);
    c_.forceFluid(data, dt_s);
  }
  void applyReaction(rigid::RigidData& data) const override { c_.applyReaction(data); }
  /// The last step's flesh and fluid forces on the bones, whatever the forcing (the controller's measurements).
  void applyFluidForce(rigid::RigidData& data) const override { c_.applyFluidForce(data); }
  const std::vector<Vec3>& bodyForce_n() const override { return c_.bodyForce_n(); }
  const std::vector<Vec3>& boneForce_n() const override { return c_.boneForce_n(); }
  int forcingIterations() const override { return c_.forcingIterations(); }
  void placeMarkers(const rigid::RigidData& data) override { c_.placeMarkers(data); }
  void save(std::unique_ptr<FluidSnapshot>& s) const override;
  void restore(const FluidSnapshot& s, const rigid::RigidData& data) override;
  bool exactSnapshot() const override { return true; }
  const coupling3d::FleshFluidCoupling3& coupling() const { return c_; }

 private:
  void setFlux(double time_s, double dt_s);  // the mouths' flux of the step ending at time_s
  coupling3d::FleshFluidCoupling3 c_;
  MouthPhases3 mouths_;
};

// Makes CoupledFleshFluid3s; a single-threaded one's fluid takes one thread.
CoupledFluidFactory fleshFluid(const fluid3d::FluidParams3& fluid, const coupling3d::RigidFluidParams3& p,
                               const flesh::FleshParams& flesh, const MouthPhases3& mouths = {});

}  // namespace creaturelab::control
