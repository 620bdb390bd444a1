// Speed of the driven flyer in the 3-D coupled fluid against Lentine et al. 2010 Fig. 14: 3.2 s per
// frame for the flyer without flesh (their frame: one animation frame; ours: one controller frame of
// frame_s = 1/60 s, its central differences included). The setting and the arguments: flyer3d_frames.hpp.
#include <benchmark/benchmark.h>

#include "control/fluid_controller.hpp"
#include "flyer3d_frames.hpp"

namespace creaturelab::bench {
namespace {

void BM_Flyer3dFrame(benchmark::State& state) {
  timeFlyer3dFrames(state, false, [](benchmark::State&, const control::FluidController&) {});
}
BENCHMARK(BM_Flyer3dFrame)->Apply(flyer3dArgs);

}  // namespace
}  // namespace creaturelab::bench
