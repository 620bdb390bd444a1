// Speed of the aqueous swimmer wrapped in flesh in the 3-D coupled fluid against Lentine et al. 2010 Fig. 14:
// 83 s per frame for the swimmer with flesh (their frame: one animation frame; ours: one controller frame
// of frame_s = 1/60 s, its derivative evaluations included). The setting is experiments/control/swimmer3d.toml's
// (the control_fluid3d_swimmer kind's defaults with the mouth on the body, flesh = true: the flesh in the
// coupled solve, bound at 200 Hz) on range(1) cells along x, the evaluations on range(0) threads (the fluid of the frame's own
// steps too); timed from rest. Reported as frames per CPU second of the process and per elapsed second
// (bench::timeFrames).
#include <benchmark/benchmark.h>

#include <string>

#include "control/coupled_flesh_fluid3.hpp"
#include "control/fluid_controller.hpp"
#include "frame_timing.hpp"
#include "kinds/control_fluid3d_swimmer.hpp"

namespace creaturelab::kinds {
namespace {

void BM_Swimmer3dFleshFrame(benchmark::State& state) {
  const std::string source = CREATURELAB_SOURCE_DIR;
  ControlFluid3dSwimmerParams q;
  q.controller.model_file = source + "/experiments/control/models/swimmer3d.xml";
  q.controller.threads = state.range(0);
  q.fluid.threads = int(state.range(0));
  q.fluid.cells_x = int(state.range(1));
  q.mouth_body = "body";
  q.flesh = true;
  q.flesh_params.binding_hz = 200.0;
  if (std::string e = q.validate(); !e.empty()) {
    state.SkipWithError(e.c_str());
    return;
  }
  const rigid::RigidModel model = q.controller.loadModel();
  const control::RiseSettings3 rs = q.riseSettings(model);
  control::FluidController c(model, q.controller.controllerParams(), q.fluidControlParams(), q.initialRad(),
                             q.coupledFluid(model, rs));
  bench::timeFrames(state, c);
  state.counters["max_cg_iterations"] = c.maxForcingIterations();
  state.counters["flesh_vertices"] =
      dynamic_cast<const control::CoupledFleshFluid3&>(c.coupledFluid()).coupling().surfaceMarkers();
}
BENCHMARK(BM_Swimmer3dFleshFrame)
    ->ArgNames({"threads", "cells"})
    ->Args({1, 16})
    ->Args({2, 16})
    ->Iterations(3)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace
}  // namespace creaturelab::kinds
