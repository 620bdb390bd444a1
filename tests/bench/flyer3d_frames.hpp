#pragma once
// The driven flyer's frame benchmark in the 3-D coupled fluid (bench_control_fluid3d.cpp without flesh,
// bench_flesh_flyer3d.cpp with): the control_fluid3d kind's defaults (experiments/control/flyer3d.toml's
// setting; with flesh, flyer3d_flesh.toml's) on range(1) cells along x, the evaluations on range(0)
// threads (the fluid of the frame's own steps too); the flow is developed for 0.5 s first. Reported as
// frames per CPU second of the process and per elapsed second (bench::timeFrames).
#include <benchmark/benchmark.h>

#include <string>

#include "control/fluid_controller.hpp"
#include "frame_timing.hpp"
#include "kinds/control_fluid3d.hpp"

namespace creaturelab::bench {

// Times the flyer's frames with `flesh` or without, then `counters(state, controller)` adds the bench's
// own counters; a setting that does not validate is skipped with its message.
template <class Counters>
void timeFlyer3dFrames(benchmark::State& state, bool flesh, Counters&& counters) {
  const std::string source = CREATURELAB_SOURCE_DIR;
  kinds::ControlFluid3dParams q;
  q.controller.model_file = source + "/experiments/control/models/flyer3d.xml";
  q.controller.threads = state.range(0);
  q.fluid.threads = int(state.range(0));
  q.fluid.cells_x = int(state.range(1));
  q.flesh = flesh;
  if (flesh) q.coupling.forcing = coupling3d::Forcing3::coupled;  // flyer3d_flesh.toml's
  if (std::string e = q.validate(); !e.empty()) {
    state.SkipWithError(e.c_str());
    return;
  }
  const rigid::RigidModel model = q.controller.loadModel();
  control::FluidController c(model, q.controller.controllerParams(), q.fluidControlParams(), q.initialRad(),
                             q.coupledFluid());
  c.hold(int(30 * q.controller.substeps));  // the flow develops
  timeFrames(state, c);
  state.counters["max_cg_iterations"] = c.maxForcingIterations();
  counters(state, c);
}

// The arguments (threads, cells along x: 1 x 16, 1 x 32, 2 x 32), three frames each, in seconds of
// elapsed time.
inline void flyer3dArgs(benchmark::internal::Benchmark* b) {
  b->ArgNames({"threads", "cells"})
      ->Args({1, 16})
      ->Args({1, 32})
      ->Args({2, 32})
      ->Iterations(3)
      ->Unit(benchmark::kSecond)
      ->UseRealTime();
}

}  // namespace creaturelab::bench
