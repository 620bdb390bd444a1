#pragma once
// Shared glue between the spring-mass engine and the kinds that use it.
#include <string>

#include "kinds/kind.hpp"
#include "springs/integrator.hpp"
#include "springs/simulate.hpp"

namespace creaturelab::kinds {

inline springs::IntegratorKind parseIntegratorOrThrow(const std::string& name) {
  auto k = springs::parseIntegrator(name);
  if (!k) throw std::logic_error("integrator '" + name + "' passed validation but is unknown");
  return *k;
}

// Runs the engine; a divergence becomes a RunFailure carrying the frames recorded so far.
template <int D, class OnFrame>
springs::SimulationSummary runOrFail(const springs::System<D>& system, springs::State<D>& state,
                                     const springs::SimulationOptions& options, OnFrame&& on_frame, Result& partial) {
  try {
    return springs::simulate<D>(system, state, options, on_frame);
  } catch (const springs::DivergenceError& e) {
    throw RunFailure(e.what(), partial);
  }
}

}  // namespace creaturelab::kinds
