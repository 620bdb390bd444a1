#pragma once
// The fluid the controller in the fluid (fluid_controller.hpp) steps with the creature's bodies:
// one coupled step of Lentine et al. 2010 §6 in the caller's order (advanceFluid; the caller steps
// the solid under the last reaction; forceAndProject at the new pose), the fluid's force per body,
// and snapshots for §4.3's derivative evaluations ("each perturbation needs its own copy of the
// fluid state"). Adapters: CoupledFluid2 (coupling::RigidFluidCoupling, the planar fluid, here) and
// CoupledFluid3 (coupling3d::RigidFluidCoupling3, coupled_fluid3.hpp).
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include "coupling/rigid_fluid_coupling.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::control {

using rigid::Vec3;

// A copy of a coupled fluid's state (the adapter's own type behind it).
struct FluidSnapshot {
  virtual ~FluidSnapshot() = default;
};

class CoupledFluid {
 public:
  virtual ~CoupledFluid() = default;
  // §6 steps 2 and 5: external forces, advection, viscosity -> u~.
  virtual void advanceFluid(double dt_s) = 0;
  // §6 step 4: the markers at data's pose force the fluid with the solid's effective velocity, and
  // the projection gives u^{n+1}; the bodies' reaction is kept for the next step.
  virtual void forceAndProject(const rigid::RigidData& data, double dt_s) = 0;
  // True when the step's forcing is Eq. 9's coupled solve (Lentine et al. 2010 §5): then the caller steps
  // the solid without the fluid's force and calls forceAndCorrect in place of forceAndProject.
  virtual bool coupledSolve() const { return false; }
  // The coupled solve at data's pose: the forcing solved with the bodies' velocities, the DOFs in
  // held_dofs (the servo's prescribed ones) of infinite mass; data gets the fluid's impulse. Only when
  // coupledSolve() (else std::logic_error).
  virtual void forceAndCorrect(rigid::RigidData&, double, const std::vector<int>&) {
    throw std::logic_error("forceAndCorrect: this fluid's forcing is not the coupled solve");
  }
  // Adds the last step's reaction on every moving body to data's applied forces.
  virtual void applyReaction(rigid::RigidData& data) const = 0;
  // Adds the last step's fluid force on every moving body to data's applied forces, whatever the forcing
  // (the controller's measurements); the reaction unless the adapter says otherwise.
  virtual void applyFluidForce(rigid::RigidData& data) const { applyReaction(data); }
  // Per body (world body 0 included), the force (N, world) the fluid exerted in the last step.
  virtual const std::vector<Vec3>& bodyForce_n() const = 0;
  // Per body, the force (N, world) its bone took in the last step: with flesh (coupled_flesh_fluid3.hpp) the
  // flesh's binding reaction plus the fluid's force on the bone's interior; without flesh bodyForce_n.
  virtual const std::vector<Vec3>& boneForce_n() const { return bodyForce_n(); }
  virtual int forcingIterations() const = 0;
  // Moves the markers to data's pose without a step (§3.3's placed perturbation).
  virtual void placeMarkers(const rigid::RigidData& data) = 0;
  // Copies the state into `s` (made or reused), and back; restore follows data's restored pose.
  virtual void save(std::unique_ptr<FluidSnapshot>& s) const = 0;
  virtual void restore(const FluidSnapshot& s, const rigid::RigidData& data) = 0;
  // True when restore brings back everything that decides the next step. When false (the last
  // step's reaction and the forcing's warm start stay the adapter's own), the controller gives each
  // derivative evaluation its own copy, so results still do not depend on the thread count.
  virtual bool exactSnapshot() const = 0;
};

// Makes a coupled fluid around data's pose (data.kinematics() done); `single_threaded`: for a
// derivative evaluation that runs beside others (its fluid then takes one thread).
using CoupledFluidFactory =
    std::function<std::unique_ptr<CoupledFluid>(const rigid::RigidData& data, bool single_threaded)>;

// The planar fluid (coupling::RigidFluidCoupling): forceAndProject is forceFluid then project.
class CoupledFluid2 final : public CoupledFluid {
 public:
  CoupledFluid2(const rigid::RigidData& data, const fluid::FluidParams& fluid, const coupling::RigidFluidParams& p)
      : c_(data, fluid, p) {}
  void advanceFluid(double dt_s) override { c_.advanceFluid(dt_s); }
  void forceAndProject(const rigid::RigidData& data, double dt_s) override;
  void applyReaction(rigid::RigidData& data) const override { c_.applyReaction(data); }
  const std::vector<Vec3>& bodyForce_n() const override { return c_.bodyForce_n(); }
  int forcingIterations() const override { return c_.forcingIterations(); }
  void placeMarkers(const rigid::RigidData& data) override { c_.placeMarkers(data); }
  void save(std::unique_ptr<FluidSnapshot>& s) const override;
  void restore(const FluidSnapshot& s, const rigid::RigidData& data) override;
  bool exactSnapshot() const override { return true; }
  const coupling::RigidFluidCoupling& coupling() const { return c_; }

 private:
  coupling::RigidFluidCoupling c_;
};

// Makes CoupledFluid2s; a single-threaded one's fluid takes one thread.
CoupledFluidFactory planarFluid(const fluid::FluidParams& fluid, const coupling::RigidFluidParams& p);

}  // namespace creaturelab::control
