#pragma once
// Shared glue between the spring-mass engine and the kinds that use it.
#include <cstdio>
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

// Kind::estimateCost of a spring run: the step simulate() would take, found without stepping.
template <int D>
CostEstimate springRunCost(const springs::Network<D>& net, const springs::State<D>& state,
                           const springs::SimulationOptions& options, const std::string& integrator) {
  try {
    const springs::StepEstimate e = springs::estimateSteps<D>(net, state, options);
    char detail[256];
    std::snprintf(detail, sizeof detail, "dt = %.3g s (%s%s), %d substep(s) per %.3g s frame, %.3g s simulated",
                  e.dt_s, options.dt_s == 0 ? "dt_s = \"auto\" for " : "", integrator.c_str(), e.substeps_per_frame,
                  options.frame_interval_s, options.end_time_s);
    return {e.steps, 0, detail};
  } catch (const std::exception&) {
    return {};  // no stable step at all: simulate() says why when the point runs
  }
}

}  // namespace creaturelab::kinds
