// Speed of the driven flyer wrapped in flesh in the 3-D coupled fluid against Lentine et al. 2010 Fig. 14:
// 34 s per frame for the flyer with flesh (their frame: one animation frame; ours: one controller frame
// of frame_s = 1/60 s, its central differences included). The setting is
// experiments/control/flyer3d_flesh.toml's (the control_fluid3d kind's defaults with flesh = true) on
// range(1) cells along x, the evaluations on range(0) threads (the fluid of the frame's own steps too);
// the flow is developed for 0.5 s first. Reported as frames per CPU second of the process and per
// elapsed second (bench::timeFrames).
#include <benchmark/benchmark.h>

#include <string>

#include "control/coupled_flesh_fluid3.hpp"
#include "control/fluid_controller.hpp"
#include "frame_timing.hpp"
#include "kinds/control_fluid3d.hpp"

namespace creaturelab::kinds {
namespace {

void BM_Flyer3dFleshFrame(benchmark::State& state) {
  const std::string source = CREATURELAB_SOURCE_DIR;
  ControlFluid3dParams q;
  q.controller.model_file = source + "/experiments/control/models/flyer3d.xml";
  q.controller.threads = state.range(0);
  q.fluid.threads = int(state.range(0));
  q.fluid.cells_x = int(state.range(1));
  q.flesh = true;
  if (std::string e = q.validate(); !e.empty()) {
    state.SkipWithError(e.c_str());
    return;
  }
  const rigid::RigidModel model = q.controller.loadModel();
  control::FluidController c(model, q.controller.controllerParams(), q.fluidControlParams(), q.initialRad(),
                             q.coupledFluid());
  c.hold(int(30 * q.controller.substeps));  // the flow develops
  bench::timeFrames(state, c);
  state.counters["max_cg_iterations"] = c.maxForcingIterations();
  state.counters["flesh_vertices"] =
      dynamic_cast<const control::CoupledFleshFluid3&>(c.coupledFluid()).coupling().surfaceMarkers();
}
BENCHMARK(BM_Flyer3dFleshFrame)
    ->ArgNames({"threads", "cells"})
    ->Args({1, 16})
    ->Args({1, 32})
    ->Args({2, 32})
    ->Iterations(3)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace
}  // namespace creaturelab::kinds
