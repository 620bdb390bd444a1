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

void CoupledFleshFluid3::setFlux(double time_s, double dt_s) {
  if (mouths_.flux_m_per_s.empty()) return;
  // The bodies' time is the step's end: the flux of the step's middle.
  const double flux = mouths_.flux_m_per_s[coupling::phaseAt(mouths_.schedule, time_s - 0.5 * dt_s)];
  for (std::size_t m = 0; m < c_.params().mouths.size(); ++m) c_.setMouthFlux(m, flux);
}

CoupledFluidFactory fleshFluid(const fluid3d::FluidParams3& fluid, const coupling3d::RigidFluidParams3& p,
                               const flesh::FleshParams& flesh, const MouthPhases3& mouths) {
  return [fluid, p, flesh, mouths](const rigid::RigidData& data, bool single_threaded) -> std::unique_ptr<CoupledFluid> {
    fluid3d::FluidParams3 f = fluid;
    if (single_threaded) f.threads = 1;
    return std::make_unique<CoupledFleshFluid3>(data, f, p, flesh, mouths);
  };
}

}  // namespace creaturelab::control
