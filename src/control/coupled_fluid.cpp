#include "control/coupled_fluid.hpp"

namespace creaturelab::control {
namespace {
struct FluidSnapshot2 final : FluidSnapshot {
  coupling::CouplingState state;
};
}  // namespace

void CoupledFluid2::forceAndProject(const rigid::RigidData& data, double dt_s) {
  c_.forceFluid(data, dt_s);
  c_.project(dt_s);
}

void CoupledFluid2::save(std::unique_ptr<FluidSnapshot>& s) const {
  if (!dynamic_cast<FluidSnapshot2*>(s.get())) s = std::make_unique<FluidSnapshot2>();
  c_.save(static_cast<FluidSnapshot2&>(*s).state);
}

void CoupledFluid2::restore(const FluidSnapshot& s, const rigid::RigidData&) {
  c_.restore(dynamic_cast<const FluidSnapshot2&>(s).state);
}

CoupledFluidFactory planarFluid(const fluid::FluidParams& fluid, const coupling::RigidFluidParams& p) {
  return [fluid, p](const rigid::RigidData& data, bool single_threaded) -> std::unique_ptr<CoupledFluid> {
    fluid::FluidParams f = fluid;
    if (single_threaded) f.threads = 1;
    return std::make_unique<CoupledFluid2>(data, f, p);
  };
}

}  // namespace creaturelab::control
