// Speed of Tu's artificial fish. The thesis: 30 frames per second with up to 5 wireframe
// fish on a 1996 SGI Indigo2. Goals here, on one core: one fish step (controller + unit forces +
// water + LDL^T solve) <= 10 us; the skin of one fish at 32 x 64 <= 100 us; and a school swept over
// its size (BM_School: fish-steps per second; the fish do not interact, so a school of N costs N
// single fish steps and one core keeps 1,000 fish in real time at 0.055 s steps when a step is
// under 55 us).
#include <benchmark/benchmark.h>

#include <vector>

#include "fish/fish_run.hpp"
#include "fish/fish_solver.hpp"
#include "fish/motor.hpp"
#include "fish/skin.hpp"

namespace creaturelab::fish {
namespace {

// The setting these figures are for: the [reimpl] soft units (c = 38, 30, 28 N/m) at its 0.055 s step
// in linear water, alpha = 0.7 (the structs' defaults are the fish kind's calibrated body at 2 ms).
FishModel softFish() {
  UnitParams u;
  u.stiffness_cross_n_per_m = 38.0;
  u.stiffness_other_n_per_m = 30.0;
  u.stiffness_muscle_n_per_m = 28.0;
  FishGeometry g;
  g.body_length_m = 1.0;
  return buildFish(g, u);
}

SolverParams softSolver() {
  SolverParams p;
  p.dt_s = 0.055;
  p.water.mu = 100;
  p.water.law = WaterLaw::linear;
  return p;
}

MotorParams softMotor() {
  MotorParams m;
  m.swim = {0.7, 0.004, 0.7, 0.004};
  m.turn_amplitude = 0.7;
  m.turn_rate = 0.016;
  return m;
}

// One full step of a swimming fish in water at the default 0.055 s step.
void BM_FishStep(benchmark::State& state) {
  const FishModel fish = softFish();
  const SolverParams p = softSolver();
  FishSolver solver(fish, p);
  MotorController motor(fish, softMotor(), parseSchedule("swim 1000000"));
  FishState s = restState(fish);
  for (auto _ : state) {
    motor.apply(s.time_s, p.dt_s, s.rest_m);
    if (solver.step(s).status != StepStatus::ok) state.SkipWithError("blew up");
    benchmark::DoNotOptimize(s.x_m.data());
  }
  state.counters["us_per_step"] = benchmark::Counter(double(state.iterations()) * 1e-6,
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FishStep);

// The skin of one fish from its node positions: control points (24 face frames, 408 bound control
// points), then both body halves sampled 32 around x 64 along plus the two fins, with vertex normals.
void BM_Skin32x64(benchmark::State& state) {
  const FishModel fish = softFish();
  FishSkin skin(fish, {});
  NodeMatrix x = fish.rest_positions_m;
  x(13, 1) += 0.05;  // a bent peduncle: not the rest shape
  SkinMesh mesh;
  skin.mesh(32, 64, mesh);  // the sampled basis is cached after the first call
  for (auto _ : state) {
    skin.update(x);
    skin.mesh(32, 64, mesh);
    benchmark::DoNotOptimize(mesh.positions.data());
  }
  state.counters["vertices"] = double(mesh.positions.size());
}
BENCHMARK(BM_Skin32x64)->Unit(benchmark::kMicrosecond);

// A school of N independent fish, stepped one after the other: one iteration is one step of all N.
void BM_School(benchmark::State& state) {
  const int n = int(state.range(0));
  const FishModel fish = softFish();
  const SolverParams p = softSolver();
  std::vector<FishSolver> solvers;
  std::vector<MotorController> motors;
  std::vector<FishState> states;
  solvers.reserve(n);
  motors.reserve(n);
  for (int k = 0; k < n; ++k) {
    solvers.emplace_back(fish, p);
    MotorParams m = softMotor();
    m.swim.amplitude_anterior = m.swim.amplitude_posterior = 0.6 + 0.1 * (k % 3);  // not all in step
    motors.emplace_back(fish, m, parseSchedule("swim 1000000"));
    states.push_back(restState(fish));
  }
  for (auto _ : state) {
    for (int k = 0; k < n; ++k) {
      motors[k].apply(states[k].time_s, p.dt_s, states[k].rest_m);
      if (solvers[k].step(states[k]).status != StepStatus::ok) state.SkipWithError("blew up");
    }
    benchmark::ClobberMemory();
  }
  state.counters["fish_steps_per_s"] = benchmark::Counter(double(state.iterations()) * n, benchmark::Counter::kIsRate);
  state.counters["school_steps_per_s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
  // simulated seconds per second at 0.055 s per step (>= 1: real time)
  state.counters["realtime_factor"] =
      benchmark::Counter(double(state.iterations()) * p.dt_s, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_School)->RangeMultiplier(10)->Range(1, 1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace creaturelab::fish
