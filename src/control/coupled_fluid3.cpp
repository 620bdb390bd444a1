#include "control/coupled_fluid3.hpp"

namespace creaturelab::control {
namespace {
struct FluidSnapshot3 final : FluidSnapshot {
  coupling3d::CouplingState3 state;
};
}  // namespace

void CoupledFluid3::save(std::unique_ptr<FluidSnapshot>& s) const {
  if (!dynamic_cast<FluidSnapshot3*>(s.get())) s = std::make_unique<FluidSnapshot3>();
  c_.save(static_cast<FluidSnapshot3&>(*s).state);
}

void CoupledFluid3::restore(const FluidSnapshot& s, const rigid::RigidData&) {
  c_.restore(dynamic_cast<const FluidSnapshot3&>(s).state);
}

CoupledFluidFactory spatialFluid(const fluid3d::FluidParams3& fluid, const coupling3d::RigidFluidParams3& p) {
  return [fluid, p](const rigid::RigidData& data, bool single_threaded) -> std::unique_ptr<CoupledFluid> {
    fluid3d::FluidParams3 f = fluid;
    if (single_threaded) f.threads = 1;
    return std::make_unique<CoupledFluid3>(data, f, p);
  };
}

}  // namespace creaturelab::control
