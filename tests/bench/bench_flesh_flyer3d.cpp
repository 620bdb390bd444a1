// Speed of the driven flyer wrapped in flesh in the 3-D coupled fluid against Lentine et al. 2010 Fig. 14:
// 34 s per frame for the flyer with flesh (their frame: one animation frame; ours: one controller frame
// of frame_s = 1/60 s, its central differences included). The setting (flesh = true) and the arguments:
// flyer3d_frames.hpp; the flesh's vertices counted beside.
#include <benchmark/benchmark.h>

#include "control/coupled_flesh_fluid3.hpp"
#include "control/fluid_controller.hpp"
#include "flyer3d_frames.hpp"

namespace creaturelab::bench {
namespace {

void BM_Flyer3dFleshFrame(benchmark::State& state) {
  timeFlyer3dFrames(state, true, [](benchmark::State& s, const control::FluidController& c) {
    s.counters["flesh_vertices"] =
        dynamic_cast<const control::CoupledFleshFluid3&>(c.coupledFluid()).coupling().surfaceMarkers();
  });
}
BENCHMARK(BM_Flyer3dFleshFrame)->Apply(flyer3dArgs);

}  // namespace
}  // namespace creaturelab::bench
