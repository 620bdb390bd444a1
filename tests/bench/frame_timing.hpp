#pragma once
// Times a controller's frames in a Google Benchmark loop (bench_control.cpp, bench_control_fluid.cpp):
// one frame per iteration, reported as frames per CPU second of the process (all threads counted,
// "frames_per_cpu_s") and per elapsed second ("frames_per_s").
#include <benchmark/benchmark.h>
#include <time.h>

namespace creaturelab::bench {

inline double clockSeconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

template <class Controller>
void timeFrames(benchmark::State& state, Controller& c) {
  const double cpu0 = clockSeconds(CLOCK_PROCESS_CPUTIME_ID), wall0 = clockSeconds(CLOCK_MONOTONIC);
  long frames = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(c.frame());
    ++frames;
  }
  state.counters["frames_per_cpu_s"] = double(frames) / (clockSeconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0);
  state.counters["frames_per_s"] = double(frames) / (clockSeconds(CLOCK_MONOTONIC) - wall0);
}

}  // namespace creaturelab::bench
