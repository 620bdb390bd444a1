#include "control/coupled_fluid3.hpp"

namespace creaturelab::control {
namespace {
struct FluidSnapshot3 final : FluidSnapshot {
  fluid3d::MacGrid3 grid;
};
}  // namespace

void CoupledFluid3::save(std::unique_ptr<FluidSnapshot>& s) const {
  if (!dynamic_cast<FluidSnapshot3*>(s.get())) s = std::make_unique<FluidSnapshot3>();
  static_cast<FluidSnapshot3&>(*s).grid = c_.fluid().grid();
}

void CoupledFluid3::restore(const FluidSnapshot& s, const rigid::RigidData& data) {
  c_.fluid().grid() = dynamic_cast<const FluidSnapshot3&>(s).grid;
  c_.placeMarkers(data);
}

CoupledFluidFactory spatialFluid(const fluid3d::FluidParams3& fluid, const coupling3d::RigidFluidParams3& p) {
  return [fluid, p](const rigid::RigidData& data, bool single_threaded) -> std::unique_ptr<CoupledFluid> {
    fluid3d::FluidParams3 f = fluid;
    if (single_threaded) f.threads = 1;
    return std::make_unique<CoupledFluid3>(data, f, p);
  };
}

}  // namespace creaturelab::control
