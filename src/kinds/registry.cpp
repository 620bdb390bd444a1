#include "kinds/charlotte.hpp"
#include "kinds/control.hpp"
#include "kinds/control_fluid.hpp"
#include "kinds/control_fluid3d.hpp"
#include "kinds/control_fluid3d_swimmer.hpp"
#include "kinds/fish.hpp"
#include "kinds/fluid.hpp"
#include "kinds/fluid3d.hpp"
#include "kinds/jellyfish.hpp"
#include "kinds/kind.hpp"
#include "kinds/membrane.hpp"
#include "kinds/oscillator.hpp"
#include "kinds/strand.hpp"
#include "kinds/web.hpp"

namespace creaturelab::kinds {

Registry defaultRegistry() {
  Registry r;
  r.add(std::make_unique<OscillatorKind>());
  r.add(std::make_unique<StrandKind>());
  r.add(std::make_unique<FluidKind>());
  r.add(std::make_unique<WebKind>());
  r.add(std::make_unique<CharlotteKind>());
  r.add(std::make_unique<MembraneKind>());
  r.add(std::make_unique<JellyfishKind>());
  r.add(std::make_unique<ControlKind>());
  r.add(std::make_unique<ControlFluidKind>());
  r.add(std::make_unique<FishKind>());
  r.add(std::make_unique<Fluid3dKind>());
  r.add(std::make_unique<ControlFluid3dKind>());
  r.add(std::make_unique<ControlFluid3dSwimmerKind>());
  return r;
}

Params withDefaults(const Kind& kind, Params params) {
  for (const auto& spec : kind.params()) params.emplace(spec.name, spec.default_value);
  return params;
}

}  // namespace creaturelab::kinds
