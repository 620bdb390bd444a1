#include "control/coupled_flesh_fluid3.hpp"

namespace creaturelab::control {
namespace {
struct FleshFluidSnapshot3 final : FluidSnapshot {
  coupling3d::FleshFluidState3 state;
};
}  // namespace

void CoupledFleshFluid3::save(std::unique_ptr<FluidSnapshot>& s) const {
  if (!dynamic_cast<FleshFluidSnapshot3*>(s.get())) s = std::make_unique<FleshFluidSnapshot3>();
  c_.save(static_cast<FleshFluidSnapshot3&>(*s).state);
}

void CoupledFleshFluid3::restore(const FluidSnapshot& s, const rigid::RigidData& data) {
  c_.restore(dynamic_cast<const FleshFluidSnapshot3&>(s).state, data);
}

CoupledFluidFactory fleshFluid(const fluid3d::FluidParams3& fluid, const coupling3d::RigidFluidParams3& p,
                               const flesh::FleshParams& flesh) {
  return [fluid, p, flesh](const rigid::RigidData& data, bool single_threaded) -> std::unique_ptr<CoupledFluid> {
    fluid3d::FluidParams3 f = fluid;
    if (single_threaded) f.threads = 1;
    return std::make_unique<CoupledFleshFluid3>(data, f, p, flesh);
  };
}

}  // namespace creaturelab::control
