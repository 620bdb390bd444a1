// Speed of the jellyfish's 3-D extrapolation (Rudolf & Mould 2009 §4: simulation plus 3-D
// extrapolation at 30-40 frames per second on a 1.6 GHz laptop). Goal: a 64 x 128 umbrella plus
// tentacles with every variation in <= 2 ms per frame on one core, so that a 100² swim renders
// live at >= 30 frames per second.
//
// BM_RenderFrame: one frame of a recorded swim (the kind's 100² bell: 33 markers, two 10-marker
// tentacles) through the whole pipeline (slice splines, discs, structural + ridges + noise,
// normals twice), at rings x segments with 16 tentacles of 24 x 8. BM_LiveSwim: the 100² swim
// stepped to each frame at 30 frames/s (3-4 coupled steps of 0.01 s) and rendered at 64 x 128:
// frames per CPU second, simulation and rendering together. Both report CPU time of the process.
#include <benchmark/benchmark.h>
#include <time.h>

#include <cmath>
#include <memory>

#include "jellyfish/swimmer.hpp"
#include "render/jellyfish_renderer.hpp"

namespace creaturelab::render {
namespace {

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// The jellyfish kind's model on the paper's 100² grid, from the paper's setting (paperSwimmer()): the calibrated
// active-tension bell, MacCormack advection, a box 1.5 times as tall as wide, dt = 0.01 s.
jellyfish::SwimmerConfig kindConfig() {
  jellyfish::SwimmerConfig c = jellyfish::paperSwimmer();
  c.fluid.cells_x = 100;
  c.fluid.cells_y = 150;
  c.fluid.domain_height_m = 1.5 * c.fluid.domain_width_m;
  c.fluid.time_step_policy = fluid::TimeStepPolicy::fixed;
  c.fluid.fixed_step_s = c.dt_s = 0.01;
  c.fluid.advection = fluid::AdvectionScheme::maccormack;
  c.coupling.kernel = ib::Kernel::peskin4;
  c.bell.segments = 32;
  c.bell.muscle_model = jellyfish::MuscleModel::active_tension;
  c.bell.muscle_tension_n_per_m2 = 5.0;
  c.bell.bending_rigidity_n_m = 1.0e-4;
  c.start_y_fraction = 0.2;
  return c;
}

SliceTopology topologyOf(const jellyfish::Swimmer& s) {
  const auto& m = s.body().model();
  std::vector<std::int64_t> springs, muscles;
  for (int k = 0; k < m.network.springCount(); ++k) springs.insert(springs.end(), {m.network.spring_a[k], m.network.spring_b[k]});
  for (const auto& muscle : m.muscles) muscles.insert(muscles.end(), {muscle.a, muscle.b});
  return sliceTopology(m.bell_markers, springs, muscles, int(s.markers_m().size()));
}

// The swimmer's state now, as a run records it.
struct Frame {
  std::vector<double> xy, activation;
  double time_s = 0;
  SliceFrame view() const { return {time_s, xy, activation}; }
};

Frame record(const jellyfish::Swimmer& s) {
  Frame f;
  f.time_s = s.time_s();
  for (const auto& p : s.markers_m()) f.xy.insert(f.xy.end(), {p.x, p.y});
  for (int m = 0; m < int(s.body().model().muscles.size()); ++m) f.activation.push_back(s.body().activation(m, f.time_s));
  return f;
}

void BM_RenderFrame(benchmark::State& state) {
  jellyfish::Swimmer swimmer(kindConfig());
  for (int k = 0; k < 160; ++k) swimmer.step();  // 1.6 s: into the second contraction
  const Frame frame = record(swimmer);
  RenderParams p;
  p.rings = int(state.range(0));
  p.segments = int(state.range(1));
  JellyfishRenderer renderer(p, topologyOf(swimmer), int(swimmer.markers_m().size()));
  double cpu = 0;
  long frames = 0;
  for (auto _ : state) {
    const double t0 = cpuSeconds();
    benchmark::DoNotOptimize(renderer.render(frame.view()).positions.data());
    cpu += cpuSeconds() - t0;
    ++frames;
  }
  state.counters["ms_per_frame_cpu"] = 1e3 * cpu / double(frames);
  state.counters["vertices"] = renderer.layout().vertices();
  state.counters["triangles"] = renderer.layout().triangles();
}
BENCHMARK(BM_RenderFrame)->ArgNames({"rings", "segments"})->Args({64, 128})->Args({32, 64})->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_LiveSwim(benchmark::State& state) {
  const auto fresh = [] {
    auto s = std::make_unique<jellyfish::Swimmer>(kindConfig());
    for (int k = 0; k < 143; ++k) s->step();  // a warm-up cycle
    return s;
  };
  auto swimmer = fresh();
  JellyfishRenderer renderer(RenderParams{}, topologyOf(*swimmer), int(swimmer->markers_m().size()));
  const double fps = 30;
  double cpu = 0, cpu_render = 0;
  long frames = 0;
  for (auto _ : state) {
    if (frames > 0 && frames % 300 == 0) {  // it swims away after about 10 s: a fresh one (not timed)
      state.PauseTiming();
      swimmer = fresh();
      state.ResumeTiming();
    }
    const double t0 = cpuSeconds();
    const double target = swimmer->time_s() + 1.0 / fps;
    while (swimmer->time_s() < target - 1e-9) swimmer->step();
    const Frame frame = record(*swimmer);
    const double t1 = cpuSeconds();
    benchmark::DoNotOptimize(renderer.render(frame.view()).positions.data());
    const double t2 = cpuSeconds();
    cpu += t2 - t0;
    cpu_render += t2 - t1;
    ++frames;
  }
  state.counters["frames_per_cpu_s"] = double(frames) / cpu;
  state.counters["ms_render_per_frame"] = 1e3 * cpu_render / double(frames);
  state.counters["ms_simulate_per_frame"] = 1e3 * (cpu - cpu_render) / double(frames);
}
BENCHMARK(BM_LiveSwim)->Unit(benchmark::kMillisecond)->MinTime(3.0);

}  // namespace
}  // namespace creaturelab::render
